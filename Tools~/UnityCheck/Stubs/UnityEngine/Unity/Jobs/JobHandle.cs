namespace Unity.Jobs
{
    // source: unity:Runtime/Jobs/ScriptBindings/JobHandle.bindings.cs
    public partial struct JobHandle
    {
        public static void ScheduleBatchedJobs() => throw null!;
    }
}
