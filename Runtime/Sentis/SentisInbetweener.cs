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
            IInferenceBackend whole = factory.Create(model, ModelGraphKind.Whole);
            IInferenceBackend? keys = null;
            IInferenceBackend? frame = null;
            try
            {
                if (model.HasLazyGraphs)
                {
                    keys = factory.Create(model, ModelGraphKind.Keys);
                    frame = factory.Create(model, ModelGraphKind.Frame);
                }
            }
            catch
            {
                whole.Dispose();
                keys?.Dispose();
                throw;
            }

            return new Inbetweener(whole, keys, frame) { Id = model.name, DisplayName = model.name };
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
            bool lazy = keys != null && frame != null;
            if (lazy && (keysMetadata == null || frameMetadata == null))
            {
                throw new ArgumentException("the keys and frame graphs need their metadata too");
            }

            SentisBackend wholeBackend = SentisBackend.Load(whole, wholeMetadata, source, backendType);
            SentisBackend? keysBackend = null;
            SentisBackend? frameBackend = null;
            try
            {
                if (lazy)
                {
                    keysBackend = SentisBackend.Load(keys!, keysMetadata!, source + " (keys graph)", backendType);
                    frameBackend = SentisBackend.Load(frame!, frameMetadata!, source + " (frame graph)", backendType);
                }
            }
            catch
            {
                wholeBackend.Dispose();
                keysBackend?.Dispose();
                throw;
            }

            // The Inbetweener owns the backends from here: it disposes them when a check fails.
            return new Inbetweener(wholeBackend, keysBackend, frameBackend);
        }
    }
}
