using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Clips;

namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// One clip cut from a BVH file's frames (the <c>.bvh</c> importer's <i>Clips</i> setting makes one clip per range):
    /// frames <see cref="FirstFrame"/> to <see cref="LastFrame"/> of the file, inclusive, keyed from time 0, and whether the
    /// clip loops. A looping clip plays its last frame, then its first: cut it so that the first frame is what would come after
    /// the last (<see cref="LoopSeam"/> measures that), and the wrap is one ordinary step. A <see cref="PingPong"/> clip plays
    /// the range forward then back, so it loops without a seam on motion that never comes back to where it started (a
    /// standing idle's slow sway).
    /// </summary>
    public sealed class BvhClipRange
    {
        /// <summary>A range; <see cref="Check"/> holds it against a file.</summary>
        public BvhClipRange(string name, int firstFrame, int lastFrame, bool loop, bool pingPong = false)
        {
            Name = name ?? "";
            FirstFrame = firstFrame;
            LastFrame = lastFrame;
            Loop = loop;
            PingPong = pingPong;
        }

        /// <summary>The clip's name (the sub-asset's name, and part of its identifier).</summary>
        public string Name { get; }

        /// <summary>The file's frame the clip starts on (0-based).</summary>
        public int FirstFrame { get; }

        /// <summary>The file's frame the clip ends on, inclusive.</summary>
        public int LastFrame { get; }

        /// <summary>Whether the clip loops (Unity's <i>Loop Time</i>).</summary>
        public bool Loop { get; }

        /// <summary>Whether the clip plays the range forward, then back to the frame after the first (a loop then wraps by one ordinary step).</summary>
        public bool PingPong { get; }

        /// <summary>Frames in the range.</summary>
        public int FrameCount => LastFrame - FirstFrame + 1;

        /// <summary>The file's frames the clip shows, in order: the range, and with <see cref="PingPong"/> back down to <see cref="FirstFrame"/> + 1.</summary>
        public int[] ClipFrames()
        {
            int span = LastFrame - FirstFrame;
            var frames = new int[PingPong && span > 0 ? 2 * span : span + 1];
            for (int k = 0; k < frames.Length; k++) frames[k] = k <= span ? FirstFrame + k : FirstFrame + 2 * span - k;
            return frames;
        }

        /// <summary>The sub-asset identifier of the clip: fixed by its name, so references to it survive re-imports and edits of other ranges.</summary>
        public string SubAssetId => BvhSubAssets.ClipId + ":" + Name;

        /// <summary>Refuses ranges that do not fit <paramref name="import"/>: an empty or repeated name, a frame outside the file, an end before the start.</summary>
        /// <exception cref="DataFormatException">Names the file, the range and what was expected.</exception>
        public static void Check(IReadOnlyList<BvhClipRange> ranges, BvhImportResult import)
        {
            if (ranges == null) throw new ArgumentNullException(nameof(ranges));
            if (import == null) throw new ArgumentNullException(nameof(import));
            var names = new HashSet<string>(StringComparer.Ordinal);
            for (int i = 0; i < ranges.Count; i++)
            {
                BvhClipRange r = ranges[i] ?? throw new ArgumentNullException(nameof(ranges), $"range {i} is null");
                string which = $"clip range {i}" + (r.Name.Length > 0 ? $" ('{r.Name}')" : "");
                if (r.Name.Trim().Length == 0) throw new DataFormatException(import.SourceName, $"{which} has no name", "expected a clip name");
                if (!names.Add(r.Name)) throw new DataFormatException(import.SourceName, $"{which} repeats the name '{r.Name}'", "expected one range per clip name");
                if (r.FirstFrame < 0 || r.LastFrame >= import.FrameCount || r.LastFrame < r.FirstFrame)
                {
                    throw new DataFormatException(import.SourceName, $"{which} spans frames {r.FirstFrame} to {r.LastFrame}", $"expected 0 ≤ first ≤ last ≤ {import.FrameCount - 1} (the file has {import.FrameCount} frames)");
                }
            }
        }

        /// <summary>The clip's transform curves: every joint's local rotation (and position where the file has position channels) on each of <see cref="ClipFrames"/>, keyed from 0.</summary>
        public IReadOnlyList<ClipCurve> Curves(BvhImportResult import) => BvhClipImport.Curves(import, ClipFrames());
    }
}
