using System;

namespace DeltaInterpolator.Core.Rotations
{
    /// <summary>
    /// The continuous 6D rotation representation as the model contract defines it: the first two
    /// <b>rows</b> of the rotation matrix, [R00, R01, R02, R10, R11, R12] (pytorch3d's convention), decoded
    /// by Gram–Schmidt on rows. Python mirror: <c>rotation6d.from_matrix</c> / <c>to_matrix</c>.
    /// </summary>
    internal static class Rotation6D
    {
        /// <summary>Number of values in one 6D rotation.</summary>
        public const int Size = 6;

        /// <summary>Writes the first two rows of m to <paramref name="destination"/>[0..6).</summary>
        public static void FromMatrix(Matrix3x3D m, Span<double> destination)
        {
            if (destination.Length < Size)
            {
                throw new ArgumentException("destination must hold 6 values", nameof(destination));
            }

            destination[0] = m.M00;
            destination[1] = m.M01;
            destination[2] = m.M02;
            destination[3] = m.M10;
            destination[4] = m.M11;
            destination[5] = m.M12;
        }

        /// <summary>
        /// Decodes six values (two rows, not necessarily orthonormal — e.g. a baseline plus a predicted
        /// delta) into a rotation matrix: b1 = N(a1), b2 = N(a2 − (b1·a2) b1), b3 = b1 × b2, with
        /// N(v) = v / max(|v|, 1e-12) so that degenerate input gives zeros instead of NaN.
        /// </summary>
        public static Matrix3x3D ToMatrix(ReadOnlySpan<double> sixD)
        {
            if (sixD.Length < Size)
            {
                throw new ArgumentException("a 6D rotation has 6 values", nameof(sixD));
            }

            Vector3D a1 = new Vector3D(sixD[0], sixD[1], sixD[2]);
            Vector3D a2 = new Vector3D(sixD[3], sixD[4], sixD[5]);
            Vector3D b1 = SafeNormalize(a1);
            Vector3D b2 = SafeNormalize(a2 - Vector3D.Dot(b1, a2) * b1);
            Vector3D b3 = Vector3D.Cross(b1, b2);
            return new Matrix3x3D(b1.X, b1.Y, b1.Z, b2.X, b2.Y, b2.Z, b3.X, b3.Y, b3.Z);
        }

        private static Vector3D SafeNormalize(Vector3D v)
        {
            double n = Math.Max(v.Length, 1e-12);
            return (1.0 / n) * v;
        }
    }
}
