"""Skeleton: joint names, parent indices and bone offsets (mirrors `Runtime/Core/Skeletons/Skeleton.cs`)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import List, Sequence

import numpy as np


@dataclass(frozen=True)
class Skeleton:
    names: List[str]
    parents: List[int]
    offsets: np.ndarray  # (J, 3), data units; the root's is ignored (its translation comes from the data)

    def __post_init__(self) -> None:
        j = len(self.names)
        if len(self.parents) != j or self.offsets.shape != (j, 3):
            raise ValueError(f"skeleton has {j} names, {len(self.parents)} parents, offsets {self.offsets.shape}")
        if j == 0 or self.parents[0] != -1 or any(p == -1 for p in self.parents[1:]):
            raise ValueError("skeleton must have exactly one root, at index 0")
        for i, p in enumerate(self.parents[1:], start=1):
            if not 0 <= p < i:
                raise ValueError(f"joint {self.names[i]} has parent {p}; parents must come before children")
        if len(set(self.names)) != j:
            raise ValueError("joint names must be unique")

    @property
    def joint_count(self) -> int:
        return len(self.names)

    def index(self, name: str) -> int:
        return self.names.index(name)

    def mirror_map(self) -> List[int]:
        """For each joint, the index of its left/right counterpart (itself when unpaired)."""
        out = []
        for n in self.names:
            other = n.replace("Left", "\0").replace("Right", "Left").replace("\0", "Right")
            out.append(self.names.index(other) if other in self.names else self.names.index(n))
        return out

    def to_json(self) -> dict:
        return {"names": list(self.names), "parents": list(self.parents),
                "offsets": [[float(v) for v in o] for o in self.offsets]}

    @staticmethod
    def from_json(d: dict) -> "Skeleton":
        return Skeleton(list(d["names"]), [int(p) for p in d["parents"]],
                        np.asarray(d["offsets"], dtype=np.float64).reshape(-1, 3))


def with_offsets(skeleton: Skeleton, offsets: Sequence[Sequence[float]]) -> Skeleton:
    return Skeleton(skeleton.names, skeleton.parents, np.asarray(offsets, dtype=np.float64).reshape(-1, 3))
