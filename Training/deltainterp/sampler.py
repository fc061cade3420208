"""Key layouts for training: which frames of a window are keys and which are missing.

The paper's layout is P past keys, a gap of n missing frames, one target key, with p(n) ∝ 1/n on
[min_gap, max_gap]. Other layouts (sparse keys, periodic keys) subclass `KeyLayoutSampler`.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import List

import numpy as np


@dataclass(frozen=True)
class KeyLayout:
    past: int          # P: past keys at frames 0..P-1
    gap: int           # n: missing frames P..P+n-1
    key_frames: List[int]
    query_frames: List[int]

    @property
    def length(self) -> int:
        return max(self.key_frames + self.query_frames) + 1

    @property
    def reference_key(self) -> int:
        """Index (into key_frames) of the last past key: the localization reference."""
        return self.past - 1


class KeyLayoutSampler:
    def sample(self, rng: np.random.Generator) -> KeyLayout:
        raise NotImplementedError


class TransitionSampler(KeyLayoutSampler):
    """P past keys + gap n + 1 target, n ~ p(n) ∝ 1/n (or uniform) on [min_gap, max_gap]."""

    def __init__(self, past: int = 10, min_gap: int = 5, max_gap: int = 39, inverse_weighting: bool = True):
        if not 1 <= past or not 1 <= min_gap <= max_gap:
            raise ValueError("need past ≥ 1 and 1 ≤ min_gap ≤ max_gap")
        self.past = past
        self.gaps = np.arange(min_gap, max_gap + 1)
        w = 1.0 / self.gaps if inverse_weighting else np.ones(len(self.gaps))
        self.probabilities = w / w.sum()

    def layout(self, gap: int) -> KeyLayout:
        p = self.past
        return KeyLayout(p, gap, list(range(p)) + [p + gap], list(range(p, p + gap)))

    def sample(self, rng: np.random.Generator) -> KeyLayout:
        return self.layout(int(rng.choice(self.gaps, p=self.probabilities)))

    @property
    def max_length(self) -> int:
        return self.past + int(self.gaps[-1]) + 1
