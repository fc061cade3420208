"""Network input features of key frames (mirrors `Runtime/Core/Inference/KeyFeatureBuilder.cs`)."""
from __future__ import annotations

from typing import Sequence

import torch

from . import quaternions, rotation6d
from .kinematics import forward_kinematics

Tensor = torch.Tensor


def key_features(root_positions: Tensor, local_quaternions: Tensor, offsets: Tensor,
                 parents: Sequence[int], reference_key: int, input_delta_mode: str = "last_pose") -> Tensor:
    """Localized key frames → (B, K, 9J): per joint [local 6D − root 6D at the reference key,
    global position − root position at the reference key] (input Δ-mode `last_pose`), or the raw values
    (input Δ-mode `none`).

    root_positions (B, K, 3) and offsets (J, 3) in model units; local_quaternions (B, K, J, 4).
    """
    r6 = rotation6d.from_matrix(quaternions.to_matrix(local_quaternions))  # (B, K, J, 6)
    _, positions = forward_kinematics(local_quaternions, root_positions, offsets, parents)
    if input_delta_mode == "last_pose":
        r6 = r6 - r6[:, reference_key:reference_key + 1, :1]
        positions = positions - positions[:, reference_key:reference_key + 1, :1]
    elif input_delta_mode != "none":
        raise ValueError(f"unknown input delta mode {input_delta_mode!r}")
    b, k, j, _ = r6.shape
    return torch.cat((r6, positions), dim=-1).reshape(b, k, 9 * j)
