namespace DeltaInterpolator.Core.Baking
{
    /// <summary>One gap between consecutive keys and how it will be filled.</summary>
    public readonly struct BakeGap
    {
        /// <summary>Creates a gap description.</summary>
        public BakeGap(int startKey, int endKey, int pastAvailable, int pastKeys)
        {
            StartKey = startKey;
            EndKey = endKey;
            PastAvailable = pastAvailable;
            PastKeys = pastKeys;
        }

        /// <summary>Frame index of the key before the gap (the last past key).</summary>
        public int StartKey { get; }

        /// <summary>Frame index of the key after the gap (the target).</summary>
        public int EndKey { get; }

        /// <summary>Missing frames n = EndKey − StartKey − 1.</summary>
        public int Missing => EndKey - StartKey - 1;

        /// <summary>Frames up to and including <see cref="StartKey"/> that are given as context (keys or frames already filled).</summary>
        public int PastAvailable { get; }

        /// <summary>Past keys of the request: <see cref="PastAvailable"/>, or more when the earliest is repeated.</summary>
        public int PastKeys { get; }
    }
}
