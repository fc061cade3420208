namespace UnityEngine
{
    // source: unity:Modules/InputLegacy/Input.bindings.cs
    public partial class Input
    {
        public static bool GetKeyDown(KeyCode key) => throw null!;
    }
}
