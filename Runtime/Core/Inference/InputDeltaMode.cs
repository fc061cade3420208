namespace DeltaInterpolator.Core.Inference
{
    /// <summary>What the key features are taken relative to (Documentation~/model-contract.md, "Network inputs").</summary>
    public enum InputDeltaMode
    {
        /// <summary>Relative to the root at the last past key (the only mode this runtime runs).</summary>
        LastPose,
        /// <summary>Raw features plus a <c>query_features</c> input (ablation; refused by this runtime).</summary>
        None,
    }
}
