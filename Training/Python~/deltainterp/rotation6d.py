"""6D rotation representation: the first two ROWS of the rotation matrix, mirroring
`Runtime/Core/Rotations/Rotation6D.cs` (the reference implementation's pytorch3d convention)."""
from __future__ import annotations

import torch

Tensor = torch.Tensor


def from_matrix(m: Tensor) -> Tensor:
    """(..., 3, 3) → (..., 6) = [R00, R01, R02, R10, R11, R12]."""
    return m[..., :2, :].reshape(m.shape[:-2] + (6,))


def to_matrix(r6: Tensor, eps: float = 1e-12) -> Tensor:
    """Gram–Schmidt on rows: b1 = N(a1), b2 = N(a2 − (b1·a2) b1), b3 = b1 × b2, R = [b1; b2; b3]."""
    a1, a2 = r6[..., :3], r6[..., 3:]
    b1 = a1 / a1.norm(dim=-1, keepdim=True).clamp_min(eps)
    b2 = a2 - (b1 * a2).sum(-1, keepdim=True) * b1
    b2 = b2 / b2.norm(dim=-1, keepdim=True).clamp_min(eps)
    b3 = torch.cross(b1, b2, dim=-1)
    return torch.stack((b1, b2, b3), dim=-2)
