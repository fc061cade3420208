#nullable enable
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Unity;
using UnityEditor;

namespace DeltaInterpolator.Editor.Models
{
    /// <summary>
    /// Inspector of the model asset: its fields, then the contract checks as help boxes (info, warning,
    /// error), each with its remedy — the same list the CLI prints. Checks run when the inspector opens
    /// and whenever a field changes, not on every repaint.
    /// </summary>
    [CustomEditor(typeof(InbetweeningModel))]
    internal sealed class InbetweeningModelEditor : UnityEditor.Editor
    {
        private IReadOnlyList<ContractCheck>? _checks;

        /// <inheritdoc />
        public override void OnInspectorGUI()
        {
            bool changed = DrawDefaultInspector();
            if (_checks == null || changed) _checks = ((InbetweeningModel)target).CheckContract();
            foreach (ContractCheck check in _checks)
            {
                EditorGUILayout.HelpBox(Text(check), Severity(check.Severity));
            }
        }

        internal static string Text(ContractCheck check) => string.IsNullOrEmpty(check.Remedy) ? check.Message : check.Message + "\n" + check.Remedy;

        internal static MessageType Severity(ContractCheckSeverity severity)
        {
            switch (severity)
            {
                case ContractCheckSeverity.Error: return MessageType.Error;
                case ContractCheckSeverity.Warning: return MessageType.Warning;
                default: return MessageType.Info;
            }
        }
    }
}
