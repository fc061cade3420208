namespace DeltaInterpolator.Core.Inference
{
    /// <summary>
    /// Tensor names of the exported graphs (Documentation~/model-contract.md). Python mirror:
    /// <c>Training/Python~/deltainterp/contract.py</c>. Renaming one is a contract change: bump
    /// <see cref="ModelContract.Version"/>.
    /// </summary>
    public static class TensorNames
    {
        /// <summary>Input, float32 [1, K, 9·J]: localized key-frame features.</summary>
        public const string KeyFeatures = "key_features";

        /// <summary>Input, int64 [K]: frame index of every key (0..P−1, then P+n).</summary>
        public const string KeyFrameIndices = "key_frame_indices";

        /// <summary>Input, int64 [N]: the missing frames wanted, each in P..P+n−1.</summary>
        public const string QueryFrameIndices = "query_frame_indices";

        /// <summary>Input, int64 [1]: the gap length n.</summary>
        public const string GapLength = "gap_length";

        /// <summary>Input of ablation models (input Δ-mode <c>none</c>) only; this runtime refuses them.</summary>
        public const string QueryFeatures = "query_features";

        /// <summary>Output of the keys graph, input of the frame graph, float32 [R, 2, K, D].</summary>
        public const string KeyMemory = "key_memory";

        /// <summary>Output, float32 [1, N, 3]: Δ of the localized root position, model units.</summary>
        public const string RootPositionDelta = "root_position_delta";

        /// <summary>Output, float32 [1, N, J, 6]: Δ of every joint's local 6D rotation (rows).</summary>
        public const string Rotation6DDelta = "rotation_6d_delta";

        /// <summary>
        /// Optional output of the whole and frame graphs (contract version 3), float32 [B, N, 4]: per query frame the
        /// probability that each foot joint of <see cref="ModelContract.ContactJoints"/> is planted.
        /// </summary>
        public const string FootContacts = "foot_contacts";

        /// <summary>Constant output, int64 [1]: the contract version the graph was exported with.</summary>
        public const string ContractVersion = "contract_version";

        /// <summary>Constant output, int64 [1]: the number of joints J.</summary>
        public const string JointCount = "joint_count";

        /// <summary>Constant output, int64 [1]: 9·J.</summary>
        public const string KeyFeatureSize = "key_feature_size";

        /// <summary>Metadata key holding the contract version as a string.</summary>
        public const string ContractVersionMetadata = "contract_version";

        /// <summary>Metadata key holding the contract's JSON object.</summary>
        public const string DescriptionMetadata = "deltainterp";
    }
}
