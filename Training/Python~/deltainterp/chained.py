"""Chained validation: the validation tails baked as a user bakes a clip, gap after gap.

`train`'s validation scores one gap whose past frames are the ground truth. A bake (`inbetween bake`, the
C# `ClipBaker` with filled frames as context) fills gap after gap, and each gap's past frames are the
previous gap's output: errors there are fed back. This module measures that on the training files'
validation tails (the last 10 % of each file that is not a time-scaled copy, as `split_windows` cuts them),
so a model trained for far-apart keys is chosen on validation, never on held-out subjects.
"""
from __future__ import annotations

from typing import Dict, List

import numpy as np
import torch

from . import quaternions
from .benchmark import l2q as benchmark_l2q
from .data import MotionPack
from .kinematics import forward_kinematics
from .localize import unlocalize
from .objective import SkeletonTensors, make_batch, predict
from .sampler import TransitionSampler


def tail_keys(frames: int, interval: int) -> List[int]:
    """Keys 0, K, 2K, … and the tail's last frame (as `KeyFrames.Every`), the last gap never empty."""
    keys = list(range(0, frames, interval))
    if keys[-1] != frames - 1:
        if frames - 1 - keys[-1] < 2 and len(keys) > 1:
            keys[-1] = frames - 1  # a last frame right after a key: that key goes, the last gap grows
        else:
            keys.append(frames - 1)
    return keys


def chained_metrics(model, pack: MotionPack, skeleton: SkeletonTensors, interval: int, past: int = 10,
                    validation_fraction: float = 0.1) -> Dict[str, float]:
    """Every validation tail with at least `interval` + 1 frames, keys every `interval` frames, filled gap
    after gap with up to `past` past frames (key and filled frames alike), and by SLERP of the same keys.
    Returns the mean global joint position error (model units) and L2Q over every non-key frame of every
    tail, model and SLERP, their ratios, and how many tails, gaps and frames were scored."""
    cfg = getattr(model, "module", model).config
    sampler = TransitionSampler(past=10)
    was_training = model.training
    model.eval()
    preds, slerps, truths = [], [], []
    tails = gaps = 0
    with torch.no_grad():
        for i in range(len(pack.files)):
            if pack.is_augmented(i):
                continue
            a, b = pack.file_frames(i)
            cut = a + int(round((b - a) * (1.0 - validation_fraction)))
            frames = b - cut
            if frames < interval + 1:
                continue
            truth_root = torch.from_numpy(pack.root_positions[cut:b])
            truth_rot = torch.from_numpy(pack.local_quaternions[cut:b])
            root, rot = truth_root.clone(), truth_rot.clone()
            s_root, s_rot = truth_root.clone(), truth_rot.clone()
            keys = tail_keys(frames, interval)
            for k0, k1 in zip(keys[:-1], keys[1:]):
                n = k1 - k0 - 1
                if n < 1:
                    continue
                p = min(past, k0 + 1)
                layout = sampler.layout(n, past=p)
                window = slice(k0 - p + 1, k1 + 1)
                batch = make_batch(root[None, window], rot[None, window], layout, skeleton, cfg.output_delta_mode,
                                   cfg.input_delta_mode)
                q_root, q_rot, _, _ = predict(model, batch, with_keys=False)
                q_root, q_rot = unlocalize(q_root, q_rot, batch.localization, skeleton.unit_scale)
                root[k0 + 1:k1], rot[k0 + 1:k1] = q_root[0], q_rot[0]
                b_root, b_rot = unlocalize(batch.base_root, batch.base_rotations, batch.localization, skeleton.unit_scale)
                s_root[k0 + 1:k1], s_rot[k0 + 1:k1] = b_root[0], b_rot[0]
                gaps += 1
            tails += 1
            span = slice(0, keys[-1] + 1)
            filled = torch.ones(keys[-1] + 1, dtype=torch.bool)
            filled[keys] = False
            for out, (r, q) in ((preds, (root, rot)), (slerps, (s_root, s_rot)), (truths, (truth_root, truth_rot))):
                out.append((r[span][filled], q[span][filled]))
    if was_training:
        model.train()
    if not truths:
        return {"tails": 0}
    offsets = skeleton.offsets
    gq, gp = forward_kinematics(torch.cat([q for _, q in truths]), torch.cat([r for r, _ in truths]) * skeleton.unit_scale,
                                offsets, skeleton.parents)
    out: Dict[str, float] = {"tails": tails, "gaps": gaps, "frames": int(gq.shape[0])}
    for name, parts in (("model", preds), ("slerp", slerps)):
        pq, pp = forward_kinematics(torch.cat([q for _, q in parts]), torch.cat([r for r, _ in parts]) * skeleton.unit_scale,
                                    offsets, skeleton.parents)
        pq = quaternions.align_hemisphere(pq, gq)
        out[f"{name}_position"] = float((pp - gp).norm(dim=-1).mean())
        out[f"{name}_l2q"] = benchmark_l2q(pq[None], gq[None])
    out["position_vs_slerp"] = out["model_position"] / out["slerp_position"]
    out["l2q_vs_slerp"] = out["model_l2q"] / out["slerp_l2q"]
    return out


__all__ = ["tail_keys", "chained_metrics"]
