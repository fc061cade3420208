using System;
using DeltaInterpolator.Core.Rotations;

namespace DeltaInterpolator.Tests
{
    /// <summary>Seeded random values for property-style tests (reproducible failures).</summary>
    public sealed class TestRandom
    {
        private readonly Random _random;

        public TestRandom(int seed)
        {
            _random = new Random(seed);
        }

        public double Uniform(double low, double high) => low + (high - low) * _random.NextDouble();

        public int Next(int low, int high) => _random.Next(low, high);

        public double Gaussian()
        {
            double u1 = 1.0 - _random.NextDouble();
            double u2 = _random.NextDouble();
            return Math.Sqrt(-2.0 * Math.Log(u1)) * Math.Cos(2.0 * Math.PI * u2);
        }

        /// <summary>A uniformly distributed unit quaternion, random sign.</summary>
        public QuaternionD Rotation()
        {
            var q = new QuaternionD(Gaussian(), Gaussian(), Gaussian(), Gaussian());
            return Quaternions.Normalize(q);
        }

        public Vector3D Vector(double scale) => new Vector3D(Uniform(-scale, scale), Uniform(-scale, scale), Uniform(-scale, scale));
    }
}
