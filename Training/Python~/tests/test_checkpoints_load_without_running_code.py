"""Checkpoints (issues 8, 16): a checkpoint never runs code when it is read (format 2 loads weights-only; a
crafted pickle is refused before anything in it runs), older formats still load and resume exactly, and a
bad checkpoint is one line naming it, exit 2, for every verb that reads one."""
from __future__ import annotations

import json
import os
import pickle
from pathlib import Path

import numpy as np
import pytest
import torch

from deltainterp.checkpoint import (CheckpointError, load_checkpoint, read_checkpoint, save_checkpoint_file, FORMAT,
                                    FORMAT_VERSION)
from deltainterp.train import train

from cli_checks import (bad_checkpoint, run_cli, assert_one_line_error, run_config, train_argv, run_cli_within,
                        one_line)


class _Payload:
    """Unpickling this would create the marker file (os.system through __reduce__)."""

    def __init__(self, marker: Path):
        self.marker = marker

    def __reduce__(self):
        return os.system, (f"touch {self.marker}",)

def crafted_checkpoints(folder: Path, marker: Path):
    """A torch zip without floats (torch's weights-only unpickler sees the global), one with a float before
    the payload (on torch 1.13 that goes through our restricted unpickler), and a raw pickle file."""
    evil = _Payload(marker)
    paths = {}
    paths["zip"] = folder / "zip.pt"
    torch.save({"model": evil, "model_config": {}}, paths["zip"])
    paths["zip-with-floats"] = folder / "floats.pt"
    torch.save({"unit_scale": 0.01, "model": {}, "payload": evil}, paths["zip-with-floats"])
    paths["raw-pickle"] = folder / "raw.pt"
    paths["raw-pickle"].write_bytes(pickle.dumps({"unit_scale": 0.01, "payload": evil}, protocol=2))
    return paths

@pytest.mark.parametrize("kind", ["zip", "zip-with-floats", "raw-pickle"])
def test_a_crafted_pickle_is_refused_without_running(kind, tmp_path, capsys, synthetic_pack_path):
    marker = tmp_path / "marker"
    path = crafted_checkpoints(tmp_path, marker)[kind]
    with pytest.raises(CheckpointError) as e:
        read_checkpoint(path)
    assert not marker.exists(), "the crafted checkpoint ran code"
    assert str(e.value).startswith(f"{path}: ")
    if kind != "raw-pickle":
        assert "posix.system" in str(e.value) or "os.system" in str(e.value)
    for argv in (["evaluate", "--checkpoint", path, "--json", tmp_path / "b.json", "--data", tmp_path],
                 ["export", "--checkpoint", path, "--out", tmp_path / "m.onnx"]):
        code, _, err = run_cli(capsys, argv)
        assert_one_line_error(code, err, path)
        assert not marker.exists(), f"{argv[0]} ran code from the crafted checkpoint"
    run = tmp_path / "run"
    run.mkdir()
    (run / "checkpoint.pt").write_bytes(path.read_bytes())
    code, _, err = run_cli(capsys, ["train", "--out", run, "--data", tmp_path / "none.npz", "--preset", "tiny"])
    assert_one_line_error(code, err, run / "checkpoint.pt")
    assert not marker.exists(), "train ran code from the crafted checkpoint"
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, tmp_path / "fresh", 3, "--init-from", path))
    assert_one_line_error(code, err, path)
    assert not marker.exists(), "train --init-from ran code from the crafted checkpoint"
    assert not (tmp_path / "b.json").exists() and not (tmp_path / "m.onnx").exists()

def test_a_version_1_checkpoint_still_loads_and_resumes_exactly(synthetic_pack_path, tmp_path):
    """Checkpoints written before this change (a pickled dict with floats, tuples and RNG dicts, as train.py
    and fixtures wrote them): the run in progress and Tests/Fixtures~/tiny-model.pt of older trees."""
    straight = read_checkpoint(train(run_config(synthetic_pack_path, tmp_path / "a", 9), progress=False))
    train(run_config(synthetic_pack_path, tmp_path / "b", 4), progress=False)
    ckpt = tmp_path / "b" / "checkpoint.pt"
    state = read_checkpoint(ckpt)
    assert isinstance(state["python_rng"], tuple) and isinstance(state["rng"][0]["state"]["state"], int)
    torch.save(state, ckpt)  # exactly what the old train.py wrote: torch.save of the logical dict
    assert "format" not in read_checkpoint(ckpt)  # read as version 1
    resumed = read_checkpoint(train(run_config(synthetic_pack_path, tmp_path / "b", 9), progress=False))
    assert resumed["step"] == straight["step"] == 9
    for name, w in straight["model"].items():
        assert torch.equal(w, resumed["model"][name]), f"{name} differs after resuming a version-1 checkpoint"
    assert resumed["rng"] == straight["rng"] and resumed["python_rng"] == straight["python_rng"]

def test_the_new_format_loads_with_torch_weights_only(tiny_checkpoint):
    raw = torch.load(tiny_checkpoint, map_location="cpu", weights_only=True)  # torch's own safe unpickler
    assert raw["format"] == "deltainterp-checkpoint" and raw["version"] == 2
    assert isinstance(raw["meta"], str)

def test_the_committed_fixture_checkpoint_loads():
    fixture = Path(__file__).resolve().parents[3] / "Tests" / "Fixtures~" / "tiny-model.pt"
    loaded = load_checkpoint(fixture)
    assert loaded.config.joints == 22 and loaded.unit_scale == pytest.approx(0.01)

BAD_CHECKPOINTS = ["zero-byte", "random", "truncated", "directory", "missing", "fifo", "wrong-shape",
                   "wrong-architecture", "unknown-config", "nan-weights", "not-ours", "a-list"]

@pytest.mark.parametrize("kind", BAD_CHECKPOINTS)
@pytest.mark.parametrize("verb", ["evaluate", "export"])
def test_bad_checkpoints_give_one_line(verb, kind, tmp_path, tiny_checkpoint, capsys):
    path = bad_checkpoint(kind, tmp_path, tiny_checkpoint)
    argv = (["evaluate", "--checkpoint", path, "--json", tmp_path / "b.json", "--data", tmp_path / "nodata"]
            if verb == "evaluate" else ["export", "--checkpoint", path, "--out", tmp_path / "m.onnx"])
    code, _, err = run_cli(capsys, argv)
    line = assert_one_line_error(code, err, path)
    assert "nodata" not in line, "the checkpoint is checked before the data is read"
    assert not (tmp_path / "b.json").exists() and not (tmp_path / "m.onnx").exists()

def test_a_checkpoint_with_deeply_nested_json_gives_one_line(tmp_path, capsys):
    path = tmp_path / "deep.pt"
    torch.save({"format": FORMAT, "version": FORMAT_VERSION, "meta": "[" * 3000 + "]" * 3000, "tensors": [],
                "model": {}}, path)
    code, _, err = run_cli_within(capsys, ["export", "--checkpoint", path, "--out", tmp_path / "m.onnx"])
    one_line(code, err, str(path))
