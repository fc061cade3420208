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


def past_probabilities(min_past: int, max_past: int, longest_share: float, uniform: bool = False) -> np.ndarray:
    """p(P) on [min_past, max_past]: `longest_share` on P = max_past (the game's full history and the
    benchmark), `(1 - longest_share) / 2` on P = 1 (a clip's first gap when baking keys), the rest spread
    evenly over the lengths between; or, with `uniform`, the same for every length. With min_past ==
    max_past it is that one length."""
    count = max_past - min_past + 1
    if count == 1:
        return np.ones(1)
    if uniform:
        return np.full(count, 1.0 / count)
    if not 0.0 < longest_share < 1.0:
        raise ValueError(f"the longest past's share must be in (0, 1), got {longest_share}")
    p = np.zeros(count)
    p[-1] = longest_share
    if count == 2:
        p[0] = 1.0 - longest_share
    else:
        p[0] = (1.0 - longest_share) / 2.0
        p[1:-1] = (1.0 - longest_share) / 2.0 / (count - 2)
    return p


class TransitionSampler(KeyLayoutSampler):
    """P past keys + gap n + 1 target; n ~ p(n) ∝ 1/n (or uniform) on [min_gap, max_gap], and P on
    [min_past, past] by `past_probabilities` (P = `past` always when min_past is not given)."""

    def __init__(self, past: int = 10, min_gap: int = 5, max_gap: int = 39, inverse_weighting: bool = True,
                 min_past: int | None = None, longest_past_share: float = 0.4, uniform_past: bool = False):
        min_past = past if min_past is None else min_past
        if not 1 <= min_past <= past or not 1 <= min_gap <= max_gap:
            raise ValueError("need 1 ≤ min_past ≤ past and 1 ≤ min_gap ≤ max_gap")
        self.past = past
        self.pasts = np.arange(min_past, past + 1)
        self.past_probabilities = past_probabilities(min_past, past, longest_past_share, uniform_past)
        self.gaps = np.arange(min_gap, max_gap + 1)
        w = 1.0 / self.gaps if inverse_weighting else np.ones(len(self.gaps))
        self.probabilities = w / w.sum()

    def layout(self, gap: int, past: int | None = None) -> KeyLayout:
        p = self.past if past is None else past
        return KeyLayout(p, gap, list(range(p)) + [p + gap], list(range(p, p + gap)))

    def sample(self, rng: np.random.Generator) -> KeyLayout:
        gap = int(rng.choice(self.gaps, p=self.probabilities))
        if len(self.pasts) == 1:  # draw nothing more: keeps single-layout runs' RNG streams as they were
            return self.layout(gap)
        return self.layout(gap, int(rng.choice(self.pasts, p=self.past_probabilities)))

    @property
    def max_length(self) -> int:
        return self.past + int(self.gaps[-1]) + 1
