namespace DeltaInterpolator.Core.Baking
{
    /// <summary>One gap between consecutive keys and how it will be filled.</summary>
    public readonly struct BakeGap
    {
        /// <summary>Creates a gap description.</summary>
        public BakeGap(int startKey, int endKey, int pastAvailable, int pastFrames)
        {
            StartKey = startKey;
            EndKey = endKey;
            PastAvailable = pastAvailable;
            PastFrames = pastFrames;
        }

        /// <summary>Frame index of the key before the gap (the last past key).</summary>
        public int StartKey { get; }

        /// <summary>Frame index of the key after the gap (the target).</summary>
        public int EndKey { get; }

        /// <summary>Missing frames n = EndKey − StartKey − 1.</summary>
        public int MissingFrames => EndKey - StartKey - 1;

        /// <summary>The gap G = n + 1 (model frames from the last past key to the target).</summary>
        public int Gap => EndKey - StartKey;

        /// <summary>Frames up to and including <see cref="StartKey"/> that are given as context (keys or frames already filled).</summary>
        public int PastAvailable { get; }

        /// <summary>Past frames P of the request: <see cref="PastAvailable"/>, or more when the earliest is repeated.</summary>
        public int PastFrames { get; }
    }
}
