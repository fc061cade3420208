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
    }
}
