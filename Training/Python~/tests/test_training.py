"""Training: the loss falls, a resumed run equals an uninterrupted one, DDP runs on two processes."""
from __future__ import annotations

import csv
import os
import socket
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import torch

from deltainterp.checkpoint import read_checkpoint
from deltainterp.data import load_pack, split_windows
from deltainterp.model import DeltaInterpolator, ModelConfig, preset
from deltainterp.objective import loss, make_batch
from deltainterp.sampler import TransitionSampler
from deltainterp.train import TrainConfig, WindowSource, skeleton_tensors, train

TRAINING = Path(__file__).resolve().parents[1]


def config(pack: Path, out: Path, steps: int, **kw) -> TrainConfig:
    base = dict(data=str(pack), out=str(out), preset="tiny", batch_size=8, steps=steps, peak_lr=3e-3,
                warmup_steps=5, decay_at=1.0, checkpoint_every=1000, validate_every=1000, threads=1,
                model_overrides={"dropout": 0.1})  # dropout: the torch RNG state must resume too
    base.update(kw)
    return TrainConfig(**base)


def fixed_batch_loss(pack_path: Path, model: DeltaInterpolator) -> float:
    pack = load_pack(str(pack_path))
    train_starts, _ = split_windows(pack)
    skel = skeleton_tensors(pack, 0.01, "cpu")
    source = WindowSource(pack, train_starts, 50, TransitionSampler(), False, False, "cpu")
    rng = np.random.default_rng(123)
    total = 0.0
    model.eval()
    with torch.no_grad():
        for _ in range(4):
            layout, roots, quats = source.draw(rng, 16)
            batch = make_batch(roots, quats, layout, skel, "slerp", "last_pose")
            total += float(loss(model, batch, skel)["total"])
    return total / 4


def test_loss_falls(synthetic_pack_path, tmp_path):
    cfg = config(synthetic_pack_path, tmp_path / "run", steps=60)
    torch.manual_seed(cfg.seed)
    initial = DeltaInterpolator(preset("tiny", joints=22, dropout=0.1))
    before = fixed_batch_loss(synthetic_pack_path, initial)
    state = read_checkpoint(train(cfg, progress=False))
    trained = DeltaInterpolator(ModelConfig(**state["model_config"]))
    trained.load_state_dict(state["model"])
    after = fixed_batch_loss(synthetic_pack_path, trained)
    assert state["step"] == 60
    # deterministic (seeded data, one thread, eval-mode loss on fixed batches): measured 3.45 → 3.16;
    # the synthetic motion swings faster than any 39-frame interpolation can follow, hence the modest drop
    assert after < 0.95 * before, f"loss did not fall: {before:.4f} → {after:.4f}"
    assert (tmp_path / "run" / "validation.jsonl").exists()
    rows = list(csv.reader(open(tmp_path / "run" / "log.csv")))
    assert len(rows) == 3 and all(len(r) == len(rows[0]) for r in rows), "log.csv rows must match its header"


def test_resume_equals_uninterrupted_run(synthetic_pack_path, tmp_path):
    straight = read_checkpoint(train(config(synthetic_pack_path, tmp_path / "a", steps=12), progress=False))
    train(config(synthetic_pack_path, tmp_path / "b", steps=5), progress=False)
    resumed = read_checkpoint(train(config(synthetic_pack_path, tmp_path / "b", steps=12), progress=False))
    assert resumed["step"] == straight["step"] == 12
    for name, w in straight["model"].items():
        assert torch.equal(w, resumed["model"][name]), f"{name} differs after resume"
    assert straight["rng"] == resumed["rng"]


def test_weight_averaging_keeps_the_mean_of_the_late_steps_and_resumes_exactly(synthetic_pack_path, tmp_path):
    # Three runs of the same seed: 6 steps live, 9 steps averaging after step 6, and the latter stopped at
    # step 7 and resumed. The averaged checkpoint's "model" is the mean of steps 7-9's live weights.
    live = {}
    for steps in (7, 8, 9):
        live[steps] = read_checkpoint(train(config(synthetic_pack_path, tmp_path / f"live{steps}", steps=steps),
                                            progress=False))["model"]
    straight = read_checkpoint(train(config(synthetic_pack_path, tmp_path / "avg", steps=9, average_from=6),
                                     progress=False))
    train(config(synthetic_pack_path, tmp_path / "part", steps=7, average_from=6), progress=False)
    resumed = read_checkpoint(train(config(synthetic_pack_path, tmp_path / "part", steps=9, average_from=6),
                                    progress=False))
    assert straight["averaged_count"] == resumed["averaged_count"] == 3
    for name, w in straight["model"].items():
        if not w.is_floating_point():
            continue
        mean = (live[7][name] + live[8][name] + live[9][name]) / 3
        assert torch.allclose(w, mean, atol=1e-6), f"{name} is not the mean of steps 7-9"
        assert torch.equal(straight["live_model"][name], live[9][name]), f"{name}: live weights changed"
        assert torch.equal(w, resumed["model"][name]), f"{name} differs after resume"
    assert any(not torch.equal(w, live[9][name]) for name, w in straight["model"].items()), \
        "the averaged weights equal the last step's: nothing was averaged"


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_two_process_gloo_ddp(synthetic_pack_path, tmp_path):
    """Two ranks started the way torchrun starts them (RANK/WORLD_SIZE/MASTER_* in the environment).
    (Debian's torch 1.13 `torch.distributed.run` fails on Python 3.12 before launching anything.)"""
    out = tmp_path / "ddp"
    port = _free_port()
    cmd = [sys.executable, "-m", "deltainterp", "train", "--data", str(synthetic_pack_path), "--out", str(out),
           "--preset", "tiny", "--steps", "4", "--batch-size", "4", "--warmup", "2", "--threads", "1",
           "--validate-every", "1000", "--checkpoint-every", "2"]
    procs = []
    for rank in range(2):
        env = {**os.environ, "PYTHONPATH": str(TRAINING), "OMP_NUM_THREADS": "1", "WORLD_SIZE": "2",
               "RANK": str(rank), "LOCAL_RANK": str(rank), "MASTER_ADDR": "127.0.0.1", "MASTER_PORT": str(port),
               "CUDA_VISIBLE_DEVICES": ""}
        procs.append(subprocess.Popen(cmd, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True))
    logs = []
    for p in procs:
        try:
            logs.append(p.communicate(timeout=240)[0])
        except subprocess.TimeoutExpired:
            for q in procs:
                q.kill()
            raise
    assert [p.returncode for p in procs] == [0, 0], "\n".join(log[-3000:] for log in logs)
    state = read_checkpoint(out / "checkpoint.pt")
    assert state["step"] == 4
    assert len(state["rng"]) == 2 and state["rng"][0] != state["rng"][1]  # one data stream per rank


def test_long_gaps_draw_whole_windows_inside_each_files_training_part(synthetic_pack_path):
    """--max-gap beyond 39: a 10 + n + 1 frame layout comes from windows of its own length that never
    cross into the validation tail or the next file; short layouts keep the 50-frame windows."""
    from deltainterp.data import training_ranges
    pack = load_pack(str(synthetic_pack_path))
    train_starts, _ = split_windows(pack)
    ranges = training_ranges(pack)
    source = WindowSource(pack, train_starts, 50, TransitionSampler(min_gap=100, max_gap=119), False, False,
                          "cpu", ranges=ranges)
    assert source.starts_for(41)[0] is train_starts
    for length in (111, 130):
        starts, window = source.starts_for(length)
        assert window == length and len(starts) > 0
        assert all(any(a <= s and s + length <= b for a, b in ranges) for s in starts)
    layout, roots, quats = source.draw(np.random.default_rng(0), 4)
    assert 100 <= layout.gap <= 119 and roots.shape[1] == layout.length
    with pytest.raises(ValueError, match="no training window of 700 frames"):
        source.starts_for(700)


def test_max_gap_trains_validates_and_exports_its_range(skeleton, tmp_path):
    from conftest import synthetic_motion
    from deltainterp.checkpoint import load_checkpoint
    from deltainterp.data import MotionPack, save_pack
    from deltainterp.export import export_model
    import json, onnx
    # 1000-frame files: 100-frame tails hold a 71-frame window for the gap of 60
    motion = [synthetic_motion(1000, skeleton.joint_count, seed) for seed in (21, 22)]
    pack = MotionPack(skeleton, ["a_subject1.bvh", "b_subject2.bvh"], np.array([0, 1000, 2000]),
                      np.concatenate([r for r, _ in motion]), np.concatenate([q for _, q in motion]), 1 / 30)
    save_pack(pack, str(tmp_path / "long.npz"))
    path = train(config(tmp_path / "long.npz", tmp_path / "run", steps=6, max_gap=70, validate_every=6), progress=False)
    record = json.loads((tmp_path / "run" / "validation.jsonl").read_text().splitlines()[-1])
    assert "model_l2q_60" in record and "slerp_l2p_60" in record  # the long gap is validated on its own windows
    report = export_model(load_checkpoint(str(path)), str(tmp_path / "m.onnx"), "long")
    meta = {p.key: p.value for p in onnx.load(report.paths["whole"]).metadata_props}
    contract = json.loads(next(v for v in meta.values() if '"missing_frames"' in v))
    assert contract["training"]["missing_frames"] == [5, 70]


def test_max_gap_beyond_the_frame_embedding_is_refused(synthetic_pack_path, tmp_path):
    with pytest.raises(ValueError, match="expected --max-gap ≤ 245"):
        train(config(synthetic_pack_path, tmp_path / "run", steps=1, preset="runtime", max_gap=246), progress=False)


def test_chained_batches_take_their_past_frames_from_the_network(synthetic_pack_path, tiny):
    """--chained-share: the trained transition's past frames before the key are the network's fill of the
    gap before it; the key and the target stay the ground truth."""
    from deltainterp.data import training_ranges
    pack = load_pack(str(synthetic_pack_path))
    train_starts, _ = split_windows(pack)
    skel = skeleton_tensors(pack, 0.01, "cpu")
    sampler = TransitionSampler(min_past=5, past=10, min_gap=8, max_gap=8)
    chained = WindowSource(pack, train_starts, 50, sampler, False, False, "cpu", ranges=training_ranges(pack))
    plain = WindowSource(pack, train_starts, 50, sampler, False, False, "cpu", ranges=training_ranges(pack))
    layout, roots, quats = chained.draw_chained(np.random.default_rng(3), 4, tiny.model, skel)
    rng = np.random.default_rng(3)
    sampler.sample(rng)  # the same layout draw, then the same windows, untouched
    truth_roots, truth_quats = plain.windows(rng, 4, 10 + 8 + 1 + 8 + 1)
    start = 10 + 8 - layout.past + 1
    assert roots.shape[1] == layout.length and layout.gap == 8
    key = layout.past - 1
    assert torch.equal(roots[:, key], truth_roots[:, start + key]) and torch.equal(quats[:, -1], truth_quats[:, -1])
    assert not torch.allclose(roots[:, :key], truth_roots[:, start:start + key])  # filled, not the truth
    assert torch.equal(roots[:, key + 1:], truth_roots[:, start + key + 1:])  # the trained gap and target: truth
