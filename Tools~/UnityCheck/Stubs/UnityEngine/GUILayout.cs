namespace UnityEngine
{
    // source: unity:Modules/IMGUI/GUILayout.cs
    public partial class GUILayout
    {
        public static bool Button(string text, params GUILayoutOption[] options) => throw null!;
    }
}
