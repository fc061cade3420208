namespace UnityEngine
{
    // source: unity:Runtime/Export/Time/Time.bindings.cs
    public partial class Time
    {
        public static int frameCount => throw null!;

        public static double timeAsDouble => throw null!;

        public static float deltaTime => throw null!;

        public static float unscaledDeltaTime => throw null!;

        public static float fixedDeltaTime { get => throw null!; set => throw null!; }
    }
}
