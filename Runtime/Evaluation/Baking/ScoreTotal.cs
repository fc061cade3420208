using System.Collections.Generic;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>Frame-weighted means of some rows of a <see cref="ScoreSheet"/>, per method, and their ratios to the baseline (the last method).</summary>
    public sealed class ScoreTotal
    {
        internal ScoreTotal(int files, int frames, double[] positionPerLeg, double[] l2q, double[] footSkating, int contactSamples, double truthFootSkating)
        {
            FootSkating = footSkating;
            ContactSamples = contactSamples;
            TruthFootSkating = truthFootSkating;
            Files = files;
            Frames = frames;
            PositionPerLeg = positionPerLeg;
            L2Q = l2q;
        }

        /// <summary>Files added up.</summary>
        public int Files { get; }

        /// <summary>Non-key frames added up.</summary>
        public int Frames { get; }

        /// <summary>Per method: mean joint position error ÷ leg length.</summary>
        public IReadOnlyList<double> PositionPerLeg { get; }

        /// <summary>Per method: L2Q.</summary>
        public IReadOnlyList<double> L2Q { get; }

        /// <summary>Per method: foot skating (leg lengths per second) over every planted (frame, joint) pair; NaN with none.</summary>
        public IReadOnlyList<double> FootSkating { get; }

        /// <summary>Planted (frame, joint) pairs added up.</summary>
        public int ContactSamples { get; }

        /// <summary>The ground truth's own foot skating over the same pairs.</summary>
        public double TruthFootSkating { get; }

        /// <summary>Method <paramref name="i"/>'s position error ÷ the baseline's.</summary>
        public double PositionRatio(int i) => PositionPerLeg[i] / PositionPerLeg[PositionPerLeg.Count - 1];

        /// <summary>Method <paramref name="i"/>'s L2Q ÷ the baseline's.</summary>
        public double L2QRatio(int i) => L2Q[i] / L2Q[L2Q.Count - 1];
    }
}
