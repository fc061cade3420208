using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Network outputs → poses (Documentation~/model-contract.md, "Decoding"; Python mirror
    /// <c>decoding.decode_outputs</c>): root = baseline + Δ; rotation = Gram–Schmidt(6D(baseline) + Δ6D)
    /// → quaternion, put in the baseline quaternion's hemisphere so that a track never flips sign.
    /// Allocation-free.
    /// </summary>
    public static class OutputDecoder
    {
        /// <summary>Decodes one joint's rotation.</summary>
        /// <param name="mode">Output Δ-mode (<see cref="OutputDeltaMode.None"/>: the 6D baseline is zero).</param>
        /// <param name="baseline">The baseline quaternion (unit): 6D baseline and hemisphere reference.</param>
        /// <param name="delta">Six predicted values (rows of the matrix).</param>
        /// <returns>A unit quaternion with ⟨q, baseline⟩ ≥ 0.</returns>
        public static QuaternionD Rotation(OutputDeltaMode mode, QuaternionD baseline, ReadOnlySpan<float> delta)
        {
            double a0 = delta[0], a1 = delta[1], a2 = delta[2], a3 = delta[3], a4 = delta[4], a5 = delta[5];
            if (mode != OutputDeltaMode.None)
            {
                Matrix3x3D b = Quaternions.ToMatrix(baseline);
                a0 += b.M00; a1 += b.M01; a2 += b.M02;
                a3 += b.M10; a4 += b.M11; a5 += b.M12;
            }

            QuaternionD q = Quaternions.FromMatrix(GramSchmidt(a0, a1, a2, a3, a4, a5));
            return Quaternions.Dot(q, baseline) < 0 ? q.Negated : q;
        }

        /// <summary>Decodes the root position: baseline + Δ (model units, localized).</summary>
        public static Vector3D RootPosition(Vector3D baseline, ReadOnlySpan<float> delta)
        {
            return new Vector3D(baseline.X + delta[0], baseline.Y + delta[1], baseline.Z + delta[2]);
        }

        /// <summary>
        /// Gram–Schmidt on rows, as <see cref="Rotation6D.ToMatrix"/> (b1 = N(a1), b2 = N(a2 − (b1·a2) b1),
        /// b3 = b1 × b2, N(v) = v / max(|v|, 1e-12)) without a span.
        /// </summary>
        public static Matrix3x3D GramSchmidt(double a0, double a1, double a2, double a3, double a4, double a5)
        {
            double n1 = 1.0 / Math.Max(Math.Sqrt(a0 * a0 + a1 * a1 + a2 * a2), 1e-12);
            double b10 = a0 * n1, b11 = a1 * n1, b12 = a2 * n1;
            double d = b10 * a3 + b11 * a4 + b12 * a5;
            double c0 = a3 - d * b10, c1 = a4 - d * b11, c2 = a5 - d * b12;
            double n2 = 1.0 / Math.Max(Math.Sqrt(c0 * c0 + c1 * c1 + c2 * c2), 1e-12);
            double b20 = c0 * n2, b21 = c1 * n2, b22 = c2 * n2;
            return new Matrix3x3D(
                b10, b11, b12,
                b20, b21, b22,
                b11 * b22 - b12 * b21, b12 * b20 - b10 * b22, b10 * b21 - b11 * b20);
        }
    }
}
