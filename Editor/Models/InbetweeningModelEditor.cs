#nullable enable
using System.Collections.Generic;
using DeltaInterpolator.Core;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Unity;
using UnityEditor;
using UnityEngine;

namespace DeltaInterpolator.Editor.Models
{
    /// <summary>
    /// Inspector of the model asset: its fields, then the model checks (<see cref="ModelChecks"/>) as help
    /// boxes (info, warning, error), each with its remedy — the same list <c>inbetween check</c> prints.
    /// The contract comes the way the ONNX Runtime backend reads it: the graph's metadata, captured at
    /// import (<see cref="ContractMetadataCapture"/>), read by <see cref="ModelContract.FromMetadata"/>;
    /// when it differs from the asset's <see cref="InbetweeningModel.ContractJson"/> the asset is updated
    /// (with undo). Checks run when the inspector opens and whenever a field changes, not on every repaint.
    /// </summary>
    [CustomEditor(typeof(InbetweeningModel))]
    internal sealed class InbetweeningModelEditor : UnityEditor.Editor
    {
        private ModelCheckReport? _report;

        /// <inheritdoc />
        public override void OnInspectorGUI()
        {
            bool changed = DrawDefaultInspector();
            if (_report == null || changed) _report = Check((InbetweeningModel)target);
            foreach (ModelCheck check in _report)
            {
                EditorGUILayout.HelpBox(Text(check), Severity(check.Severity));
            }
        }

        /// <summary>Every check of <paramref name="model"/>; captures the whole graph's contract into the asset.</summary>
        internal static ModelCheckReport Check(InbetweeningModel model)
        {
            var report = new ModelCheckReport();
            if (model.WholeGraph == null)
            {
                report.Error(model.name, "no whole graph is assigned", "assign the imported NAME.onnx (exported by `python3 -m deltainterp export`)");
                return report;
            }

            ModelContract? whole = Captured(model.WholeGraph, ModelGraphKind.Whole, report);
            if (whole == null)
            {
                return report;
            }

            string json = whole.ToJson();
            if (json != model.ContractJson)
            {
                Undo.RecordObject(model, "Capture model contract");
                model.Assign(json, model.WholeGraph, model.KeysGraph, model.FrameGraph);
                EditorUtility.SetDirty(model);
            }

            if ((model.KeysGraph == null) != (model.FrameGraph == null))
            {
                report.Warning(model.name, "only one of the lazy graphs is assigned, so transitions are decoded whole",
                    "assign both NAME.keys.onnx and NAME.frame.onnx, or neither");
            }
            else if (model.KeysGraph != null && model.FrameGraph != null)
            {
                ModelContract? keys = Captured(model.KeysGraph, ModelGraphKind.Keys, report);
                if (keys != null) ModelChecks.SameExport(whole, keys, report);
                ModelContract? frame = Captured(model.FrameGraph, ModelGraphKind.Frame, report);
                if (frame != null) ModelChecks.SameExport(whole, frame, report);
            }

            if (!report.HasErrors)
            {
                report.Info(whole.Source, $"{whole.Name}: contract {whole.ContractVersion}, {whole.Skeleton.JointCount} joints, {(model.HasLazyGraphs ? "lazy (frame-by-frame) decoding" : "whole-transition decoding")}", "");
            }

            return report;
        }

        // metadata (captured at import) → ModelContract → graph-kind check: the ONNX Runtime backend's path.
        private static ModelContract? Captured(Object graph, ModelGraphKind kind, ModelCheckReport report)
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

        internal static string Text(ModelCheck check) => string.IsNullOrEmpty(check.Remedy) ? check.Message : check.Message + "\n" + check.Remedy;

        internal static MessageType Severity(CheckSeverity severity)
        {
            switch (severity)
            {
                case CheckSeverity.Error: return MessageType.Error;
                case CheckSeverity.Warning: return MessageType.Warning;
                default: return MessageType.Info;
            }
        }
    }
}
