"""LaFAN1's official statistics file (train_stats_official.json): the mean and standard deviation that L2P
standardises with and the training bone offsets that the benchmark's ground truth uses (method-spec §1.9).
Its own module so that both `data` (packing LaFAN1 with those offsets) and `benchmark` read it without
importing each other."""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .safe_input import check_regular


@dataclass
class Statistics:
    x_mean: np.ndarray   # (66,) index 3·joint + axis, cm
    x_std: np.ndarray    # (66,)
    offsets: np.ndarray  # (J, 3) cm, the root's row is zero
    path: str


def load_statistics(path: str | Path) -> Statistics:
    path = Path(path)
    if not path.exists():
        raise FileNotFoundError(f"{path}: statistics file not found; expected LaFAN1's train_stats_official.json")
    check_regular(path, "LaFAN1's train_stats_official.json")  # a named pipe would block the read
    try:
        s = json.loads(path.read_text())
    except (ValueError, RecursionError) as e:  # not JSON, not UTF-8, nested too deeply: name the file
        detail = " ".join(str(e).split())[:120] if not isinstance(e, RecursionError) else "nested too deeply"
        raise ValueError(f"{path}: not JSON ({detail}); expected LaFAN1's train_stats_official.json") from None
    for key in ("x_mean", "x_std", "offsets"):
        if not isinstance(s, dict) or key not in s:
            raise ValueError(f"{path}: missing '{key}'; expected LaFAN1's train_stats_official.json "
                             "(x_mean, x_std, offsets)")
    mean = np.asarray(s["x_mean"], dtype=np.float64).reshape(-1)
    std = np.asarray(s["x_std"], dtype=np.float64).reshape(-1)
    rest = np.asarray(s["offsets"], dtype=np.float64).reshape(-1, 3)
    offsets = np.concatenate((np.zeros((1, 3)), rest))
    if mean.shape != std.shape or mean.size != 3 * len(offsets):
        raise ValueError(f"{path}: x_mean {mean.shape}, x_std {std.shape} and {len(offsets)} joints disagree")
    return Statistics(mean, std, offsets, str(path))
