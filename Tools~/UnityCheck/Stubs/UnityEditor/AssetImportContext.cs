using UnityEngine;

namespace UnityEditor.AssetImporters
{
    // source: unity:Editor/Mono/AssetPipeline/AssetImportContext.bindings.cs
    public partial class AssetImportContext
    {
        public void AddObjectToAsset(string identifier, Object obj) => throw null!;

        public string assetPath { get => throw null!; }
    }
}
