"""Output Δ-mode baselines: what the network's deltas are added to (mirrors
`Runtime/Core/Inference/DeltaBaseline.cs`)."""
from __future__ import annotations

from typing import Tuple

import torch

from . import quaternions

Tensor = torch.Tensor


def interpolation_weights(query_frames: Tensor, reference_frame: int, gap: int) -> Tensor:
    """a = (f − r) / (n + 1) for query frames f (N,) — the official benchmark's linspace weights."""
    return (query_frames.to(torch.float64) - reference_frame) / (gap + 1)


def slerp_baseline(last_root: Tensor, target_root: Tensor, last_rotations: Tensor,
                   target_rotations: Tensor, weights: Tensor) -> Tuple[Tensor, Tensor]:
    """Root LERP and per-joint official SLERP between the last past key and the target.

    last_root/target_root (B, 3); last_rotations/target_rotations (B, J, 4); weights (N,) →
    root (B, N, 3), local quaternions (B, N, J, 4) (normalised).
    """
    w = weights.to(last_root.dtype)
    root = last_root[:, None] + w[None, :, None] * (target_root - last_root)[:, None]
    a = quaternions.normalize(last_rotations)[:, None]
    b = quaternions.normalize(target_rotations)[:, None]
    rot = quaternions.slerp(a.expand(-1, w.shape[0], -1, -1), b.expand(-1, w.shape[0], -1, -1),
                            w[None, :, None].expand(a.shape[0], -1, a.shape[2]))
    return root, quaternions.normalize(rot)


def baseline(mode: str, last_root: Tensor, target_root: Tensor, last_rotations: Tensor,
             target_rotations: Tensor, weights: Tensor) -> Tuple[Tensor, Tensor]:
    """Baseline root (B, N, 3) and quaternions (B, N, J, 4) for an output Δ-mode.

    For `none` the quaternions returned are still the SLERP ones (used as hemisphere references);
    the caller zeroes the 6D baseline itself.
    """
    root, rot = slerp_baseline(last_root, target_root, last_rotations, target_rotations, weights)
    if mode == "slerp" or mode == "none":
        return root, rot
    if mode == "last_pose":
        n = weights.shape[0]
        return last_root[:, None].expand(-1, n, -1), quaternions.normalize(last_rotations)[:, None].expand(-1, n, -1, -1)
    raise ValueError(f"unknown output delta mode {mode!r}")
