"""The 22-joint LaFAN1 skeleton: names, parents and the official benchmark's bone offsets.

The offsets are the official statistics file's (`train_stats_official.json`, method-spec Appendix A),
rounded to 6 decimals, so that fixtures built with or without `../shared` are byte-identical.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import numpy as np

from .skeleton import Skeleton

NAMES = [
    "Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToe", "RightUpLeg", "RightLeg", "RightFoot",
    "RightToe", "Spine", "Spine1", "Spine2", "Neck", "Head", "LeftShoulder", "LeftArm", "LeftForeArm",
    "LeftHand", "RightShoulder", "RightArm", "RightForeArm", "RightHand",
]
PARENTS = [-1, 0, 1, 2, 3, 0, 5, 6, 7, 0, 9, 10, 11, 12, 11, 14, 15, 16, 11, 18, 19, 20]
# cm; method-spec Appendix A (joints 1..21); the root's offset is unused (its translation is data).
OFFSETS = [
    [0.0, 0.0, 0.0],
    [0.103456, 1.857840, 10.548509], [43.499999, -0.000043, 0.000010], [42.372191, 0.000019, -0.000000],
    [17.299999, -0.000000, 0.000003], [0.103456, 1.857823, -10.548508], [43.500041, -0.000028, 0.000004],
    [42.372260, -0.000001, 0.000010], [17.299994, -0.000006, 0.000017], [6.901967, -2.603732, -0.000003],
    [12.588099, 0.000010, 0.000008], [12.343201, -0.000018, -0.000005], [25.832890, 0.000023, 0.000007],
    [11.766609, -0.000008, -0.000006], [19.745909, -1.480347, 6.000101], [11.284133, 0.000018, -0.000020],
    [33.000049, -0.000014, 0.000018], [25.200004, 0.000032, 0.000011], [19.746101, -1.480358, -6.000078],
    [11.284140, 0.000000, -0.000001], [33.000102, 0.000016, -0.000000], [25.199761, 0.000123, 0.000432],
]


def builtin_skeleton() -> Skeleton:
    return Skeleton(list(NAMES), list(PARENTS), np.asarray(OFFSETS, dtype=np.float64) + 0.0)  # no −0.0


def skeleton_from_stats(stats_path: str | Path, decimals: Optional[int] = 6) -> Skeleton:
    """Names from the statistics file (or the built-in list), offsets from its `offsets` table."""
    s = json.loads(Path(stats_path).read_text())
    names = list(s.get("joints", NAMES))
    if names != NAMES:
        raise ValueError(f"{stats_path}: joints {names} are not the 22 LaFAN1 joints in BVH order")
    offsets = np.zeros((len(names), 3))
    offsets[1:] = np.asarray(s["offsets"], dtype=np.float64).reshape(-1, 3)
    if decimals is not None:
        offsets = np.round(offsets, decimals) + 0.0  # + 0.0 turns −0.0 into 0.0
    return Skeleton(names, list(PARENTS), offsets)


def lafan1_skeleton(data_dir: Optional[str | Path] = None) -> Skeleton:
    """The skeleton from `data_dir` (its smallest BVH's hierarchy and `train_stats_official.json`'s offsets)
    when present, else the built-in copy; both give the same numbers (offsets rounded to 6 decimals)."""
    if data_dir is not None:
        stats = Path(data_dir) / "train_stats_official.json"
        bvhs = sorted(Path(data_dir).glob("*.bvh"))
        if stats.exists() and bvhs:
            from .bvh import read_bvh
            smallest = min(bvhs, key=lambda f: f.stat().st_size)
            hierarchy = read_bvh(smallest, fix_continuity=False).skeleton
            if hierarchy.names != NAMES or hierarchy.parents != PARENTS:
                raise ValueError(f"{bvhs[0]}: hierarchy differs from the 22-joint LaFAN1 skeleton")
            return skeleton_from_stats(stats)
    return builtin_skeleton()
