using System;
using System.Globalization;
using DeltaInterpolator.Core.Rotations;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Changes a clip's frame rate: rotations by SLERP (shortest arc, renormalised), translations by LERP,
    /// between the two source frames around each new frame's time. Frame 0 stays at time 0 and the new
    /// clip covers the old one's span [0, (N − 1)·dt] (its last frame is at or before the old last frame).
    /// CMU's 120 fps → the model's 30 fps keeps every fourth frame exactly; the way back interpolates.
    /// </summary>
    public static class MotionResampler
    {
        /// <summary>
        /// The most frames × joints a resampled clip may have: 10 million (e.g. 450,000 frames of a 22-joint
        /// skeleton, over 4 hours at 30 fps; about 560 MB of motion). A longer result is refused before
        /// anything is allocated (a 2-frame file with <c>Frame Time: 1e5</c> would otherwise ask for gigabytes).
        /// </summary>
        public const long MaxJointFrames = 10_000_000;

        /// <summary>The clip at <paramref name="frameTime"/> seconds per frame.</summary>
        /// <param name="clip">The motion.</param>
        /// <param name="frameTime">The new seconds per frame (&gt; 0).</param>
        /// <param name="source">The file the motion came from, for the message when the result is too long.</param>
        /// <exception cref="DataFormatException">The result would exceed <see cref="MaxJointFrames"/>.</exception>
        public static MotionClip Resample(MotionClip clip, double frameTime, string? source = null)
        {
            if (clip == null) throw new ArgumentNullException(nameof(clip));
            if (!(frameTime > 0) || double.IsInfinity(frameTime)) throw new ArgumentOutOfRangeException(nameof(frameTime), "frame time must be a positive number of seconds");
            int j = clip.Skeleton.JointCount;
            if (clip.FrameCount == 0) return new MotionClip(clip.Skeleton, 0, frameTime, new double[0], new double[0]);
            double span = (clip.FrameCount - 1) * clip.FrameTime;
            // The small tolerance keeps the last frame when the span is a whole number of new frames up to rounding.
            CheckLength(Math.Floor(span / frameTime + 1e-6) + 1, j, clip.FrameCount, clip.FrameTime, frameTime, source);
            int count = (int)Math.Floor(span / frameTime + 1e-6) + 1;
            var positions = new double[count * j * 3];
            var rotations = new double[count * j * 4];
            for (int f = 0; f < count; f++)
            {
                Sample(clip, f * frameTime / clip.FrameTime, positions.AsSpan(f * j * 3, j * 3), rotations.AsSpan(f * j * 4, j * 4));
            }

            Quaternions.FixContinuity(rotations, count, j);
            return new MotionClip(clip.Skeleton, count, frameTime, positions, rotations);
        }

        /// <summary>
        /// Refuses, with <see cref="DataFormatException"/>, a resampled length of <paramref name="frames"/>
        /// frames of <paramref name="joints"/> joints beyond <see cref="MaxJointFrames"/> (or not a number).
        /// </summary>
        internal static void CheckLength(double frames, int joints, int sourceFrames, double sourceFrameTime, double frameTime, string? source)
        {
            if (frames * Math.Max(1, joints) <= MaxJointFrames) return;
            throw new DataFormatException(
                source ?? "motion",
                string.Format(CultureInfo.InvariantCulture,
                    "{0:N0} frames at {1:0.###} s per frame ({2:0.###e+0} s) make {3:0.###e+0} frames at {4:0.##} fps, {5} joints each",
                    sourceFrames, sourceFrameTime, (sourceFrames - 1) * sourceFrameTime, frames, 1 / frameTime, joints),
                string.Format(CultureInfo.InvariantCulture,
                    "expected at most {0:N0} frames × joints after resampling (check the file's Frame Time: line, --fps and --input-fps)", MaxJointFrames));
        }

        /// <summary>
        /// One pose at a fractional frame index (clamped to the clip): SLERP and LERP between the frames
        /// around it.
        /// </summary>
        /// <param name="clip">The motion.</param>
        /// <param name="frame">Fractional frame index.</param>
        /// <param name="positions">Output, joints × 3 local translations.</param>
        /// <param name="rotations">Output, joints × 4 local rotations.</param>
        public static void Sample(MotionClip clip, double frame, Span<double> positions, Span<double> rotations)
        {
            int last = clip.FrameCount - 1;
            if (last < 0) throw new ArgumentException("the clip has no frames", nameof(clip));
            if (!(frame > 0)) frame = 0;
            if (frame > last) frame = last;
            int f0 = (int)Math.Floor(frame + 1e-9);
            if (f0 > last) f0 = last;
            double t = frame - f0;
            if (t < 1e-9) t = 0;
            int f1 = Math.Min(f0 + 1, last);
            Blend(clip, f0, f1, t, positions, rotations);
        }

        /// <summary>(1 − t)·frame f0 + t·frame f1: LERP of translations and SLERP of rotations.</summary>
        internal static void Blend(MotionClip clip, int f0, int f1, double t, Span<double> positions, Span<double> rotations)
        {
            int j = clip.Skeleton.JointCount;
            int p0 = clip.PositionIndex(f0, 0), p1 = clip.PositionIndex(f1, 0);
            int r0 = clip.RotationIndex(f0, 0), r1 = clip.RotationIndex(f1, 0);
            double[] lp = clip.LocalPositions, lr = clip.LocalRotations;
            for (int i = 0; i < 3 * j; i++) positions[i] = t == 0 ? lp[p0 + i] : (1 - t) * lp[p0 + i] + t * lp[p1 + i];
            for (int k = 0; k < j; k++)
            {
                QuaternionD a = QuaternionD.Read(lr, r0 + 4 * k);
                QuaternionD q = t == 0 ? a : Quaternions.Slerp(a, QuaternionD.Read(lr, r1 + 4 * k), t);
                Quaternions.Normalize(q).Write(rotations, 4 * k);
            }
        }
    }
}
