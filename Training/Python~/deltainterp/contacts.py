"""Foot contacts the network predicts (contract version 3's `foot_contacts`): labels, a contact head trained on a
frozen trunk, and precision / recall of planted frames in bakes.

Labels are the skating measure's rule with a ground level per foot joint (C# `FootSkating.ContactLabels`)
applied to the ground truth: a foot joint (contract.CONTACT_JOINTS: ankle and toe of each side, left first) is
planted on a frame when it stands within 3 % of a leg length of its own ground level (the 5th percentile over the
span's frames of that joint's height) and its horizontal speed (central differences, one-sided at the span's ends)
is below 15 % of a leg length per second. A joint's own level, because an ankle stands a heel's height above the
floor when the foot is flat: measured from the toe's level (the skating measure's one ground level, the lowest
joint's), the rule planted a CMU ankle on 0.004 % of the training frames, so the ankles could be neither learnt
nor scored; each joint from its own level, ankles and toes are each planted on about 23 % of them.

The head sits on the query tokens after the trunk's last block. Training it alone (`train_contact_head`) leaves
every weight the motion outputs depend on as it was, so the motion of the model it starts from is unchanged
(`export` then checks the graphs; the model card gives the measured difference). Precision and recall
(`contact_scores`) are counted as a bake meets them: clips baked gap after gap with keys every K frames, each
gap's past frames the previous gap's output, every non-key frame scored, each foot joint separately.
"""
from __future__ import annotations

import copy
import json
import math
import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np
import torch

from . import contract as C, safe_output
from .chained import tail_keys
from .checkpoint import LoadedModel, load_checkpoint, read_checkpoint, save_checkpoint_file
from .decoding import decode_outputs
from .data import MotionPack, load_pack, split_windows, training_ranges
from .export import example_inputs, graph_paths
from .kinematics import forward_kinematics
from .localize import unlocalize
from .model import CONTACT_HEADS, DeltaInterpolator
from .onnx_reference import run_model
from .objective import (CONTACT_HEIGHT, CONTACT_SPEED, SkeletonTensors, _network_inputs, leg_length, make_batch,
                        predict)
from .sampler import TransitionSampler
from .safe_input import load_onnx
from .train import WindowSource, run_checkpoint
from .warm_start import load_exported_model

Tensor = torch.Tensor
GROUND_PERCENTILE = 5.0                # C# FootSkating.GroundPercentile
MIRRORED_CHANNELS = [2, 3, 0, 1]       # left ↔ right (a mirrored clip's left foot is the original's right)
THRESHOLDS = tuple(round(0.05 * i, 2) for i in range(1, 20))  # 0.05 … 0.95, the candidates chosen among


# -- labels ------------------------------------------------------------------------------------------------
def contact_joint_indices(names: Sequence[str]) -> List[int]:
    lacking = [j for j in C.CONTACT_JOINTS if j not in names]
    if lacking:
        raise ValueError(f"the skeleton has no joint {lacking[0]}; expected the contact joints "
                         f"{', '.join(C.CONTACT_JOINTS)}")
    return [list(names).index(j) for j in C.CONTACT_JOINTS]


def foot_positions(root_positions, local_quaternions, skeleton) -> np.ndarray:
    """(frames, 4, 3) global positions of the contact joints, data units (float64)."""
    offsets = torch.tensor(np.asarray(skeleton.offsets), dtype=torch.float64)
    feet = contact_joint_indices(skeleton.names)
    out = []
    for a in range(0, len(root_positions), 4096):  # chunks: a pack holds hundreds of thousands of frames
        r = torch.as_tensor(np.asarray(root_positions[a:a + 4096]), dtype=torch.float64)
        q = torch.as_tensor(np.asarray(local_quaternions[a:a + 4096]), dtype=torch.float64)
        _, p = forward_kinematics(q, r, offsets, list(skeleton.parents))
        out.append(p[:, feet].numpy())
    return np.concatenate(out) if out else np.zeros((0, len(feet), 3))


def ground_levels(feet: np.ndarray) -> np.ndarray:
    """(joints,) each foot joint's own ground level over a span's positions `feet` (frames, joints, 3): the
    GROUND_PERCENTILE-th percentile of its height (linear, as C# `FootSkating.GroundLevels`)."""
    return np.percentile(feet[:, :, 1], GROUND_PERCENTILE, axis=0)


def planted(feet: np.ndarray, frame_time: float, leg: float) -> np.ndarray:
    """(frames, 4) flags of the rule above for one span's foot-joint positions `feet` (frames, 4, 3): C#
    `FootSkating.ContactLabels` of the same span."""
    frames = feet.shape[0]
    if frames < 2:
        return np.zeros(feet.shape[:2], dtype=bool)
    ground = ground_levels(feet)[None, :]
    before = np.maximum(np.arange(frames) - 1, 0)
    after = np.minimum(np.arange(frames) + 1, frames - 1)
    d = feet[after] - feet[before]
    speed = np.sqrt(d[..., 0] ** 2 + d[..., 2] ** 2) / ((after - before)[:, None] * frame_time)
    return (feet[:, :, 1] <= ground + CONTACT_HEIGHT * leg) & (speed < CONTACT_SPEED * leg)


def contact_label_vectors() -> Dict:
    """Golden vectors of the label rule for C# (`FootSkating.ContactLabels`): synthetic spans of foot-joint
    positions (a walk on a raised floor whose ankles stand a heel's height above their toes, with capture noise;
    the same crawling slowly; a two-frame span; a one-frame span) with each joint's ground level and planted flags
    as `planted` gives them."""
    rng = np.random.default_rng(29)
    cases = []

    def walk(frames: int, floor: float, stride: float, noise: float) -> np.ndarray:
        t = np.arange(frames) / 30.0
        feet = np.zeros((frames, 4, 3))
        for side in range(2):
            phase = 2 * np.pi * 1.1 * t + np.pi * side
            swing = np.maximum(np.sin(phase), 0.0)        # half of each cycle in the air
            for joint, (height, lead) in enumerate(((0.08, 0.0), (0.02, 0.14))):
                k = 2 * side + joint
                lift = swing * (0.12 if joint == 0 else 0.07)  # the heel leaves first and higher
                feet[:, k, 0] = 0.1 * side + rng.normal(0, noise, frames)
                feet[:, k, 1] = floor + height + lift + rng.normal(0, noise, frames)
                feet[:, k, 2] = lead + np.cumsum(swing) * stride / 8  # forward only while in the air
        return feet

    for name, feet in (("walk", walk(48, 0.31, 0.6, 0.002)), ("slow", walk(40, -0.2, 0.05, 0.001)),
                       ("two-frames", walk(2, 0.0, 0.6, 0.0)), ("one-frame", walk(1, 0.0, 0.6, 0.0))):
        frame_time, leg = 1.0 / 30.0, 0.9
        cases.append({"name": name, "frame_time": frame_time, "leg_length": leg,
                      "feet": feet.reshape(-1).tolist(),
                      "ground_levels": ground_levels(feet).tolist() if len(feet) else [],
                      "planted": planted(feet, frame_time, leg).astype(int).reshape(-1).tolist()})
    return {"rule": "planted: height <= own ground (5th percentile of the joint's height) + 0.03 leg and "
                    "horizontal central-difference speed < 0.15 leg/s; frames x 4 joints (LeftFoot, LeftToe, "
                    "RightFoot, RightToe), row-major", "cases": cases}


def write_contact_label_vectors(path) -> Path:
    """Writes `contact_label_vectors()` to `path` (Tests/Fixtures~/contact-labels.json)."""
    path = Path(path)
    safe_output.write_text(path, json.dumps(contact_label_vectors(), indent=1) + "\n")
    return path


def pack_leg_length(pack: MotionPack) -> float:
    leg = leg_length(list(pack.skeleton.names), pack.skeleton.offsets)
    if not leg > 0:
        raise ValueError("the pack's skeleton has no LeftLeg/LeftFoot/LeftToe chain; expected the model's skeleton")
    return leg


def pack_labels(pack: MotionPack) -> np.ndarray:
    """(frames, 4) planted flags of every frame of the pack, each file's ground level its own (the whole file is
    the span: a bake's first and last keys are its first and last frames)."""
    leg = pack_leg_length(pack)
    feet = foot_positions(pack.root_positions, pack.local_quaternions, pack.skeleton)
    labels = np.zeros(feet.shape[:2], dtype=bool)
    for i in range(len(pack.files)):
        a, b = pack.file_frames(i)
        labels[a:b] = planted(feet[a:b], float(pack.frame_time), leg)
    return labels


# -- baking with contacts ----------------------------------------------------------------------------------
def _predict_contacts(model: DeltaInterpolator, batch) -> Tuple[Tensor, Tensor, Tensor]:
    """Localized root, local quaternions and contact probabilities of a batch's query frames."""
    qr, q6, contacts = model(*_network_inputs(model, batch), with_contacts=True)
    geo = batch.base_root.dtype
    root, rot = decode_outputs(model.config.output_delta_mode, batch.base_root, batch.base_rotations,
                               qr.to(geo), q6.to(geo))
    return root, rot, contacts


def bake_contacts(model: DeltaInterpolator, skeleton: SkeletonTensors, roots: Tensor, quats: Tensor,
                  keys: List[int], past: int = 10, baked: Optional[list] = None) -> np.ndarray:
    """Bakes one clip (`roots` (F, 3), `quats` (F, J, 4), data units) as `inbetween bake` does — keys at `keys`,
    gap after gap, each gap's past frames the previous output — and returns (F, 4) contact probabilities on the
    filled frames (NaN on keys and outside the keys' span). `baked`, a list: the baked clip's root positions and
    local quaternions are appended to it."""
    cfg = model.config
    sampler = TransitionSampler(past=10)
    root, rot = roots.clone(), quats.clone()
    probabilities = np.full((roots.shape[0], len(C.CONTACT_JOINTS)), np.nan)
    for k0, k1 in zip(keys[:-1], keys[1:]):
        n = k1 - k0 - 1
        if n < 1:
            continue
        p = min(past, k0 + 1)
        layout = sampler.layout(n, past=p)
        window = slice(k0 - p + 1, k1 + 1)
        batch = make_batch(root[None, window], rot[None, window], layout, skeleton, cfg.output_delta_mode,
                           cfg.input_delta_mode)
        q_root, q_rot, contacts = _predict_contacts(model, batch)
        q_root, q_rot = unlocalize(q_root, q_rot, batch.localization, skeleton.unit_scale)
        root[k0 + 1:k1], rot[k0 + 1:k1] = q_root[0].to(root.dtype), q_rot[0].to(rot.dtype)
        probabilities[k0 + 1:k1] = contacts[0].double().numpy()
    if baked is not None:
        baked.extend((root, rot))
    return probabilities


@dataclass
class ContactCounts:
    """Per channel: counts of (predicted, truth) planted pairs over scored frames, at each candidate threshold."""
    true_positive: np.ndarray   # (thresholds, 4)
    predicted: np.ndarray       # (thresholds, 4)
    actual: np.ndarray          # (4,)
    frames: int

    @staticmethod
    def empty(thresholds: Sequence[float]) -> "ContactCounts":
        k = len(C.CONTACT_JOINTS)
        return ContactCounts(np.zeros((len(thresholds), k), np.int64), np.zeros((len(thresholds), k), np.int64),
                             np.zeros(k, np.int64), 0)

    def add(self, probabilities: np.ndarray, truth: np.ndarray, thresholds: Sequence[float]) -> None:
        scored = ~np.isnan(probabilities[:, 0])
        p, t = probabilities[scored], truth[scored]
        for i, threshold in enumerate(thresholds):
            guess = p >= threshold
            self.true_positive[i] += (guess & t).sum(0)
            self.predicted[i] += guess.sum(0)
        self.actual += t.sum(0)
        self.frames += int(scored.sum())

    def precision(self) -> np.ndarray:
        return self.true_positive / np.maximum(self.predicted, 1)

    def recall(self) -> np.ndarray:
        return self.true_positive / np.maximum(self.actual, 1)[None]


def clip_spans(pack: MotionPack, split: str) -> List[Tuple[int, int]]:
    """[start, end) frames scored: `validation`, the last 10 % of each file that is not a time-scaled copy (the
    tails `chained` and `train` validate on); `all`, every such file whole (a held-out pack)."""
    if split not in ("validation", "all"):
        raise ValueError(f"split {split!r}; expected 'validation' or 'all'")
    spans = []
    for i in range(len(pack.files)):
        if pack.is_augmented(i):
            continue
        a, b = pack.file_frames(i)
        if split == "validation":
            a = a + int(round((b - a) * 0.9))
        spans.append((a, b))
    return spans


def contact_scores(loaded: LoadedModel, pack: MotionPack, every: Sequence[int], split: str,
                   thresholds: Sequence[float] = THRESHOLDS, from_motion: Optional[Dict[int, ContactCounts]] = None
                   ) -> Dict[int, ContactCounts]:
    """Per key spacing: the counts over every non-key frame of every clip of the split, baked gap after gap.
    `from_motion`, a dict: per spacing also the counts of the same rule applied to the baked motion itself (its
    own ground level) — contacts labelled from the filled motion, which is what a locker without predicted
    contacts has to go by; every threshold gives the same counts."""
    model = loaded.model.eval()
    if not model.has_contacts:
        raise ValueError("the model has no foot_contacts output; expected a model with a contact head")
    skeleton = loaded.skeleton_tensors(torch.float64)
    leg = pack_leg_length(pack)
    frame_time = float(pack.frame_time)
    out = {k: ContactCounts.empty(thresholds) for k in every}
    with torch.no_grad():
        for a, b in clip_spans(pack, split):
            roots = torch.from_numpy(pack.root_positions[a:b]).double()
            quats = torch.from_numpy(pack.local_quaternions[a:b]).double()
            feet = foot_positions(pack.root_positions[a:b], pack.local_quaternions[a:b], pack.skeleton)
            for k in every:
                if b - a < k + 1:
                    continue
                keys = tail_keys(b - a, k)
                span = slice(keys[0], keys[-1] + 1)  # the bake's span: its ground level, its frames
                truth = np.zeros((b - a, len(C.CONTACT_JOINTS)), dtype=bool)
                truth[span] = planted(feet[span], frame_time, leg)
                baked: list = []
                probabilities = bake_contacts(model, skeleton, roots, quats, keys, baked=baked)
                out[k].add(probabilities, truth, thresholds)
                if from_motion is not None:
                    filled = foot_positions(baked[0].numpy(), baked[1].numpy(), pack.skeleton)
                    guess = np.where(np.isnan(probabilities), np.nan, planted(filled[span], frame_time, leg)[
                        np.arange(b - a).clip(keys[0], keys[-1]) - keys[0]].astype(float))
                    from_motion.setdefault(k, ContactCounts.empty(thresholds)).add(guess, truth, thresholds)
    return out


MIN_PLANTED_SHARE = 0.05  # a channel planted on fewer of the scored frames does not choose the threshold


def choose_threshold(counts: Dict[int, ContactCounts], thresholds: Sequence[float] = THRESHOLDS) -> Tuple[float, float]:
    """The threshold whose worst precision or recall over every spacing and channel is highest (ties: the one
    nearer 0.5), and that worst value. Channels the rule plants on under MIN_PLANTED_SHARE of the scored frames
    are left out of the choice (a clip set whose rule plants a joint on a few crouching frames only would let
    those frames decide the threshold for all four channels; with a ground level per joint every CMU channel is
    planted on about a quarter of the frames, so all four choose)."""
    worst = np.full(len(thresholds), np.inf)
    for c in counts.values():
        used = c.actual >= MIN_PLANTED_SHARE * max(c.frames, 1)
        if used.any():
            worst = np.minimum(worst, np.minimum(c.precision(), c.recall())[:, used].min(axis=1))
    if not np.isfinite(worst).any():
        return 0.5, float("nan")
    order = sorted(range(len(thresholds)), key=lambda i: (-worst[i], abs(thresholds[i] - 0.5)))
    return float(thresholds[order[0]]), float(worst[order[0]])


def format_scores(counts: Dict[int, ContactCounts], threshold: float, thresholds: Sequence[float] = THRESHOLDS) -> List[str]:
    i = int(np.argmin([abs(t - threshold) for t in thresholds]))
    lines = []
    for k, c in counts.items():
        cells = "  ".join(f"{j} P {c.precision()[i, n]:.3f} R {c.recall()[i, n]:.3f}"
                          for n, j in enumerate(C.CONTACT_JOINTS))
        lines.append(f"every {k}: {c.frames} frames, planted share {c.actual.sum() / max(4 * c.frames, 1):.3f}; {cells}")
    return lines


def motion_difference(model_path, other_path) -> Dict[str, float]:
    """Largest |difference| between two exported models' motion outputs on the same inputs (several K, N and
    batches of rows with different gaps), graph by graph: the whole graph's `root_position_delta` and
    `rotation_6d_delta`, the keys graph's `key_memory`, and the frame graph's deltas fed each file's own keys
    output. A contact head on a frozen trunk must give 0 up to float rounding in every one."""
    model = load_exported_model(model_path).model
    graphs = {}
    for name, path in (("model", model_path), ("other", other_path)):
        graphs[name] = {k: load_onnx(p) for k, p in graph_paths(path).items()}
    worst: Dict[str, float] = {}
    motion = (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA)
    for keys, queries, gaps in ((11, 5, [5]), (11, 14, [14, 29, 20]), (11, 29, [29, 29]), (3, 1, [7, 1])):
        feeds = {k: v.numpy() for k, v in example_inputs(model, "whole", keys, queries, gaps, seed=keys + queries).items()}
        key_feeds = {k: feeds[k] for k in (C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.GAP_LENGTH)}
        got = {}
        for name, g in graphs.items():
            memory = run_model(g["keys"], key_feeds)[C.KEY_MEMORY]
            frame = run_model(g["frame"], {C.KEY_MEMORY: memory, C.QUERY_FRAME_INDICES: feeds[C.QUERY_FRAME_INDICES],
                                           C.GAP_LENGTH: feeds[C.GAP_LENGTH]})
            got[name] = (run_model(g["whole"], feeds), memory, frame)
        pairs = [(f"whole {o}", got["model"][0][o], got["other"][0][o]) for o in motion]
        pairs.append(("keys key_memory", got["model"][1], got["other"][1]))
        pairs += [(f"frame {o}", got["model"][2][o], got["other"][2][o]) for o in motion]
        for what, a, b in pairs:
            d = float(np.abs(a - b).max())
            worst[what] = max(worst.get(what, 0.0), d if math.isfinite(d) else math.inf)
    return worst


# -- training the head -------------------------------------------------------------------------------------
@dataclass
class ContactTrainConfig:
    data: str = "Training/.data/cmu-train.npz"
    out: str = "Training/runs/contacts"
    init_from: str = "Runtime/Models/DeltaInterpolator-CMU.onnx"
    head: str = "mlp"
    hidden: int = 128
    steps: int = 6000
    batch_size: int = 64
    lr: float = 1e-3
    chained_share: float = 0.5
    mirror: bool = True
    seed: int = 0
    checkpoint_every: int = 250
    validate_every: int = 0             # 0: only at the end; else also every N steps (chained bakes: slow)
    decay_at: float = 0.8               # the learning rate drops ×0.1 after this share of the steps
    max_minutes: float = 0.0
    every: Tuple[int, ...] = (15, 30)   # key spacings the threshold is chosen for (validation)

    def check(self) -> None:
        """ValueError naming the option for a value no run can use."""
        if self.head not in CONTACT_HEADS or self.head == "none":
            raise ValueError(f"--head {self.head}; expected 'linear', 'mlp' or 'block'")
        if not 1 <= self.hidden <= 4096:
            raise ValueError(f"--hidden {self.hidden}; expected 1..4096")
        if not 1 <= self.steps <= 10_000_000:
            raise ValueError(f"--steps {self.steps}; expected 1..10000000")
        if not 1 <= self.batch_size <= 4096:
            raise ValueError(f"--batch-size {self.batch_size}; expected 1..4096")
        if not (math.isfinite(self.lr) and 0 < self.lr <= 1):
            raise ValueError(f"--lr {self.lr}; expected a learning rate in (0, 1]")
        if not (math.isfinite(self.chained_share) and 0 <= self.chained_share <= 1):
            raise ValueError(f"--chained-share {self.chained_share}; expected a share from 0 to 1")
        if not 1 <= self.checkpoint_every <= 10_000_000:
            raise ValueError(f"--checkpoint-every {self.checkpoint_every}; expected ≥ 1")
        if not 0 <= self.validate_every <= 10_000_000:
            raise ValueError(f"--validate-every {self.validate_every}; expected ≥ 0 (0: only at the end)")
        if not (math.isfinite(self.decay_at) and 0 < self.decay_at <= 1):
            raise ValueError(f"--decay-at {self.decay_at}; expected a share of the steps in (0, 1]")
        if not (math.isfinite(self.max_minutes) and self.max_minutes >= 0):
            raise ValueError(f"--max-minutes {self.max_minutes}; expected ≥ 0 (0: no limit)")
        if not self.every or any(not 2 <= k <= 200 for k in self.every):
            raise ValueError(f"--every {list(self.every)}; expected key spacings of 2..200 model frames")


# What a resumed run must share with the run it continues (else it is another experiment).
RESUME_SETTINGS = ("head", "hidden", "batch_size", "lr", "chained_share", "mirror", "seed", "init_from", "decay_at")


def initial_model(path: str, head: str, hidden: int) -> LoadedModel:
    """The model `path` holds (an exported .onnx or a checkpoint) with a fresh contact head on its trunk; a
    contact head it already has is replaced."""
    base = load_exported_model(path) if str(path).endswith(".onnx") else load_checkpoint(path)
    config = copy.deepcopy(base.config)
    config.contact_head, config.contact_hidden = head, hidden
    model = DeltaInterpolator(config)
    trunk = {k: v for k, v in base.model.state_dict().items() if not k.startswith("contact_head.")}
    missing, unexpected = model.load_state_dict(trunk, strict=False)
    if unexpected or any(not k.startswith("contact_head.") for k in missing):
        raise ValueError(f"{path}: its weights do not fit the network with a contact head ({(unexpected or missing)[:2]})")
    if head == "block":  # the head's block starts as the last block: it reads the key memory the same way
        last = {k: v for k, v in model.blocks[-1].state_dict().items()
                if not k.startswith(("attention.key.", "attention.value."))}
        model.contact_head.block.load_state_dict(last)
    base.model = model.eval()
    return base


def _windows(source_starts, rng, batch_size: int, length: int, window: int) -> np.ndarray:
    picks = source_starts[rng.integers(0, len(source_starts), batch_size)]
    shift = rng.integers(0, window - length + 1, batch_size)
    return (picks + shift)[:, None] + np.arange(length)[None]


def train_contact_head(cfg: ContactTrainConfig, progress: bool = True) -> Path:
    """Trains only the contact head (the trunk frozen, in eval mode, so its tokens are those it gives at run time)
    with binary cross-entropy on the labels above; batches as `train` draws them (`--chained-share` of them with
    past frames from the network's own fill of the gap before, as a bake feeds them; `--mirror`). Resumable from
    OUT/checkpoint.pt. At the end, chooses the threshold on the validation tails (chained bakes, keys every
    `cfg.every`) and writes it into the checkpoint; `export` then writes the model."""
    cfg.check()
    out = Path(cfg.out)
    existing = run_checkpoint(out)
    ckpt_path = out / "checkpoint.pt"
    state = read_checkpoint(existing) if existing else None
    if state is not None:
        saved = dict(state.get("contact_train_config") or {})
        if not saved:
            raise ValueError(f"{ckpt_path}: not a run of train-contacts; expected a new --out")
        different = [f"{k} {getattr(cfg, k)} but the run used {saved.get(k)}" for k in RESUME_SETTINGS
                     if k in saved and saved[k] != getattr(cfg, k)]
        if different:
            raise ValueError(f"{ckpt_path}: resuming with {', '.join(different)}; expected the same settings (or a new --out)")
    torch.manual_seed(cfg.seed)
    loaded = initial_model(cfg.init_from, cfg.head, cfg.hidden)
    model = loaded.model
    pack = load_pack(cfg.data)
    if list(pack.skeleton.names) != list(loaded.skeleton.names):
        raise ValueError(f"{cfg.data}: its skeleton is not the model's ({cfg.init_from}); expected the pack the model "
                         "was trained on")
    labels = torch.from_numpy(pack_labels(pack))
    train_starts, _ = split_windows(pack)
    if len(train_starts) == 0:
        raise ValueError(f"{cfg.data}: no training window; expected files of at least 57 frames")
    skeleton = loaded.skeleton_tensors(torch.float32)
    sampler = TransitionSampler(min_past=int(loaded.train_config.get("min_past", 1)), min_gap=5, max_gap=39)
    source = WindowSource(pack, train_starts, 50, sampler, False, False, torch.device("cpu"),
                          ranges=training_ranges(pack))
    for p in model.trunk_parameters():
        p.requires_grad_(False)
    optimizer = torch.optim.Adam(model.contact_head.parameters(), lr=cfg.lr)
    rng = np.random.default_rng([cfg.seed, 29])
    step = 0
    if state is not None:
        model.load_state_dict(state["model"])
        optimizer.load_state_dict(state["optimizer"])
        rng.bit_generator.state = state["rng"]
        torch.set_rng_state(state["torch_rng"])
        step = int(state["step"])
        if progress:
            print(f"resumed from {ckpt_path} at step {step}")
    out.mkdir(parents=True, exist_ok=True)
    log = out / "contacts-log.csv"
    mirror_map = torch.as_tensor(pack.skeleton.mirror_map())
    roots_all = torch.from_numpy(pack.root_positions)
    quats_all = torch.from_numpy(pack.local_quaternions)
    loss_fn = torch.nn.BCEWithLogitsLoss()
    started, window_losses = time.time(), []

    def save(threshold: float, validation: Dict) -> None:
        save_checkpoint_file({
            "model": model.state_dict(), "model_config": model.config.to_dict(),
            "skeleton": loaded.skeleton.to_json(), "unit_scale": loaded.unit_scale, "step": step,
            "train_config": dict(loaded.train_config), "contact_train_config": asdict(cfg),
            "validation": validation, "contact_threshold": threshold, "fps": loaded.fps,
            "data_description": loaded.data_description,
            "facing_local_axis": list(loaded.facing_local_axis), "facing_target_axis": list(loaded.facing_target_axis),
            "optimizer": optimizer.state_dict(), "rng": rng.bit_generator.state, "torch_rng": torch.get_rng_state(),
        }, ckpt_path)

    model.eval()  # the trunk's dropout stays off: the head learns the tokens the exported graphs give
    def validate() -> Tuple[float, Dict]:
        counts = contact_scores(loaded, pack, cfg.every, "validation")
        threshold, worst = choose_threshold(counts)
        i = THRESHOLDS.index(threshold)
        scores = {f"every_{k}_{j}_{m}": float(getattr(c, m)()[i, n])
                  for k, c in counts.items() for n, j in enumerate(C.CONTACT_JOINTS) for m in ("precision", "recall")}
        scores["contact_threshold_worst"] = worst
        safe_output.append_text(out / "validation.jsonl", json.dumps({"step": step, "threshold": threshold, **scores}) + "\n")
        if progress:
            print(f"step {step}: threshold {threshold} (worst precision or recall {worst:.3f}) on validation:")
            for line in format_scores(counts, threshold):
                print("  " + line, flush=True)
        return threshold, scores

    while step < cfg.steps:
        for group in optimizer.param_groups:
            group["lr"] = cfg.lr * (0.1 if step >= cfg.decay_at * cfg.steps else 1.0)
        layout = sampler.sample(rng)
        n, p = layout.gap, layout.past
        chained = cfg.chained_share > 0 and rng.random() < cfg.chained_share
        first = sampler.layout(n, past=10)
        length = first.length + n + 1 if chained else layout.length
        starts, window = source.starts_for(length)
        idx = torch.from_numpy(_windows(starts, rng, cfg.batch_size, length, window))
        roots, quats, truth = roots_all[idx].double(), quats_all[idx].double(), labels[idx]
        if cfg.mirror:
            flip = torch.from_numpy(rng.random(cfg.batch_size) < 0.5)
            roots = torch.where(flip[:, None, None], roots * roots.new_tensor([1.0, 1.0, -1.0]), roots)
            quats = torch.where(flip[:, None, None, None],
                                quats[:, :, mirror_map] * quats.new_tensor([1.0, -1.0, -1.0, 1.0]), quats)
            truth = torch.where(flip[:, None, None], truth[:, :, MIRRORED_CHANNELS], truth)
        roots, quats = roots.float(), quats.float()
        with torch.no_grad():
            if chained:  # the first gap filled by the network, then the trained gap's P past frames end at its key
                b = make_batch(roots[:, :first.length], quats[:, :first.length], first, skeleton,
                               model.config.output_delta_mode, model.config.input_delta_mode)
                fill_root, fill_rot, _, _ = predict(model, b, with_keys=False)
                fill_root, fill_rot = unlocalize(fill_root, fill_rot, b.localization, skeleton.unit_scale)
                roots, quats = roots.clone(), quats.clone()
                roots[:, 10:10 + n], quats[:, 10:10 + n] = fill_root.to(roots.dtype), fill_rot.to(quats.dtype)
                start = 10 + n - p + 1
                roots, quats, truth = roots[:, start:], quats[:, start:], truth[:, start:]
            batch = make_batch(roots, quats, layout, skeleton, model.config.output_delta_mode,
                               model.config.input_delta_mode)
            inputs = _network_inputs(model, batch)
            _, memory = model.encode_keys(inputs[0], inputs[1], inputs[3])
            tokens = model.decode_queries(memory, inputs[2], inputs[3], inputs[4])
        target = truth[:, list(layout.query_frames)].float()
        loss = loss_fn(model.contact_logits(tokens, memory), target)
        optimizer.zero_grad(set_to_none=True)
        loss.backward()
        optimizer.step()
        step += 1
        window_losses.append(float(loss))
        if not math.isfinite(window_losses[-1]):
            raise ValueError(f"{ckpt_path}: the contact loss became non-finite at step {step}; expected finite "
                             "(lower --lr?). The last checkpoint is kept")
        if step % 50 == 0 or step == cfg.steps:
            line = f"{step},{np.mean(window_losses):.5f},{time.time() - started:.1f}\n"
            if not log.exists():
                line = "step,bce,seconds\n" + line
            safe_output.append_text(log, line)
            if progress:
                print(f"step {step}: bce {np.mean(window_losses):.4f} ({time.time() - started:.0f} s)", flush=True)
            window_losses.clear()
        out_of_time = cfg.max_minutes > 0 and time.time() - started > cfg.max_minutes * 60
        if step % cfg.checkpoint_every == 0 or step == cfg.steps or out_of_time:
            save(0.5, {})
        if out_of_time:
            if progress:
                print(f"stopping at step {step}: --max-minutes {cfg.max_minutes} reached (resume to continue)")
            return ckpt_path
        if cfg.validate_every and step % cfg.validate_every == 0 and step < cfg.steps:
            validate()
    # the threshold: chosen on the validation tails' chained bakes (never on held-out subjects)
    threshold, validation = validate()
    save(threshold, validation)
    return ckpt_path


__all__ = ["ground_levels", "planted", "pack_labels", "bake_contacts", "contact_scores", "choose_threshold", "ContactTrainConfig",
           "train_contact_head", "initial_model"]
