namespace UnityEngine
{
    // source: unity:Runtime/Export/Graphics/Mesh.cs
    public sealed partial class Mesh : Object
    {
    }
}
