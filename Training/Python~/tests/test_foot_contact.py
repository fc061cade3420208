"""The contact-weighted foot-velocity loss (train --foot-contact-weight) and the validation foot-skating number."""
from __future__ import annotations

import numpy as np
import pytest
import torch

from deltainterp.data import load_pack, split_windows
from deltainterp.objective import (CONTACT_HEIGHT, CONTACT_SPEED, foot_contact, foot_joint_indices, foot_skating,
                                   leg_length, loss, make_batch)
from deltainterp.sampler import TransitionSampler
from deltainterp.train import WindowSource, skeleton_tensors, validation_metrics

LEG, DT = 1.0, 1.0 / 30


def planted_span(frames: int = 9, joints: int = 4) -> torch.Tensor:
    """(1, frames, joints, 3): joint 0 planted on the ground, joint 1 swinging fast, joints 2-3 high up."""
    feet = torch.zeros(1, frames, joints, 3, dtype=torch.float64)
    t = torch.arange(frames, dtype=torch.float64)
    feet[0, :, 1, 0] = t * 0.1           # 3 leg lengths per second: never planted
    feet[0, :, 2:, 1] = 0.5              # far above the ground
    return feet


def test_contact_is_the_csharp_rule_on_the_truth():
    feet = planted_span()
    mask = foot_contact(feet, LEG, DT)
    assert mask.shape == (1, 7, 4)
    assert mask[0, :, 0].all() and not mask[0, :, 1:].any()
    # just above the height limit, or just faster than the speed limit: not planted
    lifted = feet.clone()
    lifted[0, 4, 0, 1] = CONTACT_HEIGHT * LEG * 1.01
    assert not foot_contact(lifted, LEG, DT)[0, 3, 0]
    creeping = feet.clone()
    creeping[0, :, 0, 2] = torch.arange(9, dtype=torch.float64) * CONTACT_SPEED * LEG * DT * 1.01
    assert not foot_contact(creeping, LEG, DT)[0, :, 0].any()
    creeping[0, :, 0, 2] *= 0.98 / 1.01
    assert foot_contact(creeping, LEG, DT)[0, :, 0].all()


def test_term_is_zero_when_the_prediction_equals_the_truth():
    feet = planted_span()
    total, count = foot_skating(feet.clone(), feet, LEG, DT)
    assert count == 7 and total.item() == pytest.approx(0.0, abs=1e-4)


def test_term_is_positive_when_a_planted_foot_moves_and_has_a_gradient():
    feet = planted_span()
    pred = feet.clone()
    pred[0, 4, 0, 0] += 0.05  # the planted joint slides on one filled frame
    pred.requires_grad_(True)
    total, count = foot_skating(pred, feet, LEG, DT)
    assert total.item() > 0 and count == 7
    total.backward()
    assert pred.grad[0, 4, 0, 0] != 0
    # a joint the truth does not plant may move freely
    free = feet.clone()
    free[0, 4, 1, 0] += 0.05
    assert foot_skating(free, feet, LEG, DT)[0].item() == pytest.approx(0.0, abs=1e-4)
    # vertical motion (a foot rolling or lifting) is not skating
    lift = feet.clone()
    lift[0, 4, 0, 1] += 0.05
    assert foot_skating(lift, feet, LEG, DT)[0].item() == pytest.approx(0.0, abs=1e-4)


def test_leg_length_and_feet_of_the_lafan1_skeleton(skeleton):
    feet = foot_joint_indices(skeleton.names)
    assert [skeleton.names[i] for i in feet] == ["LeftFoot", "LeftToe", "RightFoot", "RightToe"]
    # thigh + shin + half the ankle→toe bone (pointed 30° down), LaFAN1 centimetres
    assert 80 < leg_length(skeleton.names, skeleton.offsets) < 110
    assert foot_joint_indices(["Hips", "Spine"]) == ()


def _batch(pack_path, seed=5):
    pack = load_pack(str(pack_path))
    starts, val = split_windows(pack)
    skel = skeleton_tensors(pack, 0.01, "cpu")
    source = WindowSource(pack, starts, 50, TransitionSampler(), False, False, "cpu")
    layout, roots, quats = source.draw(np.random.default_rng(seed), 4)
    return pack, val, skel, layout, roots, quats


def test_loss_is_unchanged_by_default_and_adds_the_weighted_term(synthetic_pack_path, tiny):
    torch.manual_seed(0)
    _, _, skel, layout, roots, quats = _batch(synthetic_pack_path)
    model = tiny.model if hasattr(tiny, "model") else tiny
    cfg = model.config
    batch = make_batch(roots, quats, layout, skel, cfg.output_delta_mode, cfg.input_delta_mode)
    model.eval()
    with torch.no_grad():
        base = loss(model, batch, skel)
        off = loss(model, batch, skel, foot_contact_weight=0.0)
        on = loss(model, batch, skel, foot_contact_weight=2.0)
    assert "foot" not in base and torch.equal(base["total"], off["total"])
    assert on["foot"].item() >= 0
    assert on["total"].item() == pytest.approx(base["total"].item() + 2.0 * on["foot"].item(), rel=1e-5)


def test_validation_reports_foot_skating_for_model_and_slerp(synthetic_pack_path, tiny):
    pack, val, skel, *_ = _batch(synthetic_pack_path)
    model = tiny.model if hasattr(tiny, "model") else tiny
    out = validation_metrics(model, pack, val, skel, gaps=(15,))
    skates = {k: v for k, v in out.items() if "_skate_" in k}
    # the synthetic motion may or may not plant a foot; where it does, both are scored and finite
    assert set(skates) in (set(), {"model_skate_15", "slerp_skate_15"})
    assert all(np.isfinite(v) and v >= 0 for v in skates.values())
