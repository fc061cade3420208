using System;

namespace DeltaInterpolator.Evaluation.Baking
{
    /// <summary>One file's line of a <see cref="ScoreSheet"/>: per method, the mean joint position error ÷ the file's leg length and L2Q over its non-key frames.</summary>
    public sealed class ScoreRow
    {
        /// <summary>Creates a row; every value must be finite.</summary>
        /// <exception cref="ArgumentException">A value is not finite, or the methods' counts differ.</exception>
        public ScoreRow(string file, string group, int frames, double legLength, double[] positionPerLeg, double[] l2q)
            : this(file, group, frames, legLength, positionPerLeg, l2q, new double[l2q.Length], 0, double.NaN)
        {
        }

        /// <summary>Creates a row with foot skating: per method and the ground truth's, over <paramref name="contactSamples"/> planted (frame, joint) pairs.</summary>
        /// <exception cref="ArgumentException">A position or L2Q value is not finite, or the methods' counts differ.</exception>
        public ScoreRow(string file, string group, int frames, double legLength, double[] positionPerLeg, double[] l2q,
            double[] footSkating, int contactSamples, double truthFootSkating)
        {
            if (footSkating.Length != l2q.Length) throw new ArgumentException("one foot-skating value per method", nameof(footSkating));
            if (positionPerLeg.Length != l2q.Length) throw new ArgumentException("one position and one L2Q value per method", nameof(l2q));
            for (int i = 0; i < l2q.Length; i++)
            {
                if (!IsFinite(positionPerLeg[i]) || !IsFinite(l2q[i])) throw new ArgumentException($"{file}: non-finite errors; expected finite motion values", nameof(l2q));
            }

            File = file;
            Group = group;
            Frames = frames;
            LegLength = legLength;
            Errors = new MethodErrors(positionPerLeg, l2q, footSkating, contactSamples, truthFootSkating);
        }

        /// <summary>The file's name (relative to its data folder).</summary>
        public string File { get; }

        /// <summary>Its subject ("" when the manifest names none).</summary>
        public string Group { get; }

        /// <summary>Non-key frames scored.</summary>
        public int Frames { get; }

        /// <summary>The file's leg length in its units.</summary>
        public double LegLength { get; }

        /// <summary>Every method's errors over the file's non-key frames (foot skating 0 with no contact samples).</summary>
        public MethodErrors Errors { get; }

        private static bool IsFinite(double v) => !double.IsNaN(v) && !double.IsInfinity(v);
    }
}
