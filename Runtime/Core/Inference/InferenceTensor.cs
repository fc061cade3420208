using System;

namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// A named tensor whose memory Core owns: a flat float or long array and a fixed shape. Core
    /// allocates one per tensor and request shape and reuses it; a backend binds it once
    /// (<see cref="IInferenceBackend.Bind"/>) and reads inputs from / writes outputs into
    /// <see cref="Floats"/> or <see cref="Longs"/> on every run, so no call allocates.
    /// </summary>
    public sealed class InferenceTensor
    {
        private InferenceTensor(string name, TensorElementKind kind, long[] shape, float[]? floats, long[]? longs)
        {
            Name = name;
            Kind = kind;
            Shape = shape;
            Floats = floats;
            Longs = longs;
            Length = Count(shape);
        }

        /// <summary>A float32 tensor of the given shape, zero-filled.</summary>
        public static InferenceTensor Float(string name, params long[] shape) =>
            new InferenceTensor(name, TensorElementKind.Float32, shape, new float[Count(shape)], null);

        /// <summary>An int64 tensor of the given shape, zero-filled.</summary>
        public static InferenceTensor Int64(string name, params long[] shape) =>
            new InferenceTensor(name, TensorElementKind.Int64, shape, null, new long[Count(shape)]);

        /// <summary>Tensor name in the graph.</summary>
        public string Name { get; }

        /// <summary>Element type (decides which of <see cref="Floats"/> and <see cref="Longs"/> is set).</summary>
        public TensorElementKind Kind { get; }

        /// <summary>Dimensions (all fixed). Do not modify: backends bind memory for this shape.</summary>
        public long[] Shape { get; }

        /// <summary>Elements of a float32 tensor, row-major; null for other kinds.</summary>
        public float[]? Floats { get; }

        /// <summary>Elements of an int64 tensor, row-major; null for other kinds.</summary>
        public long[]? Longs { get; }

        /// <summary>
        /// Number of elements: the first <see cref="Length"/> elements of <see cref="Floats"/> or
        /// <see cref="Longs"/> (a <see cref="Prefix"/> view shares a longer array).
        /// </summary>
        public int Length { get; }

        /// <summary>True when the array is longer than the tensor (a <see cref="Prefix"/> view): backends bind only its first <see cref="Length"/> elements.</summary>
        public bool IsView => (Floats?.Length ?? Longs!.Length) != Length;

        /// <summary>
        /// The first <paramref name="rows"/> rows (along axis 0) of this tensor, sharing its array: a batch
        /// of fewer transitions than the capacity the array was made for, bound without a copy.
        /// </summary>
        public InferenceTensor Prefix(int rows)
        {
            if (Shape.Length == 0 || rows < 0 || rows > Shape[0]) throw new ArgumentOutOfRangeException(nameof(rows), rows, $"expected 0..{(Shape.Length == 0 ? 0 : Shape[0])} rows");
            var shape = (long[])Shape.Clone();
            shape[0] = rows;
            return new InferenceTensor(Name, Kind, shape, Floats, Longs);
        }

        private static int Count(long[] shape)
        {
            if (shape == null) throw new ArgumentNullException(nameof(shape));
            long n = 1;
            foreach (long d in shape)
            {
                if (d < 0) throw new ArgumentException("tensor dimensions must be fixed (≥ 0) when Core allocates them", nameof(shape));
                n *= d;
            }

            if (n > int.MaxValue) throw new ArgumentException("tensor too large", nameof(shape));
            return (int)n;
        }

        /// <inheritdoc />
        public override string ToString() => $"{Name} ({Kind}, [{string.Join(", ", Shape)}])";
    }
}
