namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/ScriptableObject.bindings.cs
    public partial class ScriptableObject : Object
    {
        public static T CreateInstance<T>() where T : ScriptableObject => throw null!;
    }
}
