namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/GameObject.bindings.cs
    public sealed partial class GameObject : Object
    {
        public Transform transform => throw null!;

        public GameObject(string name) => throw null!;

        public static GameObject CreatePrimitive(PrimitiveType type) => throw null!;

        public T GetComponent<T>() => throw null!;

        public T[] GetComponents<T>() => throw null!;

        public T AddComponent<T>() where T : Component => throw null!;
    }
}
