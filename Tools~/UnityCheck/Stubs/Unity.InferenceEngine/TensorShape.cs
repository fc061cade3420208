using System;

namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/TensorShape.cs
    public partial struct TensorShape
    {
        public TensorShape(ReadOnlySpan<int> shape) => throw null!;

        public int length => throw null!;
    }
}
