using System;

namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/Tensor.cs
    public abstract partial class Tensor : IDisposable
    {
        public DataType dataType => throw null!;

        public TensorShape shape => throw null!;

        public void CompleteAllPendingOperations() => throw null!;

        public bool IsReadbackRequestDone() => throw null!;

        public void ReadbackRequest() => throw null!;

        public void Dispose() => throw null!;
    }

    // source: inference:Runtime/Core/TensorGeneric.cs
    public partial class Tensor<T> : Tensor where T : unmanaged
    {
        public Tensor(TensorShape shape, bool clearOnInit = true) => throw null!;

        public void Upload(T[] srcData) => throw null!;

        public ReadOnlySpan<T> AsReadOnlySpan() => throw null!;

        public T[] DownloadToArray() => throw null!;
    }
}
