"""The model contract shared with the C# runtime (Documentation~/model-contract.md).

`CONTRACT_VERSION` mirrors `ModelContract.Version` in Runtime/Core; a test keeps them equal.
"""
from __future__ import annotations

CONTRACT_VERSION = 2  # 2: a batch axis on every graph input and output (1: batch 1)

# Input and output tensor names of the exported graphs.
KEY_FEATURES = "key_features"
KEY_FRAME_INDICES = "key_frame_indices"
QUERY_FRAME_INDICES = "query_frame_indices"
GAP_LENGTH = "gap_length"
QUERY_FEATURES = "query_features"  # only with input Δ-mode "none" (ablation)
KEY_MEMORY = "key_memory"
ROOT_POSITION_DELTA = "root_position_delta"
ROTATION_6D_DELTA = "rotation_6d_delta"
CONSTANT_OUTPUTS = ("contract_version", "joint_count", "key_feature_size")

FEATURES_PER_JOINT = 9  # local 6D rotation (6) then global position (3)
MAX_FRAME_INDEX = 255   # embedding tables have 256 rows

OUTPUT_DELTA_MODES = ("slerp", "last_pose", "none")
INPUT_DELTA_MODES = ("last_pose", "none")
