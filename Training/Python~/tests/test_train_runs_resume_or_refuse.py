"""`train --out` (issues 8, 16): a run folder resumes only with the settings it was started with, a folder or
pack that is not a run's is refused in one line, interrupted checkpoint and log writes leave the old files,
log records after the checkpoint are dropped on resume, and a pack too small to validate on still trains."""
from __future__ import annotations

import json
import os
import time
from pathlib import Path

import numpy as np
import pytest

from deltainterp import safe_output
from deltainterp.checkpoint import read_checkpoint
from deltainterp.data import MotionPack, save_pack
from deltainterp.train import train

from conftest import synthetic_motion
from cli_checks import (bad_checkpoint, run_cli, assert_one_line_error, no_temporaries, run_config, train_argv,
                        run_cli_within)


def test_train_refuses_folders_that_are_not_its_runs(synthetic_pack_path, tmp_path, capsys, tiny_checkpoint):
    regular = tmp_path / "file"
    regular.write_text("x")
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, regular, 3))
    assert "is a file" in assert_one_line_error(code, err, regular)
    other = tmp_path / "other"
    other.mkdir()
    (other / "log.csv").write_text("time,value\n1,2\n")
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, other, 3))
    assert "no checkpoint.pt" in assert_one_line_error(code, err, other)
    assert (other / "log.csv").read_text() == "time,value\n1,2\n" and len(list(other.iterdir())) == 1
    for kind in ("zero-byte", "random", "truncated", "directory"):
        run = tmp_path / f"run-{kind}"
        run.mkdir()
        src = bad_checkpoint(kind, tmp_path, tiny_checkpoint)
        if kind == "directory":
            (run / "checkpoint.pt").mkdir()
        else:
            (run / "checkpoint.pt").write_bytes(src.read_bytes())
        code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 3))
        assert_one_line_error(code, err, run / "checkpoint.pt")
    run = tmp_path / "fixture-as-run"  # a checkpoint for evaluation only: no optimizer state to resume
    run.mkdir()
    (run / "checkpoint.pt").write_bytes(tiny_checkpoint.read_bytes())
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 3))
    assert "lacks 'optimizer'" in assert_one_line_error(code, err, run / "checkpoint.pt")

@pytest.mark.parametrize("kind", ["missing", "zero-byte", "random", "directory", "not-a-pack"])
def test_train_bad_packs_give_one_line(kind, tmp_path, capsys):
    pack = tmp_path / "pack.npz"
    if kind == "zero-byte":
        pack.write_bytes(b"")
    elif kind == "random":
        pack.write_bytes(np.random.default_rng(2).bytes(1000))
    elif kind == "directory":
        pack.mkdir()
    elif kind == "not-a-pack":
        np.savez(pack, something=np.zeros(3))
    code, _, err = run_cli(capsys, train_argv(pack, tmp_path / "run", 3))
    assert_one_line_error(code, err, pack)
    assert not (tmp_path / "run").exists() or not any((tmp_path / "run").iterdir())

def test_resuming_refuses_other_settings_and_warns_about_other_steps(synthetic_pack_path, tmp_path, capsys):
    run = tmp_path / "run"
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 4, "--lr", "0.0003"))
    assert code == 0, err
    before = (run / "checkpoint.pt").read_bytes()
    refusals = [(["--lr", "0.001"], "resuming with --lr 0.001 but the run used 0.0003; expected the same settings"),
                (["--lr", "0.0003", "--seed", "7"], "--seed 7 but the run used 0"),
                (["--lr", "0.0003", "--width", "64"], "resuming another architecture: width 64 but the run used 32"),
                (["--lr", "0.0003", "--mirror"], "--mirror True but the run used False")]
    for extra, message in refusals:
        code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 6, *extra))
        assert message in assert_one_line_error(code, err, run / "checkpoint.pt")
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 2, "--lr", "0.0003"))
    assert "already at step 4, past --steps 2; expected --steps ≥ 4" in assert_one_line_error(code, err)
    assert (run / "checkpoint.pt").read_bytes() == before, "a refused resume must not touch the run"
    code, out, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 4, "--lr", "0.0003"))
    assert code == 0 and "complete at step 4" in out, out + err
    code, out, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 6, "--lr", "0.0003"))
    assert code == 0, err
    assert "warning:" in out and "--steps 6 but the run used 4" in out
    assert read_checkpoint(run / "checkpoint.pt")["step"] == 6

def test_interrupted_checkpoint_and_log_writes_leave_the_old_files(synthetic_pack_path, tmp_path, monkeypatch):
    cfg = run_config(synthetic_pack_path, tmp_path / "run", 50, validate_every=50)
    train(cfg, progress=False)
    run = tmp_path / "run"
    old = {n: (run / n).read_bytes() for n in ("checkpoint.pt", "log.csv", "validation.jsonl")}

    def fail(temporary, target):
        raise OSError(28, "No space left on device (simulated)", str(target))

    for name in old:
        old[name] = (run / name).read_bytes()  # an earlier round's successful appends changed the logs
        monkeypatch.setattr(safe_output, "_rename",
                            lambda t, p, name=name: fail(t, p) if Path(p).name == name else os.replace(t, p))
        with pytest.raises(OSError, match="simulated"):
            train(run_config(synthetic_pack_path, run, 100, validate_every=50), progress=False)
        monkeypatch.undo()
        assert (run / name).read_bytes() == old[name], f"{name} changed by a failed write"
        no_temporaries(run)

def test_resuming_drops_log_records_written_after_the_checkpoint(synthetic_pack_path, tmp_path, capsys):
    """A run stopped between a log row and its next checkpoint redoes those steps: their records must not
    appear twice."""
    run = tmp_path / "run"
    train(run_config(synthetic_pack_path, run, 50, validate_every=50), progress=False)
    log, val = run / "log.csv", run / "validation.jsonl"
    log.write_text(log.read_text() + "100,0.001,9,9,9,9,9,9.0\n")  # records of steps the checkpoint lacks
    val.write_text(val.read_text() + json.dumps({"step": 100, "model_l2q_5": 9.0}) + "\n")
    code, out, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 100, "--lr", "0.003", "--warmup", 2,
                                                "--decay-at", 1.0, "--validate-every", 50))
    assert code == 0, err
    assert "dropped 2 log record(s)" in out
    steps = [int(line.split(",")[0]) for line in log.read_text().splitlines()[1:]]
    assert steps == [50, 100] and "9,9,9" not in log.read_text()
    assert [json.loads(line)["step"] for line in val.read_text().splitlines()] == [50, 100]

def test_train_on_a_small_pack_trains_without_validation(tmp_path, capsys, skeleton):
    roots, quats = [], []
    for seed in (3, 4):
        r, q = synthetic_motion(200, skeleton.joint_count, seed)
        roots.append(r)
        quats.append(q)
    pack = MotionPack(skeleton, ["a.bvh", "b.bvh"], np.array([0, 200, 400]), np.concatenate(roots),
                      np.concatenate(quats), 1 / 30)
    pack_path = tmp_path / "small.npz"
    save_pack(pack, str(pack_path))
    run = tmp_path / "run"
    code, out, err = run_cli_within(capsys, ["train", "--data", pack_path, "--out", run, "--preset", "tiny", "--steps", 3,
                                      "--batch-size", 2, "--warmup", 1, "--validate-every", 1,
                                      "--checkpoint-every", 1000])
    assert code == 0, err
    assert (run / "checkpoint.pt").exists()
    assert "training without validation" in out + err
