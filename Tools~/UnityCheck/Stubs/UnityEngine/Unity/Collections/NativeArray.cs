using System;

namespace Unity.Collections
{
    // source: unity:Runtime/Export/Collections/NativeCollectionEnums.bindings.cs
    public enum Allocator
    {
        Persistent = 4,
    }

    // source: unity:Runtime/Export/NativeArray/NativeArray.cs
    public enum NativeArrayOptions
    {
        UninitializedMemory = 0,
        ClearMemory = 1,
    }

    // source: unity:Runtime/Export/NativeArray/NativeArray.cs
    public partial struct NativeArray<T> : IDisposable
        where T : struct
    {
        public NativeArray(int length, Allocator allocator, NativeArrayOptions options = NativeArrayOptions.ClearMemory) => throw null!;

        public int Length => throw null!;

        public T this[int index] { get => throw null!; set => throw null!; }

        public bool IsCreated => throw null!;

        public void Dispose() => throw null!;

        public Span<T> AsSpan() => throw null!;

        public ReadOnlySpan<T> AsReadOnlySpan() => throw null!;
    }
}

namespace Unity.Collections
{
    // source: unity:Runtime/Export/Collections/NativeCollectionAccessPolicies.cs
    [System.AttributeUsage(System.AttributeTargets.Field | System.AttributeTargets.Parameter | System.AttributeTargets.ReturnValue)]
    public sealed partial class ReadOnlyAttribute : System.Attribute
    {
    }
}
