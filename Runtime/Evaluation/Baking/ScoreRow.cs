using System;
using System.Collections.Generic;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>One file's line of a <see cref="ScoreSheet"/>: per method, the mean joint position error ÷ the file's leg length and L2Q over its non-key frames.</summary>
    public sealed class ScoreRow
    {
        /// <summary>Creates a row; every value must be finite.</summary>
        /// <exception cref="ArgumentException">A value is not finite, or the methods' counts differ.</exception>
        public ScoreRow(string file, string group, int frames, double legLength, double[] positionPerLeg, double[] l2q)
        {
            if (positionPerLeg.Length != l2q.Length) throw new ArgumentException("one position and one L2Q value per method", nameof(l2q));
            for (int i = 0; i < l2q.Length; i++)
            {
                if (!IsFinite(positionPerLeg[i]) || !IsFinite(l2q[i])) throw new ArgumentException($"{file}: non-finite errors; expected finite motion values", nameof(l2q));
            }

            File = file;
            Group = group;
            Frames = frames;
            LegLength = legLength;
            PositionPerLeg = positionPerLeg;
            L2Q = l2q;
        }

        /// <summary>The file's name (relative to its data folder).</summary>
        public string File { get; }

        /// <summary>Its subject ("" when the manifest names none).</summary>
        public string Group { get; }

        /// <summary>Non-key frames scored.</summary>
        public int Frames { get; }

        /// <summary>The file's leg length in its units.</summary>
        public double LegLength { get; }

        /// <summary>Per method: mean joint position error ÷ leg length.</summary>
        public IReadOnlyList<double> PositionPerLeg { get; }

        /// <summary>Per method: L2Q.</summary>
        public IReadOnlyList<double> L2Q { get; }

        private static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);
    }
}
