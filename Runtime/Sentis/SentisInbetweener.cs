#nullable enable
using System;
using System.Collections.Generic;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Unity;
using Unity.InferenceEngine;

namespace DeltaInterpolator.Sentis
{
    /// <summary>
    /// Loads an exported model's graphs on Sentis into a Core <see cref="Inbetweener"/> (the same class
    /// ONNX Runtime feeds), so that contract checks, decoding and lazy transitions are the same code on
    /// both backends.
    /// </summary>
    public static class SentisInbetweener
    {
        /// <summary>
        /// Loads the graphs of a model asset (the whole graph, and the keys and frame graphs when both are
        /// assigned), each described by the contract the asset captured at import, as
        /// <see cref="MotionInbetweener"/> does through <see cref="SentisBackendFactory"/>.
        /// </summary>
        /// <param name="model">The model asset.</param>
        /// <param name="backendType">CPU (default) or a GPU backend; every graph runs on it.</param>
        /// <exception cref="ModelContractException">A graph is missing, cannot be loaded or does not fit the contract.</exception>
        public static Inbetweener Load(InbetweeningModel model, BackendType backendType = BackendType.CPU)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            var factory = new SentisBackendFactory(backendType == BackendType.CPU ? SentisBackendFactory.CpuName : SentisBackendFactory.GpuName, backendType);
            return ModelAssetGraphs.Load(model, factory);
        }

        /// <summary>
        /// Loads the whole graph and, when both are given, the keys and frame graphs for lazy decoding.
        /// </summary>
        /// <param name="whole">The whole-transition graph (<c>NAME.onnx</c>) as imported.</param>
        /// <param name="wholeMetadata">Its ONNX <c>metadata_props</c> captured at import.</param>
        /// <param name="source">The model's name for messages (e.g. the model asset's path).</param>
        /// <param name="backendType">CPU (default) or a GPU backend; every graph runs on it.</param>
        /// <param name="keys">The keys graph (<c>NAME.keys.onnx</c>), or null.</param>
        /// <param name="keysMetadata">Its metadata, or null.</param>
        /// <param name="frame">The frame graph (<c>NAME.frame.onnx</c>), or null.</param>
        /// <param name="frameMetadata">Its metadata, or null.</param>
        /// <exception cref="ModelContractException">A graph is missing, cannot be loaded or does not fit the contract.</exception>
        public static Inbetweener Load(
            ModelAsset whole, IReadOnlyDictionary<string, string> wholeMetadata, string source, BackendType backendType = BackendType.CPU,
            ModelAsset? keys = null, IReadOnlyDictionary<string, string>? keysMetadata = null,
            ModelAsset? frame = null, IReadOnlyDictionary<string, string>? frameMetadata = null)
        {
            if (keys != null && frame != null && (keysMetadata == null || frameMetadata == null))
            {
                throw new ArgumentException("the keys and frame graphs need their metadata too");
            }

            return InbetweenerLoader.Load(new AssetGraphs(whole, wholeMetadata, source, backendType, keys, keysMetadata, frame, frameMetadata));
        }

        /// <summary>Graphs given as imported assets with their captured metadata.</summary>
        private sealed class AssetGraphs : IModelGraphs
        {
            private readonly ModelAsset _whole;
            private readonly IReadOnlyDictionary<string, string> _wholeMetadata;
            private readonly BackendType _backendType;
            private readonly ModelAsset? _keys;
            private readonly IReadOnlyDictionary<string, string>? _keysMetadata;
            private readonly ModelAsset? _frame;
            private readonly IReadOnlyDictionary<string, string>? _frameMetadata;

            public AssetGraphs(ModelAsset whole, IReadOnlyDictionary<string, string> wholeMetadata, string source, BackendType backendType,
                ModelAsset? keys, IReadOnlyDictionary<string, string>? keysMetadata, ModelAsset? frame, IReadOnlyDictionary<string, string>? frameMetadata)
            {
                _whole = whole;
                _wholeMetadata = wholeMetadata;
                Source = source;
                _backendType = backendType;
                _keys = keys;
                _keysMetadata = keysMetadata;
                _frame = frame;
                _frameMetadata = frameMetadata;
            }

            public string Source { get; }

            public bool HasLazyGraphs => _keys != null && _frame != null;

            public IInferenceBackend Open(ModelGraphKind graph)
            {
                switch (graph)
                {
                    case ModelGraphKind.Keys: return SentisBackend.Load(_keys!, _keysMetadata!, Source + " (keys graph)", _backendType);
                    case ModelGraphKind.Frame: return SentisBackend.Load(_frame!, _frameMetadata!, Source + " (frame graph)", _backendType);
                    default: return SentisBackend.Load(_whole, _wholeMetadata, Source, _backendType);
                }
            }
        }
    }
}
