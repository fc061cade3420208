using UnityEngine;

namespace UnityEditor
{
    // source: unity:Modules/AssetDatabase/Editor/ScriptBindings/AssetDatabase.bindings.cs
    public partial class AssetDatabase
    {
        public static string GenerateUniqueAssetPath(string path) => throw null!;

        public static void CreateAsset(Object asset, string path) => throw null!;

        public static T LoadAssetAtPath<T>(string assetPath) where T : Object => throw null!;

        public static Object LoadMainAssetAtPath(string assetPath) => throw null!;

        public static void SaveAssets() => throw null!;

        public static string GetAssetPath(Object assetObject) => throw null!;

        public static Object[] LoadAllAssetsAtPath(string assetPath) => throw null!;

        public static string GUIDToAssetPath(string guid) => throw null!;

        public static void SaveAssetIfDirty(Object obj) => throw null!;

        // source: unity:Editor/Mono/AssetDatabase/AssetDatabaseSearching.cs
        public static string[] FindAssets(string filter) => throw null!;

        public static string CreateFolder(string parentFolder, string newFolderName) => throw null!;

        public static void ImportAsset(string path) => throw null!;

        public static bool DeleteAsset(string path) => throw null!;
    }
}
