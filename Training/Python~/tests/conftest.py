"""Shared test set-up: one torch thread (the machine may be training), paths, small synthetic data."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
import torch

TRAINING = Path(__file__).resolve().parents[1]
REPO = TRAINING.parents[1]  # Training/Python~ -> the repository
sys.path.insert(0, str(TRAINING))

torch.set_num_threads(1)

from deltainterp import safe_output  # noqa: E402
from deltainterp.checkpoint import save_checkpoint_file  # noqa: E402
from deltainterp.data import MotionPack, save_pack  # noqa: E402
from deltainterp.fixtures import Case, checkpoint_state, make_tiny_model, synthetic_request  # noqa: E402
from deltainterp.lafan1 import builtin_skeleton  # noqa: E402

LAFAN1 = REPO.parent / "shared" / "data" / "lafan1"
STATS = LAFAN1 / "train_stats_official.json"


@pytest.fixture(scope="session")
def lafan1_dir() -> Path:
    if not (LAFAN1.exists() and STATS.exists() and any(LAFAN1.glob("*_subject5.bvh"))):
        pytest.skip(f"LaFAN1 data not found at {LAFAN1} (../shared/data/lafan1 beside the repository); "
                    "tests on the real benchmark need it")
    return LAFAN1


@pytest.fixture(scope="session")
def skeleton():
    return builtin_skeleton()


@pytest.fixture(scope="session")
def tiny(skeleton):
    """A tiny model whose heads are random and non-zero (so its output is not SLERP)."""
    return make_tiny_model(skeleton)


def synthetic_motion(frames: int, joints: int, seed: int):
    """Smooth, seeded motion: root walking and turning, joints swinging (float32 like a pack)."""
    case = Case("synthetic", 10, frames - 11, (0.0, 0.0), 0.0, 90.0, 2.0, seed)
    root, local = synthetic_request(case, joints)
    return root.astype(np.float32), local.astype(np.float32)


@pytest.fixture(scope="session")
def synthetic_pack_path(tmp_path_factory, skeleton) -> Path:
    """Two 700-frame files: enough for 50-frame training windows and 65-frame validation tails."""
    roots, quats = [], []
    for seed in (11, 12):
        r, q = synthetic_motion(700, skeleton.joint_count, seed)
        roots.append(r)
        quats.append(q)
    pack = MotionPack(skeleton, ["a_subject1.bvh", "b_subject2.bvh"], np.array([0, 700, 1400]),
                      np.concatenate(roots), np.concatenate(quats), 1 / 30)
    path = tmp_path_factory.mktemp("pack") / "synthetic.npz"
    save_pack(pack, str(path))
    return path


@pytest.fixture
def failing_rename(monkeypatch):
    """Every safe_output rename fails after the temporary file was written in full: what an interrupted
    or failing write leaves behind. Records the temporary files it saw."""
    seen = []

    def fail(temporary, target):
        assert Path(temporary).exists() and Path(temporary).parent == Path(target).parent
        seen.append(Path(temporary))
        raise OSError(28, "No space left on device (simulated)", str(target))

    monkeypatch.setattr(safe_output, "_rename", fail)
    return seen


@pytest.fixture(scope="module")
def tiny_checkpoint(tmp_path_factory, tiny) -> Path:
    path = tmp_path_factory.mktemp("ckpt") / "tiny.pt"
    save_checkpoint_file(checkpoint_state(tiny), path)
    return path
