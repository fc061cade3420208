using System;

namespace DeltaInterpolator.Core.Rotations
{
    /// <summary>
    /// A double-precision 3×3 matrix, row-major: <c>M01</c> is row 0, column 1. Rotation matrices act on
    /// column vectors (v' = M v), matching <see cref="Quaternions.Apply"/>.
    /// </summary>
    public readonly struct Matrix3x3D
    {
        /// <summary>Row 0.</summary>
        public readonly double M00, M01, M02;
        /// <summary>Row 1.</summary>
        public readonly double M10, M11, M12;
        /// <summary>Row 2.</summary>
        public readonly double M20, M21, M22;

        /// <summary>Creates a matrix from its entries, row by row.</summary>
        public Matrix3x3D(
            double m00, double m01, double m02,
            double m10, double m11, double m12,
            double m20, double m21, double m22)
        {
            M00 = m00; M01 = m01; M02 = m02;
            M10 = m10; M11 = m11; M12 = m12;
            M20 = m20; M21 = m21; M22 = m22;
        }

        /// <summary>The identity matrix.</summary>
        public static Matrix3x3D Identity => new Matrix3x3D(1, 0, 0, 0, 1, 0, 0, 0, 1);

        /// <summary>Entry at (row, column), both 0..2.</summary>
        public double this[int row, int column]
        {
            get
            {
                switch (row * 3 + column)
                {
                    case 0: return M00;
                    case 1: return M01;
                    case 2: return M02;
                    case 3: return M10;
                    case 4: return M11;
                    case 5: return M12;
                    case 6: return M20;
                    case 7: return M21;
                    case 8: return M22;
                    default: throw new ArgumentOutOfRangeException(nameof(row), "row and column must be 0..2");
                }
            }
        }

        /// <summary>Row <paramref name="row"/> as a vector.</summary>
        public Vector3D Row(int row) => new Vector3D(this[row, 0], this[row, 1], this[row, 2]);

        /// <summary>The transpose (the inverse, for a rotation).</summary>
        public Matrix3x3D Transposed => new Matrix3x3D(M00, M10, M20, M01, M11, M21, M02, M12, M22);

        /// <summary>Matrix product a·b.</summary>
        public static Matrix3x3D operator *(Matrix3x3D a, Matrix3x3D b)
        {
            return new Matrix3x3D(
                a.M00 * b.M00 + a.M01 * b.M10 + a.M02 * b.M20,
                a.M00 * b.M01 + a.M01 * b.M11 + a.M02 * b.M21,
                a.M00 * b.M02 + a.M01 * b.M12 + a.M02 * b.M22,
                a.M10 * b.M00 + a.M11 * b.M10 + a.M12 * b.M20,
                a.M10 * b.M01 + a.M11 * b.M11 + a.M12 * b.M21,
                a.M10 * b.M02 + a.M11 * b.M12 + a.M12 * b.M22,
                a.M20 * b.M00 + a.M21 * b.M10 + a.M22 * b.M20,
                a.M20 * b.M01 + a.M21 * b.M11 + a.M22 * b.M21,
                a.M20 * b.M02 + a.M21 * b.M12 + a.M22 * b.M22);
        }

        /// <summary>Matrix-vector product M v.</summary>
        public static Vector3D operator *(Matrix3x3D m, Vector3D v)
        {
            return new Vector3D(
                m.M00 * v.X + m.M01 * v.Y + m.M02 * v.Z,
                m.M10 * v.X + m.M11 * v.Y + m.M12 * v.Z,
                m.M20 * v.X + m.M21 * v.Y + m.M22 * v.Z);
        }
    }
}
