using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>
    /// The one key planner of the CLI's <c>--every</c> and the editor baker's "every N": keys at equal times
    /// from a first frame, the clip's last frame a key, no two keys on one model frame, and the last gap kept
    /// in the model's trained range where the clip allows.
    /// </summary>
    /// <remarks>
    /// Keys are placed by time (key k at first + k × spacing, on the nearest input frame), so one spacing
    /// gives the same keys on a 30, 60 or 120 fps file whatever unit it is written in. The clip's last frame is
    /// always a key (the whole clip is baked); when the gap it closes has fewer missing model frames than
    /// the model was trained on (<c>minMissing</c>), the key before it moves to the middle of the last two gaps
    /// when both halves then hold enough missing frames, and is dropped (the two gaps merge) otherwise.
    /// </remarks>
    public static class KeyPlanner
    {
        /// <summary>Keys for <paramref name="spacing"/> over input frames <paramref name="first"/>..<paramref name="frameCount"/> − 1.</summary>
        /// <param name="spacing">The spacing (any unit).</param>
        /// <param name="frameCount">Frames in the clip.</param>
        /// <param name="frameTime">Seconds per input frame.</param>
        /// <param name="modelFps">The model's frame rate.</param>
        /// <param name="first">The first key (frames before it are never keys).</param>
        /// <param name="minMissing">The fewest missing model frames the model was trained on (5 for the shipped models).</param>
        /// <exception cref="KeyLayoutException">Too few frames, or a spacing below two model frames (no frame left to fill).</exception>
        public static int[] Plan(KeySpacing spacing, int frameCount, double frameTime, double modelFps, int first, int minMissing)
        {
            if (!(frameTime > 0) || !(modelFps > 0)) throw new ArgumentOutOfRangeException(nameof(frameTime), "expected positive frame times and rates");
            if (first < 0 || first > frameCount - 2)
            {
                throw new KeyLayoutException($"the first key {first} leaves fewer than two of the clip's {frameCount} frames", "expected a first key at least two frames before the end");
            }

            double seconds = spacing.Seconds(frameTime, modelFps);
            double modelFrames = seconds * modelFps;
            if (modelFrames < 2 - 1e-6)
            {
                throw new KeyLayoutException(string.Format(System.Globalization.CultureInfo.InvariantCulture, "a key {0} leaves no model frame to fill", spacing.Describe(frameTime, modelFps)),
                    "expected keys at least two model frames apart");
            }

            int last = frameCount - 1;
            double step = seconds / frameTime;
            // One model frame in input frames, and one more above 1 (BVH files round their frame time: 4.0002 means 4),
            // so that rounding keys to model frames can never put two on one frame.
            double ratio = 1.0 / (modelFps * frameTime);
            int apart = ratio <= 1 + 1e-3 ? 1 : (int)Math.Ceiling(ratio - 1e-3) + 1;
            var keys = new List<int> { first };
            for (long k = 1; ; k++)
            {
                double at = first + k * step;
                if (at > last + 1e-9) break;
                int f = (int)Math.Round(at, MidpointRounding.AwayFromZero);
                if (f > last) break;
                if (f - keys[keys.Count - 1] >= apart) keys.Add(f);
            }

            if (keys[keys.Count - 1] != last)
            {
                if (last - keys[0] < apart)
                {
                    throw new KeyLayoutException($"frames {first}..{last} span less than {apart} frames", $"expected at least {apart} frames between the first and the last key");
                }

                keys.Add(last);
            }

            while (keys.Count > 2 && last - keys[keys.Count - 2] < apart) keys.RemoveAt(keys.Count - 2);
            if (keys.Count > 2 && Missing(keys[keys.Count - 2], last, frameTime, modelFps) < minMissing)
            {
                int before = keys[keys.Count - 3];
                // The middle on the model's frame grid from the first key, so 30, 60 and 120 fps files agree.
                double middleModel = Math.Round(((before + last) / 2.0 - first) * frameTime * modelFps, MidpointRounding.AwayFromZero);
                int middle = first + (int)Math.Round(middleModel / (modelFps * frameTime), MidpointRounding.AwayFromZero);
                if (Missing(before, middle, frameTime, modelFps) >= minMissing && Missing(middle, last, frameTime, modelFps) >= minMissing)
                {
                    keys[keys.Count - 2] = middle;
                }
                else
                {
                    keys.RemoveAt(keys.Count - 2);
                }
            }

            return keys.ToArray();
        }

        /// <summary>
        /// Keys for a clip known by its length and frame rate (the editor baker's "every N" on an AnimationClip):
        /// planned on the clip's frames from its start (<see cref="Plan"/>), then as times and as frames of the
        /// model's timeline, where the bake runs.
        /// </summary>
        /// <param name="spacing">The spacing (any unit; input frames are the clip's).</param>
        /// <param name="clipSeconds">The clip's length.</param>
        /// <param name="clipFps">The clip's frame rate.</param>
        /// <param name="modelFps">The model's frame rate.</param>
        /// <param name="minMissing">The fewest missing model frames the model was trained on.</param>
        /// <exception cref="KeyLayoutException">The clip is too short, or the spacing leaves nothing to fill.</exception>
        public static (int[] ModelFrames, double[] Times) PlanClip(KeySpacing spacing, double clipSeconds, double clipFps, double modelFps, int minMissing)
        {
            if (!(clipFps > 0) || !(clipSeconds >= 0) || double.IsInfinity(clipSeconds)) throw new ArgumentOutOfRangeException(nameof(clipFps), "expected a positive frame rate and a finite length");
            double frames = Math.Floor(clipSeconds * clipFps + 1e-6) + 1;
            if (frames > int.MaxValue / 2) throw new KeyLayoutException($"a clip of {frames} frames", "expected a shorter clip");
            int[] keys = Plan(spacing, (int)frames, 1.0 / clipFps, modelFps, 0, minMissing);
            var times = new double[keys.Length];
            var modelFrames = new int[keys.Length];
            for (int i = 0; i < keys.Length; i++)
            {
                times[i] = keys[i] / clipFps;
                modelFrames[i] = (int)Math.Round(times[i] * modelFps, MidpointRounding.AwayFromZero);
            }

            return (modelFrames, times);
        }

        /// <summary>Missing model frames between two input-frame keys (as the bake rounds them onto the model's timeline).</summary>
        private static int Missing(int a, int b, double frameTime, double modelFps) =>
            (int)Math.Round((b - a) * frameTime * modelFps, MidpointRounding.AwayFromZero) - 1;
    }
}
