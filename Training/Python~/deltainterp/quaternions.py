"""Quaternion math on torch tensors, (w, x, y, z), mirroring `Runtime/Core/Rotations/Quaternions.cs`.

Every function broadcasts over leading dimensions; the last dimension holds the 4 components.
"""
from __future__ import annotations

import math

import torch

Tensor = torch.Tensor


def multiply(a: Tensor, b: Tensor) -> Tensor:
    """Hamilton product a ⊗ b (apply b first, then a)."""
    aw, ax, ay, az = a.unbind(-1)
    bw, bx, by, bz = b.unbind(-1)
    return torch.stack(
        (
            aw * bw - ax * bx - ay * by - az * bz,
            aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
        ),
        dim=-1,
    )


def inverse(q: Tensor) -> Tensor:
    """Conjugate; the inverse of a unit quaternion."""
    return q * q.new_tensor([1.0, -1.0, -1.0, -1.0])


def apply(q: Tensor, v: Tensor) -> Tensor:
    """Rotate vectors v (..., 3) by unit quaternions q (..., 4): v' = v + 2w(u×v) + u×(2u×v)."""
    u = q[..., 1:]
    w = q[..., :1]
    t = 2.0 * torch.cross(u.expand(v.shape[:-1] + (3,)), v, dim=-1)
    return v + w * t + torch.cross(u.expand(t.shape), t, dim=-1)


def normalize(q: Tensor, eps: float = 1e-12) -> Tensor:
    return q / q.norm(dim=-1, keepdim=True).clamp_min(eps)


_AXES = {"x": 1, "y": 2, "z": 3}


def axis_angle(axis: str, angle: Tensor) -> Tensor:
    """Rotation by `angle` radians about the named axis."""
    q = torch.zeros(angle.shape + (4,), dtype=angle.dtype, device=angle.device)
    q[..., 0] = torch.cos(angle * 0.5)
    q[..., _AXES[axis]] = torch.sin(angle * 0.5)
    return q


def from_euler(angles: Tensor, order: str) -> Tensor:
    """Intrinsic Euler angles (radians, (..., 3) in `order`'s column order) → quaternion.

    q = q_{order[0]}(e0) ⊗ q_{order[1]}(e1) ⊗ q_{order[2]}(e2), as BVH CHANNELS lines are read.
    """
    order = order.lower()
    q = axis_angle(order[0], angles[..., 0])
    for i in (1, 2):
        q = multiply(q, axis_angle(order[i], angles[..., i]))
    return q


def to_matrix(q: Tensor) -> Tensor:
    """Unit quaternion → 3×3 rotation matrix (acting on column vectors)."""
    w, x, y, z = normalize(q).unbind(-1)
    return torch.stack(
        (
            1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
            2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
            2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
        ),
        dim=-1,
    ).reshape(q.shape[:-1] + (3, 3))


def from_matrix(m: Tensor) -> Tensor:
    """Rotation matrix → unit quaternion with w ≥ 0 (differentiable, branch-free selection).

    Four candidate quaternions are built, one per largest diagonal term; the best-conditioned one is
    picked per element, which keeps gradients finite everywhere.
    """
    m00, m01, m02 = m[..., 0, 0], m[..., 0, 1], m[..., 0, 2]
    m10, m11, m12 = m[..., 1, 0], m[..., 1, 1], m[..., 1, 2]
    m20, m21, m22 = m[..., 2, 0], m[..., 2, 1], m[..., 2, 2]
    four_sq = torch.stack(
        (
            1.0 + m00 + m11 + m22,
            1.0 + m00 - m11 - m22,
            1.0 - m00 + m11 - m22,
            1.0 - m00 - m11 + m22,
        ),
        dim=-1,
    )
    root = torch.sqrt(four_sq.clamp_min(1e-8))  # = 2|component|
    candidates = torch.stack(
        (
            torch.stack((root[..., 0] ** 2, m21 - m12, m02 - m20, m10 - m01), -1),
            torch.stack((m21 - m12, root[..., 1] ** 2, m10 + m01, m02 + m20), -1),
            torch.stack((m02 - m20, m10 + m01, root[..., 2] ** 2, m21 + m12), -1),
            torch.stack((m10 - m01, m20 + m02, m21 + m12, root[..., 3] ** 2), -1),
        ),
        dim=-2,
    ) / (2.0 * root[..., None].clamp_min(0.1))
    best = four_sq.argmax(dim=-1)
    q = torch.gather(candidates, -2, best[..., None, None].expand(best.shape + (1, 4))).squeeze(-2)
    q = normalize(q)
    return torch.where(q[..., :1] < 0, -q, q)


def align_hemisphere(q: Tensor, reference: Tensor) -> Tensor:
    """Flip q where it lies in the opposite hemisphere of `reference` (dot < 0)."""
    dot = (q * reference).sum(-1, keepdim=True)
    return torch.where(dot < 0, -q, q)


def slerp(a: Tensor, b: Tensor, t: Tensor) -> Tensor:
    """The official LaFAN1 benchmark's slerp: flip b into a's hemisphere, linear weights when the
    quaternions are nearly parallel (1 − d < 0.01). The caller normalises the result.

    `t` broadcasts against the leading dimensions of a and b (shape (...,) or (..., 1)).
    """
    if t.dim() < a.dim():
        t = t.unsqueeze(-1)
    d = (a * b).sum(-1, keepdim=True)
    b = torch.where(d < 0, -b, b)
    d = d.abs()
    linear = (1.0 - d) < 0.01
    omega = torch.acos(d.clamp(-1.0, 1.0))
    sin_omega = torch.sin(omega)
    safe = torch.where(linear, torch.ones_like(sin_omega), sin_omega)
    wa = torch.where(linear, 1.0 - t, torch.sin((1.0 - t) * omega) / safe)
    wb = torch.where(linear, t, torch.sin(t * omega) / safe)
    return wa * a + wb * b


def remove_discontinuities(q: Tensor, dim: int = 0) -> Tensor:
    """The continuity fix along `dim`: flip q_t when ⟨q_{t−1}, q_t⟩ < 0, using the already-fixed q_{t−1}."""
    q = q.transpose(0, dim).clone()
    for t in range(1, q.shape[0]):
        flip = (q[t - 1] * q[t]).sum(-1, keepdim=True) < 0
        q[t] = torch.where(flip, -q[t], q[t])
    return q.transpose(0, dim)


def between(u: Tensor, v: Tensor) -> Tensor:
    """Shortest-arc unit quaternion rotating direction u onto direction v (both (..., 3)).

    Antiparallel inputs (where the official code returns a zero quaternion) get a half turn about +Y,
    the vertical axis every caller here rotates about.
    """
    w = torch.sqrt((u * u).sum(-1) * (v * v).sum(-1)) + (u * v).sum(-1)
    xyz = torch.cross(u, v, dim=-1)
    q = torch.cat((w[..., None], xyz), dim=-1)
    degenerate = q.norm(dim=-1, keepdim=True) < 1e-9
    half_turn = q.new_tensor([0.0, 0.0, 1.0, 0.0]).expand(q.shape)
    return normalize(torch.where(degenerate, half_turn, q))


def angle_between(a: Tensor, b: Tensor) -> Tensor:
    """Geodesic angle (radians) between unit quaternions, sign-insensitive."""
    d = (a * b).sum(-1).abs().clamp(max=1.0)
    return 2.0 * torch.acos(d)


__all__ = [
    "multiply", "inverse", "apply", "normalize", "axis_angle", "from_euler", "to_matrix",
    "from_matrix", "align_hemisphere", "slerp", "remove_discontinuities", "between", "angle_between",
]

_ = math  # kept for callers that import math helpers from here
