using System;

namespace UnityEditor.AssetImporters
{
    // source: unity:Modules/AssetPipelineEditor/Public/ScriptedImporter.cs
    public abstract partial class ScriptedImporter : AssetImporter
    {
        public abstract void OnImportAsset(AssetImportContext ctx);
    }

    // source: unity:Modules/AssetPipelineEditor/Public/ScriptedImporter.cs
    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public partial class ScriptedImporterAttribute : Attribute
    {
        public ScriptedImporterAttribute(int version, string ext) => throw null!;
    }
}
