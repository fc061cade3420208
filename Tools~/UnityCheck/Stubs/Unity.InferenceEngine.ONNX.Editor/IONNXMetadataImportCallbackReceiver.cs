using System.Collections.Generic;
using UnityEditor.AssetImporters;

namespace Unity.InferenceEngine
{
    // source: inference:Editor/ONNX/Metadata/IONNXMetadataImportCallbackReceiver.cs
    public partial struct ONNXModelMetadata
    {
        public Dictionary<string, string> MetadataProps;
    }

    // source: inference:Editor/ONNX/Metadata/IONNXMetadataImportCallbackReceiver.cs
    public partial interface IONNXMetadataImportCallbackReceiver
    {
        void OnMetadataImported(AssetImportContext ctx, ONNXModelMetadata metadata);
    }
}
