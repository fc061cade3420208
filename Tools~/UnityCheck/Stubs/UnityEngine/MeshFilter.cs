namespace UnityEngine
{
    // source: unity:Runtime/Export/Graphics/GraphicsComponents.bindings.cs
    public sealed partial class MeshFilter : Component
    {
        public Mesh sharedMesh { get => throw null!; set => throw null!; }
    }
}
