"""Chained validation: tails baked gap after gap, each gap's past frames the previous gap's output."""
from __future__ import annotations

import copy

import pytest
import torch

from deltainterp.chained import chained_metrics, tail_keys
from deltainterp.data import load_pack
from deltainterp.train import skeleton_tensors


def test_tail_keys_follow_every_and_never_leave_an_empty_last_gap():
    assert tail_keys(61, 15) == [0, 15, 30, 45, 60]
    assert tail_keys(70, 15) == [0, 15, 30, 45, 60, 69]
    assert tail_keys(62, 15) == [0, 15, 30, 45, 61]  # frame 61 right after key 60: the last gap grows


def test_a_network_that_adds_nothing_scores_exactly_slerp(tiny, synthetic_pack_path):
    net = copy.deepcopy(tiny.model)  # the fixture is shared: zero a copy
    pack = load_pack(str(synthetic_pack_path))
    skeleton = skeleton_tensors(pack, 0.01, "cpu")
    with torch.no_grad():
        for head in (net.root_head, net.rotation_head):
            head.weight.zero_()
            head.bias.zero_()
    out = chained_metrics(net, pack, skeleton, 15)
    assert out["tails"] == 2 and out["gaps"] >= 8 and out["frames"] > 100
    assert out["position_vs_slerp"] == pytest.approx(1.0, abs=1e-6)
    assert out["l2q_vs_slerp"] == pytest.approx(1.0, abs=1e-6)


def test_the_network_changes_the_chained_result(tiny, synthetic_pack_path):
    pack = load_pack(str(synthetic_pack_path))
    out = chained_metrics(tiny.model, pack, skeleton_tensors(pack, 0.01, "cpu"), 15)
    assert abs(out["position_vs_slerp"] - 1.0) > 1e-3  # a random network's deltas are not SLERP's


def test_the_chained_verb_prints_every_spacing(synthetic_pack_path, capsys):
    from pathlib import Path
    from deltainterp.cli import main
    tiny_pt = Path(__file__).resolve().parents[3] / "Tests" / "Fixtures~" / "tiny-model.pt"
    assert main(["chained", "--data", str(synthetic_pack_path), "--checkpoint", str(tiny_pt), "--every", "15", "30"]) == 0
    lines = capsys.readouterr().out.strip().splitlines()
    assert len(lines) == 2 and "every 15: 2 tails" in lines[0] and "every 30:" in lines[1] and "vs SLERP" in lines[1]
