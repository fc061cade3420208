"""Localization of a transition request (mirrors `Runtime/Core/Inference/Localizer.cs`).

The network is trained and run on requests whose last past key faces `facing_target_axis` (+X) and
whose root sits above the origin, in model units. Training, evaluation and the C# runtime all go through
this one definition (Documentation~/model-contract.md, "Localization").
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence, Tuple

import torch

from . import quaternions
from .facing import yaw_toward

Tensor = torch.Tensor


@dataclass
class Localization:
    yaw: Tensor     # (B, 4) rotation applied to the request
    origin: Tensor  # (B, 3) data units, Y = 0


def localize(root_positions: Tensor, local_quaternions: Tensor, reference_frame: int,
             facing_local_axis: Sequence[float], facing_target_axis: Sequence[float],
             unit_scale: float) -> Tuple[Tensor, Tensor, Localization]:
    """root_positions (B, L, 3) data units, local_quaternions (B, L, J, 4) → the same, localized, with
    positions in model units."""
    yaw = yaw_toward(local_quaternions[:, reference_frame, 0], facing_local_axis, facing_target_axis)
    origin = root_positions[:, reference_frame] * root_positions.new_tensor([1.0, 0.0, 1.0])
    yaw_t = yaw[:, None].expand(root_positions.shape[:-1] + (4,))
    positions = quaternions.apply(yaw_t, root_positions - origin[:, None]) * unit_scale
    rotations = local_quaternions.clone()
    rotations[:, :, 0] = quaternions.multiply(yaw_t, local_quaternions[:, :, 0])
    return positions, rotations, Localization(yaw, origin)


def unlocalize(root_positions: Tensor, local_quaternions: Tensor, localization: Localization,
               unit_scale: float) -> Tuple[Tensor, Tensor]:
    """The exact inverse of `localize`: (B, N, 3) model units and (B, N, J, 4) → world, data units."""
    inv = quaternions.inverse(localization.yaw)[:, None].expand(root_positions.shape[:-1] + (4,))
    positions = quaternions.apply(inv, root_positions / unit_scale) + localization.origin[:, None]
    rotations = local_quaternions.clone()
    rotations[:, :, 0] = quaternions.multiply(inv, local_quaternions[:, :, 0])
    return positions, rotations
