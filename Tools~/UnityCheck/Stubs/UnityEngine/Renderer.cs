namespace UnityEngine
{
    // source: unity:Runtime/Export/Graphics/GraphicsRenderers.bindings.cs
    public partial class Renderer : Component
    {
        public Material sharedMaterial { get => throw null!; set => throw null!; }

        public bool enabled { get => throw null!; set => throw null!; }
    }

    // source: unity:Runtime/Export/Graphics/GraphicsRenderers.bindings.cs
    public partial class MeshRenderer : Renderer
    {
    }
}
