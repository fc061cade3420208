using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>Common key layouts for <see cref="ClipBaker"/>.</summary>
    public static class KeyFrames
    {
        /// <summary>
        /// Frames 0, K, 2K, … and the clip's last frame (so the whole clip is baked even when its length
        /// is not a multiple of K; the last gap is then shorter).
        /// </summary>
        /// <param name="interval">K, frames between keys (≥ 1).</param>
        /// <param name="frameCount">Frames in the clip (≥ 2).</param>
        /// <exception cref="KeyLayoutException">K &lt; 1 or fewer than two frames.</exception>
        public static int[] Every(int interval, int frameCount)
        {
            if (interval < 1) throw new KeyLayoutException($"a key every {interval} frames", "expected an interval of at least 1 frame");
            if (frameCount < 2) throw new KeyLayoutException($"the clip has {frameCount} frame(s)", "expected at least two frames to hold two keys");
            var keys = new List<int>(frameCount / interval + 2);
            for (int f = 0; f < frameCount; f += interval) keys.Add(f);
            if (keys[keys.Count - 1] != frameCount - 1) keys.Add(frameCount - 1);
            return keys.ToArray();
        }

        /// <summary>
        /// <see cref="Every(int, int)"/> from frame <paramref name="first"/> on (frames before it — a T-pose,
        /// conversion artefacts — are never keys), with no two keys closer than <paramref name="minimumSpacing"/>
        /// frames: when the clip's last frame falls closer than that to the key before it, that key is
        /// dropped and the last gap grows instead (keys that work, never a refusal of the layout's own keys).
        /// </summary>
        /// <param name="interval">K, frames between keys (≥ 1).</param>
        /// <param name="frameCount">Frames in the clip.</param>
        /// <param name="first">The first key frame (≥ 0).</param>
        /// <param name="minimumSpacing">The fewest frames between two keys (≥ 1), e.g. one model frame in input frames.</param>
        /// <exception cref="KeyLayoutException">K &lt; 1, or fewer than two usable frames.</exception>
        public static int[] Every(int interval, int frameCount, int first, int minimumSpacing)
        {
            if (first < 0 || first > frameCount - 2)
            {
                throw new KeyLayoutException($"the first key {first} leaves fewer than two of the clip's {frameCount} frames", "expected a first key at least two frames before the end");
            }

            int[] keys = Every(interval, frameCount - first);
            var result = new List<int>(keys.Length);
            foreach (int k in keys) result.Add(k + first);
            int spacing = Math.Max(1, minimumSpacing);
            if (result[result.Count - 1] - result[0] < spacing)
            {
                throw new KeyLayoutException($"frames {first}..{frameCount - 1} span less than {spacing} frames", $"expected at least {spacing} frames between the first and the last key");
            }

            while (result.Count > 2 && result[result.Count - 1] - result[result.Count - 2] < spacing) result.RemoveAt(result.Count - 2);
            return result.ToArray();
        }
    }
}
