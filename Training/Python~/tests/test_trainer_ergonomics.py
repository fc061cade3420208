"""Issue 30, item 8: the trainer as a newcomer runs it — a warm-up longer than the run is shortened with a
warning, progress in a log (not a terminal) is one line per log interval instead of a tqdm flood, and
./Tools~/train runs the trainer with the interpreter and module path ./Tools~/test uses."""
import os
import subprocess
from pathlib import Path

from deltainterp.cli import main
from deltainterp.train import TrainConfig, learning_rate, warmup_steps

ROOT = Path(__file__).resolve().parents[3]


def test_a_warmup_longer_than_the_run_is_a_tenth_of_it():
    cfg = TrainConfig(steps=40, warmup_steps=500, peak_lr=1e-3, decay_at=1.0)
    assert warmup_steps(cfg) == 4
    assert learning_rate(cfg, 4) == 1e-3, "the run reaches its learning rate"
    assert learning_rate(cfg, 2) < 1e-3
    # A warm-up that fits is left alone, including one exactly as long as the run.
    assert warmup_steps(TrainConfig(steps=40, warmup_steps=40)) == 40
    assert warmup_steps(TrainConfig(steps=10000, warmup_steps=500)) == 500
    assert warmup_steps(TrainConfig(steps=5, warmup_steps=500)) == 1


def test_progress_is_one_line_per_interval_off_a_terminal_and_the_warmup_warning_is_printed(capsys, synthetic_pack_path, tmp_path):
    code = main([str(a) for a in ["train", "--data", synthetic_pack_path, "--out", tmp_path / "run", "--preset", "tiny",
                                  "--steps", 100, "--batch-size", 2, "--validate-every", 1000, "--checkpoint-every", 1000]])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "warning: --warmup 500 is longer than --steps 100: warming up over 10 steps (a tenth of the run) instead" in out
    assert "\r" not in err, "no carriage-return redraws in a log"
    progress = [line for line in out.splitlines() if line.startswith("train tiny: step ")]
    assert [line.split()[3] for line in progress] == ["50/100", "100/100"], out
    assert "train tiny: step" not in err, "stderr keeps one line per error"
    assert "%|" not in err, "no tqdm bar"


def test_the_train_wrapper_runs_the_trainer_and_refuses_a_missing_interpreter(tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "DELTAINTERP_PYTHON")}
    # From another folder and without PYTHONPATH: the wrapper sets the module path itself.
    done = subprocess.run([str(ROOT / "Tools~" / "train"), "export", "--help"], cwd=tmp_path, env=env,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "--checkpoint" in done.stdout
    env["DELTAINTERP_PYTHON"] = str(tmp_path / "no-python")
    refused = subprocess.run([str(ROOT / "Tools~" / "train"), "--help"], env=env, capture_output=True, text=True, timeout=60)
    assert refused.returncode == 2
    assert refused.stderr.splitlines() == [f"train: {tmp_path / 'no-python'}: no such interpreter; expected /usr/bin/python3 or DELTAINTERP_PYTHON naming one"]
    # An interpreter without torch (here one that finds nothing): refused in one line before the trainer starts.
    bare = tmp_path / "bare-python"
    bare.write_text("#!/bin/sh\nexit 1\n")
    bare.chmod(0o755)
    env["DELTAINTERP_PYTHON"] = str(bare)
    refused = subprocess.run([str(ROOT / "Tools~" / "train"), "--help"], env=env, capture_output=True, text=True, timeout=60)
    assert refused.returncode == 2
    assert len(refused.stderr.splitlines()) == 1 and "lacks torch or numpy; expected" in refused.stderr, refused.stderr
