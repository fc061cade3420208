namespace DeltaInterpolator.Evaluation.Metrics
{
    /// <summary>
    /// Running sums of the three benchmark metrics for one method and one transition length, in
    /// double, over any number of windows. The averages are the official ones: L2Q and L2P are means
    /// over (window, frame); NPSS is the power-weighted mean over (window, feature). Foot skating (not an
    /// official metric; an extra table) is the mean over the (frame, foot joint) samples where the truth is planted.
    /// </summary>
    public sealed class MetricTotals
    {
        /// <summary>Σ of per-frame L2Q.</summary>
        public double L2QSum;

        /// <summary>Σ of per-frame L2P.</summary>
        public double L2PSum;

        /// <summary>Number of scored frames.</summary>
        public long FrameCount;

        /// <summary>Σ EMD × weight.</summary>
        public double NpssWeightedSum;

        /// <summary>Σ weight (ground-truth total power).</summary>
        public double NpssWeightSum;

        /// <summary>Mean L2Q over scored frames.</summary>
        public double L2Q => L2QSum / FrameCount;

        /// <summary>Mean L2P over scored frames.</summary>
        public double L2P => L2PSum / FrameCount;

        /// <summary>Power-weighted NPSS.</summary>
        public double Npss => NpssWeightedSum / NpssWeightSum;

        /// <summary>Σ of the result's foot-joint speeds where the truth's are planted (leg lengths per second; <see cref="Baking.FootSkating"/>).</summary>
        public double FootSkatingSum;

        /// <summary>Number of (filled frame, foot joint) samples where the truth's foot is planted.</summary>
        public long FootContactSamples;

        /// <summary>Mean foot skating, leg lengths per second (<see cref="Baking.FootSkating"/>); NaN without samples.</summary>
        public double FootSkating => FootContactSamples == 0 ? double.NaN : FootSkatingSum / FootContactSamples;
    }
}
