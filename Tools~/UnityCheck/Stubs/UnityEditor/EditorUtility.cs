namespace UnityEditor
{
    public partial class EditorUtility
    {
        // source: unity:Editor/Mono/EditorUtility.bindings.cs
        public static bool DisplayDialog(string title, string message, string ok, string cancel) => throw null!;

        // source: unity:Editor/Mono/EditorUtility.bindings.cs
        public static bool DisplayDialog(string title, string message, string ok) => throw null!;

        // source: unity:Editor/Mono/EditorUtility.bindings.cs
        public static void DisplayProgressBar(string title, string info, float progress) => throw null!;

        // source: unity:Editor/Mono/EditorUtility.bindings.cs
        public static void ClearProgressBar() => throw null!;

        // source: unity:Editor/Mono/EditorUtility.bindings.cs
        public static void SetDirty(UnityEngine.Object target) => throw null!;

        // source: unity:Editor/Mono/EditorUtility.cs
        public static string SaveFilePanelInProject(string title, string defaultName, string extension, string message) => throw null!;
    }
}
