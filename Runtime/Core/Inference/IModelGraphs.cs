namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Where one exported model's graphs come from on one inference engine: files beside each other for
    /// ONNX Runtime (<c>NAME.onnx</c>, <c>NAME.keys.onnx</c>, <c>NAME.frame.onnx</c>), imported assets for
    /// Sentis. <see cref="InbetweenerLoader"/> opens them in one order and owns what it opened, so every engine
    /// loads a model by the same rule.
    /// </summary>
    public interface IModelGraphs
    {
        /// <summary>The model's name for messages (a path or an asset name).</summary>
        string Source { get; }

        /// <summary>True when both lazy graphs (keys and frame) are there to open.</summary>
        bool HasLazyGraphs { get; }

        /// <summary>Loads one graph; the caller owns (and disposes) the backend.</summary>
        /// <exception cref="ModelContractException">The graph is missing or cannot be loaded.</exception>
        IInferenceBackend Open(ModelGraphKind graph);
    }
}
