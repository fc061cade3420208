using System;
using System.Runtime.CompilerServices;

namespace DeltaInterpolator.Core.Rotations
{
    /// <summary>
    /// Quaternion operations on (w, x, y, z) quaternions, mirrored function for function by
    /// <c>Training/</c>'s <c>quaternions</c> module (<c>multiply</c>, <c>inverse</c>, <c>apply</c>, ...).
    /// Formulas follow the official LaFAN1 benchmark code where it defines one, so that baselines and
    /// metrics computed here agree with it.
    /// </summary>
    public static class Quaternions
    {
        /// <summary>Hamilton product a ⊗ b: the rotation b followed by a (for column vectors).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static QuaternionD Multiply(QuaternionD a, QuaternionD b)
        {
            return new QuaternionD(
                a.W * b.W - a.X * b.X - a.Y * b.Y - a.Z * b.Z,
                a.W * b.X + a.X * b.W + a.Y * b.Z - a.Z * b.Y,
                a.W * b.Y - a.X * b.Z + a.Y * b.W + a.Z * b.X,
                a.W * b.Z + a.X * b.Y - a.Y * b.X + a.Z * b.W);
        }

        /// <summary>The conjugate (w, −x, −y, −z); the inverse of a unit quaternion.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static QuaternionD Conjugate(QuaternionD q) => new QuaternionD(q.W, -q.X, -q.Y, -q.Z);

        /// <summary>
        /// The multiplicative inverse, conjugate / |q|². Equals <see cref="Conjugate"/> for unit quaternions
        /// (which is what the official benchmark uses as its inverse).
        /// </summary>
        /// <exception cref="ArgumentException">q is zero.</exception>
        public static QuaternionD Inverse(QuaternionD q)
        {
            double n2 = q.W * q.W + q.X * q.X + q.Y * q.Y + q.Z * q.Z;
            if (n2 == 0)
            {
                throw new ArgumentException("the zero quaternion has no inverse", nameof(q));
            }

            double s = 1.0 / n2;
            return new QuaternionD(q.W * s, -q.X * s, -q.Y * s, -q.Z * s);
        }

        /// <summary>Four-dimensional dot product.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Dot(QuaternionD a, QuaternionD b) => a.W * b.W + a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>q / |q|. The zero quaternion is returned unchanged (there is no direction to keep).</summary>
        public static QuaternionD Normalize(QuaternionD q)
        {
            double n = q.Length;
            if (n == 0)
            {
                return q;
            }

            double s = 1.0 / n;
            return new QuaternionD(q.W * s, q.X * s, q.Y * s, q.Z * s);
        }

        /// <summary>
        /// Rotates v by the unit quaternion q: v + 2w(u × v) + u × (2 u × v) with u = (x, y, z), the
        /// official code's formula (it does not renormalise q).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D Apply(QuaternionD q, Vector3D v)
        {
            double tx = 2.0 * (q.Y * v.Z - q.Z * v.Y);
            double ty = 2.0 * (q.Z * v.X - q.X * v.Z);
            double tz = 2.0 * (q.X * v.Y - q.Y * v.X);
            return new Vector3D(
                v.X + q.W * tx + (q.Y * tz - q.Z * ty),
                v.Y + q.W * ty + (q.Z * tx - q.X * tz),
                v.Z + q.W * tz + (q.X * ty - q.Y * tx));
        }

        /// <summary>The rotation by <paramref name="angle"/> radians about the unit <paramref name="axis"/>.</summary>
        public static QuaternionD FromAxisAngle(Vector3D axis, double angle)
        {
            double half = 0.5 * angle;
            double s = Math.Sin(half);
            return new QuaternionD(Math.Cos(half), s * axis.X, s * axis.Y, s * axis.Z);
        }

        /// <summary>
        /// Euler angles in degrees (as BVH motion lines hold them, in the order's value order) to a
        /// quaternion: <see cref="FromEuler"/> of the angles times π/180.
        /// </summary>
        public static QuaternionD FromEulerDegrees(double d0, double d1, double d2, EulerOrder order)
        {
            const double degreesToRadians = Math.PI / 180.0;
            return FromEuler(d0 * degreesToRadians, d1 * degreesToRadians, d2 * degreesToRadians, order);
        }

        /// <summary>
        /// Euler angles (radians, in the order's value order) to a quaternion, composed intrinsically:
        /// q = q_{a0}(e0) ⊗ q_{a1}(e1) ⊗ q_{a2}(e2), as BVH and the official code do.
        /// </summary>
        public static QuaternionD FromEuler(double e0, double e1, double e2, EulerOrder order)
        {
            QuaternionD q0 = AxisRotation(order.Axis(0), e0);
            QuaternionD q1 = AxisRotation(order.Axis(1), e1);
            QuaternionD q2 = AxisRotation(order.Axis(2), e2);
            // Same association as the official euler_to_quat: q0 ⊗ (q1 ⊗ q2).
            return Multiply(q0, Multiply(q1, q2));
        }

        /// <summary>
        /// Euler angles (radians) of q in <paramref name="order"/>, such that
        /// <see cref="FromEuler"/> gives back the same rotation (q or −q). The middle angle lies in
        /// [−π/2, π/2]; at gimbal lock (middle angle ±π/2) the last angle is set to 0.
        /// </summary>
        public static Vector3D ToEuler(QuaternionD q, EulerOrder order)
        {
            Matrix3x3D m = ToMatrix(Normalize(q));
            int i = order.Axis(0), j = order.Axis(1), k = order.Axis(2);
            // s = +1 for cyclic orders (XYZ, YZX, ZXY), −1 otherwise: it carries the sign of e_i × e_j = s·e_k.
            double s = (j - i + 3) % 3 == 1 ? 1.0 : -1.0;
            double sinMiddle = Math.Max(-1.0, Math.Min(1.0, s * m[i, k]));
            double middle = Math.Asin(sinMiddle);
            double first, last;
            if (Math.Abs(sinMiddle) < 1.0 - 1e-12)
            {
                first = Math.Atan2(-s * m[j, k], m[k, k]);
                last = Math.Atan2(-s * m[i, j], m[i, i]);
            }
            else
            {
                // Gimbal lock: only first ± last is defined. With last = 0, R = R_i(first)·R_j(middle) and
                // column j of R is R_i(first)·e_j = cos(first)·e_j + s·sin(first)·e_k.
                first = Math.Atan2(s * m[k, j], m[j, j]);
                last = 0.0;
            }

            return new Vector3D(first, middle, last);
        }

        /// <summary>The rotation matrix of the unit quaternion q (acting on column vectors).</summary>
        public static Matrix3x3D ToMatrix(QuaternionD q)
        {
            double w = q.W, x = q.X, y = q.Y, z = q.Z;
            double xx = x * x, yy = y * y, zz = z * z;
            double xy = x * y, xz = x * z, yz = y * z;
            double wx = w * x, wy = w * y, wz = w * z;
            return new Matrix3x3D(
                1 - 2 * (yy + zz), 2 * (xy - wz), 2 * (xz + wy),
                2 * (xy + wz), 1 - 2 * (xx + zz), 2 * (yz - wx),
                2 * (xz - wy), 2 * (yz + wx), 1 - 2 * (xx + yy));
        }

        /// <summary>
        /// A unit quaternion of the rotation matrix m (Shepperd's method: divides by the largest of the
        /// four candidate terms, so it stays accurate near 180°). The sign is unspecified; choose the
        /// hemisphere afterwards (e.g. dot ≥ 0 with a reference) where it matters.
        /// </summary>
        public static QuaternionD FromMatrix(Matrix3x3D m)
        {
            double trace = m.M00 + m.M11 + m.M22;
            QuaternionD q;
            if (trace > m.M00 && trace > m.M11 && trace > m.M22)
            {
                double s = 2.0 * Math.Sqrt(1.0 + trace);
                q = new QuaternionD(0.25 * s, (m.M21 - m.M12) / s, (m.M02 - m.M20) / s, (m.M10 - m.M01) / s);
            }
            else if (m.M00 > m.M11 && m.M00 > m.M22)
            {
                double s = 2.0 * Math.Sqrt(Math.Max(0.0, 1.0 + m.M00 - m.M11 - m.M22));
                q = new QuaternionD((m.M21 - m.M12) / s, 0.25 * s, (m.M01 + m.M10) / s, (m.M02 + m.M20) / s);
            }
            else if (m.M11 > m.M22)
            {
                double s = 2.0 * Math.Sqrt(Math.Max(0.0, 1.0 + m.M11 - m.M00 - m.M22));
                q = new QuaternionD((m.M02 - m.M20) / s, (m.M01 + m.M10) / s, 0.25 * s, (m.M12 + m.M21) / s);
            }
            else
            {
                double s = 2.0 * Math.Sqrt(Math.Max(0.0, 1.0 + m.M22 - m.M00 - m.M11));
                q = new QuaternionD((m.M10 - m.M01) / s, (m.M02 + m.M20) / s, (m.M12 + m.M21) / s, 0.25 * s);
            }

            return Normalize(q);
        }

        /// <summary>
        /// Spherical linear interpolation with the official LaFAN1 benchmark's semantics: d = ⟨a, b⟩;
        /// if d &lt; 0, b and d are negated (shortest arc); if 1 − d &lt; 0.01 the weights are the linear
        /// (1 − t, t), otherwise sin((1 − t)ω)/sin ω and sin(tω)/sin ω with ω = acos d.
        /// The result is not renormalised; the benchmark normalises its inputs and the result.
        /// </summary>
        public static QuaternionD Slerp(QuaternionD a, QuaternionD b, double t) => new SlerpPair(a, b).At(t);

        /// <summary>
        /// The shortest-arc rotation taking direction <paramref name="from"/> to <paramref name="to"/>
        /// (unit result). Unlike the official <c>quat_between</c>, which returns the zero quaternion when
        /// the two are antiparallel, this returns a half turn about an axis perpendicular to both
        /// (about <paramref name="preferredAxis"/> when it is perpendicular, e.g. +Y for a yaw).
        /// </summary>
        public static QuaternionD Between(Vector3D from, Vector3D to, Vector3D preferredAxis)
        {
            Vector3D c = Vector3D.Cross(from, to);
            double w = Math.Sqrt(Vector3D.Dot(from, from) * Vector3D.Dot(to, to)) + Vector3D.Dot(from, to);
            QuaternionD q = new QuaternionD(w, c.X, c.Y, c.Z);
            double n = q.Length;
            double scale = Math.Sqrt(Vector3D.Dot(from, from) * Vector3D.Dot(to, to));
            if (n <= 1e-12 * Math.Max(scale, 1e-300))
            {
                Vector3D axis = preferredAxis;
                if (Math.Abs(Vector3D.Dot(axis, from)) > 1e-9 * from.Length * axis.Length || axis.Length == 0)
                {
                    // Any axis perpendicular to `from` will do: cross with the least aligned basis vector.
                    Vector3D basis = Math.Abs(from.X) < Math.Abs(from.Y)
                        ? (Math.Abs(from.X) < Math.Abs(from.Z) ? Vector3D.UnitX : Vector3D.UnitZ)
                        : (Math.Abs(from.Y) < Math.Abs(from.Z) ? Vector3D.UnitY : Vector3D.UnitZ);
                    axis = Vector3D.Cross(from, basis);
                }

                double l = axis.Length;
                return new QuaternionD(0.0, axis.X / l, axis.Y / l, axis.Z / l);
            }

            return new QuaternionD(q.W / n, q.X / n, q.Y / n, q.Z / n);
        }

        /// <summary>
        /// Removes sign flips along time, in place: for every frame t ≥ 1 and joint, q_t is replaced by
        /// −q_t when ⟨q_{t−1}, q_t⟩ &lt; 0, comparing with the already fixed q_{t−1} (the official
        /// <c>remove_quat_discontinuities</c>; Python <c>quaternions.fix_continuity</c>).
        /// </summary>
        /// <param name="rotations">Flat frames × joints × 4 array of (w, x, y, z).</param>
        /// <param name="frameCount">Number of frames.</param>
        /// <param name="jointCount">Number of joints per frame.</param>
        public static void FixContinuity(Span<double> rotations, int frameCount, int jointCount)
        {
            int stride = jointCount * 4;
            if (rotations.Length < frameCount * stride)
            {
                throw new ArgumentException("rotations holds fewer than frameCount × jointCount × 4 values", nameof(rotations));
            }

            for (int t = 1; t < frameCount; t++)
            {
                int cur = t * stride;
                int prev = cur - stride;
                for (int j = 0; j < jointCount; j++)
                {
                    int c = cur + 4 * j, p = prev + 4 * j;
                    double dot = rotations[c] * rotations[p] + rotations[c + 1] * rotations[p + 1]
                        + rotations[c + 2] * rotations[p + 2] + rotations[c + 3] * rotations[p + 3];
                    if (dot < 0.0)
                    {
                        rotations[c] = -rotations[c];
                        rotations[c + 1] = -rotations[c + 1];
                        rotations[c + 2] = -rotations[c + 2];
                        rotations[c + 3] = -rotations[c + 3];
                    }
                }
            }
        }

        private static QuaternionD AxisRotation(int axis, double angle)
        {
            double half = 0.5 * angle;
            double s = Math.Sin(half), c = Math.Cos(half);
            switch (axis)
            {
                case 0: return new QuaternionD(c, s, 0, 0);
                case 1: return new QuaternionD(c, 0, s, 0);
                default: return new QuaternionD(c, 0, 0, s);
            }
        }
    }
}
