using UnityEngine;

namespace UnityEditor.AssetImporters
{
    // source: unity:Editor/Mono/AssetPipeline/AssetImportContext.bindings.cs
    public partial class AssetImportContext
    {
        public void AddObjectToAsset(string identifier, Object obj) => throw null!;

        public void SetMainObject(Object obj) => throw null!;

        public void LogImportError(string msg, Object obj = null) => throw null!;

        public void LogImportWarning(string msg, Object obj = null) => throw null!;

        public string assetPath { get => throw null!; }
    }
}
