"""Network outputs → poses (mirrors `Runtime/Core/Inference/OutputDecoder.cs`)."""
from __future__ import annotations

from typing import Tuple

import torch

from . import quaternions, rotation6d

Tensor = torch.Tensor


def decode_outputs(mode: str, base_root: Tensor, base_rotations: Tensor, root_delta: Tensor,
                   rotation_delta: Tensor) -> Tuple[Tensor, Tensor]:
    """Δ + baseline → localized root positions (B, N, 3) and local quaternions (B, N, J, 4).

    The 6D sum is decoded by Gram–Schmidt on rows; each quaternion is put in the hemisphere of the
    baseline's quaternion so that sign never differs from what a continuous track would carry.
    """
    base6 = rotation6d.from_matrix(quaternions.to_matrix(base_rotations))
    if mode == "none":
        base6 = torch.zeros_like(base6)
        base_root = torch.zeros_like(base_root)
    r6 = base6 + rotation_delta
    q = quaternions.from_matrix(rotation6d.to_matrix(r6))
    return base_root + root_delta, quaternions.align_hemisphere(q, base_rotations)
