using DeltaInterpolator.Core.Characters;
using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Playback;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Playback
{
    /// <summary>
    /// A humanoid character as the Unity layer would describe it (<see cref="CharacterRig"/>), built from a
    /// motion-capture skeleton so that it is not the model's: bones renamed to <c>HumanBodyBones</c> names
    /// (joints between human bones kept under their own names, fingers and eyes dropped as the component
    /// never collects them), every bone's local frame turned at random (another rig's axes), mirrored into
    /// Unity's left-handed space, converted to metres, and hung under an armature that is turned and scaled
    /// (as an FBX from Blender: −90° about X, 0.01). Poses of the source clip come out as the animation
    /// stream would hold them.
    /// </summary>
    public sealed class UnityHumanoid
    {
        private readonly MotionClip _clip;
        private readonly int[] _sourceOf;        // rig bone → source joint
        private readonly QuaternionD[] _frame;   // rig bone → its local frame change
        private readonly double _metres;

        private UnityHumanoid(string name, MotionClip clip, IReadOnlyDictionary<string, string> humanNames, double metresPerUnit, RootFrame armature, int seed, ReferencePose? reference)
        {
            _clip = clip;
            _metres = metresPerUnit;
            Armature = armature;
            Skeleton s = clip.Skeleton;
            var keep = new bool[s.JointCount];
            for (int j = 0; j < s.JointCount; j++)
            {
                if (!humanNames.ContainsKey(s.Names[j])) continue;
                for (int k = j; k >= 0 && !keep[k]; k = s.Parents[k]) keep[k] = true;
            }

            var sourceOf = new List<int>();
            var bone = new int[s.JointCount];
            var names = new List<string>();
            var parents = new List<int>();
            for (int j = 0; j < s.JointCount; j++)
            {
                bone[j] = -1;
                if (!keep[j]) continue;
                bone[j] = sourceOf.Count;
                sourceOf.Add(j);
                names.Add(humanNames.TryGetValue(s.Names[j], out string? human) ? human : s.Names[j]);
                parents.Add(j == 0 ? -1 : bone[s.Parents[j]]);
            }

            _sourceOf = sourceOf.ToArray();
            var random = new TestRandom(seed);
            _frame = new QuaternionD[_sourceOf.Length];
            for (int b = 0; b < _frame.Length; b++) _frame[b] = random.Rotation();
            Parents = parents.ToArray();
            ReferencePose pose = reference ?? ReferencePose.FromFrame(clip, 0);
            var refRoot = new double[3];
            var refRotations = new double[4 * _sourceOf.Length];
            var positions = new double[3 * _sourceOf.Length];
            Convert(pose.RootPosition, pose.LocalRotations, refRoot, refRotations, positions);
            ReferenceRotations = refRotations;
            Rig = new CharacterRig(name, names, Parents, positions, refRotations, armature);
            Positions = positions;
        }

        /// <summary>The rig description the component would build.</summary>
        public CharacterRig Rig { get; }

        /// <summary>The armature the root bone hangs under.</summary>
        public RootFrame Armature { get; }

        /// <summary>Rig bone parents.</summary>
        public int[] Parents { get; }

        /// <summary>Rig bone local positions (the stream's units).</summary>
        public double[] Positions { get; }

        /// <summary>The reference pose's local rotations (stream space).</summary>
        public double[] ReferenceRotations { get; }

        /// <summary>Frames of the source clip.</summary>
        public int FrameCount => _clip.FrameCount;

        /// <summary>Bones the rig has.</summary>
        public int BoneCount => _sourceOf.Length;

        /// <summary>A CMU (Hahne, 31 joints) skeleton as a humanoid: LowerBack/Spine/Spine1 are Spine/Chest/UpperChest, Neck1 stays between Neck and Head.</summary>
        public static UnityHumanoid Cmu(MotionClip clip, int seed) => new UnityHumanoid("CMU humanoid", clip, CmuNames, 0.056444, Blender, seed, null);

        /// <summary>A CMU "Daz-friendly" Poser skeleton as a humanoid: no upper chest, no toes; its bind (zero) pose is the reference.</summary>
        public static UnityHumanoid Poser(MotionClip clip, int seed) => new UnityHumanoid("Poser humanoid", clip, PoserNames, 0.01, Blender, seed, ReferencePose.Zero(clip.Skeleton));

        /// <summary>The model's own skeleton (LaFAN1 centimetres) as a humanoid, its T-pose the reference.</summary>
        public static UnityHumanoid Model(Skeleton model, RootFrame armature, int seed)
        {
            var names = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (string joint in model.Names)
            {
                IReadOnlyList<string> chain = JointMap.UnityHumanoid.SourceChain(joint)!;
                names[joint] = chain[chain.Count - 1];
            }

            ReferencePose tpose = ReferencePose.ModelTPose(model);
            MotionClip clip = MotionClip.CreateRestPose(model, 1, 1.0 / 30.0);
            for (int i = 0; i < tpose.LocalRotations.Count; i++) clip.LocalRotations[i] = tpose.LocalRotations[i];
            Vector3D root = tpose.RootPosition;
            root.Write(clip.LocalPositions, 0);
            return new UnityHumanoid("model humanoid", clip, names, 0.01, armature, seed, tpose);
        }

        /// <summary>An FBX armature from Blender: turned −90° about X, centimetres under a metre character.</summary>
        public static RootFrame Blender => new RootFrame(new Vector3D(0.0, 0.02, 0.0), Quaternions.FromAxisAngle(Vector3D.UnitX, -Math.PI / 2), 0.01);

        /// <summary>The pose of source frame <paramref name="frame"/> as the animation stream holds it.</summary>
        public void Pose(int frame, double[] root, double[] rotations)
        {
            int j = _clip.Skeleton.JointCount;
            var local = new double[4 * j];
            Array.Copy(_clip.LocalRotations, _clip.RotationIndex(frame, 0), local, 0, 4 * j);
            Convert(Vector3D.Read(_clip.LocalPositions, _clip.PositionIndex(frame, 0)), local, root, rotations, null);
        }

        /// <summary>Character-space (Unity) global positions of every bone of a stream pose.</summary>
        public Vector3D[] GlobalPositions(double[] root, double[] rotations)
        {
            int n = BoneCount;
            var position = new Vector3D[n];
            var rotation = new QuaternionD[n];
            for (int b = 0; b < n; b++)
            {
                QuaternionD q = QuaternionD.Read(rotations, 4 * b);
                if (b == 0)
                {
                    position[0] = Armature.PointToParent(Vector3D.Read(root, 0));
                    rotation[0] = Armature.RotationToParent(q);
                    continue;
                }

                int p = Parents[b];
                position[b] = position[p] + Quaternions.Apply(rotation[p], Armature.Scale * Vector3D.Read(Positions, 3 * b));
                rotation[b] = Quaternions.Multiply(rotation[p], q);
            }

            return position;
        }

        /// <summary>Names → the rig bone index.</summary>
        public int BoneIndex(string name) => Rig.Skeleton.IndexOf(name);

        private void Convert(Vector3D sourceRoot, IReadOnlyList<double> sourceLocal, double[] root, double[] rotations, double[]? positions)
        {
            Skeleton s = _clip.Skeleton;
            for (int b = 0; b < _sourceOf.Length; b++)
            {
                int j = _sourceOf[b];
                QuaternionD q = new QuaternionD(sourceLocal[4 * j], sourceLocal[4 * j + 1], sourceLocal[4 * j + 2], sourceLocal[4 * j + 3]);
                // Another rig's bone axes: the world pose is the same, each bone's local frame is turned by F.
                QuaternionD parentFrame = b == 0 ? QuaternionD.Identity : _frame[Parents[b]];
                QuaternionD reframed = Quaternions.Multiply(Quaternions.Conjugate(parentFrame), Quaternions.Multiply(q, _frame[b]));
                QuaternionD unity = Handedness.RotationToUnity(Quaternions.Normalize(reframed));
                if (b == 0)
                {
                    Armature.PointFromParent(Handedness.PositionToUnity(_metres * sourceRoot)).Write(root, 0);
                    Armature.RotationFromParent(unity).Write(rotations, 0);
                    if (positions != null) Vector3D.Read(root, 0).Write(positions, 0);
                    continue;
                }

                unity.Write(rotations, 4 * b);
                if (positions != null)
                {
                    Vector3D offset = Quaternions.Apply(Quaternions.Conjugate(parentFrame), Vector3D.Read(s.OffsetSpan, 3 * j));
                    ((1.0 / Armature.Scale) * Handedness.PositionToUnity(_metres * offset)).Write(positions, 3 * b);
                }
            }
        }

        /// <summary>The CMU Poser folder beside the repository (../shared/data/cmu-more); skips the test when absent.</summary>
        public static string RequireCmuMore()
        {
            string? root = TestEnvironment.RepositoryRoot;
            string? dir = root != null ? Path.GetFullPath(Path.Combine(root, "..", "shared", "data", "cmu-more")) : null;
            if (dir == null || !File.Exists(Path.Combine(dir, "12_01.bvh")))
            {
                Assert.Ignore($"CMU Poser data absent: {dir ?? "../shared/data/cmu-more"}/12_01.bvh not found (place the cgspeed Daz-friendly CMU BVH files in ../shared/data/cmu-more); skipping the data-dependent test.");
            }

            return dir!;
        }

        private static readonly Dictionary<string, string> CmuNames = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            ["Hips"] = "Hips", ["LeftUpLeg"] = "LeftUpperLeg", ["LeftLeg"] = "LeftLowerLeg", ["LeftFoot"] = "LeftFoot", ["LeftToeBase"] = "LeftToes",
            ["RightUpLeg"] = "RightUpperLeg", ["RightLeg"] = "RightLowerLeg", ["RightFoot"] = "RightFoot", ["RightToeBase"] = "RightToes",
            ["LowerBack"] = "Spine", ["Spine"] = "Chest", ["Spine1"] = "UpperChest", ["Neck"] = "Neck", ["Head"] = "Head",
            ["LeftShoulder"] = "LeftShoulder", ["LeftArm"] = "LeftUpperArm", ["LeftForeArm"] = "LeftLowerArm", ["LeftHand"] = "LeftHand",
            ["RightShoulder"] = "RightShoulder", ["RightArm"] = "RightUpperArm", ["RightForeArm"] = "RightLowerArm", ["RightHand"] = "RightHand",
        };

        private static readonly Dictionary<string, string> PoserNames = new Dictionary<string, string>(StringComparer.Ordinal)
        {
            ["hip"] = "Hips", ["lThigh"] = "LeftUpperLeg", ["lShin"] = "LeftLowerLeg", ["lFoot"] = "LeftFoot",
            ["rThigh"] = "RightUpperLeg", ["rShin"] = "RightLowerLeg", ["rFoot"] = "RightFoot",
            ["abdomen"] = "Spine", ["chest"] = "Chest", ["neck"] = "Neck", ["head"] = "Head",
            ["lCollar"] = "LeftShoulder", ["lShldr"] = "LeftUpperArm", ["lForeArm"] = "LeftLowerArm", ["lHand"] = "LeftHand",
            ["rCollar"] = "RightShoulder", ["rShldr"] = "RightUpperArm", ["rForeArm"] = "RightLowerArm", ["rHand"] = "RightHand",
        };
    }
}
