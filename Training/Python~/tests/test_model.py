"""Network shapes, Δ-mode semantics and the split into key encoding + query decoding."""
from __future__ import annotations

import copy
import math

import numpy as np
import pytest
import torch

from deltainterp import quaternions as Q
from deltainterp import rotation6d
from deltainterp.checkpoint import LoadedModel
from deltainterp.decoding import decode_outputs
from deltainterp.fixtures import Case, synthetic_request
from deltainterp.model import DeltaInterpolator, MultiHeadAttention, preset
from deltainterp.transition import run_transition


def request(case: Case, joints: int = 22, dtype=torch.float64):
    root, local = synthetic_request(case, joints)
    p = case.past
    to = lambda a: torch.from_numpy(a).to(dtype)  # noqa: E731
    return to(root[None, :p]), to(local[None, :p]), to(root[None, -1]), to(local[None, -1])


CASE = Case("model-test", 10, 7, (120.0, -40.0), 35.0, 50.0, 2.0, 7)


@pytest.mark.parametrize("name, overrides", [("tiny", {}), ("tiny", {"joints": 5}),
                                             ("tiny", {"width": 24, "heads": 3, "blocks": 3})])
@pytest.mark.parametrize("keys, queries", [(11, 5), (3, 1), (11, 39)])
def test_shapes(name, overrides, keys, queries):
    cfg = preset(name, **overrides)
    model = DeltaInterpolator(cfg).eval()
    feats = torch.randn(2, keys, 9 * cfg.joints)
    key_idx = torch.tensor(list(range(keys - 1)) + [keys - 1 + queries])
    query_idx = torch.arange(keys - 1, keys - 1 + queries)
    root, rot = model(feats, key_idx, query_idx, torch.tensor([queries]))
    assert root.shape == (2, queries, 3) and rot.shape == (2, queries, cfg.joints, 6)
    (kr, k6), (qr, q6) = model(feats, key_idx, query_idx, torch.tensor([queries]), with_keys=True)
    assert kr.shape == (2, keys, 3) and k6.shape == (2, keys, cfg.joints, 6)
    assert torch.equal(qr, root) and torch.equal(q6, rot)


def test_presets_parameter_counts():
    assert DeltaInterpolator(preset("runtime")).parameter_count() == 1_979_271
    with pytest.raises(ValueError, match="divisible"):
        preset("tiny", width=30, heads=4)
    with pytest.raises(ValueError, match="unknown preset"):
        preset("huge")


def test_lazy_decoding_equals_whole(tiny):
    model = tiny.model
    feats = torch.randn(1, 11, 198)
    key_idx = torch.tensor(list(range(10)) + [25])
    query_idx = torch.arange(10, 25)
    gap = torch.tensor([15])
    with torch.no_grad():
        whole = model(feats, key_idx, query_idx, gap)
        _, memory = model.encode_keys(feats, key_idx, gap)
        one_by_one = [model.heads(model.decode_queries(memory, query_idx[i:i + 1], gap)) for i in range(15)]
    assert torch.allclose(torch.cat([r for r, _ in one_by_one], 1), whole[0], atol=1e-6)
    assert torch.allclose(torch.cat([q for _, q in one_by_one], 1), whole[1], atol=1e-6)


@pytest.mark.parametrize("width, heads", [(256, 8), (24, 3)])
@pytest.mark.parametrize("keys, queries", [(11, 1), (5, 1), (1, 1), (11, 4)])
def test_attend_rows_equals_attend(width, heads, keys, queries):
    # the frame graph's attention (Mul/ReduceSum over each row's (B, 1, K, D) memory) is attend's maths
    torch.manual_seed(keys * 10 + queries)
    attention = MultiHeadAttention(width, heads).eval()
    x, k, v = torch.randn(3, queries, width), torch.randn(3, keys, width), torch.randn(3, keys, width)
    with torch.no_grad():
        want = attention.attend(x, k, v)
        got = attention.attend_rows(x, k.unsqueeze(1), v.unsqueeze(1))
    assert got.shape == want.shape
    assert torch.allclose(got, want, atol=1e-5, rtol=0)


def _untrained(mode: str, skeleton) -> LoadedModel:
    torch.manual_seed(0)
    return LoadedModel(DeltaInterpolator(preset("tiny", output_delta_mode=mode)).eval().double(), skeleton,
                       0.01, 0)


def test_untrained_slerp_mode_is_exact_slerp(skeleton):
    loaded = _untrained("slerp", skeleton)
    past_r, past_q, tgt_r, tgt_q = request(CASE)
    out = run_transition(loaded, past_r, past_q, tgt_r, tgt_q, CASE.gap)
    assert torch.count_nonzero(out.root_delta) == 0 and torch.count_nonzero(out.rotation_delta) == 0
    # the official SLERP/LERP in world space, computed independently of the localization
    n = CASE.gap
    a = torch.arange(1, n + 1, dtype=torch.float64) / (n + 1)
    lerp = past_r[:, -1:] + a[None, :, None] * (tgt_r - past_r[:, -1])[:, None]
    assert torch.allclose(out.root_positions, lerp, atol=1e-9)
    last, tgt = Q.normalize(past_q[:, -1]), Q.normalize(tgt_q)
    slerp = torch.stack([Q.normalize(Q.slerp(last, tgt, w.expand(1, 22))) for w in a], 1)
    assert torch.allclose(out.local_quaternions, slerp, atol=1e-9)  # same hemisphere too, not just rotation


def test_untrained_last_pose_mode_holds_the_last_key(skeleton):
    loaded = _untrained("last_pose", skeleton)
    past_r, past_q, tgt_r, tgt_q = request(CASE)
    out = run_transition(loaded, past_r, past_q, tgt_r, tgt_q, CASE.gap)
    assert torch.allclose(out.root_positions, past_r[:, -1:].expand_as(out.root_positions), atol=1e-9)
    want = Q.normalize(past_q[:, -1:]).expand_as(out.local_quaternions)
    assert torch.allclose(out.local_quaternions, want, atol=1e-9)


def test_none_mode_outputs_are_absolute():
    """Output Δ-mode none: the network's 6D IS the rotation and its root output IS the position."""
    g = torch.Generator().manual_seed(3)
    q = Q.normalize(torch.randn(1, 4, 22, 4, generator=g, dtype=torch.float64))
    base_q = Q.normalize(torch.randn(1, 4, 22, 4, generator=g, dtype=torch.float64))
    r6 = rotation6d.from_matrix(Q.to_matrix(q))
    root = torch.randn(1, 4, 3, generator=g, dtype=torch.float64)
    out_root, out_q = decode_outputs("none", torch.ones(1, 4, 3, dtype=torch.float64), base_q, root, r6)
    assert torch.allclose(out_root, root)
    assert torch.allclose(Q.to_matrix(out_q), Q.to_matrix(q), atol=1e-9)
    assert torch.all((out_q * base_q).sum(-1) >= 0)  # hemisphere of the (SLERP) reference


@pytest.mark.parametrize("mode", ["slerp", "last_pose"])
def test_decoded_quaternions_follow_the_baseline_hemisphere(mode, tiny):
    loaded = copy.deepcopy(tiny)
    loaded.model.config.output_delta_mode = mode
    past_r, past_q, tgt_r, tgt_q = request(Case("flip", 10, 9, (0, 0), 170.0, 40.0, 1.0, 9, True))
    out = run_transition(loaded, past_r, past_q, tgt_r, tgt_q, 9)
    assert torch.all((out.local_quaternions[:, :, 1:] * out.batch.base_rotations[:, :, 1:]).sum(-1) >= 0)
    assert torch.allclose(out.local_quaternions.norm(dim=-1), torch.ones(1, 9, 22, dtype=torch.float64))


# -- equivariance -----------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def tiny64(tiny):
    loaded = copy.deepcopy(tiny)
    loaded.model = loaded.model.double()
    return loaded


@pytest.mark.parametrize("shift", [(0.0, 0.0, 0.0), (500.0, 0.0, -300.0), (-12.5, 40.0, 7.25),
                                   (1e4, -30.0, 2e4)])
def test_translation_equivariance(tiny64, shift):
    past_r, past_q, tgt_r, tgt_q = request(CASE)
    c = torch.tensor(shift, dtype=torch.float64)
    base = run_transition(tiny64, past_r, past_q, tgt_r, tgt_q, CASE.gap)
    moved = run_transition(tiny64, past_r + c, past_q, tgt_r + c, tgt_q, CASE.gap)
    assert torch.count_nonzero(base.rotation_delta) > 0, "the test needs a model that is not pure SLERP"
    assert torch.allclose(moved.root_positions, base.root_positions + c, atol=1e-8, rtol=0)
    assert torch.allclose(moved.local_quaternions, base.local_quaternions, atol=1e-9)


@pytest.mark.parametrize("facing", [0.0, 90.0, 178.0, -135.0])
@pytest.mark.parametrize("turn_deg", [0.0, 37.0, -90.0, 180.0, 263.5])
def test_yaw_equivariance(tiny64, facing, turn_deg):
    case = Case("yaw", 10, 6, (80.0, 25.0), facing, 60.0, 2.0, 21)
    past_r, past_q, tgt_r, tgt_q = request(case)
    yaw = Q.axis_angle("y", torch.tensor(math.radians(turn_deg), dtype=torch.float64))

    def turn_positions(p):
        return Q.apply(yaw.expand(p.shape[:-1] + (4,)), p)

    def turn_quaternions(q):
        q = q.clone()
        q[..., 0, :] = Q.multiply(yaw.expand(q[..., 0, :].shape), q[..., 0, :])
        return q

    base = run_transition(tiny64, past_r, past_q, tgt_r, tgt_q, case.gap)
    turned = run_transition(tiny64, turn_positions(past_r), turn_quaternions(past_q), turn_positions(tgt_r),
                            turn_quaternions(tgt_q[:, None])[:, 0], case.gap)
    assert torch.allclose(turned.root_positions, turn_positions(base.root_positions), atol=1e-5, rtol=0)
    want = turn_quaternions(base.local_quaternions)
    assert torch.allclose(Q.align_hemisphere(turned.local_quaternions, want), want, atol=1e-5)


def test_model_is_not_yaw_invariant_without_localization(tiny64):
    """Why localization exists: the raw network sees world-axis differences (method-spec §4.4)."""
    feats = torch.randn(1, 11, 198, dtype=torch.float64)
    key_idx, query_idx, gap = torch.tensor(list(range(10)) + [15]), torch.arange(10, 15), torch.tensor([5])
    a = tiny64.model(feats, key_idx, query_idx, gap)[0]
    r = feats.reshape(1, 11, 22, 9).clone()
    r[..., 6:] = r[..., 6:][..., [2, 1, 0]] * torch.tensor([1.0, 1.0, -1.0], dtype=torch.float64)
    b = tiny64.model(r.reshape(1, 11, 198), key_idx, query_idx, gap)[0]
    assert not np.allclose(a.detach().numpy(), b.detach().numpy(), atol=1e-6)
