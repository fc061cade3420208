"""Helpers the trainer's refusal tests share: running the CLI in process (with a time limit where a named
pipe could block), the one-line error contract, tiny training runs and small data folders."""
from __future__ import annotations

import json
import os
import threading
from pathlib import Path

import numpy as np
import pytest
import torch

from deltainterp.checkpoint import read_checkpoint, save_checkpoint_file
from deltainterp.cli import main
from deltainterp.train import TrainConfig

from conftest import LAFAN1, REPO, STATS


def run_cli(capsys, argv):
    """main(argv) in-process → (exit code, stdout, stderr)."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def assert_one_line_error(code, err, path=None):
    assert code == 2, err
    lines = [line for line in err.replace("\r", "\n").splitlines() if line.strip() and "%|" not in line]  # tqdm bars
    assert len(lines) == 1, f"expected one line on stderr, got:\n{err}"
    assert lines[0].startswith("error: ") and "Traceback" not in err
    assert "expected" in lines[0], lines[0]
    if path is not None:
        assert f"error: {path}" in lines[0], lines[0]
    return lines[0]


def no_temporaries(folder: Path):
    left = [p.name for p in folder.iterdir() if p.name.endswith(".tmp") or "write-probe" in p.name]
    assert not left, f"temporary files left behind: {left}"


def run_config(pack: Path, out: Path, steps: int, **kw) -> TrainConfig:
    base = dict(data=str(pack), out=str(out), preset="tiny", batch_size=4, steps=steps, peak_lr=3e-3,
                warmup_steps=2, decay_at=1.0, checkpoint_every=1000, validate_every=1000, threads=1)
    base.update(kw)
    return TrainConfig(**base)


def train_argv(pack: Path, out: Path, steps: int, *extra):
    return ["train", "--data", pack, "--out", out, "--preset", "tiny", "--steps", steps, "--batch-size", 4,
            "--warmup", 2, "--validate-every", 1000, "--checkpoint-every", 1000, *extra]


def needs_lafan1():
    if not (LAFAN1 / "ground1_subject5.bvh").exists() or not STATS.exists():
        pytest.skip(f"LaFAN1 data not found at {LAFAN1}; the evaluate write tests need one subject-5 file")


def one_file_data(tmp_path: Path, huge: bool = False) -> Path:
    """A --data folder with one real subject-5 file (optionally with one value set to 1e308, which the
    reader accepts as finite and which turns L2P into NaN)."""
    data = tmp_path / "data"
    data.mkdir()
    source = LAFAN1 / "ground1_subject5.bvh"
    if not huge:
        os.symlink(source, data / source.name)
        return data
    lines = source.read_text().splitlines(keepends=True)
    first = next(i for i, line in enumerate(lines) if line.startswith("Frame Time")) + 1
    values = lines[first + 12].split()
    values[0] = "1e308"
    lines[first + 12] = " ".join(values) + "\n"
    (data / source.name).write_text("".join(lines))
    return data


FIXTURE_FILES = REPO / "Tests" / "Fixtures~"


ONE_JOINT_HEADER = ("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation "
          "Yrotation Xrotation\n  End Site\n  {\n    OFFSET 0 1 0\n  }\n}\nMOTION\n")


ONE_JOINT_STATS = {"x_mean": [0.0] * 3, "x_std": [1.0] * 3, "offsets": []}  # one joint, as ONE_JOINT_HEADER


def bvh(frames: int = 3, root: str = "0") -> str:
    rows = [f"{root if f == 1 else '0'} 90 0 0 0 0" for f in range(frames)]
    return ONE_JOINT_HEADER + f"Frames: {frames}\nFrame Time: 0.0333333\n" + "\n".join(rows) + "\n"


def run_cli_within(capsys, argv, seconds: float = 120):
    """main(argv) in a thread → (exit code, stdout, stderr); fails instead of hanging (a FIFO blocks an open)."""
    result = {}

    def target():
        try:
            result["code"] = main([str(a) for a in argv])
        except BaseException as e:  # noqa: BLE001 - reported below
            result["error"] = e

    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"{argv[0]} did not finish within {seconds} s (blocked on a named pipe?)"
    if "error" in result:
        raise result["error"]
    out, err = capsys.readouterr()
    return result["code"], out, err


def one_line(code, err, phrase=None):
    assert code == 2, err
    lines = [line for line in err.replace("\r", "\n").splitlines() if line.strip() and "%|" not in line]
    assert len(lines) == 1, f"expected one line on stderr, got:\n{err}"
    assert lines[0].startswith("error: ") and "Traceback" not in err and "expected" in lines[0], lines[0]
    if phrase is not None:
        assert phrase in lines[0], lines[0]
    return lines[0]


def lafan1_folder(tmp_path: Path, text: str = None) -> Path:
    data = tmp_path / "data"
    data.mkdir()
    (data / "walk1_subject1.bvh").write_text(text or bvh())
    (data / "walk1_subject5.bvh").write_text(bvh())
    (tmp_path / "stats.json").write_text(json.dumps(ONE_JOINT_STATS))
    return data


def bad_checkpoint(kind: str, folder: Path, good: Path) -> Path:
    path = folder / f"{kind}.pt"
    data = good.read_bytes()
    if kind == "zero-byte":
        path.write_bytes(b"")
    elif kind == "random":
        path.write_bytes(np.random.default_rng(1).bytes(4096))
    elif kind == "truncated":
        path.write_bytes(data[: len(data) // 2])
    elif kind == "directory":
        path.mkdir()
    elif kind == "missing":
        pass
    elif kind == "fifo":
        os.mkfifo(path)
    else:
        state = read_checkpoint(good)
        if kind == "wrong-shape":
            name = next(iter(state["model"]))
            state["model"][name] = torch.zeros(3, 5)
        elif kind == "wrong-architecture":
            state["model_config"] = {**state["model_config"], "width": state["model_config"]["width"] * 2}
        elif kind == "unknown-config":
            state["model_config"] = {**state["model_config"], "colour": "blue"}
        elif kind == "nan-weights":
            name = next(k for k, v in state["model"].items() if v.is_floating_point())
            state["model"][name] = torch.full_like(state["model"][name], float("nan"))
        elif kind == "not-ours":
            torch.save({"weights": torch.zeros(3), "scale": 0.5}, path)
            return path
        elif kind == "a-list":
            torch.save([torch.zeros(3)], path)
            return path
        save_checkpoint_file(state, path)
    return path
