namespace UnityEditor
{
    // source: unity:Editor/Mono/AssetPipeline/AssetImporter.bindings.cs
    public partial class AssetImporter : UnityEngine.Object
    {
    }
}
