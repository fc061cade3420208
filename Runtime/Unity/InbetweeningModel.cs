using UnityEngine;

namespace DeltaInterpolator.Unity
{
    /// <summary>
    /// An exported in-betweening model as a Unity asset: its contract (the ONNX <c>deltainterp</c>
    /// metadata, which engines do not carry to run time, captured when the model is imported) and its
    /// three graphs. The graphs are typed as <see cref="Object"/> so that this assembly needs no inference
    /// engine: a backend (<see cref="IInferenceBackendFactory"/>) casts them to its own asset type
    /// (Sentis: <c>Unity.InferenceEngine.ModelAsset</c>).
    /// </summary>
    [CreateAssetMenu(fileName = "InbetweeningModel", menuName = "Δ-Interpolator/In-betweening Model", order = 410)]
    public sealed class InbetweeningModel : ScriptableObject
    {
        [SerializeField]
        [Tooltip("The model contract: the JSON of the ONNX metadata 'deltainterp', captured when the model was imported.")]
        private string contractJson = "";

        [SerializeField]
        [Tooltip("The whole-transition graph (NAME.onnx).")]
        private Object? wholeGraph;

        [SerializeField]
        [Tooltip("The lazy keys graph (NAME.keys.onnx); optional, with the frame graph.")]
        private Object? keysGraph;

        [SerializeField]
        [Tooltip("The lazy frame graph (NAME.frame.onnx); optional, with the keys graph.")]
        private Object? frameGraph;

        /// <summary>The contract JSON (the ONNX metadata <c>deltainterp</c> of the whole graph, as exported).</summary>
        public string ContractJson => contractJson;

        /// <summary>The whole-transition graph asset.</summary>
        public Object? WholeGraph => wholeGraph;

        /// <summary>The lazy keys graph asset, or null.</summary>
        public Object? KeysGraph => keysGraph;

        /// <summary>The lazy frame graph asset, or null.</summary>
        public Object? FrameGraph => frameGraph;

        /// <summary>True when both lazy graphs are assigned (frame-by-frame decoding is possible).</summary>
        public bool HasLazyGraphs => keysGraph != null && frameGraph != null;

        /// <summary>Fills the asset (editor import and tools).</summary>
        internal void Assign(string contract, Object whole, Object? keys, Object? frame)
        {
            contractJson = contract;
            wholeGraph = whole;
            keysGraph = keys;
            frameGraph = frame;
        }
    }
}
