namespace UnityEngine
{
    // source: unity:Runtime/Export/Time/Time.bindings.cs
    public partial class Time
    {
        public static double timeAsDouble => throw null!;

        public static float deltaTime => throw null!;
    }
}
