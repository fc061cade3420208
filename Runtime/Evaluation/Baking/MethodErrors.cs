using System.Collections.Generic;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>
    /// Every method's errors over some non-key frames, one file's (<see cref="ScoreRow"/>) or several files' weighted together
    /// (<see cref="ScoreTotal"/>): position error ÷ leg length and L2Q per method, foot skating per method and the ground truth's
    /// where the truth's feet are planted, and each method's ratio to the baseline (the last method).
    /// </summary>
    public sealed class MethodErrors
    {
        internal MethodErrors(double[] positionPerLeg, double[] l2q, double[] footSkating, int contactSamples, double truthFootSkating)
        {
            PositionPerLeg = positionPerLeg;
            L2Q = l2q;
            FootSkating = footSkating;
            ContactSamples = contactSamples;
            TruthFootSkating = truthFootSkating;
        }

        /// <summary>Per method: mean joint position error ÷ leg length.</summary>
        public IReadOnlyList<double> PositionPerLeg { get; }

        /// <summary>Per method: L2Q.</summary>
        public IReadOnlyList<double> L2Q { get; }

        /// <summary>Per method: foot skating in leg lengths per second over the planted (frame, joint) pairs (a row: 0 with none; a total: NaN with none).</summary>
        public IReadOnlyList<double> FootSkating { get; }

        /// <summary>Planted (frame, joint) pairs of the ground truth on the non-key frames: the weight of <see cref="FootSkating"/>.</summary>
        public int ContactSamples { get; }

        /// <summary>The ground truth's own foot skating over the same pairs (NaN with none).</summary>
        public double TruthFootSkating { get; }

        /// <summary>Method <paramref name="i"/>'s position error ÷ the baseline's.</summary>
        public double PositionRatio(int i) => PositionPerLeg[i] / PositionPerLeg[PositionPerLeg.Count - 1];

        /// <summary>Method <paramref name="i"/>'s L2Q ÷ the baseline's.</summary>
        public double L2QRatio(int i) => L2Q[i] / L2Q[L2Q.Count - 1];
    }
}
