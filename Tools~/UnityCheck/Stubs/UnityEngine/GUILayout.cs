namespace UnityEngine
{
    // source: unity:Modules/IMGUI/GUILayout.cs
    public partial class GUILayout
    {
        public static bool Button(string text, params GUILayoutOption[] options) => throw null!;

        public static void Label(string text, params GUILayoutOption[] options) => throw null!;

        public static void BeginArea(Rect screenRect, GUIStyle style) => throw null!;

        public static void EndArea() => throw null!;

        public static GUILayoutOption Height(float height) => throw null!;
    }
}
