namespace DeltaInterpolator.Core.Workflows
{
    /// <summary>Progress of a bake over every method's gaps: what <see cref="InbetweenBake.Run"/> reports.</summary>
    public readonly struct BakeProgress
    {
        /// <summary>Creates a report.</summary>
        public BakeProgress(string method, int gapsDone, int gapsTotal)
        {
            Method = method;
            GapsDone = gapsDone;
            GapsTotal = gapsTotal;
        }

        /// <summary>The method filling gaps now.</summary>
        public string Method { get; }

        /// <summary>Gaps filled so far, over every method.</summary>
        public int GapsDone { get; }

        /// <summary>Gaps to fill over every method.</summary>
        public int GapsTotal { get; }
    }
}
