using System;
using System.Collections.Generic;
using System.IO;
using DeltaInterpolator.Core.Bvh;
using DeltaInterpolator.Core.Characters;
using DeltaInterpolator.Core.Clips;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Core.Retargeting;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Clips
{
    /// <summary>
    /// A clip as an animator keys it, made from the Demo sample's CMU walk: the character is the BVH's skeleton in
    /// Unity's space under an FBX-like armature (turned, scale 0.01), and the clip holds keys only on the chosen
    /// model frames, on every bone's rotation (quaternion or <c>localEulerAnglesRaw</c> curves, as the Animation
    /// window keys them) and the root bone's position, with tangent modes and tangents an animator's keys carry.
    /// A scale curve, which no fill touches, rides along.
    /// </summary>
    public sealed class KeyedClipFixture
    {
        public const string Sample = "Samples~/Demo/cmu_09_12_walk_navigate.bvh";
        public const double ModelFps = 30;

        /// <summary>Unity's packed tangent mode of a ClampedAuto key (left 4 at bits 1–4, right 4 at bits 5–8).</summary>
        public const int ClampedAuto = (4 << 1) | (4 << 5);

        public static readonly RootFrame Armature = new RootFrame(new Vector3D(0.3, 0, -0.2), Quaternions.FromAxisAngle(new Vector3D(0, 1, 0), 0.7), 0.01);

        private KeyedClipFixture(MotionClip walk, CharacterRig rig, string[] paths, List<KeyedCurve> curves, int[] keyFrames)
        {
            Walk = walk;
            Rig = rig;
            BonePaths = paths;
            Curves = curves;
            KeyFrames = keyFrames;
        }

        /// <summary>The walk at its own rate (120 fps), frame 0 the T-pose.</summary>
        public MotionClip Walk { get; }

        public CharacterRig Rig { get; }

        public string[] BonePaths { get; }

        public List<KeyedCurve> Curves { get; }

        /// <summary>The keyed model frames.</summary>
        public int[] KeyFrames { get; }

        /// <summary>Seconds of the clip: its last key.</summary>
        public double Length => KeyFrames[KeyFrames.Length - 1] / ModelFps;

        /// <summary>The scene pose: the rig's reference pose (root position, then rotations w, x, y, z).</summary>
        public double[] ScenePose()
        {
            int n = Rig.BoneNames.Count;
            var pose = new double[3 + 4 * n];
            for (int c = 0; c < 3; c++) pose[c] = Rig.LocalPositions[c];
            for (int i = 0; i < 4 * n; i++) pose[3 + i] = Rig.ReferenceRotations[i];
            return pose;
        }

        /// <summary>Keys on <paramref name="keyFrames"/> (model frames) of the walk, rotations as quaternions or Euler.</summary>
        public static KeyedClipFixture Create(int[] keyFrames, bool euler)
        {
            string path = ShippedModels.Find(Sample);
            if (!File.Exists(path)) Assert.Ignore($"{Sample} not found above {AppContext.BaseDirectory}");
            MotionClip walk = BvhReader.Read(path).Motion.Excerpt(0, 481);
            Skeleton s = walk.Skeleton;
            int n = s.JointCount;
            CharacterRig rig = Character(walk);
            var paths = new string[n];
            for (int b = 0; b < n; b++) paths[b] = s.Parents[b] < 0 ? "Armature/" + s.Names[b] : paths[s.Parents[b]] + "/" + s.Names[b];

            int keys = keyFrames.Length;
            var rotations = new double[keys][];
            var roots = new double[keys][];
            for (int k = 0; k < keys; k++)
            {
                rotations[k] = new double[4 * n];
                roots[k] = new double[3];
                UnityPose(walk, WalkFrame(walk, keyFrames[k]), roots[k], rotations[k]);
            }

            var curves = new List<KeyedCurve>();
            var times = new float[keys];
            for (int k = 0; k < keys; k++) times[k] = (float)(keyFrames[k] / ModelFps);
            for (int b = 0; b < n; b++)
            {
                if (euler)
                {
                    var values = new double[keys][];
                    for (int k = 0; k < keys; k++)
                    {
                        values[k] = new double[3];
                        QuaternionD q = QuaternionD.Read(rotations[k], 4 * b);
                        Vector3D e = Quaternions.ToEuler(q, EulerOrder.Yxz);
                        double[] raw = { e.Y * 180 / Math.PI, e.X * 180 / Math.PI, e.Z * 180 / Math.PI };
                        // As the Animation window records: each key within half a turn of the one before, after a first key
                        // a whole turn away on some axes (a bone that spun earlier in the clip), so a fill that does not
                        // unwrap to the neighbouring keys flips by 360°.
                        for (int c = 0; c < 3; c++) values[k][c] = k == 0 ? raw[c] + 360 * ((b + c) % 3 - 1) : raw[c] + 360 * Math.Round((values[k - 1][c] - raw[c]) / 360);
                    }

                    for (int c = 0; c < 3; c++) curves.Add(Curve(paths[b], "localEulerAnglesRaw." + "xyz"[c], times, k => values[k][c]));
                }
                else
                {
                    for (int k = 1; k < keys; k++)
                    {
                        double dot = 0;
                        for (int c = 0; c < 4; c++) dot += rotations[k][4 * b + c] * rotations[k - 1][4 * b + c];
                        if (dot < 0) for (int c = 0; c < 4; c++) rotations[k][4 * b + c] = -rotations[k][4 * b + c];
                    }

                    for (int c = 0; c < 4; c++)
                    {
                        int component = (c + 1) % 4; // x, y, z, w from (w, x, y, z)
                        curves.Add(Curve(paths[b], "m_LocalRotation." + "xyzw"[c], times, k => rotations[k][4 * b + component]));
                    }
                }
            }

            for (int c = 0; c < 3; c++) curves.Add(Curve(paths[0], "m_LocalPosition." + "xyz"[c], times, k => roots[k][c]));
            curves.Add(new KeyedCurve(paths[1], "m_LocalScale.x", new[] { new CurveKey(0f, 1f, 0f, 0f), new CurveKey(times[keys - 1], 1.5f, 0.25f, 0.25f) }));
            return new KeyedClipFixture(walk, rig, paths, curves, keyFrames);
        }

        /// <summary>The walk's frame at model frame <paramref name="modelFrame"/> (the walk runs at 120 fps).</summary>
        public static int WalkFrame(MotionClip walk, int modelFrame) => (int)Math.Round(modelFrame / ModelFps / walk.FrameTime);

        /// <summary>
        /// The key poses straight from the walk, rounded to floats as the curves hold them, into a track: what
        /// <see cref="KeyFill.KeyPoses"/> must read off the curves.
        /// </summary>
        public CharacterPoseTrack TrackFromWalk(IReadOnlyList<int> keyFrames)
        {
            int n = Rig.BoneNames.Count;
            var track = new CharacterPoseTrack(Rig, keyFrames[keyFrames.Count - 1] + 1, 1.0 / ModelFps);
            var root = new double[3];
            var rotations = new double[4 * n];
            foreach (int f in keyFrames)
            {
                UnityPose(Walk, WalkFrame(Walk, f), root, rotations);
                for (int i = 0; i < 3; i++) root[i] = (float)root[i];
                for (int i = 0; i < 4 * n; i++) rotations[i] = (float)rotations[i];
                track.SetUnityPose(f, root, rotations);
            }

            return track;
        }

        /// <summary>Keys with ClampedAuto tangent modes and the slopes between them, as an animator's keys have.</summary>
        private static KeyedCurve Curve(string path, string property, float[] times, Func<int, double> value)
        {
            var keys = new CurveKey[times.Length];
            for (int k = 0; k < keys.Length; k++)
            {
                float v = (float)value(k);
                float slope = k + 1 < keys.Length ? (float)((value(k + 1) - value(k)) / (times[k + 1] - times[k])) : 0f;
                keys[k] = new CurveKey(times[k], v, slope, slope, 1f / 3, 1f / 3, 0, ClampedAuto);
            }

            return new KeyedCurve(path, property, keys);
        }

        /// <summary>The rig as the Unity layer collects it: Unity's space, bones under the armature, frame 0 (a T-pose) the reference.</summary>
        private static CharacterRig Character(MotionClip clip)
        {
            Skeleton s = clip.Skeleton;
            int n = s.JointCount;
            var positions = new double[3 * n];
            for (int b = 0; b < n; b++)
            {
                Vector3D unity = Handedness.PositionToUnity(Vector3D.Read(s.OffsetSpan, 3 * b));
                (b == 0 ? Armature.PointFromParent(unity) : (1 / Armature.Scale) * unity).Write(positions, 3 * b);
            }

            var root = new double[3];
            var rotations = new double[4 * n];
            UnityPose(clip, 0, root, rotations);
            return new CharacterRig("cmu-character", s.Names, s.Parents, positions, rotations, Armature);
        }

        /// <summary>Frame <paramref name="frame"/> of the walk as Unity's transforms hold it under the armature.</summary>
        private static void UnityPose(MotionClip clip, int frame, double[] root, double[] rotations)
        {
            int n = clip.Skeleton.JointCount;
            for (int b = 0; b < n; b++)
            {
                QuaternionD q = Handedness.RotationToUnity(QuaternionD.Read(clip.LocalRotations, clip.RotationIndex(frame, b)));
                (b == 0 ? Armature.RotationFromParent(q) : q).Write(rotations, 4 * b);
            }

            Armature.PointFromParent(Handedness.PositionToUnity(Vector3D.Read(clip.LocalPositions, clip.PositionIndex(frame, 0)))).Write(root, 0);
        }
    }
}
