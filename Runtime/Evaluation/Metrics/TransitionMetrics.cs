using System;

namespace DeltaInterpolator.Evaluation.Metrics
{
    /// <summary>
    /// The per-frame errors of the official LaFAN1 benchmark, summed over frames so that callers can
    /// average over any number of windows in double precision.
    /// </summary>
    public static class TransitionMetrics
    {
        /// <summary>
        /// Σ over frames of ‖ĝ_t − g_t‖₂, the norm taken over all joints × 4 global quaternion
        /// components of a frame at once (L2Q; no hemisphere alignment, as in the official code).
        /// </summary>
        public static double SumL2Q(ReadOnlySpan<double> predicted, ReadOnlySpan<double> truth, int frameCount, int jointCount)
        {
            int stride = jointCount * 4;
            RequireLength(predicted, frameCount * stride, nameof(predicted));
            RequireLength(truth, frameCount * stride, nameof(truth));
            double total = 0;
            for (int f = 0; f < frameCount; f++)
            {
                double s = 0;
                int b = f * stride;
                for (int i = 0; i < stride; i++)
                {
                    double d = predicted[b + i] - truth[b + i];
                    s += d * d;
                }

                total += Math.Sqrt(s);
            }

            return total;
        }

        /// <summary>
        /// Σ over frames of √(Σ_k ((p̂_k − p_k) / σ_k)²) over the joints × 3 global position coordinates
        /// (L2P). The official code standardises both sides, (p − μ)/σ; μ cancels in the difference.
        /// </summary>
        /// <param name="predicted">frames × joints × 3 global positions.</param>
        /// <param name="truth">frames × joints × 3 global positions.</param>
        /// <param name="frameCount">Number of frames.</param>
        /// <param name="jointCount">Joints per frame.</param>
        /// <param name="standardDeviations">joints × 3 per-coordinate standard deviations (index 3·joint + axis).</param>
        public static double SumL2P(
            ReadOnlySpan<double> predicted,
            ReadOnlySpan<double> truth,
            int frameCount,
            int jointCount,
            ReadOnlySpan<double> standardDeviations)
        {
            int stride = jointCount * 3;
            RequireLength(predicted, frameCount * stride, nameof(predicted));
            RequireLength(truth, frameCount * stride, nameof(truth));
            RequireLength(standardDeviations, stride, nameof(standardDeviations));
            double total = 0;
            for (int f = 0; f < frameCount; f++)
            {
                double s = 0;
                int b = f * stride;
                for (int i = 0; i < stride; i++)
                {
                    double d = (predicted[b + i] - truth[b + i]) / standardDeviations[i];
                    s += d * d;
                }

                total += Math.Sqrt(s);
            }

            return total;
        }

        private static void RequireLength(ReadOnlySpan<double> values, int length, string name)
        {
            if (values.Length < length) throw new ArgumentException($"{name} holds {values.Length} values; expected at least {length}", name);
        }
    }
}
