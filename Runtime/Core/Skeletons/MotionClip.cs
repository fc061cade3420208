using System;

namespace DeltaInterpolator.Core.Skeletons
{
    /// <summary>
    /// Skeletal motion on flat arrays (structure of arrays, frames × joints): the local translation of
    /// every joint (the root's is its global position; the others usually equal their offsets) and the
    /// local rotation of every joint as a (w, x, y, z) quaternion (the root's is global).
    /// Arrays are exposed for hot loops; the clip owns them.
    /// </summary>
    public sealed class MotionClip
    {
        /// <summary>Creates a clip over the given arrays (not copied).</summary>
        /// <param name="skeleton">The joint hierarchy.</param>
        /// <param name="frameCount">Number of frames (≥ 0).</param>
        /// <param name="frameTime">Seconds per frame (&gt; 0).</param>
        /// <param name="localPositions">frames × joints × 3 values.</param>
        /// <param name="localRotations">frames × joints × 4 values, (w, x, y, z).</param>
        public MotionClip(Skeleton skeleton, int frameCount, double frameTime, double[] localPositions, double[] localRotations)
        {
            Skeleton = skeleton ?? throw new ArgumentNullException(nameof(skeleton));
            if (frameCount < 0) throw new ArgumentOutOfRangeException(nameof(frameCount), "frame count must be ≥ 0");
            if (!(frameTime > 0) || double.IsInfinity(frameTime))
            {
                throw new ArgumentOutOfRangeException(nameof(frameTime), "frame time must be a positive number of seconds");
            }

            int j = skeleton.JointCount;
            if (localPositions == null || localPositions.Length != frameCount * j * 3)
            {
                throw new ArgumentException($"local positions must hold frames × joints × 3 = {frameCount * j * 3} values", nameof(localPositions));
            }

            if (localRotations == null || localRotations.Length != frameCount * j * 4)
            {
                throw new ArgumentException($"local rotations must hold frames × joints × 4 = {frameCount * j * 4} values", nameof(localRotations));
            }

            FrameCount = frameCount;
            FrameTime = frameTime;
            LocalPositions = localPositions;
            LocalRotations = localRotations;
        }

        /// <summary>Frames <paramref name="start"/>..start + count − 1 as a clip of their own (copies).</summary>
        /// <exception cref="ArgumentOutOfRangeException">The frames are not all in the clip.</exception>
        public MotionClip Excerpt(int start, int count)
        {
            if (start < 0 || count < 1 || start + count > FrameCount)
            {
                throw new ArgumentOutOfRangeException(nameof(count), $"frames {start}..{start + count - 1} of a {FrameCount}-frame clip");
            }

            int j = Skeleton.JointCount;
            var positions = new double[count * j * 3];
            var rotations = new double[count * j * 4];
            Array.Copy(LocalPositions, start * j * 3, positions, 0, positions.Length);
            Array.Copy(LocalRotations, start * j * 4, rotations, 0, rotations.Length);
            return new MotionClip(Skeleton, count, FrameTime, positions, rotations);
        }

        /// <summary>Creates an empty-motion clip of <paramref name="frameCount"/> frames: offsets and identity rotations.</summary>
        public static MotionClip CreateRestPose(Skeleton skeleton, int frameCount, double frameTime)
        {
            int j = skeleton.JointCount;
            var positions = new double[frameCount * j * 3];
            var rotations = new double[frameCount * j * 4];
            ReadOnlySpan<double> offsets = skeleton.OffsetSpan;
            for (int f = 0; f < frameCount; f++)
            {
                offsets.CopyTo(positions.AsSpan(f * j * 3, j * 3));
                for (int k = 0; k < j; k++) rotations[(f * j + k) * 4] = 1.0;
            }

            return new MotionClip(skeleton, frameCount, frameTime, positions, rotations);
        }

        /// <summary>The joint hierarchy.</summary>
        public Skeleton Skeleton { get; }

        /// <summary>Number of frames.</summary>
        public int FrameCount { get; }

        /// <summary>Seconds per frame.</summary>
        public double FrameTime { get; }

        /// <summary>Duration in seconds, frames × frame time.</summary>
        public double Duration => FrameCount * FrameTime;

        /// <summary>Flat frames × joints × 3 local translations (root: global position).</summary>
        public double[] LocalPositions { get; }

        /// <summary>Flat frames × joints × 4 local rotations, (w, x, y, z) (root: global rotation).</summary>
        public double[] LocalRotations { get; }

        /// <summary>Index of (frame, joint)'s first position value in <see cref="LocalPositions"/>.</summary>
        public int PositionIndex(int frame, int joint) => (frame * Skeleton.JointCount + joint) * 3;

        /// <summary>Index of (frame, joint)'s w in <see cref="LocalRotations"/>.</summary>
        public int RotationIndex(int frame, int joint) => (frame * Skeleton.JointCount + joint) * 4;
    }
}
