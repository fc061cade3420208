"""Quaternion and 6D conventions on hand-checked values (mirrored by the C# Rotations tests)."""
from __future__ import annotations

import math

import pytest
import torch

from deltainterp import quaternions as Q
from deltainterp import rotation6d
from deltainterp.facing import yaw_toward

D = torch.float64
S = math.sqrt(0.5)


def t(*v):
    return torch.tensor(v, dtype=D)


@pytest.mark.parametrize("axis, matrix", [
    ("x", [[1, 0, 0], [0, 0, -1], [0, 1, 0]]),
    ("y", [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]),
    ("z", [[0, -1, 0], [1, 0, 0], [0, 0, 1]]),
])
def test_quarter_turns(axis, matrix):
    q = Q.axis_angle(axis, t(math.pi / 2))
    assert torch.allclose(Q.to_matrix(q), torch.tensor(matrix, dtype=D), atol=1e-12)
    assert torch.allclose(rotation6d.from_matrix(Q.to_matrix(q)), torch.tensor(matrix[0] + matrix[1], dtype=D),
                          atol=1e-12)


def test_hamilton_product_order():
    # q_z(90°) ⊗ q_x(90°): apply x first, then z; +Y → (x) +Z → (z) +Z
    q = Q.multiply(Q.axis_angle("z", t(math.pi / 2)), Q.axis_angle("x", t(math.pi / 2)))
    assert torch.allclose(q, t(0.5, 0.5, 0.5, 0.5), atol=1e-12)
    assert torch.allclose(Q.apply(q, t(0, 1, 0)[None]), t(0, 0, 1)[None], atol=1e-12)


def test_bvh_euler_zyx_is_intrinsic():
    e = t(0.3, -0.7, 1.1)  # columns in CHANNELS order Z, Y, X
    q = Q.from_euler(e, "zyx")
    expected = Q.to_matrix(Q.axis_angle("z", e[0])) @ Q.to_matrix(Q.axis_angle("y", e[1])) \
        @ Q.to_matrix(Q.axis_angle("x", e[2]))
    assert torch.allclose(Q.to_matrix(q), expected, atol=1e-12)


def test_gram_schmidt_on_rows():
    # rows a1 = (2, 0, 0), a2 = (1, 3, 0) → b1 = +X, b2 = +Y, b3 = +Z
    assert torch.allclose(rotation6d.to_matrix(t(2, 0, 0, 1, 3, 0)), torch.eye(3, dtype=D))
    # a row-convention 6D of a rotation decodes to the same rotation, also when perturbed along a1
    q = Q.normalize(t(0.3, -0.2, 0.9, 0.25))
    r6 = rotation6d.from_matrix(Q.to_matrix(q))
    assert torch.allclose(rotation6d.to_matrix(r6 * t(3, 3, 3, 1, 1, 1)), Q.to_matrix(q), atol=1e-12)


def test_matrix_quaternion_round_trip_up_to_sign():
    g = torch.Generator().manual_seed(0)
    q = Q.normalize(torch.randn(2000, 4, generator=g, dtype=D))
    back = Q.from_matrix(Q.to_matrix(q))
    assert torch.all(back[:, 0] >= 0)
    assert torch.allclose(Q.align_hemisphere(back, q), q, atol=1e-9)


def test_official_slerp():
    a = t(1, 0, 0, 0)
    b = Q.axis_angle("y", t(math.radians(60)))
    mid = Q.normalize(Q.slerp(a, b, t(0.5)))
    assert torch.allclose(mid, Q.axis_angle("y", t(math.radians(30))), atol=1e-12)
    # b in the other hemisphere gives the same (short-way) result
    assert torch.allclose(Q.normalize(Q.slerp(a, -b, t(0.25))), Q.axis_angle("y", t(math.radians(15))), atol=1e-12)
    # nearly parallel: the official code switches to linear weights (1 − d < 0.01)
    c = Q.axis_angle("y", t(0.1))
    assert torch.allclose(Q.slerp(a, c, t(0.3)), 0.7 * a + 0.3 * c, atol=1e-15)


@pytest.mark.parametrize("forward, expected_deg", [((1, 0, 0), 0.0), ((0, 0, -1), -90.0), ((0, 0, 1), 90.0),
                                                   ((-1, 0, 0), 180.0)])
def test_between_turns_forward_onto_plus_x(forward, expected_deg):
    q = Q.between(t(*forward), t(1, 0, 0))
    assert torch.allclose(Q.apply(q, t(*forward)), t(1, 0, 0), atol=1e-12)
    assert math.degrees(Q.angle_between(q, t(1, 0, 0, 0))) == pytest.approx(abs(expected_deg), abs=1e-9)
    if expected_deg == 180.0:  # the antiparallel guard: a half turn about +Y, not the official zero quaternion
        assert torch.allclose(q, t(0, 0, 1, 0))


def test_yaw_toward_turns_the_facing_onto_plus_x_about_y():
    """Mirrors the C# FacingTests: one definition of the facing yaw for localization and the benchmark."""
    g = torch.Generator().manual_seed(5)
    roots = Q.normalize(torch.randn(100, 4, dtype=D, generator=g))
    yaw = yaw_toward(roots, (0.0, 1.0, 0.0), (1.0, 0.0, 0.0))
    assert torch.all(yaw[:, [1, 3]].abs() <= 1e-15), "a rotation about +Y only"
    forward = Q.apply(Q.multiply(yaw, roots), t(0, 1, 0).expand(100, 3))
    assert torch.all(forward[:, 2].abs() < 1e-12) and torch.all(forward[:, 0] > 0)
    # hips +Y pointing to −X: a half turn, not the official zero quaternion
    backwards = Q.axis_angle("z", torch.tensor(math.pi / 2, dtype=D))
    assert torch.allclose(yaw_toward(backwards, (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)), t(0, 0, 1, 0), atol=1e-12)
    # no horizontal facing (shorter than 1e-6): the identity
    for up in (t(1, 0, 0, 0), Q.axis_angle("z", torch.tensor(1e-7, dtype=D))):
        assert torch.equal(yaw_toward(up, (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)), t(1, 0, 0, 0))


def test_continuity_fix_uses_the_fixed_previous_frame():
    q = torch.stack([t(1, 0, 0, 0), t(-1, 0, 0, 0), t(1, 0, 0, 0), t(-0.9, 0.1, 0, 0)])
    fixed = Q.remove_discontinuities(q.clone(), dim=0)
    assert torch.all(fixed[:, 0] > 0)
