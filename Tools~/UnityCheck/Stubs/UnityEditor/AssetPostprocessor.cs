namespace UnityEditor
{
    // Its callbacks (OnPostprocessAllAssets, ...) are declared nowhere: the engine finds them by name.
    // source: unity:Editor/Mono/AssetPostprocessor.cs
    public partial class AssetPostprocessor
    {
    }
}
