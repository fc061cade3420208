"""Issue 29's cheap route to foot contacts: a small classifier over what a bake already has once the model has
filled the gaps — the filled motion's foot joints (height over their own ground level, horizontal and vertical
speed, the other joint of the same foot), the keys around the frame (their joints' heights) and where the frame
sits in its gap — optionally beside the contact head's probability. A frozen-trunk head sees only the trunk's
tokens; the filled motion says where the network put the feet, which is what a locker has to agree with.

Everything is counted as `contacts.contact_scores` counts it (chained bakes, keys every K, every filled frame,
each foot joint separately, labels by `contacts.planted`). Records come from the training part of each training
file (fit), its validation tail (threshold and choice) and, once, the held-out pack.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Dict, List, Sequence, Tuple

import numpy as np
import torch

from . import contract as C
from .chained import tail_keys
from .checkpoint import LoadedModel
from .contacts import (THRESHOLDS, ContactCounts, bake_contacts, foot_positions, ground_levels, pack_leg_length,
                       planted)
from .data import MotionPack

OFFSETS = (-4, -2, -1, 0, 1, 2, 4)   # frames around the scored one whose motion the classifier reads
OTHER_JOINT = [1, 0, 3, 2]            # the same foot's other joint (ankle ↔ toe)


@dataclass
class BakeRecord:
    """One chained bake of one span: the filled clip's foot joints and what the classifier is scored against."""
    feet: np.ndarray        # (F, 4, 3) the baked clip's foot-joint positions (keys are the truth's)
    truth: np.ndarray       # (F, 4) planted labels of the truth over the bake's span
    head: np.ndarray        # (F, 4) the contact head's probabilities on filled frames, NaN on keys
    keys: List[int]


def spans(pack: MotionPack, part: str) -> List[Tuple[int, int]]:
    """[start, end) frames of every file that is not a time-scaled copy: `train`, each file's first 90 %;
    `validation`, its last 10 % (as `contacts.clip_spans`); `all`, the whole file (a held-out pack)."""
    out = []
    for i in range(len(pack.files)):
        if pack.is_augmented(i):
            continue
        a, b = pack.file_frames(i)
        cut = a + int(round((b - a) * 0.9))
        out.append({"train": (a, cut), "validation": (cut, b), "all": (a, b)}[part])
    return out


def bake_records(loaded: LoadedModel, pack: MotionPack, part: str, every: Sequence[int],
                 progress: bool = True) -> Dict[int, List[BakeRecord]]:
    model = loaded.model.eval()
    skeleton = loaded.skeleton_tensors(torch.float64)
    leg, frame_time = pack_leg_length(pack), float(pack.frame_time)
    out: Dict[int, List[BakeRecord]] = {k: [] for k in every}
    started = time.time()
    todo = spans(pack, part)
    with torch.no_grad():
        for n, (a, b) in enumerate(todo):
            roots = torch.from_numpy(pack.root_positions[a:b]).double()
            quats = torch.from_numpy(pack.local_quaternions[a:b]).double()
            truth_feet = foot_positions(pack.root_positions[a:b], pack.local_quaternions[a:b], pack.skeleton)
            for k in every:
                if b - a < k + 1:
                    continue
                keys = tail_keys(b - a, k)
                span = slice(keys[0], keys[-1] + 1)
                baked: list = []
                head = bake_contacts(model, skeleton, roots, quats, keys, baked=baked)
                feet = foot_positions(baked[0].numpy(), baked[1].numpy(), pack.skeleton)
                out[k].append(BakeRecord(feet[span], planted(truth_feet[span], frame_time, leg), head[span],
                                         [q - keys[0] for q in keys]))
            if progress and (n % 20 == 0 or n == len(todo) - 1):
                print(f"  {part}: {n + 1}/{len(todo)} spans baked ({time.time() - started:.0f} s)", flush=True)
    return out


def features(record: BakeRecord, leg: float, frame_time: float, with_head: bool) -> Tuple[np.ndarray, np.ndarray]:
    """(filled frames × 4, D) features and (filled frames × 4,) labels of one bake. Units: leg lengths and leg
    lengths per second, so the classifier is the same for any skeleton's size; the ground level is each joint's
    own over the baked clip (what a bake knows; the truth's is not known at run time)."""
    feet, frames = record.feet, record.feet.shape[0]
    ground = ground_levels(feet)[None, :]
    rise = (feet[:, :, 1] - ground) / leg                                               # (F, 4)
    before, after = np.maximum(np.arange(frames) - 1, 0), np.minimum(np.arange(frames) + 1, frames - 1)
    steps = np.maximum(after - before, 1)[:, None] * frame_time
    d = feet[after] - feet[before]
    hspeed = np.sqrt(d[..., 0] ** 2 + d[..., 2] ** 2) / steps / leg
    vspeed = d[..., 1] / steps / leg
    keys = record.keys
    is_key = np.zeros(frames, dtype=bool)
    is_key[keys] = True
    gap = np.searchsorted(keys, np.arange(frames), side="right") - 1
    gap = np.clip(gap, 0, len(keys) - 2)
    k0, k1 = np.asarray(keys)[gap], np.asarray(keys)[gap + 1]
    where = (np.arange(frames) - k0) / np.maximum(k1 - k0, 1)
    length = (k1 - k0) / 30.0
    rows, labels = [], []
    filled = np.flatnonzero(~is_key)
    for c in range(4):
        o = OTHER_JOINT[c]
        cols = []
        for s in OFFSETS:
            g = np.clip(filled + s, 0, frames - 1)
            cols += [np.minimum(rise[g, c], 0.5), np.minimum(hspeed[g, c], 5.0), np.clip(vspeed[g, c], -3, 3),
                     np.minimum(rise[g, o], 0.5), np.minimum(hspeed[g, o], 5.0)]
        cols += [np.minimum(rise[k0[filled], c], 0.5), np.minimum(rise[k1[filled], c], 0.5),
                 np.minimum(hspeed[k0[filled], c], 5.0), np.minimum(hspeed[k1[filled], c], 5.0),
                 # the truth's plant at each key, as far as its height and the filled neighbour's speed tell it
                 where[filled], 1 - where[filled], length[filled], np.full(len(filled), float(c % 2))]
        if with_head:
            cols.append(np.nan_to_num(record.head[filled, c], nan=0.5))
        rows.append(np.stack(cols, axis=1))
        labels.append(record.truth[filled, c])
    return np.concatenate(rows).astype(np.float32), np.concatenate(labels).astype(np.float32)


def channel_features(record: BakeRecord, leg: float, frame_time: float, with_head: bool):
    x, y = features(record, leg, frame_time, with_head)
    return x.reshape(4, -1, x.shape[1]), y.reshape(4, -1)


class ContactClassifier(torch.nn.Module):
    """Per foot joint, the same small MLP (left and right share it: mirrored clips look alike)."""

    def __init__(self, inputs: int, hidden: int = 64) -> None:
        super().__init__()
        self.register_buffer("mean", torch.zeros(inputs))
        self.register_buffer("scale", torch.ones(inputs))
        self.net = torch.nn.Sequential(torch.nn.Linear(inputs, hidden), torch.nn.ReLU(), torch.nn.Linear(hidden, hidden),
                                       torch.nn.ReLU(), torch.nn.Linear(hidden, 1))

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return self.net((x - self.mean) / self.scale).squeeze(-1)


def fit(x: np.ndarray, y: np.ndarray, hidden: int = 64, epochs: int = 30, seed: int = 0, lr: float = 2e-3,
        progress: bool = True) -> ContactClassifier:
    torch.manual_seed(seed)
    model = ContactClassifier(x.shape[1], hidden)
    xt, yt = torch.from_numpy(x), torch.from_numpy(y)
    model.mean.copy_(xt.mean(0))
    model.scale.copy_(xt.std(0).clamp_min(1e-3))
    optimizer = torch.optim.Adam(model.parameters(), lr=lr)
    loss_fn = torch.nn.BCEWithLogitsLoss()
    rng = np.random.default_rng(seed)
    for epoch in range(epochs):
        for group in optimizer.param_groups:
            group["lr"] = lr * (0.1 if epoch >= 0.8 * epochs else 1.0)
        order = torch.from_numpy(rng.permutation(len(xt)))
        total = 0.0
        for i in range(0, len(order), 1024):
            idx = order[i:i + 1024]
            loss = loss_fn(model(xt[idx]), yt[idx])
            optimizer.zero_grad(set_to_none=True)
            loss.backward()
            optimizer.step()
            total += float(loss) * len(idx)
        if progress and (epoch % 5 == 4 or epoch == epochs - 1):
            print(f"  epoch {epoch + 1}: bce {total / len(xt):.4f}", flush=True)
    return model.eval()


def score(model: ContactClassifier, records: Dict[int, List[BakeRecord]], leg: float, frame_time: float,
          with_head: bool, thresholds: Sequence[float] = THRESHOLDS) -> Dict[int, ContactCounts]:
    out = {}
    with torch.no_grad():
        for k, recs in records.items():
            counts = ContactCounts.empty(thresholds)
            for r in recs:
                x, y = channel_features(r, leg, frame_time, with_head)
                p = torch.sigmoid(model(torch.from_numpy(x))).numpy().T      # (filled, 4)
                counts.add(p.astype(float), y.T.astype(bool), thresholds)
            out[k] = counts
    return out


def head_counts(records: Dict[int, List[BakeRecord]], thresholds: Sequence[float] = THRESHOLDS) -> Dict[int, ContactCounts]:
    """The contact head's own counts on the same bakes (its probabilities as they are)."""
    out = {}
    for k, recs in records.items():
        counts = ContactCounts.empty(thresholds)
        for r in recs:
            counts.add(r.head, r.truth, thresholds)
        out[k] = counts
    return out


def rule_counts(records: Dict[int, List[BakeRecord]], leg: float, frame_time: float,
                thresholds: Sequence[float] = THRESHOLDS) -> Dict[int, ContactCounts]:
    """The label rule applied to the filled motion itself (its own ground levels): no learning at all."""
    out = {}
    for k, recs in records.items():
        counts = ContactCounts.empty(thresholds)
        for r in recs:
            guess = planted(r.feet, frame_time, leg).astype(float)
            guess[np.isnan(r.head[:, 0])] = np.nan
            counts.add(guess, r.truth, thresholds)
        out[k] = counts
    return out


__all__ = ["BakeRecord", "bake_records", "features", "ContactClassifier", "fit", "score", "head_counts", "rule_counts"]


def probabilities(model: ContactClassifier, record: BakeRecord, leg: float, frame_time: float) -> np.ndarray:
    """(F, 4) the classifier's probabilities on a bake's filled frames, NaN on keys (no head feature)."""
    x, _ = channel_features(record, leg, frame_time, with_head=False)
    out = np.full(record.feet.shape[:2], np.nan)
    filled = np.setdiff1d(np.arange(record.feet.shape[0]), record.keys)
    with torch.no_grad():
        out[filled] = torch.sigmoid(model(torch.from_numpy(x))).double().numpy().T
    return out


def classifier_document(model: ContactClassifier, threshold: float, record: BakeRecord, leg: float,
                        frame_time: float) -> Dict:
    """The classifier (no head feature) as JSON for the C# measure, with one bake's foot joints and the
    probabilities Python gives them (golden vectors: C# must reproduce them)."""
    layers = [m for m in model.net if isinstance(m, torch.nn.Linear)]
    return {"offsets": list(OFFSETS), "threshold": threshold,
            "mean": model.mean.tolist(), "scale": model.scale.tolist(),
            "layers": [{"weight": m.weight.detach().double().reshape(-1).tolist(), "bias": m.bias.detach().double().tolist(),
                        "inputs": m.in_features, "outputs": m.out_features} for m in layers],
            "golden": {"feet": record.feet.reshape(-1).tolist(), "keys": list(record.keys), "leg_length": leg,
                       "frame_time": frame_time,
                       "probabilities": np.nan_to_num(probabilities(model, record, leg, frame_time), nan=-1).reshape(-1).tolist()}}
