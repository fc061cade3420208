"""Forward kinematics (mirrors `Runtime/Core/Kinematics/ForwardKinematics.cs`)."""
from __future__ import annotations

from typing import Sequence, Tuple

import torch

from . import quaternions

Tensor = torch.Tensor


def forward_kinematics(local_quaternions: Tensor, root_positions: Tensor, offsets: Tensor,
                       parents: Sequence[int]) -> Tuple[Tensor, Tensor]:
    """Local quaternions (..., J, 4), root positions (..., 3), offsets (J, 3) → global quaternions
    (..., J, 4) and global positions (..., J, 3). The root's offset is ignored."""
    gq = [local_quaternions[..., 0, :]]
    gp = [root_positions]
    for j in range(1, len(parents)):
        p = parents[j]
        gp.append(gp[p] + quaternions.apply(gq[p], offsets[j].expand(root_positions.shape)))
        gq.append(quaternions.multiply(gq[p], local_quaternions[..., j, :]))
    return torch.stack(gq, dim=-2), torch.stack(gp, dim=-2)


def forward_kinematics_matrices(local_rotations: Tensor, root_positions: Tensor, offsets: Tensor,
                                parents: Sequence[int]) -> Tuple[Tensor, Tensor]:
    """The same with rotation matrices (..., J, 3, 3) → global matrices and positions."""
    gr = [local_rotations[..., 0, :, :]]
    gp = [root_positions]
    for j in range(1, len(parents)):
        p = parents[j]
        gp.append(gp[p] + (gr[p] @ offsets[j].expand(root_positions.shape)[..., None])[..., 0])
        gr.append(gr[p] @ local_rotations[..., j, :, :])
    return torch.stack(gr, dim=-3), torch.stack(gp, dim=-2)
