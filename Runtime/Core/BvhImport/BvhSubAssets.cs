namespace DeltaInterpolator.Core.BvhImport
{
    /// <summary>
    /// The identifiers a BVH import gives its sub-assets (<c>AssetImportContext.AddObjectToAsset</c>). Unity
    /// derives each sub-asset's local file id from its identifier, so fixed role names keep every reference
    /// to an imported clip or avatar valid across re-imports, importer changes and renames of the file.
    /// </summary>
    public static class BvhSubAssets
    {
        /// <summary>The skeleton prefab (the main object).</summary>
        public const string FigureId = "figure";

        /// <summary>The animation clip.</summary>
        public const string ClipId = "clip";

        /// <summary>The avatar (humanoid or generic).</summary>
        public const string AvatarId = "avatar";
    }
}
