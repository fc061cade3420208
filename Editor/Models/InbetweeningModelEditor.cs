#nullable enable
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
    /// import (<see cref="ContractMetadataCapture"/>), read by <see cref="ModelContract.FromMetadata"/>.
    /// The inspector only reads: the asset's <see cref="InbetweeningModel.ContractJson"/> is written by the
    /// import (<see cref="ModelContractPostprocessor"/>), never by drawing; a difference is shown as a warning.
    /// Checks run when the inspector opens and whenever a field changes, not on every repaint.
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

        /// <summary>Every check of <paramref name="model"/> (reads only; changes nothing).</summary>
        internal static ModelCheckReport Check(InbetweeningModel model)
        {
            var report = new ModelCheckReport();
            if (model.WholeGraph == null)
            {
                report.Error(model.name, "no whole graph is assigned", "assign the imported NAME.onnx (exported by `python3 -m deltainterp export`)");
                return report;
            }

            ModelContract? whole = ImportedContract.Read(model.WholeGraph, ModelGraphKind.Whole, report);
            if (whole == null)
            {
                return report;
            }

            // The importer (ModelContractPostprocessor) owns the asset's copy; here it is only compared.
            if (whole.ToJson() != model.ContractJson)
            {
                report.Warning(model.name, "the contract stored in this asset is not the one its whole graph was imported with",
                    "it is captured when the asset or its graphs are imported: save the project (File > Save Project) or reimport this asset");
            }

            if ((model.KeysGraph == null) != (model.FrameGraph == null))
            {
                report.Warning(model.name, "only one of the lazy graphs is assigned, so transitions are decoded whole",
                    "assign both NAME.keys.onnx and NAME.frame.onnx, or neither");
            }
            else if (model.KeysGraph != null && model.FrameGraph != null)
            {
                ModelContract? keys = ImportedContract.Read(model.KeysGraph, ModelGraphKind.Keys, report);
                if (keys != null) ModelChecks.SameExport(whole, keys, report);
                ModelContract? frame = ImportedContract.Read(model.FrameGraph, ModelGraphKind.Frame, report);
                if (frame != null) ModelChecks.SameExport(whole, frame, report);
            }

            if (!report.HasErrors)
            {
                report.Info(whole.Source, $"{whole.Name}: contract {whole.ContractVersion}, {whole.Skeleton.JointCount} joints, {(model.HasLazyGraphs ? "lazy (frame-by-frame) decoding" : "whole-transition decoding")}", "");
            }

            return report;
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
