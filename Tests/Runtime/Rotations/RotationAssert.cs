using System;
using DeltaInterpolator.Core.Rotations;
using NUnit.Framework;

namespace DeltaInterpolator.Tests.Rotations
{
    /// <summary>Comparisons that treat q and −q as the same rotation.</summary>
    public static class RotationAssert
    {
        public static double Distance(QuaternionD a, QuaternionD b)
        {
            double same = Math.Sqrt(Sq(a.W - b.W) + Sq(a.X - b.X) + Sq(a.Y - b.Y) + Sq(a.Z - b.Z));
            double flipped = Math.Sqrt(Sq(a.W + b.W) + Sq(a.X + b.X) + Sq(a.Y + b.Y) + Sq(a.Z + b.Z));
            return Math.Min(same, flipped);
        }

        public static void SameRotation(QuaternionD actual, QuaternionD expected, double tolerance, string message = "")
        {
            Assert.That(Distance(actual, expected), Is.LessThan(tolerance), $"{message} expected ±{expected}, got {actual}");
        }

        internal static void SameMatrix(Matrix3x3D actual, Matrix3x3D expected, double tolerance)
        {
            for (int r = 0; r < 3; r++)
            {
                for (int c = 0; c < 3; c++)
                {
                    Assert.That(actual[r, c], Is.EqualTo(expected[r, c]).Within(tolerance), $"entry ({r}, {c})");
                }
            }
        }

        public static void SameVector(Vector3D actual, Vector3D expected, double tolerance)
        {
            Assert.That(actual.X, Is.EqualTo(expected.X).Within(tolerance), "x");
            Assert.That(actual.Y, Is.EqualTo(expected.Y).Within(tolerance), "y");
            Assert.That(actual.Z, Is.EqualTo(expected.Z).Within(tolerance), "z");
        }

        private static double Sq(double x) => x * x;
    }
}
