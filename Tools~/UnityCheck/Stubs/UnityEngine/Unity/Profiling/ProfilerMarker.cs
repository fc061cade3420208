using System;

namespace Unity.Profiling
{
    // source: unity:Runtime/Profiler/ScriptBindings/ProfilerMarker.bindings.cs
    public partial struct ProfilerMarker
    {
        public ProfilerMarker(string name) => throw null!;

        public AutoScope Auto() => throw null!;

        public void Begin() => throw null!;

        public void End() => throw null!;

        public partial struct AutoScope : IDisposable
        {
            public void Dispose() => throw null!;
        }
    }
}
