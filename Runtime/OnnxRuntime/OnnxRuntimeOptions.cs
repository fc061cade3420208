namespace DeltaInterpolator.OnnxRuntime
{
    /// <summary>
    /// How ONNX Runtime runs the model. Defaults suit a game: one intra-op thread (the network is small;
    /// more threads rarely pay on a transition of 30 frames and compete with the game's own threads).
    /// </summary>
    public sealed class OnnxRuntimeOptions
    {
        /// <summary>
        /// Threads one inference may use (ONNX Runtime's intra-op pool; the calling thread counts as one).
        /// 0 lets ONNX Runtime pick one per physical core. Default 1.
        /// </summary>
        public int IntraOpThreads { get; set; } = 1;

        /// <summary>
        /// Whether idle pool threads spin waiting for work (ONNX Runtime's default, lowest latency) instead
        /// of sleeping (kinder to the rest of a game). Only matters with <see cref="IntraOpThreads"/> ≠ 1.
        /// </summary>
        public bool AllowSpinning { get; set; } = true;

        /// <summary>Apply all graph optimisations (default true). False helps only when debugging numerics.</summary>
        public bool OptimizeGraph { get; set; } = true;
    }
}
