using System.Collections.Generic;

namespace DeltaInterpolator.Core.Baking
{
    /// <summary>
    /// What <see cref="ClipBaker.Plan"/> found: the keys, every gap between consecutive keys (in the order
    /// they will be filled) and the warnings about gaps outside the model's trained ranges. Plans are
    /// checked before any work, so a bad layout is refused before a model runs.
    /// </summary>
    public sealed class BakePlan
    {
        internal BakePlan(int sourceFrameCount, int[] keys, BakeGap[] gaps, string[] warnings)
        {
            SourceFrameCount = sourceFrameCount;
            KeyArray = keys;
            GapArray = gaps;
            Warnings = warnings;
        }

        /// <summary>Frame count of the clip the keys index.</summary>
        public int SourceFrameCount { get; }

        /// <summary>The key frame indices, increasing.</summary>
        public IReadOnlyList<int> Keys => KeyArray;

        /// <summary>The first key: frame 0 of the baked clip.</summary>
        public int FirstKey => Keys[0];

        /// <summary>The last key: the baked clip's last frame.</summary>
        public int LastKey => Keys[Keys.Count - 1];

        /// <summary>Frames of the baked clip, LastKey − FirstKey + 1 (the source frames outside the keys are not part of it).</summary>
        public int FrameCount => LastKey - FirstKey + 1;

        /// <summary>Gaps with at least one missing frame, in fill order.</summary>
        public IReadOnlyList<BakeGap> Gaps => GapArray;

        /// <summary>Frames to be filled (the sum of the gaps' missing frames).</summary>
        public int MissingFrames
        {
            get
            {
                int total = 0;
                foreach (BakeGap g in GapArray) total += g.MissingFrames;
                return total;
            }
        }

        /// <summary>The keys as an array, for allocation-free loops.</summary>
        internal int[] KeyArray { get; }

        /// <summary>The gaps as an array, for allocation-free loops.</summary>
        internal BakeGap[] GapArray { get; }

        /// <summary>One line per kind of concern (e.g. gaps longer than the model was trained on), naming the gaps.</summary>
        public IReadOnlyList<string> Warnings { get; }
    }
}
