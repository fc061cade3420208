#nullable enable
using DeltaInterpolator.Core.Inference;
using Unity.InferenceEngine;
using UnityEditor.AssetImporters;
using UnityEngine;

namespace DeltaInterpolator.Editor.Models
{
    /// <summary>
    /// Keeps a model's contract past import. Sentis hands ONNX <c>metadata_props</c> only to this kind of
    /// callback, while the file is imported; a runtime Sentis model has none. For every <c>.onnx</c> that
    /// carries the <c>deltainterp</c> contract, the metadata is stored as a <see cref="TextAsset"/> inside
    /// the imported asset (sub-asset <see cref="SubAssetName"/>, text of <see cref="ModelMetadataText"/>).
    /// After the import, <see cref="ModelContractPostprocessor"/> copies the contract into every
    /// <see cref="DeltaInterpolator.Unity.InbetweeningModel.ContractJson"/> using the graph (player builds carry
    /// it); the inspector (<see cref="InbetweeningModelEditor"/>) only reads it. Other ONNX files are left alone.
    /// Sentis finds this class by reflection (<c>TypeCache</c>) and creates it with its parameterless
    /// constructor; reimport models imported before the package was installed.
    /// </summary>
    internal sealed class ContractMetadataCapture : IONNXMetadataImportCallbackReceiver
    {
        /// <summary>Name (and import identifier) of the metadata sub-asset.</summary>
        public const string SubAssetName = "deltainterp metadata";

        /// <inheritdoc />
        public void OnMetadataImported(AssetImportContext ctx, ONNXModelMetadata metadata)
        {
            if (metadata.MetadataProps == null || !metadata.MetadataProps.ContainsKey(TensorNames.DescriptionMetadata)) return;
            var text = new TextAsset(ModelMetadataText.Write(metadata.MetadataProps)) { name = SubAssetName };
            ctx.AddObjectToAsset(SubAssetName, text);
        }
    }
}
