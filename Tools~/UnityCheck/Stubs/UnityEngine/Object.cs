namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/UnityEngineObject.bindings.cs
    public partial class Object
    {
        public string name { get => throw null!; set => throw null!; }

        public static void DestroyImmediate(Object obj) => throw null!;

        public static T Instantiate<T>(T original) where T : Object => throw null!;

        public static void DontDestroyOnLoad(Object target) => throw null!;

        public static T FindAnyObjectByType<T>() where T : Object => throw null!;

        public static bool operator ==(Object x, Object y) => throw null!;

        public static bool operator !=(Object x, Object y) => throw null!;
    }
}
