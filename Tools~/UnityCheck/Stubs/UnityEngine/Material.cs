namespace UnityEngine
{
    // source: unity:Runtime/Export/Shaders/Material.bindings.cs
    public partial class Material : Object
    {
    }
}
