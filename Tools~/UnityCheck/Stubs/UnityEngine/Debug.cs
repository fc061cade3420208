namespace UnityEngine
{
    // source: unity:Runtime/Export/Debug/Debug.bindings.cs
    public partial class Debug
    {
        public static void Log(object message) => throw null!;

        public static void LogError(object message, Object context) => throw null!;

        public static void LogWarning(object message, Object context) => throw null!;
    }
}
