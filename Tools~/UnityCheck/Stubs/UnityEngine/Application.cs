namespace UnityEngine
{
    // source: unity:Runtime/Export/Application/Application.bindings.cs
    public partial class Application
    {
        public static bool isPlaying => throw null!;
    }
}
