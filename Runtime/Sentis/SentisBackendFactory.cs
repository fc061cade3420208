#nullable enable
using System;
using DeltaInterpolator.Core.Inference;
using DeltaInterpolator.Unity;
using Unity.InferenceEngine;
using UnityEngine;

namespace DeltaInterpolator.Sentis
{
    /// <summary>
    /// Sentis as an inference engine of <see cref="MotionInbetweener"/> and the editor's baker: registered
    /// with <see cref="InferenceBackends"/> as <c>"Sentis"</c> (CPU, the default) and <c>"Sentis GPU"</c>
    /// (<see cref="BackendType.GPUCompute"/>) when the package loads, so <see cref="InbetweenerSettings.Backend"/>
    /// selects the device by name. Each backend is one <see cref="SentisBackend"/> (input tensors made
    /// once per request shape and reused, the worker disposed with the backend).
    /// </summary>
    /// <remarks>
    /// A runtime Sentis model carries no ONNX metadata, so every backend is described with the contract the
    /// model asset captured at import (<see cref="InbetweeningModel.ContractJson"/>, as
    /// <see cref="ModelContract.ToMetadata"/> with the graph kind set): Core then checks it exactly as it
    /// checks an ONNX Runtime graph. Sentis backends are used from Unity's main thread only
    /// (<see cref="RunsOffMainThread"/> is false).
    /// </remarks>
    public sealed class SentisBackendFactory : IInferenceBackendFactory
    {
        /// <summary>The name of the CPU engine (the default of <see cref="InbetweenerSettings"/>).</summary>
        public const string CpuName = "Sentis";

        /// <summary>The name of the GPU (compute shader) engine.</summary>
        public const string GpuName = "Sentis GPU";

        /// <summary>Creates a factory whose backends run on <paramref name="backendType"/>.</summary>
        public SentisBackendFactory(string name, BackendType backendType)
        {
            Name = name ?? throw new ArgumentNullException(nameof(name));
            BackendType = backendType;
        }

        /// <inheritdoc />
        public string Name { get; }

        /// <summary>The Sentis backend every graph runs on.</summary>
        public BackendType BackendType { get; }

        /// <inheritdoc />
        public bool RunsOffMainThread => false;

        /// <inheritdoc />
        public IInferenceBackend Create(InbetweeningModel model, ModelGraphKind graph)
        {
            if (model == null) throw new ArgumentNullException(nameof(model));
            string source = model.name + " (" + ModelContract.GraphName(graph) + " graph)";
            UnityEngine.Object? asset = graph == ModelGraphKind.Whole ? model.WholeGraph : graph == ModelGraphKind.Keys ? model.KeysGraph : model.FrameGraph;
            if (!(asset is ModelAsset modelAsset))
            {
                throw new ModelContractException(source, asset == null ? "no graph is assigned" : "the graph is not a Sentis model asset",
                    "expected the .onnx file imported by com.unity.ai.inference (assign it in the model asset)");
            }

            ModelContract contract = ModelContract.FromJson(model.ContractJson, model.name).ForGraph(graph);
            return SentisBackend.Load(modelAsset, contract.ToMetadata(), source, BackendType);
        }

        // Before the first scene loads in players and play mode; in the editor also on every domain
        // reload, so that edit-mode tools (the baker) find the engine without entering play mode.
#if UNITY_EDITOR
        [UnityEditor.InitializeOnLoadMethod]
#endif
        [RuntimeInitializeOnLoadMethod(RuntimeInitializeLoadType.SubsystemRegistration)]
        private static void Register()
        {
            InferenceBackends.Register(new SentisBackendFactory(CpuName, BackendType.CPU));
            InferenceBackends.Register(new SentisBackendFactory(GpuName, BackendType.GPUCompute));
        }
    }
}
