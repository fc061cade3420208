namespace DeltaInterpolator.Core.Inference
{
    /// <summary>What the network's deltas are added to (Documentation~/model-contract.md, "Decoding").</summary>
    public enum OutputDeltaMode
    {
        /// <summary>Root LERP and per-joint SLERP between the last past key and the target (the paper's choice).</summary>
        Slerp,
        /// <summary>The last past key's pose, repeated.</summary>
        LastPose,
        /// <summary>Zero: the network outputs absolute values (ablation).</summary>
        None,
    }
}
