#nullable enable
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEngine;
using Object = UnityEngine.Object;

namespace DeltaInterpolator.Editor.Models
{
    /// <summary>
    /// Owns the copy of a model's contract into <see cref="InbetweeningModel.ContractJson"/>: whenever a model
    /// asset or one of its graphs is imported (created, saved, reimported, or its <c>.onnx</c> replaced), the
    /// contract captured during the graph's import (<see cref="ContractMetadataCapture"/>) is written into
    /// every model asset using that graph, so a re-imported model is never stale and player builds carry the
    /// current contract. A graph imported without a contract clears it (the model then refuses to load, with
    /// a message, instead of running on an old contract). The inspector only reads what this wrote.
    /// </summary>
    internal sealed class ModelContractPostprocessor : AssetPostprocessor
    {
        // Called by the engine (by name) after every import batch.
        private static void OnPostprocessAllAssets(string[] importedAssets, string[] deletedAssets, string[] movedAssets, string[] movedFromAssetPaths)
        {
            var imported = new HashSet<string>(importedAssets, StringComparer.Ordinal);
            bool anyModelOrGraph = false;
            foreach (string path in importedAssets)
            {
                if (path.EndsWith(".onnx", StringComparison.OrdinalIgnoreCase) || path.EndsWith(".asset", StringComparison.OrdinalIgnoreCase)) anyModelOrGraph = true;
            }

            if (!anyModelOrGraph) return;
            foreach (string guid in AssetDatabase.FindAssets("t:" + nameof(InbetweeningModel)))
            {
                string path = AssetDatabase.GUIDToAssetPath(guid);
                InbetweeningModel? model = AssetDatabase.LoadAssetAtPath<InbetweeningModel>(path);
                if (model == null) continue;
                bool affected = imported.Contains(path) || (model.WholeGraph != null && imported.Contains(AssetDatabase.GetAssetPath(model.WholeGraph)));
                if (affected) Refresh(model);
            }
        }

        /// <summary>Writes the whole graph's captured contract into <paramref name="model"/> when it differs; true when it wrote.</summary>
        internal static bool Refresh(InbetweeningModel model)
        {
            string json = "";
            if (model.WholeGraph != null)
            {
                ModelContract? contract = ImportedContract.Read(model.WholeGraph, ModelGraphKind.Whole, new ModelCheckReport());
                if (contract != null) json = contract.ToJson();
            }

            if (json == model.ContractJson) return false;
            if (model.WholeGraph == null) return false;
            model.Assign(json, model.WholeGraph, model.KeysGraph, model.FrameGraph);
            EditorUtility.SetDirty(model);
            AssetDatabase.SaveAssetIfDirty(model);
            return true;
        }
    }

    /// <summary>Reads the contract captured when a graph was imported: metadata → <see cref="ModelContract"/> → graph-kind check, the ONNX Runtime backend's path.</summary>
    internal static class ImportedContract
    {
        /// <summary>The contract of <paramref name="graph"/>, or null with the reason in <paramref name="report"/>.</summary>
        public static ModelContract? Read(Object graph, ModelGraphKind kind, ModelCheckReport report)
        {
            string path = AssetDatabase.GetAssetPath(graph);
            TextAsset? captured = null;
            foreach (Object o in AssetDatabase.LoadAllAssetsAtPath(path))
            {
                if (o is TextAsset text && text.name == ContractMetadataCapture.SubAssetName) captured = text;
            }

            if (captured == null)
            {
                report.Error(path, "no model contract was captured when this file was imported",
                    "expected an .onnx exported by `python3 -m deltainterp export`; reimport it with com.unity.ai.inference 2.4.0 or later and this package installed");
                return null;
            }

            IReadOnlyDictionary<string, string> metadata;
            try
            {
                metadata = ModelMetadataText.Read(captured.text, path);
            }
            catch (DataFormatException e)
            {
                report.Error(path, "the captured metadata cannot be read (" + e.Problem + ")", "reimport the file");
                return null;
            }

            ModelContract? contract = ModelContract.FromMetadata(path, metadata, report);
            if (contract != null) ModelChecks.GraphKind(contract, kind, report);
            return contract;
        }
    }
}
