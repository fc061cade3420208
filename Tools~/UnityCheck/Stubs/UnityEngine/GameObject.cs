namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/GameObject.bindings.cs
    public sealed partial class GameObject : Object
    {
        public Transform transform => throw null!;
    }
}
