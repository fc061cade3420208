"""The model contract shared with the C# runtime (Documentation~/model-contract.md).

`CONTRACT_VERSION` mirrors `ModelContract.Version` in Runtime/Core; a test keeps them equal.
"""
from __future__ import annotations

CONTRACT_VERSION = 3  # 3: an optional `foot_contacts` output; 2: a batch axis on every graph input and output (1: batch 1)

# Input and output tensor names of the exported graphs.
KEY_FEATURES = "key_features"
KEY_FRAME_INDICES = "key_frame_indices"
QUERY_FRAME_INDICES = "query_frame_indices"
GAP_LENGTH = "gap_length"
QUERY_FEATURES = "query_features"  # only with input Δ-mode "none" (ablation)
KEY_MEMORY = "key_memory"
ROOT_POSITION_DELTA = "root_position_delta"
ROTATION_6D_DELTA = "rotation_6d_delta"
# Version 3, optional: per query frame the probability that each of CONTACT_JOINTS is planted (sigmoid inside the
# graph), [B, N, 4]; the whole and frame graphs emit it when the model has a contact head, the keys graph never.
FOOT_CONTACTS = "foot_contacts"
CONTACT_JOINTS = ("LeftFoot", "LeftToe", "RightFoot", "RightToe")  # channel order (C# FootLocker.ChannelJoints)
CONSTANT_OUTPUTS = ("contract_version", "joint_count", "key_feature_size")

FEATURES_PER_JOINT = 9  # local 6D rotation (6) then global position (3)
MAX_FRAME_INDEX = 255   # embedding tables have 256 rows



def example_frame_indices(keys: int, queries: int, gaps, batched: bool = True):
    """The contract's frame layout for example inputs (export checks, quantize probes): per row, past keys at
    frames 0..K−2 and the target at K−1+n, queries at the first N missing frames; one row per gap length
    (`batched=False`: the version 1 layout, no batch axis). Returns int64 numpy arrays (key indices [B, K],
    query indices [B, N], gap lengths [B]; without the batch axis for version 1, gap still [1])."""
    import numpy as np
    past = keys - 1
    key_idx = np.array([list(range(past)) + [past + n] for n in gaps], dtype=np.int64)
    query_idx = np.stack([np.arange(past, past + queries, dtype=np.int64)] * len(gaps))
    gap = np.array(gaps, dtype=np.int64)
    if not batched:
        key_idx, query_idx = key_idx[0], query_idx[0]
    return key_idx, query_idx, gap


OUTPUT_DELTA_MODES = ("slerp", "last_pose", "none")
INPUT_DELTA_MODES = ("last_pose", "none")
