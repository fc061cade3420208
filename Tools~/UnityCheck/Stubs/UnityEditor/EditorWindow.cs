using UnityEngine;

namespace UnityEditor
{
    // OnGUI and CreateGUI are messages, declared nowhere: the editor calls them by name.
    // source: unity:Editor/Mono/EditorWindow.cs
    public partial class EditorWindow : ScriptableObject
    {
        public static T GetWindow<T>(string title) where T : EditorWindow => throw null!;

        public static T GetWindow<T>(bool utility, string title, bool focus) where T : EditorWindow => throw null!;

        public static bool HasOpenInstances<T>() where T : UnityEditor.EditorWindow => throw null!;
    }
}
