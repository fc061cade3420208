namespace UnityEngine
{
    // source: unity:Runtime/Export/Scripting/Behaviour.bindings.cs
    public partial class Behaviour : Component
    {
        public bool enabled { get => throw null!; set => throw null!; }
    }
}
