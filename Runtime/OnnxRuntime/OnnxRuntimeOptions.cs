namespace DeltaInterpolator.OnnxRuntime
{
    /// <summary>
    /// How ONNX Runtime runs the model. Defaults suit a game: one intra-op thread (the network is small;
    /// more threads rarely pay on a transition of 30 frames and compete with the game's own threads).
    /// </summary>
    public sealed class OnnxRuntimeOptions
    {
        private int _intraOpThreads = 1;

        /// <summary>
        /// Threads one inference may use (ONNX Runtime's intra-op pool; the calling thread counts as one).
        /// 0 lets ONNX Runtime pick one per physical core. Default 1. At most <see cref="MaxIntraOpThreads"/>.
        /// </summary>
        /// <exception cref="System.ArgumentOutOfRangeException">Below 0 or above <see cref="MaxIntraOpThreads"/>.</exception>
        public int IntraOpThreads
        {
            get => _intraOpThreads;
            set
            {
                // More threads than processors only compete for the same cores, and a count in the millions fails
                // inside ONNX Runtime as std::bad_alloc, which would read as a broken model.
                if (value < 0 || value > MaxIntraOpThreads)
                {
                    throw new System.ArgumentOutOfRangeException(nameof(IntraOpThreads), value, $"IntraOpThreads {value}; expected 0 (one per physical core) to {MaxIntraOpThreads} (the processors of this machine)");
                }

                _intraOpThreads = value;
            }
        }

        /// <summary>The most intra-op threads accepted: the processors of this machine (at least 1).</summary>
        public static int MaxIntraOpThreads => System.Math.Max(1, System.Environment.ProcessorCount);

        /// <summary>
        /// Whether idle pool threads spin waiting for work (ONNX Runtime's default, lowest latency) instead
        /// of sleeping (kinder to the rest of a game). Only matters with <see cref="IntraOpThreads"/> ≠ 1.
        /// </summary>
        public bool AllowSpinning { get; set; } = true;

        /// <summary>Apply all graph optimisations (default true). False helps only when debugging numerics.</summary>
        public bool OptimizeGraph { get; set; } = true;
    }
}
