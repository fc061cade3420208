using System;
using System.Runtime.CompilerServices;

namespace DeltaInterpolator.Core.Rotations
{
    /// <summary>A double-precision 3D vector (model space: right-handed, Y up).</summary>
    public readonly struct Vector3D : IEquatable<Vector3D>
    {
        /// <summary>(0, 0, 0).</summary>
        public static readonly Vector3D Zero = new Vector3D(0, 0, 0);
        /// <summary>(1, 0, 0).</summary>
        public static readonly Vector3D UnitX = new Vector3D(1, 0, 0);
        /// <summary>(0, 1, 0).</summary>
        public static readonly Vector3D UnitY = new Vector3D(0, 1, 0);
        /// <summary>(0, 0, 1).</summary>
        public static readonly Vector3D UnitZ = new Vector3D(0, 0, 1);

        /// <summary>X component.</summary>
        public readonly double X;
        /// <summary>Y component.</summary>
        public readonly double Y;
        /// <summary>Z component.</summary>
        public readonly double Z;

        /// <summary>Creates a vector.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector3D(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>Reads three consecutive values starting at <paramref name="index"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D Read(ReadOnlySpan<double> values, int index)
        {
            return new Vector3D(values[index], values[index + 1], values[index + 2]);
        }

        /// <summary>Writes (x, y, z) to three consecutive values starting at <paramref name="index"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Write(Span<double> values, int index)
        {
            values[index] = X;
            values[index + 1] = Y;
            values[index + 2] = Z;
        }

        /// <summary>Euclidean length.</summary>
        public double Length => Math.Sqrt(X * X + Y * Y + Z * Z);

        /// <summary>Dot product.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Dot(Vector3D a, Vector3D b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>Cross product a × b.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D Cross(Vector3D a, Vector3D b)
        {
            return new Vector3D(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
        }

        /// <summary>Component-wise sum.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator +(Vector3D a, Vector3D b) => new Vector3D(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

        /// <summary>Component-wise difference.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator -(Vector3D a, Vector3D b) => new Vector3D(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

        /// <summary>Scaling.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator *(double s, Vector3D a) => new Vector3D(s * a.X, s * a.Y, s * a.Z);

        /// <inheritdoc />
        public bool Equals(Vector3D other) => X == other.X && Y == other.Y && Z == other.Z;

        /// <inheritdoc />
        public override bool Equals(object? obj) => obj is Vector3D other && Equals(other);

        /// <inheritdoc />
        public override int GetHashCode() => HashCode.Combine(X, Y, Z);

        /// <inheritdoc />
        public override string ToString() => FormattableString.Invariant($"({X}, {Y}, {Z})");
    }
}
