"""Non-finite values (issues 8, 16): a network, benchmark result, training loss or prepared motion that is NaN or
infinite is an error naming what holds it, never a file or table with NaN in it."""
from __future__ import annotations

import json

import pytest
import torch

from deltainterp.checkpoint import load_checkpoint, read_checkpoint
from deltainterp.train import train

from conftest import STATS
from cli_checks import (run_cli, assert_one_line_error, train_argv, needs_lafan1, one_file_data, bvh, run_cli_within,
                        one_line, lafan1_folder)


def test_export_refuses_a_network_with_non_finite_outputs(tmp_path, tiny_checkpoint):
    from deltainterp.export import ExportCheckError, export_model
    loaded = load_checkpoint(tiny_checkpoint)  # load_checkpoint refuses NaN weights; here they come later
    with torch.no_grad():
        next(p for p in loaded.model.parameters() if p.dim() == 2).fill_(float("inf"))
    with pytest.raises(ExportCheckError, match="non-finite"):
        export_model(loaded, tmp_path / "m.onnx")
    assert not (tmp_path / "m.onnx").exists()

def test_non_finite_benchmark_results_are_an_error():
    from deltainterp.cli import _refuse_non_finite
    report = {"results": {"model": {"l2p": {"5": float("nan")}}}}
    with pytest.raises(ValueError, match=r"DATA: the benchmark gave L2P = nan for model at n=5; expected finite"):
        _refuse_non_finite(report, "DATA")
    _refuse_non_finite({"results": {"model": {"l2p": {"5": 0.5}}}}, "DATA")

def test_evaluate_refuses_a_nan_result(tmp_path, capsys):
    needs_lafan1()
    data = one_file_data(tmp_path, huge=True)
    out = tmp_path / "b.json"
    code, stdout, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", STATS, "--lengths", "5",
                                         "--offset", "40", "--json", out])
    line = assert_one_line_error(code, err, data)
    assert ("= nan" in line or "= inf" in line) and not out.exists() and "| nan" not in stdout.lower()

def test_a_diverging_run_stops_with_one_line_and_no_nan_in_its_files(synthetic_pack_path, tmp_path, capsys,
                                                                    monkeypatch):
    from deltainterp import train as train_module
    real_loss = train_module.loss
    calls = {"n": 0}

    def diverging(*args, **kw):
        terms = real_loss(*args, **kw)
        calls["n"] += 1
        if calls["n"] >= 3:
            terms["total"] = terms["total"] * float("nan")
        return terms

    monkeypatch.setattr(train_module, "loss", diverging)
    run = tmp_path / "run"
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 6, "--checkpoint-every", "2"))
    assert "non-finite at step 3" in assert_one_line_error(code, err)
    state = read_checkpoint(run / "checkpoint.pt")
    assert state["step"] == 2 and all(torch.isfinite(v).all() for v in state["model"].values()
                                      if v.is_floating_point())

# 24. prepare packed NaN motion (and 1e308, infinite as float32) that train then rejected as "not a pack".
@pytest.mark.parametrize("value", ["nan", "1e308", "inf"])
def test_prepare_refuses_non_finite_motion(value, tmp_path, capsys):
    data = lafan1_folder(tmp_path, bvh(root=value))
    out = tmp_path / "p.npz"
    code, _, err = run_cli_within(capsys, ["prepare", "--data", data, "--stats", tmp_path / "stats.json", "--out", out])
    one_line(code, err, "walk1_subject1.bvh")
    assert not out.exists()
