using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Kinematics;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Preview
{
    /// <summary>
    /// One named motion to show: the global position of every joint on every frame (flat frames × joints
    /// × 3, in the data's own units, Y up). Positions rather than rotations because a picture only needs
    /// where the joints are, and every method (ground truth, SLERP, a model) can give them.
    /// </summary>
    public sealed class PreviewTrack
    {
        /// <summary>Creates a track over <paramref name="globalPositions"/> (not copied).</summary>
        /// <param name="name">Label shown beside the skeleton, e.g. "Ground truth", "SLERP", "Model".</param>
        /// <param name="jointCount">Joints per frame.</param>
        /// <param name="globalPositions">Flat frames × joints × 3 global positions; every value finite.</param>
        public PreviewTrack(string name, int jointCount, double[] globalPositions)
        {
            if (string.IsNullOrWhiteSpace(name)) throw new ArgumentException("a track needs a name", nameof(name));
            if (jointCount <= 0) throw new ArgumentOutOfRangeException(nameof(jointCount), "a track needs at least one joint");
            if (globalPositions == null) throw new ArgumentNullException(nameof(globalPositions));
            if (globalPositions.Length == 0 || globalPositions.Length % (3 * jointCount) != 0)
            {
                throw new ArgumentException($"track '{name}': {globalPositions.Length} values is not frames × {jointCount} joints × 3 with at least one frame", nameof(globalPositions));
            }

            for (int i = 0; i < globalPositions.Length; i++)
            {
                if (double.IsNaN(globalPositions[i]) || double.IsInfinity(globalPositions[i]))
                {
                    int frame = i / (3 * jointCount);
                    throw new ArgumentException($"track '{name}': position of joint {i / 3 % jointCount} on frame {frame} is not finite", nameof(globalPositions));
                }
            }

            Name = name;
            JointCount = jointCount;
            FrameCount = globalPositions.Length / (3 * jointCount);
            GlobalPositions = globalPositions;
        }

        /// <summary>
        /// The track of a clip: global joint positions by forward kinematics (each joint's own local
        /// translation, so BVH files whose joints carry position channels show as they are).
        /// </summary>
        public static PreviewTrack FromClip(string name, MotionClip clip)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            int j = clip.Skeleton.JointCount;
            var positions = new double[clip.FrameCount * j * 3];
            var rotations = new double[clip.FrameCount * j * 4];
            ForwardKinematics.ComputeWithLocalPositions(clip.Skeleton, clip.FrameCount, clip.LocalPositions, clip.LocalRotations, positions, rotations);
            return new PreviewTrack(name, j, positions);
        }

        /// <summary>
        /// Marks where this track's feet are planted: <paramref name="footJoints"/> (joint indices) and, per frame,
        /// one flag per foot joint (frames × foot joints). The player draws a planted joint's footprint on the floor.
        /// </summary>
        /// <exception cref="ArgumentException">The flags are not frames × foot joints, or a joint index is out of range.</exception>
        public void MarkPlantedFeet(IReadOnlyList<int> footJoints, bool[] planted)
        {
            if (footJoints == null) throw new ArgumentNullException(nameof(footJoints));
            if (planted == null) throw new ArgumentNullException(nameof(planted));
            foreach (int j in footJoints)
            {
                if (j < 0 || j >= JointCount) throw new ArgumentException($"track '{Name}': foot joint {j} is not one of its {JointCount} joints", nameof(footJoints));
            }

            if (footJoints.Count == 0 || footJoints.Count > 30 || planted.Length != FrameCount * footJoints.Count)
            {
                throw new ArgumentException($"track '{Name}': {planted.Length} planted flags for {footJoints.Count} foot joints; expected {FrameCount} frames × 1–30 foot joints", nameof(planted));
            }

            FootJoints = new List<int>(footJoints).ToArray();
            Planted = planted;
        }

        /// <summary>The joints <see cref="Planted"/> flags, or null when no feet are marked.</summary>
        public int[]? FootJoints { get; private set; }

        /// <summary>Frames × <see cref="FootJoints"/> flags: true where that foot joint is planted; null when not marked.</summary>
        public bool[]? Planted { get; private set; }

        /// <summary>The label shown beside the skeleton.</summary>
        public string Name { get; }

        /// <summary>Joints per frame.</summary>
        public int JointCount { get; }

        /// <summary>Number of frames.</summary>
        public int FrameCount { get; }

        /// <summary>Flat frames × joints × 3 global positions.</summary>
        public double[] GlobalPositions { get; }

        /// <summary>Global position of <paramref name="joint"/> on <paramref name="frame"/> (clamped to the last frame).</summary>
        internal (double X, double Y, double Z) At(int frame, int joint)
        {
            int f = Math.Min(frame, FrameCount - 1);
            int i = (f * JointCount + joint) * 3;
            return (GlobalPositions[i], GlobalPositions[i + 1], GlobalPositions[i + 2]);
        }
    }
}
