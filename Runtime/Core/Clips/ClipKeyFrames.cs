using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Core.Clips
{
    /// <summary>
    /// The key frames found in an animation clip (<see cref="ClipKeyReader.Read"/>): the distinct frame
    /// indices, at the model's frame rate, on which any pose curve has a key, and what had to be rounded
    /// or left out to get there, so that a window can say so instead of silently moving a key.
    /// </summary>
    public sealed class ClipKeyFrames
    {
        internal ClipKeyFrames(int[] frames, double frameRate, int snappedKeys, double largestSnap, int ignoredKeys)
        {
            Frames = frames;
            FrameRate = frameRate;
            SnappedKeys = snappedKeys;
            LargestSnapFrames = largestSnap;
            IgnoredKeys = ignoredKeys;
        }

        /// <summary>Key frame indices at <see cref="FrameRate"/>, ascending, distinct.</summary>
        public IReadOnlyList<int> Frames { get; }

        /// <summary>Frames per second the indices count in (the model's rate).</summary>
        public double FrameRate { get; }

        /// <summary>Keys whose time did not fall on a frame of <see cref="FrameRate"/> and were rounded to the nearest one.</summary>
        public int SnappedKeys { get; }

        /// <summary>The largest rounding among <see cref="SnappedKeys"/>, in frames (at most 0.5).</summary>
        public double LargestSnapFrames { get; }

        /// <summary>Keys before time 0 or after the clip's end, which were left out.</summary>
        public int IgnoredKeys { get; }

        /// <summary>Number of gaps with missing frames between consecutive keys.</summary>
        public int GapCount => CountGaps(Frames);

        /// <summary>
        /// Number of gaps with missing frames between consecutive keys of <paramref name="frames"/> (ascending frame
        /// indices): the one count the key readers, the key fill's plan and its "nothing to fill" refusal share.
        /// </summary>
        internal static int CountGaps(IReadOnlyList<int> frames)
        {
            int n = 0;
            for (int i = 1; i < frames.Count; i++)
            {
                if (frames[i] - frames[i - 1] > 1) n++;
            }

            return n;
        }

        /// <summary>The missing-frame count of gap <paramref name="index"/> (0-based, in order).</summary>
        /// <exception cref="ArgumentOutOfRangeException">No such gap.</exception>
        public int GapLength(int index)
        {
            int n = 0;
            for (int i = 1; i < Frames.Count; i++)
            {
                int missing = Frames[i] - Frames[i - 1] - 1;
                if (missing <= 0) continue;
                if (n == index) return missing;
                n++;
            }

            throw new ArgumentOutOfRangeException(nameof(index), $"the clip has {n} gaps");
        }

        /// <summary>
        /// The lengths of the gaps outside a model's trained range of missing frames [<paramref name="min"/>,
        /// <paramref name="max"/>], in gap order: such gaps still bake, but the model never saw them, so
        /// the window warns before baking. Empty when the range is unknown (max ≤ 0).
        /// </summary>
        public IReadOnlyList<int> GapsOutside(int min, int max)
        {
            var outside = new List<int>();
            if (max <= 0) return outside;
            for (int g = 0; g < GapCount; g++)
            {
                int n = GapLength(g);
                if (n < min || n > max) outside.Add(n);
            }

            return outside;
        }

        /// <summary>The frame count of a clip that ends on the last key (last index + 1), or 0 without keys.</summary>
        public int FrameCount => Frames.Count == 0 ? 0 : Frames[Frames.Count - 1] + 1;
    }
}
