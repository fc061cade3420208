#nullable enable
using System;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEngine;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Editor.Models
{
    /// <summary>
    /// An <see cref="InbetweeningModel"/> asset wired to the model this package ships as its default
    /// (<see cref="ShippedModels.Default"/>: the whole, keys and frame graphs imported from the package's
    /// <c>Runtime/Models</c>), with the contract captured at their import. For the Demo sample's scene and for
    /// anyone who wants the default model without picking three files.
    /// </summary>
    public static class ShippedModelAssets
    {
        [MenuItem("Assets/Create/Δ-Interpolator/In-betweening Model (shipped default)")]
        private static void CreateFromMenu()
        {
            string path = EditorUtility.SaveFilePanelInProject("Shipped in-betweening model", "DeltaInterpolator-CMU", "asset", "Where to save the model asset");
            if (string.IsNullOrEmpty(path)) return;
            try
            {
                EditorGUIUtility.PingObject(Create(path));
            }
            catch (InvalidOperationException e)
            {
                EditorUtility.DisplayDialog("Shipped in-betweening model", e.Message, "OK");
            }
        }

        /// <summary>Creates the asset at <paramref name="assetPath"/> (a new name if taken; nothing is overwritten).</summary>
        /// <exception cref="InvalidOperationException">The package's shipped graphs are not imported (or carry no contract).</exception>
        public static InbetweeningModel Create(string assetPath)
        {
            Object whole = Graph(ShippedModels.Default);
            string stem = ShippedModels.Default.Substring(0, ShippedModels.Default.Length - ".onnx".Length);
            var model = ScriptableObject.CreateInstance<InbetweeningModel>();
            model.Assign("", whole, Graph(stem + ".keys.onnx"), Graph(stem + ".frame.onnx"));
            AssetDatabase.CreateAsset(model, AssetDatabase.GenerateUniqueAssetPath(assetPath));
            ModelContractPostprocessor.Refresh(model);
            if (string.IsNullOrEmpty(model.ContractJson))
            {
                throw new InvalidOperationException($"{AssetDatabase.GetAssetPath(whole)} was imported without its model contract; reimport it (com.unity.ai.inference 2.4.0 or later with this package installed)");
            }

            return model;
        }

        // The imported graph whose asset path ends with the package-relative path (Packages/<name>/Runtime/Models/...).
        private static Object Graph(string packagePath)
        {
            string file = System.IO.Path.GetFileNameWithoutExtension(packagePath);
            foreach (string guid in AssetDatabase.FindAssets(file))
            {
                string path = AssetDatabase.GUIDToAssetPath(guid);
                if (!path.EndsWith("/" + packagePath, StringComparison.Ordinal)) continue;
                Object? asset = AssetDatabase.LoadMainAssetAtPath(path);
                if (asset != null) return asset;
            }

            throw new InvalidOperationException($"the package's {packagePath} is not imported; install com.unity.ai.inference 2.4.0 or later, which imports .onnx files, and reimport the package");
        }
    }
}
