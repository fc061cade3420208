namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/UnityEngineObject.bindings.cs
    [System.Flags]
    public enum HideFlags
    {
        None = 0,
        HideInHierarchy = 1,
        HideInInspector = 2,
        DontSaveInEditor = 4,
        NotEditable = 8,
        DontSaveInBuild = 16,
        DontUnloadUnusedAsset = 32,
        DontSave = DontSaveInEditor | DontSaveInBuild | DontUnloadUnusedAsset,
        HideAndDontSave = HideInHierarchy | DontSaveInEditor | NotEditable | DontSaveInBuild | DontUnloadUnusedAsset,
    }

    // source: unity:Runtime/Export/Scripting/UnityEngineObject.bindings.cs
    public partial class Object
    {
        public string name { get => throw null!; set => throw null!; }

        public HideFlags hideFlags { get => throw null!; set => throw null!; }

        public int GetInstanceID() => throw null!;

        public static void DestroyImmediate(Object obj) => throw null!;

        public static T Instantiate<T>(T original) where T : Object => throw null!;

        public static void Destroy(Object obj) => throw null!;

        public static void DontDestroyOnLoad(Object target) => throw null!;

        public static T FindAnyObjectByType<T>() where T : Object => throw null!;

        public static bool operator ==(Object x, Object y) => throw null!;

        public static bool operator !=(Object x, Object y) => throw null!;
    }
}
