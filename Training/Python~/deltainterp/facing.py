"""A character's facing: the horizontal direction its root points to (mirrors
`Runtime/Core/Kinematics/Facing.cs`).

The one definition behind both the request localization (`localize.py`) and the benchmark's window
normalisation (`benchmark.normalise_windows`).
"""
from __future__ import annotations

from typing import Sequence

import torch

from . import quaternions

Tensor = torch.Tensor


def yaw_toward(root_quaternion: Tensor, local_facing_axis: Sequence[float],
               target_axis: Sequence[float]) -> Tensor:
    """The rotation about +Y that turns the root's facing (`root_quaternion` applied to
    `local_facing_axis`, Y zeroed, normalised) onto `target_axis`; apply it to make the root face the
    target. The identity when the horizontal facing is shorter than 1e-6 (the axis points straight up or
    down), a half turn about +Y when it is exactly opposite to the target."""
    axis = root_quaternion.new_tensor(local_facing_axis).expand(root_quaternion.shape[:-1] + (3,))
    forward = quaternions.apply(root_quaternion, axis) * root_quaternion.new_tensor([1.0, 0.0, 1.0])
    length = forward.norm(dim=-1, keepdim=True)
    target = root_quaternion.new_tensor(target_axis).expand(forward.shape)
    yaw = quaternions.between(forward / length.clamp_min(1e-12), target)
    identity = root_quaternion.new_tensor([1.0, 0.0, 0.0, 0.0]).expand(yaw.shape)
    return torch.where(length < 1e-6, identity, yaw)
