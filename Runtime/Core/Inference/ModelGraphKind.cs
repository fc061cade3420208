namespace DeltaInterpolator.Core.Inference
{
    /// <summary>Which of the three exported graphs a model file holds.</summary>
    public enum ModelGraphKind
    {
        /// <summary><c>NAME.onnx</c>: key features and query frames in, deltas out.</summary>
        Whole,
        /// <summary><c>NAME.keys.onnx</c>: key features in, <c>key_memory</c> out (lazy decoding).</summary>
        Keys,
        /// <summary><c>NAME.frame.onnx</c>: <c>key_memory</c> and query frames in, deltas out (lazy decoding).</summary>
        Frame,
    }
}
