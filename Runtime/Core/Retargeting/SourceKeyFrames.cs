using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Skeletons;

namespace DeltaInterpolator.Core.Retargeting
{
    /// <summary>
    /// Sampling a source clip that only holds valid poses at its key frames (a clip being baked): between
    /// keys the two keys around a time are blended, before the first key the first is held, after the last
    /// the last. <see cref="SkeletonMap.ToSource"/> takes the unmapped values from it.
    /// </summary>
    internal static class SourceKeyFrames
    {
        public static void Sample(MotionClip source, int[] keys, double frame, Span<double> positions, Span<double> rotations)
        {
            if (frame <= keys[0])
            {
                MotionResampler.Blend(source, keys[0], keys[0], 0, positions, rotations);
                return;
            }

            int last = keys.Length - 1;
            if (frame >= keys[last])
            {
                MotionResampler.Blend(source, keys[last], keys[last], 0, positions, rotations);
                return;
            }

            int k = Array.BinarySearch(keys, (int)Math.Floor(frame));
            if (k < 0) k = ~k - 1;
            double t = (frame - keys[k]) / (keys[k + 1] - keys[k]);
            MotionResampler.Blend(source, keys[k], keys[k + 1], t < 1e-12 ? 0 : t, positions, rotations);
        }

        public static int[]? Check(IReadOnlyList<int>? keys, int frameCount)
        {
            if (keys == null) return null;
            if (keys.Count == 0) throw new ArgumentException("source key frames are empty; pass null to use every source frame", nameof(keys));
            var result = new int[keys.Count];
            for (int i = 0; i < result.Length; i++)
            {
                result[i] = keys[i];
                if (result[i] < 0 || result[i] >= frameCount) throw new ArgumentOutOfRangeException(nameof(keys), $"key frame {result[i]} is not in the source clip (0..{frameCount - 1})");
                if (i > 0 && result[i] <= result[i - 1]) throw new ArgumentException("source key frames must be strictly increasing", nameof(keys));
            }

            return result;
        }
    }
}
