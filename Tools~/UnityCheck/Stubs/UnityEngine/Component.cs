namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/Component.bindings.cs
    public partial class Component : Object
    {
        public Transform transform => throw null!;

        public GameObject gameObject => throw null!;

        public T GetComponent<T>() => throw null!;

        public T[] GetComponentsInChildren<T>(bool includeInactive) => throw null!;
    }
}
