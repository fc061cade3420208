using System;

namespace Unity.InferenceEngine
{
    // source: inference:Runtime/Core/Backends/Worker.cs
    public partial class Worker : IDisposable
    {
        public Worker(Model model, BackendType backendType) => throw null!;

        public void SetInput(string name, Tensor input) => throw null!;

        public void Schedule() => throw null!;

        public Tensor PeekOutput(string name) => throw null!;

        public void CopyOutput(string name, ref Tensor tensor) => throw null!;

        public void Dispose() => throw null!;
    }
}
