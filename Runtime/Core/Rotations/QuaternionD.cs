using System;
using System.Runtime.CompilerServices;

namespace DeltaInterpolator.Core.Rotations
{
    /// <summary>
    /// A double-precision quaternion in (w, x, y, z) order, the order used everywhere in Core, in
    /// <c>Training/</c>, in fixtures and in the model contract. Unit quaternions represent rotations;
    /// <see cref="Quaternions"/> holds the operations.
    /// </summary>
    public readonly struct QuaternionD : IEquatable<QuaternionD>
    {
        /// <summary>The identity rotation (1, 0, 0, 0).</summary>
        public static readonly QuaternionD Identity = new QuaternionD(1, 0, 0, 0);

        /// <summary>Real part.</summary>
        public readonly double W;
        /// <summary>First imaginary component.</summary>
        public readonly double X;
        /// <summary>Second imaginary component.</summary>
        public readonly double Y;
        /// <summary>Third imaginary component.</summary>
        public readonly double Z;

        /// <summary>Creates a quaternion from its (w, x, y, z) components.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public QuaternionD(double w, double x, double y, double z)
        {
            W = w;
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>Reads four consecutive values (w, x, y, z) starting at <paramref name="index"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static QuaternionD Read(ReadOnlySpan<double> values, int index)
        {
            return new QuaternionD(values[index], values[index + 1], values[index + 2], values[index + 3]);
        }

        /// <summary>Writes (w, x, y, z) to four consecutive values starting at <paramref name="index"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Write(Span<double> values, int index)
        {
            values[index] = W;
            values[index + 1] = X;
            values[index + 2] = Y;
            values[index + 3] = Z;
        }

        /// <summary>Euclidean length of the 4-vector.</summary>
        public double Length => Math.Sqrt(W * W + X * X + Y * Y + Z * Z);

        /// <summary>The same quaternion with every component negated (the same rotation).</summary>
        public QuaternionD Negated => new QuaternionD(-W, -X, -Y, -Z);

        /// <inheritdoc />
        public bool Equals(QuaternionD other) => W == other.W && X == other.X && Y == other.Y && Z == other.Z;

        /// <inheritdoc />
        public override bool Equals(object? obj) => obj is QuaternionD other && Equals(other);

        /// <inheritdoc />
        public override int GetHashCode() => HashCode.Combine(W, X, Y, Z);

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant($"({W}, {X}, {Y}, {Z})");
    }
}
