"""Training loop: Adam, warm-up then step schedule, checkpoints with exact resume, CSV log and plots,
CPU / GPU / torchrun (DistributedDataParallel, gloo or nccl)."""
from __future__ import annotations

import copy
import csv
import io
import json
import math
import os
import random
import sys
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Tuple

import numpy as np
import torch

from . import quaternions, safe_output
from .benchmark import l2q as benchmark_l2q
from .checkpoint import CheckpointError, load_checkpoint, read_checkpoint, save_checkpoint_file
from .data import MotionPack, load_pack, split_windows, training_ranges, windows
from .kinematics import forward_kinematics
from .model import DeltaInterpolator, ModelConfig, preset
from .localize import unlocalize
from .objective import (SkeletonTensors, foot_joint_indices, foot_skating, leg_length, loss, make_batch, predict,
                        span_feet)
from .plots import plot_training
from .progress import Progress
from .sampler import TransitionSampler
from .warm_start import load_onnx_weights


@dataclass
class TrainConfig:
    data: str = "Training/.data/lafan1-train.npz"
    out: str = "Training/runs/runtime"
    preset: str = "runtime"
    model_overrides: Dict = field(default_factory=dict)
    batch_size: int = 64
    steps: int = 20000
    peak_lr: float = 4e-4
    warmup_steps: int = 500
    decay_at: float = 0.8       # fraction of steps after which the lr drops ×0.1
    reconstruction_scale: float = 1.0
    seed: int = 0
    unit_scale: float = 0.01
    mirror: bool = False
    random_yaw: bool = False
    checkpoint_every: int = 500
    validate_every: int = 500
    max_minutes: float = 0.0    # 0 = no wall-clock limit; otherwise stop (with a checkpoint) after it
    threads: int = 0            # 0 = leave torch's default
    min_past: int = 10          # past keys P drawn on [min_past, 10] (sampler.past_probabilities)
    longest_past_share: float = 0.4
    uniform_past: bool = False  # p(P) uniform on [min_past, 10] instead of weighted to P = 10 and P = 1
    min_gap: int = 5            # missing frames n drawn on [min_gap, max_gap] with p(n) ∝ 1/n (the paper: 5..39)
    max_gap: int = 39           # longer gaps need longer windows: see WindowSource
    chained_share: float = 0.0  # share of batches whose past frames are the network's own output (draw_chained)
    init_from: str = ""         # start from these weights (an exported .onnx or a checkpoint.pt), not random
    average_from: int = 0       # 0 = off; else the run's weights are the mean of every step's after this one
    foot_contact_weight: float = 0.0  # 0 = off; else × the planted-foot speed loss (objective.loss)


def warmup_steps(cfg: TrainConfig) -> int:
    """The warm-up the run uses: --warmup, or a tenth of the run when --warmup is longer than --steps
    (a short trial run with the default 500 would otherwise never reach its learning rate)."""
    return cfg.warmup_steps if cfg.warmup_steps <= cfg.steps else max(1, cfg.steps // 10)


def learning_rate(cfg: TrainConfig, step: int) -> float:
    warmup = warmup_steps(cfg)
    if step < warmup:
        return 1e-6 + (cfg.peak_lr - 1e-6) * step / warmup
    return cfg.peak_lr * (0.1 if step >= cfg.decay_at * cfg.steps else 1.0)


def skeleton_tensors(pack: MotionPack, unit_scale: float, device) -> SkeletonTensors:
    names = list(pack.skeleton.names)
    return SkeletonTensors(list(pack.skeleton.parents),
                           torch.tensor(pack.skeleton.offsets * unit_scale, dtype=torch.float32, device=device),
                           unit_scale, foot_joints=foot_joint_indices(names),
                           leg_length=leg_length(names, pack.skeleton.offsets) * unit_scale,
                           frame_time=float(pack.frame_time))


class WindowSource:
    """Draws transition batches from training windows: one key layout per batch (one gap n), a random
    start inside each 50-frame window, optional mirror and random-yaw augmentation.

    A layout longer than the 50-frame windows (a gap beyond 39 frames with 10 past keys) is drawn from
    windows of its own length, every `long_offset` frames of each file's training part (`ranges`): cutting
    every window to the longest layout instead would drop the short files (half the CMU files are under
    160 frames) from the short gaps too."""

    def __init__(self, pack: MotionPack, starts: np.ndarray, window: int, sampler: TransitionSampler,
                 mirror: bool, random_yaw: bool, device, ranges: Optional[List[tuple]] = None,
                 long_offset: int = 5) -> None:
        self.roots = torch.from_numpy(pack.root_positions).to(device)
        self.quats = torch.from_numpy(pack.local_quaternions).to(device)
        self.starts, self.window, self.sampler = starts, window, sampler
        self.mirror, self.random_yaw = mirror, random_yaw
        self.mirror_map = pack.skeleton.mirror_map()
        self.device = device
        self.ranges = ranges or []
        self.long_offset = long_offset
        self._long_starts: Dict[int, np.ndarray] = {}

    def starts_for(self, length: int):
        """(window starts, window length) for a layout of `length` frames."""
        if length <= self.window:
            return self.starts, self.window
        if length not in self._long_starts:
            self._long_starts[length] = np.asarray(
                [a + s for a, b in self.ranges for s in windows(b - a, length, self.long_offset)], dtype=np.int64)
        starts = self._long_starts[length]
        if len(starts) == 0:
            raise ValueError(f"no training window of {length} frames (a gap of {length - 11} frames after 10 "
                             "past keys) in the first 90 % of any file; expected a smaller --max-gap")
        return starts, length

    def draw(self, rng: np.random.Generator, batch_size: int):
        layout = self.sampler.sample(rng)
        roots, quats = self.windows(rng, batch_size, layout.length)
        return layout, roots, quats

    def draw_chained(self, rng: np.random.Generator, batch_size: int, model, skeleton: SkeletonTensors):
        """A batch whose past frames are the network's own output, as in a bake: a window holds 10 ground-truth
        frames, a gap of n, key k0, a gap of n and the target; the network fills the first gap (no gradient),
        and the trained transition is the second gap with its last P past frames ending at k0 — filled frames
        and the key, as `inbetween bake` feeds them (keys every n + 1 frames)."""
        layout = self.sampler.sample(rng)
        n, p = layout.gap, layout.past
        first = self.sampler.layout(n, past=10)
        roots, quats = self.windows(rng, batch_size, first.length + n + 1)
        cfg = getattr(model, "module", model).config
        was_training = model.training
        model.eval()
        with torch.no_grad():
            b = make_batch(roots[:, :first.length], quats[:, :first.length], first, skeleton,
                           cfg.output_delta_mode, cfg.input_delta_mode)
            fill_root, fill_rot, _, _ = predict(model, b, with_keys=False)
            fill_root, fill_rot = unlocalize(fill_root, fill_rot, b.localization, skeleton.unit_scale)
        if was_training:
            model.train()
        roots, quats = roots.clone(), quats.clone()
        roots[:, 10:10 + n] = fill_root.to(roots.dtype)
        quats[:, 10:10 + n] = fill_rot.to(quats.dtype)
        start = 10 + n - p + 1
        return layout, roots[:, start:].contiguous(), quats[:, start:].contiguous()

    def windows(self, rng: np.random.Generator, batch_size: int, length: int):
        """`batch_size` windows of `length` frames (augmented), float32."""
        starts, window = self.starts_for(length)
        picks = starts[rng.integers(0, len(starts), batch_size)]
        shift = rng.integers(0, window - length + 1, batch_size)
        idx = torch.from_numpy(picks + shift)[:, None] + torch.arange(length)[None]
        idx = idx.to(self.device)
        roots, quats = self.roots[idx].double(), self.quats[idx].double()
        if self.mirror:
            flip = torch.from_numpy(rng.random(batch_size) < 0.5).to(self.device)
            m_roots = roots * roots.new_tensor([1.0, 1.0, -1.0])
            m_quats = quats[:, :, self.mirror_map] * quats.new_tensor([1.0, -1.0, -1.0, 1.0])
            roots = torch.where(flip[:, None, None], m_roots, roots)
            quats = torch.where(flip[:, None, None, None], m_quats, quats)
        if self.random_yaw:
            angle = torch.from_numpy(rng.uniform(-math.pi, math.pi, batch_size)).to(self.device)
            yaw = quaternions.axis_angle("y", angle)
            roots = quaternions.apply(yaw[:, None].expand(-1, length, -1), roots)
            quats = quats.clone()
            quats[:, :, 0] = quaternions.multiply(yaw[:, None].expand(-1, length, -1), quats[:, :, 0])
        return roots.float(), quats.float()


def validation_metrics(model: DeltaInterpolator, pack: MotionPack, val_starts: np.ndarray,
                       skeleton: SkeletonTensors, gaps=(5, 15, 30), past: int = 10) -> Dict[str, float]:
    """L2Q and L2P at each gap on the held-out tails of the training files, model and SLERP side by side.
    L2Q is the benchmark's (after hemisphere alignment to the GT); L2P divides by the per-coordinate std of
    the validation GT instead of the official statistics, so it needs no statistics file. With past < 10
    the network sees only the last `past` of the 10 context frames (same target frame, as the benchmark's
    --past-frames). With the skeleton's feet known, also `{model,slerp}_skate_{n}`: the mean horizontal
    speed (leg lengths per second) of the foot joints on the missing frames where the truth's are planted
    (the C# FootSkating contact rule, ground = the span's lowest foot-joint height)."""
    model.eval()
    sampler = TransitionSampler(past=past)
    roots = torch.from_numpy(pack.root_positions)
    quats = torch.from_numpy(pack.local_quaternions)
    out = {}
    with torch.no_grad():
        for n in gaps:
            layout = sampler.layout(n)
            idx = torch.from_numpy(val_starts + (10 - past))[:, None] + torch.arange(layout.length)[None]
            batch = make_batch(roots[idx], quats[idx], layout, skeleton, model.config.output_delta_mode,
                               model.config.input_delta_mode)
            q_idx = torch.tensor(layout.query_frames)
            gq, gp = forward_kinematics(batch.rotations[:, q_idx], batch.positions[:, q_idx], skeleton.offsets,
                                        skeleton.parents)
            std = gp.reshape(-1, gp.shape[-2] * 3).std(0).clamp_min(1e-6)
            root, rot, _, _ = predict(model, batch, with_keys=False)
            feet = list(skeleton.foot_joints) if skeleton.leg_length > 0 else []
            if feet:
                r, target = layout.past - 1, layout.past + layout.gap
                _, kp = forward_kinematics(batch.rotations[:, [r, target]], batch.positions[:, [r, target]],
                                           skeleton.offsets, skeleton.parents)
            for name, (r, q) in {"model": (root, rot), "slerp": (batch.base_root, batch.base_rotations)}.items():
                if name == "slerp" and model.config.output_delta_mode != "slerp":
                    continue
                pq, pp = forward_kinematics(q, r, skeleton.offsets, skeleton.parents)
                pq = quaternions.align_hemisphere(pq, gq)
                l2q = benchmark_l2q(pq, gq)
                l2p = ((pp - gp).reshape(*pp.shape[:2], -1) / std).norm(dim=-1).mean().item()
                out[f"{name}_l2q_{n}"] = l2q
                out[f"{name}_l2p_{n}"] = l2p
                if feet:
                    pf, gf = span_feet(pp, gp, kp[:, 0], kp[:, 1], feet)
                    total, count = foot_skating(pf, gf, skeleton.leg_length, skeleton.frame_time)
                    if count > 0:
                        out[f"{name}_skate_{n}"] = (total / count).item() / skeleton.leg_length
    model.train()
    return out


VALIDATION_SHORT_PASTS = (1, 5)   # besides P = 10, when training over several past lengths
VALIDATION_LONG_GAPS = (60,)      # besides 5, 15, 30, when --max-gap reaches them (a key every 2 s at 30 fps)
LOG_EVERY = 50                    # steps per log.csv row, and per progress line off a terminal


def initial_weights(path: str, config: ModelConfig) -> Dict[str, torch.Tensor]:
    """A warm start: the weights of an exported whole graph (.onnx) or of a checkpoint (.pt)."""
    if str(path).endswith(".onnx"):
        return load_onnx_weights(path, config)
    loaded = load_checkpoint(path)
    if loaded.config.to_dict() != config.to_dict():
        raise ValueError(f"{path}: architecture {loaded.config.to_dict()}; expected {config.to_dict()}")
    return loaded.model.state_dict()


# Settings a resumed run must share with the run it continues (else it is another experiment): option names
# as the CLI spells them. Not compared: where files are (--data, --out, --init-from), --threads, how often
# it logs, validates and checkpoints, --max-minutes, and --steps (allowed with a warning: a run may be
# extended or shortened to fit the time left). The architecture is compared on the built model_config.
RESUME_SETTINGS = {"batch_size": "--batch-size", "peak_lr": "--lr", "warmup_steps": "--warmup",
                   "decay_at": "--decay-at", "reconstruction_scale": "--reconstruction-scale", "seed": "--seed",
                   "unit_scale": "unit_scale", "mirror": "--mirror", "random_yaw": "--random-yaw",
                   "min_past": "--min-past", "longest_past_share": "--longest-past-share",
                   "uniform_past": "--uniform-past", "min_gap": "--min-gap", "max_gap": "--max-gap",
                   "chained_share": "--chained-share", "average_from": "--average-from",
                   "foot_contact_weight": "--foot-contact-weight"}


def run_checkpoint(out: Path) -> Optional[Path]:
    """OUT/checkpoint.pt when OUT is a run folder to resume, None for a new run (OUT missing or empty).
    Refuses (ValueError, `OUT: what; expected`) a regular file, or a folder that holds files but no
    checkpoint: never append our logs to someone else's files."""
    expected = "expected a new or empty folder, or a run folder written by `train`"
    if out.exists() and not out.is_dir():
        raise ValueError(f"{out}: is a file, not a folder; {expected}")
    ckpt = out / "checkpoint.pt"
    if not out.is_dir():
        return None
    if os.path.lexists(ckpt):
        return ckpt
    found = sorted(p.name for p in out.iterdir())
    if found:
        shown = ", ".join(found[:4]) + (f" and {len(found) - 4} more" if len(found) > 4 else "")
        raise ValueError(f"{out}: holds {shown} but no checkpoint.pt; {expected} (choose another --out)")
    return None


def resume_differences(saved: Dict, cfg: TrainConfig) -> List[str]:
    """`--lr 0.001 but the run used 0.0003` for every setting that must match (RESUME_SETTINGS)."""
    now = asdict(cfg)
    return [f"{option} {now[key]} but the run used {saved[key]}" for key, option in RESUME_SETTINGS.items()
            if key in saved and saved[key] != now[key]]


def architecture_differences(saved: Dict, config: ModelConfig) -> List[str]:
    now = config.to_dict()
    return [f"{key} {now.get(key)} but the run used {saved.get(key)}" for key in sorted(set(saved) | set(now))
            if saved.get(key) != now.get(key)]


def _record_step(line: str, csv_row: bool) -> Optional[int]:
    try:
        return int(line.split(",", 1)[0]) if csv_row else int(json.loads(line)["step"])
    except (ValueError, KeyError, TypeError):
        return None


def trim_run_logs(out: Path, step: int) -> int:
    """On resume: drop the log.csv rows and validation.jsonl records of steps after the checkpoint (a run
    stopped between a log and its next checkpoint redoes those steps; without this they would appear twice).
    Returns how many were dropped. Lines that are not records (the header) stay."""
    dropped = 0
    for name, csv_row in (("log.csv", True), ("validation.jsonl", False)):
        path = out / name
        if not path.is_file():
            continue
        lines = path.read_text().splitlines(keepends=True)
        kept = [line for line in lines if (_record_step(line, csv_row) or 0) <= step]
        if len(kept) != len(lines):
            dropped += len(lines) - len(kept)
            safe_output.write_text(path, "".join(kept))
    return dropped


def _distributed() -> bool:
    return int(os.environ.get("WORLD_SIZE", "1")) > 1


def average_weights(averaged: Optional[DeltaInterpolator], count: int,
                    model: DeltaInterpolator) -> Tuple[DeltaInterpolator, int]:
    """One more step into the running mean of the weights (stochastic weight averaging, Izmailov et al.
    2018): the mean of the late steps' weights lies in a flatter part of the loss than any one of them and
    usually generalizes a little better. Buffers are copied, floating parameters averaged."""
    if averaged is None:
        averaged = copy.deepcopy(model)
        averaged.eval()
        return averaged, 1
    count += 1
    with torch.no_grad():
        live = model.state_dict()
        for name, value in averaged.state_dict().items():
            if value.is_floating_point():
                value.add_(live[name] - value, alpha=1.0 / count)
            else:
                value.copy_(live[name])
    return averaged, count


@dataclass
class TrainingRun:
    """What the stages of `train` share: where the run is, its data, its model and optimizer, and the
    state an exact resume restores (step, RNG, running average, last validation)."""
    cfg: TrainConfig
    progress: bool
    rank: int
    world: int
    device: torch.device
    out: Path
    ckpt_path: Path
    pack: Optional[MotionPack] = None
    train_starts: Optional[np.ndarray] = None
    val_starts: Optional[np.ndarray] = None
    skeleton: Optional[SkeletonTensors] = None
    model_cfg: Optional[ModelConfig] = None
    model: Optional[DeltaInterpolator] = None
    net: Optional[torch.nn.Module] = None  # the model, wrapped in DistributedDataParallel when world > 1
    optimizer: Optional[torch.optim.Optimizer] = None
    rng: Optional[np.random.Generator] = None
    step: int = 0
    averaged: Optional[DeltaInterpolator] = None  # the running mean of the weights after --average-from
    averaged_count: int = 0
    last_val: Dict[str, float] = field(default_factory=dict)
    bar: object = None
    started: float = 0.0

    @property
    def speaks(self) -> bool:
        """Whether this process prints: rank 0, with progress on."""
        return self.rank == 0 and self.progress


def start_processes(cfg: TrainConfig) -> Tuple[int, int, torch.device]:
    """(rank, world size, device): joins the torchrun process group when there is one."""
    rank, world = 0, 1
    if _distributed():
        import torch.distributed as dist
        backend = "nccl" if torch.cuda.is_available() else "gloo"
        dist.init_process_group(backend)
        rank, world = dist.get_rank(), dist.get_world_size()
    device = torch.device(f"cuda:{int(os.environ.get('LOCAL_RANK', 0))}" if torch.cuda.is_available() else "cpu")
    if cfg.threads:
        torch.set_num_threads(cfg.threads)
    return rank, world, device


def open_run(run: TrainingRun) -> Optional[Dict]:
    """The checkpoint to resume from (None for a new run), refused before any work when it was written
    with other settings; creates the run folder."""
    cfg, ckpt_path = run.cfg, run.ckpt_path
    existing = run_checkpoint(run.out)  # before any work: refuses a file, or a folder of other files
    state = read_checkpoint(existing) if existing else None
    if state is not None:
        for key in ("model", "optimizer", "step", "rng", "torch_rng", "python_rng", "model_config"):
            if key not in state:
                raise CheckpointError(ckpt_path, f"lacks {key!r}", "expected a checkpoint `train` wrote (to resume)")
        saved_cfg = dict(state.get("train_config") or {})
        different = resume_differences(saved_cfg, cfg)
        if different:
            raise CheckpointError(ckpt_path, "resuming with " + ", ".join(different),
                                  "expected the same settings (or a new --out)")
        if int(state["step"]) > cfg.steps:
            raise CheckpointError(ckpt_path, f"the run is already at step {int(state['step'])}, past --steps "
                                  f"{cfg.steps}", f"expected --steps ≥ {int(state['step'])} (or a new --out)")
        if run.speaks and "steps" in saved_cfg and saved_cfg["steps"] != cfg.steps:
            print(f"warning: {ckpt_path}: --steps {cfg.steps} but the run used {saved_cfg['steps']}: training on to "
                  f"step {cfg.steps}, the lr drop moves from step {int(cfg.decay_at * saved_cfg['steps'])} to "
                  f"{int(cfg.decay_at * cfg.steps)}")
            before = warmup_steps(TrainConfig(**{**asdict(cfg), "steps": int(saved_cfg["steps"])}))
            if before != warmup_steps(cfg):
                print(f"warning: {ckpt_path}: the warm-up changes with --steps, from {before} to {warmup_steps(cfg)} steps")
        if run.speaks and saved_cfg.get("data", cfg.data) != cfg.data:
            print(f"warning: {ckpt_path}: --data {cfg.data} but the run used {saved_cfg['data']}")
    if run.speaks and warmup_steps(cfg) != cfg.warmup_steps:
        print(f"warning: --warmup {cfg.warmup_steps} is longer than --steps {cfg.steps}: warming up over "
              f"{warmup_steps(cfg)} steps (a tenth of the run) instead")
    run.out.mkdir(parents=True, exist_ok=True)
    return state


def load_training_data(run: TrainingRun) -> None:
    """The motion pack, its training and validation windows and the skeleton as tensors."""
    cfg = run.cfg
    run.pack = pack = load_pack(cfg.data)
    run.train_starts, run.val_starts = split_windows(pack)
    if len(run.train_starts) == 0:
        longest = max((int(b - a) for a, b in (pack.file_frames(i) for i in range(len(pack.files)))), default=0)
        raise ValueError(f"{cfg.data}: no 50-frame training window in the first 90 % of any file (the longest has "
                         f"{longest} frames); expected files of at least 57 frames")
    if len(run.val_starts) == 0 and run.speaks:
        # A small pack (e.g. 2 files of 200 frames) has no 65-frame tail to validate on: train anyway.
        print(f"warning: {cfg.data}: no 65-frame validation window in the last 10 % of any file (files of 660 "
              "frames or more have one); training without validation")
    run.skeleton = skeleton_tensors(pack, cfg.unit_scale, run.device)


def build_model(run: TrainingRun, state: Optional[Dict]) -> None:
    """The network (seeded, or warm-started from --init-from on a new run), its optimizer and the data RNG."""
    cfg = run.cfg
    run.model_cfg = model_cfg = preset(cfg.preset, joints=run.pack.skeleton.joint_count, **cfg.model_overrides)
    if state is not None:
        different = architecture_differences(dict(state["model_config"]), model_cfg)
        if different:
            raise CheckpointError(run.ckpt_path, "resuming another architecture: " + ", ".join(different),
                                  "expected the run's --preset and overrides (or a new --out)")
    if 10 + cfg.max_gap + 1 > model_cfg.embedding_size:
        raise ValueError(f"--max-gap {cfg.max_gap}: 10 past keys + {cfg.max_gap} missing frames + the target need "
                         f"frame indices up to {10 + cfg.max_gap}, but the {cfg.preset} network embeds frames "
                         f"0..{model_cfg.embedding_size - 1}; expected --max-gap ≤ {model_cfg.embedding_size - 11}")
    torch.manual_seed(cfg.seed)  # seed BEFORE building the model: the seed decides the initial weights
    run.model = DeltaInterpolator(model_cfg).to(run.device)
    if cfg.init_from and state is None:
        run.model.load_state_dict(initial_weights(cfg.init_from, model_cfg))
        if run.speaks:
            print(f"initial weights from {cfg.init_from}")
    run.optimizer = torch.optim.Adam(run.model.parameters(), lr=learning_rate(cfg, 0))
    run.rng = np.random.default_rng([cfg.seed, run.rank])
    if cfg.average_from < 0:
        raise ValueError(f"--average-from {cfg.average_from}; expected a step ≥ 0 (0: no averaging)")


def restore_state(run: TrainingRun, state: Dict) -> None:
    """An exact resume: weights (live and averaged), optimizer, step, every RNG; drops the log records
    written after the checkpoint's step."""
    ckpt_path, rank = run.ckpt_path, run.rank
    # read_checkpoint loaded it without running code from it (weights-only; RNG states as plain values)
    try:
        # With averaging, "model" holds the average (what export and evaluation read) and
        # "live_model" the weights the optimizer is moving.
        run.model.load_state_dict(state.get("live_model", state["model"]))
        if "live_model" in state:
            run.averaged = copy.deepcopy(run.model)
            run.averaged.load_state_dict(state["model"])
            run.averaged_count = int(state["averaged_count"])
        run.optimizer.load_state_dict(state["optimizer"])
        run.step = step = int(state["step"])
        if rank < len(state["rng"]):
            run.rng.bit_generator.state = state["rng"][rank]
        else:  # more processes than the run had: a new, distinct data stream for this one
            run.rng = np.random.default_rng([run.cfg.seed, rank, step])
        if len(state["rng"]) != run.world and run.speaks:
            print(f"warning: {ckpt_path}: the run had {len(state['rng'])} process(es), now {run.world}: "
                  "the resume is not exact (data streams differ)")
        torch.set_rng_state(state["torch_rng"])
        random.setstate(tuple(tuple(v) if isinstance(v, list) else v for v in state["python_rng"]))
    except (RuntimeError, ValueError, TypeError, KeyError, IndexError) as e:
        detail = " ".join(str(e).split())[:200]
        raise CheckpointError(ckpt_path, f"cannot be resumed ({type(e).__name__}: {detail})",
                              "expected a checkpoint `train` wrote with the same settings")
    dropped = trim_run_logs(run.out, step) if rank == 0 else 0
    if run.speaks:
        print(f"resumed from {ckpt_path} at step {step}")
        if dropped:
            print(f"dropped {dropped} log record(s) written after the checkpoint's step {step} (they are redone)")
        if step >= run.cfg.steps:
            print(f"{ckpt_path}: the run is complete at step {step} (--steps {run.cfg.steps}); nothing to train")


def window_source(run: TrainingRun) -> WindowSource:
    """The batch source for the run's sampler settings, refusing a --max-gap no file can give (and the
    loss options) before training starts."""
    cfg = run.cfg
    sampler = TransitionSampler(min_past=cfg.min_past, longest_past_share=cfg.longest_past_share,
                                uniform_past=cfg.uniform_past, min_gap=cfg.min_gap, max_gap=cfg.max_gap)
    source = WindowSource(run.pack, run.train_starts, 50, sampler, cfg.mirror, cfg.random_yaw, run.device,
                          ranges=training_ranges(run.pack))
    source.starts_for(10 + cfg.max_gap + 1 + (cfg.max_gap + 1 if cfg.chained_share > 0 else 0))
    if not (cfg.foot_contact_weight >= 0 and math.isfinite(cfg.foot_contact_weight)):
        raise ValueError(f"--foot-contact-weight {cfg.foot_contact_weight}; expected a weight ≥ 0 (0: off)")
    if not 0.0 <= cfg.chained_share <= 1.0:
        raise ValueError(f"--chained-share {cfg.chained_share}; expected a share from 0 to 1")
    return source


def log_columns(cfg: TrainConfig) -> Tuple[List[str], List[str]]:
    """(loss terms, log.csv columns): fixed for the run (--foot-contact-weight must match on resume, so the
    header stays right)."""
    losses = ["total", "quat", "pos", "key_quat", "key_pos"] + (["foot"] if cfg.foot_contact_weight > 0 else [])
    return losses, ["step", "lr"] + losses + ["seconds"]


def training_step(run: TrainingRun, source: WindowSource) -> Tuple[Dict[str, float], object, float]:
    """One optimizer step on one drawn batch: (loss terms as floats, the batch's key layout, the lr)."""
    cfg = run.cfg
    lr = learning_rate(cfg, run.step)
    for g in run.optimizer.param_groups:
        g["lr"] = lr
    if cfg.chained_share > 0 and run.rng.random() < cfg.chained_share:
        layout, roots, quats = source.draw_chained(run.rng, cfg.batch_size, run.model, run.skeleton)
    else:
        layout, roots, quats = source.draw(run.rng, cfg.batch_size)
    batch = make_batch(roots, quats, layout, run.skeleton, run.model_cfg.output_delta_mode,
                       run.model_cfg.input_delta_mode)
    terms = loss(run.net, batch, run.skeleton, cfg.reconstruction_scale, foot_contact_weight=cfg.foot_contact_weight)
    run.optimizer.zero_grad(set_to_none=True)
    terms["total"].backward()
    run.optimizer.step()
    run.step += 1
    if cfg.average_from and run.step > cfg.average_from:
        run.averaged, run.averaged_count = average_weights(run.averaged, run.averaged_count, run.model)
    values = {k: float(v) for k, v in terms.items()}
    if not math.isfinite(values["total"]):
        # Every rank sees it by the next step (the NaN gradients are all-reduced), so none hangs.
        if run.bar is not None:
            run.bar.close()  # the error line goes on a line of its own
        raise ValueError(f"{run.ckpt_path}: the training loss became non-finite at step {run.step} "
                         f"({values['total']}); expected finite (lower --lr?). The last "
                         f"checkpoint is kept; log.csv and validation.jsonl hold no NaN")
    return values, layout, lr


def write_log_row(run: TrainingRun, window_losses: List[Dict[str, float]], lr: float) -> None:
    """One log.csv row: the mean of each loss term since the last row."""
    losses, fields = log_columns(run.cfg)
    log_path = run.out / "log.csv"
    row = {k: float(np.mean([w.get(k, 0.0) for w in window_losses])) for k in losses}
    row.update(step=run.step, lr=lr, seconds=round(time.time() - run.started, 1))
    text = io.StringIO(newline="")
    # Fixed columns: validation metrics live in validation.jsonl. (Appending them here gave
    # rows with more cells than the header, which was written before the first validation.)
    w = csv.DictWriter(text, fieldnames=fields)
    if not log_path.exists():
        w.writeheader()
    w.writerow(row)
    safe_output.append_text(log_path, text.getvalue())  # whole file via temp + rename


def validate(run: TrainingRun, long_val: Dict[int, np.ndarray]) -> None:
    """Validation metrics of what the checkpoint exports, appended to validation.jsonl; refuses non-finite."""
    shipped = run.averaged or run.model  # validate what the checkpoint exports
    pack, skeleton = run.pack, run.skeleton
    last_val = validation_metrics(shipped, pack, run.val_starts, skeleton)
    for n, starts in long_val.items():
        if len(starts) > 0:
            last_val.update(validation_metrics(shipped, pack, starts, skeleton, gaps=(n,)))
    for p in VALIDATION_SHORT_PASTS if run.cfg.min_past < 10 else ():
        short = validation_metrics(shipped, pack, run.val_starts, skeleton, past=p)
        last_val.update({f"p{p}_{k}": v for k, v in short.items()})
    run.last_val = last_val
    bad = sorted(k for k, v in last_val.items() if not math.isfinite(v))
    if bad:
        if run.bar is not None:
            run.bar.close()
        raise ValueError(f"{run.ckpt_path}: validation gave non-finite {', '.join(bad[:3])} at step {run.step}; "
                         f"expected finite (a diverged network?). The last checkpoint is kept")
    safe_output.append_text(run.out / "validation.jsonl", json.dumps({"step": run.step, **last_val}) + "\n")
    if run.bar is not None:
        run.bar.write(f"step {run.step}: " + "  ".join(
            f"n={n} L2Q {last_val[f'model_l2q_{n}']:.3f} (slerp {last_val.get(f'slerp_l2q_{n}', float('nan')):.3f})"
            for n in (5, 15, 30) + tuple(n for n in long_val if f"model_l2q_{n}" in last_val)))


def save_run_checkpoint(run: TrainingRun) -> None:
    """Everything an exact resume needs. Under DDP every rank calls this (the RNG states are
    gathered); rank 0 writes atomically."""
    rngs = [run.rng.bit_generator.state]
    if run.world > 1:
        import torch.distributed as dist
        rngs = [None] * run.world
        dist.all_gather_object(rngs, run.rng.bit_generator.state)
    if run.rank != 0:
        return
    state = {"model": (run.averaged or run.model).state_dict(), "optimizer": run.optimizer.state_dict(),
             "step": run.step, "rng": rngs, "torch_rng": torch.get_rng_state(), "python_rng": random.getstate(),
             "model_config": run.model_cfg.to_dict(), "train_config": asdict(run.cfg),
             "skeleton": run.pack.skeleton.to_json(), "unit_scale": run.cfg.unit_scale, "validation": run.last_val}
    if run.averaged is not None:
        state.update(live_model=run.model.state_dict(), averaged_count=run.averaged_count)
    save_checkpoint_file(state, run.ckpt_path)  # format 2 (loads weights-only), temporary file + rename


def time_is_up(run: TrainingRun) -> bool:
    """--max-minutes reached; under DDP rank 0 decides, so every rank stops at the same step."""
    up = run.cfg.max_minutes > 0 and (time.time() - run.started) > run.cfg.max_minutes * 60
    if run.world > 1:
        import torch.distributed as dist
        flag = torch.tensor([1.0 if up else 0.0])
        dist.broadcast(flag, 0)
        up = bool(flag.item())
    return up


def run_steps(run: TrainingRun, source: WindowSource) -> None:
    """The training loop: steps, log rows every 50 steps, validation and checkpoints on their schedules,
    until --steps or --max-minutes."""
    cfg = run.cfg
    # Long gaps are validated on windows of their own length (fewer files have such tails).
    long_gaps = tuple(n for n in VALIDATION_LONG_GAPS if n <= cfg.max_gap)
    long_val = {n: split_windows(run.pack, validation_length=10 + n + 1)[1] for n in long_gaps}
    # A terminal gets a progress bar; a log file (nohup, CI) one line per log interval (deltainterp.progress,
    # as prepare and evaluate): the loss shown is the mean since the last log row.
    if run.speaks:
        run.bar = Progress(cfg.steps, f"train {cfg.preset}", "step", every=LOG_EVERY, initial=run.step)
    run.started = time.time()
    window_losses: List[Dict[str, float]] = []
    run.model.train()
    while run.step < cfg.steps:
        values, layout, lr = training_step(run, source)
        window_losses.append(values)
        step = run.step
        if run.rank == 0 and run.bar is not None:
            mean = sum(w["total"] for w in window_losses) / len(window_losses)
            run.bar.update(1, loss=f"{mean:.4f}", lr=f"{lr:.1e}")
        if run.rank == 0 and (step % LOG_EVERY == 0 or step == cfg.steps):
            write_log_row(run, window_losses, lr)
            window_losses.clear()
        if run.rank == 0 and len(run.val_starts) > 0 and (step % cfg.validate_every == 0 or step == cfg.steps):
            validate(run, long_val)
        out_of_time = time_is_up(run)
        if step % cfg.checkpoint_every == 0 or step == cfg.steps or out_of_time:
            save_run_checkpoint(run)
        if out_of_time:
            if run.rank == 0:
                print(f"stopping at step {step}: --max-minutes {cfg.max_minutes} reached (resume to continue)")
            break
    if run.bar is not None:
        run.bar.close()


def finish(run: TrainingRun) -> None:
    """Plots (rank 0), then the processes meet and leave the process group."""
    if run.rank == 0:
        try:
            plot_training(run.out)
        except Exception as e:  # plots are a convenience; never lose a run over them
            print(f"(plots skipped: {e})")
    if run.world > 1:
        # Meet before tearing down: a rank that destroys its process group (and its DDP reducer) while
        # the other is still busy (rank 0 draws the plots) hung at exit in about one run in three here.
        import torch.distributed as dist
        dist.barrier()
        run.net = None
        dist.destroy_process_group()


def train(cfg: TrainConfig, progress: bool = True) -> Path:
    """A training run in named stages; returns the checkpoint's path. Resumes OUT/checkpoint.pt exactly."""
    rank, world, device = start_processes(cfg)
    out = Path(cfg.out)
    run = TrainingRun(cfg, progress, rank, world, device, out, out / "checkpoint.pt")
    state = open_run(run)
    load_training_data(run)
    build_model(run, state)
    if state is not None:
        restore_state(run, state)
        del state
    run.net = run.model
    if world > 1:
        from torch.nn.parallel import DistributedDataParallel
        run.net = DistributedDataParallel(run.model, device_ids=[device.index] if device.type == "cuda" else None)
    source = window_source(run)
    run_steps(run, source)
    finish(run)
    return run.ckpt_path
