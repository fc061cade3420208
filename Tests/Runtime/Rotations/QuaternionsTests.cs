using System;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Rotations
{
    public class QuaternionsTests
    {
        private const double Deg = Math.PI / 180.0;

        private static Matrix3x3D AxisMatrix(int axis, double angle)
        {
            double c = Math.Cos(angle), s = Math.Sin(angle);
            switch (axis)
            {
                case 0: return new Matrix3x3D(1, 0, 0, 0, c, -s, 0, s, c);
                case 1: return new Matrix3x3D(c, 0, s, 0, 1, 0, -s, 0, c);
                default: return new Matrix3x3D(c, -s, 0, s, c, 0, 0, 0, 1);
            }
        }

        [Test]
        public void MultiplyMatchesHandComputedProduct()
        {
            // i ⊗ j = k, j ⊗ i = −k: the Hamilton convention.
            var i = new QuaternionD(0, 1, 0, 0);
            var j = new QuaternionD(0, 0, 1, 0);
            Assert.That(Quaternions.Multiply(i, j), Is.EqualTo(new QuaternionD(0, 0, 0, 1)));
            Assert.That(Quaternions.Multiply(j, i), Is.EqualTo(new QuaternionD(0, 0, 0, -1)));
            var a = new QuaternionD(1, 2, 3, 4);
            var b = new QuaternionD(5, 6, 7, 8);
            // (1 + 2i + 3j + 4k)(5 + 6i + 7j + 8k) = −60 + 12i + 30j + 24k
            Assert.That(Quaternions.Multiply(a, b), Is.EqualTo(new QuaternionD(-60, 12, 30, 24)));
        }

        [Test]
        public void ApplyRotatesAQuarterTurnAboutZ()
        {
            QuaternionD q = Quaternions.FromAxisAngle(Vector3D.UnitZ, Math.PI / 2);
            RotationAssert.SameVector(Quaternions.Apply(q, new Vector3D(1, 0, 0)), new Vector3D(0, 1, 0), 1e-15);
            RotationAssert.SameVector(Quaternions.Apply(q, new Vector3D(0, 0, 2)), new Vector3D(0, 0, 2), 1e-15);
        }

        [Test]
        public void ApplyAndMultiplyAgreeWithMatrices()
        {
            var random = new TestRandom(1);
            for (int i = 0; i < 200; i++)
            {
                QuaternionD a = random.Rotation(), b = random.Rotation();
                Vector3D v = random.Vector(10);
                RotationAssert.SameVector(Quaternions.Apply(a, v), Quaternions.ToMatrix(a) * v, 1e-12);
                RotationAssert.SameMatrix(Quaternions.ToMatrix(Quaternions.Multiply(a, b)), Quaternions.ToMatrix(a) * Quaternions.ToMatrix(b), 1e-12);
            }
        }

        [Test]
        public void InverseUndoesTheRotation()
        {
            var random = new TestRandom(2);
            for (int i = 0; i < 100; i++)
            {
                QuaternionD q = random.Rotation();
                RotationAssert.SameRotation(Quaternions.Multiply(q, Quaternions.Inverse(q)), QuaternionD.Identity, 1e-14);
                var scaled = new QuaternionD(2 * q.W, 2 * q.X, 2 * q.Y, 2 * q.Z);
                QuaternionD product = Quaternions.Multiply(scaled, Quaternions.Inverse(scaled));
                Assert.That(product.W, Is.EqualTo(1.0).Within(1e-14), "inverse of a non-unit quaternion");
            }

            Assert.That(() => Quaternions.Inverse(new QuaternionD(0, 0, 0, 0)), Throws.ArgumentException);
        }

        [Test]
        public void FromEulerComposesIntrinsicallyInChannelOrder([ValueSource(typeof(EulerOrders), nameof(EulerOrders.All))] EulerOrder order)
        {
            var random = new TestRandom(3 + (int)order);
            for (int i = 0; i < 50; i++)
            {
                double e0 = random.Uniform(-Math.PI, Math.PI), e1 = random.Uniform(-Math.PI, Math.PI), e2 = random.Uniform(-Math.PI, Math.PI);
                Matrix3x3D expected = AxisMatrix(order.Axis(0), e0) * AxisMatrix(order.Axis(1), e1) * AxisMatrix(order.Axis(2), e2);
                RotationAssert.SameMatrix(Quaternions.ToMatrix(Quaternions.FromEuler(e0, e1, e2, order)), expected, 1e-12);
            }
        }

        [Test]
        public void FromEulerZyxMatchesAHandComputedLafanValue()
        {
            // 90° about Z then 90° about (the new) Y: R = Rz(90)·Ry(90), checked by hand:
            // Ry(90)·x = (0, 0, −1); Rz(90)·(0, 0, −1) = (0, 0, −1).
            QuaternionD q = Quaternions.FromEuler(90 * Deg, 90 * Deg, 0, EulerOrder.Zyx);
            RotationAssert.SameVector(Quaternions.Apply(q, Vector3D.UnitX), new Vector3D(0, 0, -1), 1e-15);
            // Ry(90)·y = y; Rz(90)·y = (−1, 0, 0).
            RotationAssert.SameVector(Quaternions.Apply(q, Vector3D.UnitY), new Vector3D(-1, 0, 0), 1e-15);
        }

        [Test]
        public void EulerRoundTripsForEveryOrder([ValueSource(typeof(EulerOrders), nameof(EulerOrders.All))] EulerOrder order)
        {
            var random = new TestRandom(10 + (int)order);
            for (int i = 0; i < 500; i++)
            {
                QuaternionD q = random.Rotation();
                Vector3D e = Quaternions.ToEuler(q, order);
                Assert.That(Math.Abs(e.Y), Is.LessThanOrEqualTo(Math.PI / 2 + 1e-12), "middle angle range");
                RotationAssert.SameRotation(Quaternions.FromEuler(e.X, e.Y, e.Z, order), q, 1e-12);
            }
        }

        [Test]
        public void EulerRoundTripsAtGimbalLock([ValueSource(typeof(EulerOrders), nameof(EulerOrders.All))] EulerOrder order)
        {
            foreach (double middle in new[] { Math.PI / 2, -Math.PI / 2 })
            {
                QuaternionD q = Quaternions.FromEuler(0.3, middle, -0.7, order);
                Vector3D e = Quaternions.ToEuler(q, order);
                RotationAssert.SameRotation(Quaternions.FromEuler(e.X, e.Y, e.Z, order), q, 1e-7);
            }
        }

        [Test]
        public void MatrixRoundTripsIncludingHalfTurns()
        {
            var random = new TestRandom(4);
            for (int i = 0; i < 500; i++)
            {
                QuaternionD q = random.Rotation();
                RotationAssert.SameRotation(Quaternions.FromMatrix(Quaternions.ToMatrix(q)), q, 1e-12);
            }

            foreach (Vector3D axis in new[] { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ, (1 / Math.Sqrt(3)) * new Vector3D(1, 1, 1) })
            {
                QuaternionD halfTurn = Quaternions.FromAxisAngle(axis, Math.PI);
                RotationAssert.SameRotation(Quaternions.FromMatrix(Quaternions.ToMatrix(halfTurn)), halfTurn, 1e-12);
            }
        }

        [Test]
        public void SixDIsTheFirstTwoRowsAndRoundTrips()
        {
            var random = new TestRandom(5);
            Span<double> sixD = stackalloc double[6];
            for (int i = 0; i < 300; i++)
            {
                QuaternionD q = random.Rotation();
                Matrix3x3D m = Quaternions.ToMatrix(q);
                Rotation6D.FromMatrix(m, sixD);
                Assert.That(sixD[1], Is.EqualTo(m.M01), "row convention: value 1 is R01");
                Assert.That(sixD[3], Is.EqualTo(m.M10), "row convention: value 3 is R10");
                RotationAssert.SameMatrix(Rotation6D.ToMatrix(sixD), m, 1e-12);
                RotationAssert.SameRotation(Quaternions.FromMatrix(Rotation6D.ToMatrix(sixD)), q, 1e-12);
            }
        }

        [Test]
        public void SixDDecodingOrthonormalisesPerturbedRows()
        {
            // Rows (2, 0, 0) and (1, 3, 0): Gram–Schmidt gives x, y and z = x × y — the identity.
            double[] sixD = { 2, 0, 0, 1, 3, 0 };
            RotationAssert.SameMatrix(Rotation6D.ToMatrix(sixD), Matrix3x3D.Identity, 1e-15);
            var random = new TestRandom(6);
            for (int i = 0; i < 100; i++)
            {
                for (int k = 0; k < 6; k++) sixD[k] = random.Gaussian();
                Matrix3x3D m = Rotation6D.ToMatrix(sixD);
                Matrix3x3D identity = m * m.Transposed;
                RotationAssert.SameMatrix(identity, Matrix3x3D.Identity, 1e-12);
                double det = m.M00 * (m.M11 * m.M22 - m.M12 * m.M21) - m.M01 * (m.M10 * m.M22 - m.M12 * m.M20) + m.M02 * (m.M10 * m.M21 - m.M11 * m.M20);
                Assert.That(det, Is.EqualTo(1.0).Within(1e-12), "a rotation, not a reflection");
            }

            Assert.That(double.IsNaN(Rotation6D.ToMatrix(new double[6]).M00), Is.False, "all-zero input must not give NaN");
        }

        [Test]
        public void SlerpHitsItsEndpointsAndStaysUnit()
        {
            var random = new TestRandom(7);
            for (int i = 0; i < 200; i++)
            {
                QuaternionD a = random.Rotation(), b = random.Rotation();
                RotationAssert.SameRotation(Quaternions.Slerp(a, b, 0), a, 1e-12);
                RotationAssert.SameRotation(Quaternions.Slerp(a, b, 1), b, 1e-12);
                for (double t = 0.1; t < 1; t += 0.2)
                {
                    QuaternionD q = Quaternions.Slerp(a, b, t);
                    if (Math.Abs(Quaternions.Dot(a, b)) <= 0.99)
                    {
                        Assert.That(q.Length, Is.EqualTo(1.0).Within(1e-12), "spherical weights keep unit length");
                    }

                    Assert.That(Quaternions.Normalize(q).Length, Is.EqualTo(1.0).Within(1e-14));
                }
            }
        }

        [Test]
        public void SlerpMovesAtConstantAngularSpeedAlongTheShortArc()
        {
            QuaternionD a = QuaternionD.Identity;
            QuaternionD b = Quaternions.FromAxisAngle(Vector3D.UnitY, 120 * Deg).Negated; // other hemisphere
            QuaternionD q = Quaternions.Slerp(a, b, 0.25);
            RotationAssert.SameRotation(q, Quaternions.FromAxisAngle(Vector3D.UnitY, 30 * Deg), 1e-14, "shortest arc");
            Assert.That(q.W, Is.GreaterThan(0), "the hemisphere of the first argument");
        }

        [Test]
        public void SlerpUsesLinearWeightsWhenNearlyParallel()
        {
            // 1 − d < 0.01: the official code blends linearly (result not unit before normalising).
            QuaternionD a = QuaternionD.Identity;
            QuaternionD b = Quaternions.FromAxisAngle(Vector3D.UnitX, 10 * Deg); // d = cos 5° ≈ 0.9962
            QuaternionD q = Quaternions.Slerp(a, b, 0.5);
            Assert.That(q.W, Is.EqualTo(0.5 * (1 + b.W)).Within(1e-15));
            Assert.That(q.X, Is.EqualTo(0.5 * b.X).Within(1e-15));
            QuaternionD wide = Quaternions.FromAxisAngle(Vector3D.UnitX, 60 * Deg);
            Assert.That(Quaternions.Slerp(a, wide, 0.5).X, Is.EqualTo(Math.Sin(15 * Deg)).Within(1e-15), "spherical above the threshold");
        }

        [Test]
        public void FixContinuityFlipsAgainstThePreviousFixedFrame()
        {
            QuaternionD q = Quaternions.FromAxisAngle(Vector3D.UnitY, 0.1);
            double[] frames =
            {
                q.W, q.X, q.Y, q.Z,
                -q.W, -q.X, -q.Y, -q.Z,   // flipped: must be negated back
                -q.W, -q.X, -q.Y, -q.Z,   // compared with the fixed previous frame: negated too
                q.W, q.X, q.Y, q.Z,
            };
            Quaternions.FixContinuity(frames, 4, 1);
            for (int f = 0; f < 4; f++) Assert.That(frames[4 * f], Is.EqualTo(q.W), $"frame {f}");
        }

        [Test]
        public void BetweenHandlesAntiparallelDirections()
        {
            QuaternionD q = Quaternions.Between(Vector3D.UnitX, new Vector3D(-1, 0, 0), Vector3D.UnitY);
            RotationAssert.SameVector(Quaternions.Apply(q, Vector3D.UnitX), new Vector3D(-1, 0, 0), 1e-15);
            RotationAssert.SameRotation(q, new QuaternionD(0, 0, 1, 0), 1e-15);
            QuaternionD r = Quaternions.Between(Vector3D.UnitX, new Vector3D(0, 0, 1), Vector3D.UnitY);
            RotationAssert.SameVector(Quaternions.Apply(r, Vector3D.UnitX), Vector3D.UnitZ, 1e-15);
        }
    }
}
