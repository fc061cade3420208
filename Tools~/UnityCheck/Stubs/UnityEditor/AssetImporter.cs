namespace UnityEditor
{
    // source: unity:Editor/Mono/AssetPipeline/AssetImporter.bindings.cs
    public partial class AssetImporter : UnityEngine.Object
    {
        // UnityCsReference 6000.0 Editor/Mono/AssetPipeline/AssetImporter.bindings.cs:113-114 (the importer of the asset at a path)
        public static AssetImporter GetAtPath(string path) => throw null!;

        // UnityCsReference 6000.0 Editor/Mono/AssetPipeline/AssetImporter.bindings.cs:116-119 (imports the asset again with the importer's settings)
        public void SaveAndReimport() => throw null!;
    }
}
