using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Characters
{
    /// <summary>
    /// A character's rig as Unity sees it: the bones the component drives (names, parents), each bone's
    /// local position and the local rotation of a reference pose, all in Unity's space (left-handed, Y up,
    /// quaternions (w, x, y, z)), and where the root bone's parent (the armature) sits in the character.
    /// It becomes the <see cref="IPoseConverter"/> between the character and the model through Core's
    /// <see cref="SkeletonMap"/> (<see cref="CreatePoseConverter"/>), which owns every conversion: handedness,
    /// units, bone frames, joints the rig lacks.
    /// </summary>
    /// <remarks>
    /// <para>Bones are the ones the Unity layer collects: for a humanoid avatar the human bones
    /// (<c>HumanBodyBones</c> names) and every transform on the paths between them (an unnamed neck
    /// joint, a spine joint the avatar skips); for a generic rig the bones a joint map names and the paths
    /// between them. Bones not listed (fingers, twist bones, props) are never touched, so they keep the
    /// character's own animation. Parents come before children; the root bone (index 0, the hips) has
    /// parent −1.</para>
    /// <para>Local positions are in the units of each bone's parent; the armature's scale turns them into
    /// the character's units (an FBX armature at scale 0.01 holds centimetres). The character's own scale
    /// in the scene does not matter here: only root motion sees it (<see cref="Playback.RootMotion"/>).</para>
    /// </remarks>
    public sealed class CharacterRig
    {
        /// <summary>The largest angle (degrees) a mapped bone of the reference pose may point away from the model's T-pose.</summary>
        public const double DefaultMaxBoneDeviationDegrees = 25.0;

        private readonly string[] _names;
        private readonly int[] _parents;
        private readonly double[] _positions;
        private readonly double[] _rotations;

        /// <summary>Describes a rig (arrays copied).</summary>
        /// <param name="name">The character's name, for messages.</param>
        /// <param name="boneNames">Bone names, unique.</param>
        /// <param name="parents">Each bone's parent index (−1 for the root bone, which comes first).</param>
        /// <param name="localPositions">Bones × 3 local positions in Unity's space (the root's: in the armature).</param>
        /// <param name="referenceRotations">Bones × 4 local rotations (w, x, y, z) in Unity's space of the reference pose (a T-pose).</param>
        /// <param name="armature">The root bone's parent in the character's space (<see cref="RootFrame.Identity"/> when the root bone is a direct child).</param>
        /// <exception cref="ArgumentException">Counts do not match, the hierarchy is not valid, or a rotation is zero or not finite (named).</exception>
        public CharacterRig(string name, IReadOnlyList<string> boneNames, IReadOnlyList<int> parents, IReadOnlyList<double> localPositions, IReadOnlyList<double> referenceRotations, RootFrame armature)
        {
            Name = string.IsNullOrEmpty(name) ? "<character>" : name;
            if (boneNames == null) throw new ArgumentNullException(nameof(boneNames));
            if (parents == null) throw new ArgumentNullException(nameof(parents));
            if (localPositions == null) throw new ArgumentNullException(nameof(localPositions));
            if (referenceRotations == null) throw new ArgumentNullException(nameof(referenceRotations));
            int n = boneNames.Count;
            if (parents.Count != n || localPositions.Count != 3 * n || referenceRotations.Count != 4 * n)
            {
                throw new ArgumentException($"{Name}: {n} bones need {n} parents, {3 * n} position values and {4 * n} rotation values; got {parents.Count}, {localPositions.Count} and {referenceRotations.Count}");
            }

            _names = new string[n];
            _parents = new int[n];
            _positions = new double[3 * n];
            _rotations = new double[4 * n];
            for (int b = 0; b < n; b++)
            {
                _names[b] = boneNames[b];
                _parents[b] = parents[b];
                QuaternionD q = new QuaternionD(referenceRotations[4 * b], referenceRotations[4 * b + 1], referenceRotations[4 * b + 2], referenceRotations[4 * b + 3]);
                double length = q.Length;
                if (!(length > 1e-6) || double.IsInfinity(length))
                {
                    throw new ArgumentException($"{Name}: the reference rotation of bone '{boneNames[b]}' is {(double.IsNaN(length) || double.IsInfinity(length) ? "not finite" : "zero")}; expected a unit quaternion (w, x, y, z)");
                }

                Quaternions.Normalize(q).Write(_rotations, 4 * b);
            }

            for (int i = 0; i < _positions.Length; i++) _positions[i] = localPositions[i];
            Armature = armature;
            // The hierarchy and names are validated once, by the skeleton (the message names the bone).
            Skeleton = new Skeleton(_names, _parents, CharacterOffsets());
        }

        /// <summary>The character's name for messages.</summary>
        public string Name { get; }

        /// <summary>The bone names, in stream order.</summary>
        public IReadOnlyList<string> BoneNames => _names;

        /// <summary>Each bone's parent index (−1 for the root bone).</summary>
        public IReadOnlyList<int> Parents => _parents;

        /// <summary>Bones × 3 local positions (Unity's space).</summary>
        public IReadOnlyList<double> LocalPositions => _positions;

        /// <summary>Bones × 4 reference local rotations (Unity's space, w x y z).</summary>
        public IReadOnlyList<double> ReferenceRotations => _rotations;

        /// <summary>The root bone's parent in the character's space.</summary>
        public RootFrame Armature { get; }

        /// <summary>
        /// The rig as a skeleton in the character's space and the model's handedness (right-handed): offsets
        /// mirrored and scaled by the armature, the root at its reference position in the character.
        /// </summary>
        public Skeleton Skeleton { get; }

        /// <summary>The reference pose on <see cref="Skeleton"/> (the root bone's rotation relative to the character).</summary>
        public ReferencePose ReferencePose
        {
            get
            {
                var local = new double[_rotations.Length];
                for (int b = 0; b < _names.Length; b++)
                {
                    QuaternionD q = QuaternionD.Read(_rotations, 4 * b);
                    if (b == 0) q = Armature.RotationToParent(q);
                    Handedness.RotationFromUnity(q).Write(local, 4 * b);
                }

                return new ReferencePose(Skeleton, local, Vector3D.Read(Skeleton.OffsetSpan, 0));
            }
        }

        /// <summary>
        /// The map between this character and the model. Refuses, with one message naming every bone concerned,
        /// a rig that lacks a model joint (other than those a rig may lack: toes, upper chest, neck,
        /// shoulders), and a reference pose in which a mapped bone points more than
        /// <paramref name="maxBoneDeviationDegrees"/> from the model's T-pose.
        /// </summary>
        /// <param name="model">The model's skeleton (the contract's).</param>
        /// <param name="jointMap">Model joint → bone chains; null picks the built-in map that finds the most bones (<see cref="JointMap.Detect"/>).</param>
        /// <param name="maxBoneDeviationDegrees">The largest angle a mapped bone may point away from the model's T-pose.</param>
        /// <exception cref="JointMapException">A model joint has no bone, or the reference pose is not a T-pose (bones named).</exception>
        public SkeletonPoseConverter CreatePoseConverter(Skeleton model, JointMap? jointMap = null, double maxBoneDeviationDegrees = DefaultMaxBoneDeviationDegrees)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            ReferencePose declared = ReferencePose.ModelTPose(model);
            SkeletonMap map = SkeletonMap.Create(ReferencePose, declared, jointMap ?? JointMap.Detect(Skeleton, model), Name);
            BoneDirections.RequireTPose(map, declared, maxBoneDeviationDegrees, Name);
            return new SkeletonPoseConverter(map, Armature);
        }

        /// <summary>
        /// The same rig with the model's T-pose by axes as its reference (<see cref="ReferencePose.ModelTPose"/>):
        /// for a character whose bones follow the model's local axes and names (a LaFAN1 rig), whose bind pose
        /// is no T-pose (at zero rotations LaFAN1's bones all point along +X) but whose axes say where a T-pose
        /// puts each bone.
        /// </summary>
        public CharacterRig WithModelTPoseByAxes()
        {
            ReferencePose tpose = ReferencePose.ModelTPose(Skeleton);
            var rotations = new double[_rotations.Length];
            for (int b = 0; b < _names.Length; b++)
            {
                QuaternionD q = Handedness.RotationToUnity(QuaternionD.Read(ToArray(tpose.LocalRotations), 4 * b));
                if (b == 0) q = Armature.RotationFromParent(q);
                q.Write(rotations, 4 * b);
            }

            return new CharacterRig(Name, _names, _parents, _positions, rotations, Armature);
        }

        private static double[] ToArray(IReadOnlyList<double> values)
        {
            var a = new double[values.Count];
            for (int i = 0; i < a.Length; i++) a[i] = values[i];
            return a;
        }

        private double[] CharacterOffsets()
        {
            var offsets = new double[_positions.Length];
            for (int b = 0; b < _names.Length; b++)
            {
                Vector3D p = Vector3D.Read(_positions, 3 * b);
                // The root stands where the armature puts it; every other offset is a length in the
                // armature's units, which its scale turns into the character's.
                Vector3D inCharacter = b == 0 ? Armature.PointToParent(p) : Armature.Scale * p;
                Handedness.PositionFromUnity(inCharacter).Write(offsets, 3 * b);
            }

            return offsets;
        }
    }
}
