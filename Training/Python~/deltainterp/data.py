"""LaFAN1 training data: read the BVH files once, pack them, and cut training/validation windows.

`prepare` writes one compact `.npz` (root positions and continuity-fixed local quaternions of every
training file, plus the skeleton) so that a training run — here or on a remote accelerator that gets only
the working tree — never parses BVH again.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import List, Optional, Tuple

import numpy as np

from . import safe_output
from .bvh import lafan1_files, read_bvh, subject_of
from .skeleton import Skeleton, with_offsets
from .lafan1_statistics import load_statistics
from .progress import each

TRAIN_SUBJECTS = (1, 2, 3, 4)
TEST_SUBJECTS = (5,)


@dataclass
class MotionPack:
    skeleton: Skeleton
    files: List[str]
    starts: np.ndarray          # (F+1,) frame offsets of each file in the flat arrays
    root_positions: np.ndarray  # (frames, 3) float32, data units (cm)
    local_quaternions: np.ndarray  # (frames, J, 4) float32
    frame_time: float
    # Per file: True for an augmented copy (e.g. a time-scaled one): trained on (its first 90 %, like any
    # file), never validated on. None (packs written before) means no file is augmented.
    augmented: Optional[np.ndarray] = None
    # What the data is (folders, held-out globs, licences): exported into the model's metadata. "" = LaFAN1.
    description: str = ""

    def is_augmented(self, i: int) -> bool:
        return bool(self.augmented is not None and self.augmented[i])

    def file_frames(self, i: int) -> Tuple[int, int]:
        return int(self.starts[i]), int(self.starts[i + 1])


def prepare(data_dir: str, out: str, stats: Optional[str] = None, subjects=TRAIN_SUBJECTS,
            progress: bool = True) -> MotionPack:
    statistics = load_statistics(stats) if stats else None  # a bad statistics file fails before any BVH is read
    files = lafan1_files(data_dir, tuple(subjects))
    roots, quats, names = [], [], []
    skeleton = None
    frame_time = 1.0 / 30
    for f in each(files, len(files), "reading BVH", "file", progress):
        m = read_bvh(f)
        if skeleton is None:
            skeleton, frame_time = m.skeleton, m.frame_time
        elif m.skeleton.names != skeleton.names or m.skeleton.parents != skeleton.parents:
            raise ValueError(f"{f}: skeleton differs from {files[0]}")
        roots.append(m.root_positions.astype(np.float32))
        quats.append(m.local_quaternions.astype(np.float32))
        names.append(f.name)
    assert skeleton is not None
    if stats:
        # The official benchmark computes positions with the training offsets of its statistics file.
        if len(statistics.offsets) != skeleton.joint_count:
            raise ValueError(f"{stats}: offsets for {len(statistics.offsets)} joints; expected the BVH files' "
                             f"{skeleton.joint_count}")
        skeleton = with_offsets(skeleton, statistics.offsets)
    starts = np.cumsum([0] + [len(r) for r in roots])
    pack = MotionPack(skeleton, names, starts, np.concatenate(roots), np.concatenate(quats), frame_time)
    save_pack(pack, out)
    return pack


def save_pack(pack: MotionPack, path: str) -> None:
    """Writes the pack to exactly `path` through a temporary file beside it (safe_output; the caller
    checks the path, --force, before reading any BVH)."""
    _refuse_non_finite(pack)
    safe_output.write(path, lambda f: np.savez_compressed(
        f, skeleton=json.dumps(pack.skeleton.to_json()), files=np.array(pack.files), starts=pack.starts,
        root_positions=pack.root_positions, local_quaternions=pack.local_quaternions,
        frame_time=pack.frame_time,
        augmented=pack.augmented if pack.augmented is not None else np.zeros(len(pack.files), dtype=bool),
        description=np.array(pack.description)))


def _refuse_non_finite(pack: MotionPack) -> None:
    """NaN or infinity (also a finite 1e308 that float32 turns into infinity) is refused naming its file, never
    packed for `train` to reject as "not a pack"."""
    for i, name in enumerate(pack.files):
        a, b = pack.file_frames(i)
        bad = ~(np.isfinite(pack.root_positions[a:b]).all(axis=1) & np.isfinite(pack.local_quaternions[a:b]).all(axis=(1, 2)))
        if bad.any():
            raise ValueError(f"{name}: frame {int(np.argmax(bad))} holds NaN or infinite values (or values beyond "
                             "float32, e.g. 1e308); expected finite motion (nothing was written)")


PACK_EXPECTED = "expected a pack written by `python3 -m deltainterp prepare`"


def load_pack(path: str) -> MotionPack:
    """A pack written by `prepare`; ValueError (`PATH: what; expected`) for anything else. No pickles."""
    p = Path(path)
    if not p.exists():
        raise FileNotFoundError(f"{path}: not found; {PACK_EXPECTED} first")
    if not p.is_file():
        raise ValueError(f"{path}: is {'a directory' if p.is_dir() else 'not a regular file'}; {PACK_EXPECTED}")
    try:
        with np.load(path, allow_pickle=False) as z:
            pack = MotionPack(Skeleton.from_json(json.loads(str(z["skeleton"]))), [str(f) for f in z["files"]],
                              np.asarray(z["starts"]), np.asarray(z["root_positions"]),
                              np.asarray(z["local_quaternions"]), float(z["frame_time"]),
                              np.asarray(z["augmented"], dtype=bool) if "augmented" in z.files else None,
                              str(z["description"]) if "description" in z.files else "")
    except Exception as e:  # noqa: BLE001 - a file from anywhere: any failure to read it is the file's
        detail = " ".join(str(e).split())[:160]
        raise ValueError(f"{path}: not a readable pack ({type(e).__name__}: {detail}); {PACK_EXPECTED}") from None
    frames, joints = len(pack.root_positions), pack.skeleton.joint_count
    problem = None
    if pack.root_positions.shape != (frames, 3) or pack.local_quaternions.shape != (frames, joints, 4):
        problem = (f"arrays of shapes {pack.root_positions.shape} and {pack.local_quaternions.shape} for "
                   f"{joints} joints")
    elif len(pack.starts) != len(pack.files) + 1 or pack.starts[0] != 0 or pack.starts[-1] != frames \
            or np.any(np.diff(pack.starts) < 0):
        problem = "file start frames that do not cover its frames"
    elif not (np.isfinite(pack.root_positions).all() and np.isfinite(pack.local_quaternions).all()):
        problem = "non-finite motion values"
    elif pack.augmented is not None and pack.augmented.shape != (len(pack.files),):
        problem = f"an augmented flag array of shape {pack.augmented.shape} for {len(pack.files)} files"
    elif not (np.isfinite(pack.frame_time) and pack.frame_time > 0):
        problem = f"frame time {pack.frame_time}"
    if problem:
        raise ValueError(f"{path}: pack holds {problem}; {PACK_EXPECTED}")
    return pack


def windows(frame_count: int, length: int, offset: int) -> List[int]:
    """Window starts as the official benchmark cuts them: 0, offset, … while start + length < frames."""
    starts, i = [], 0
    while i + length < frame_count:
        starts.append(i)
        i += offset
    return starts


def training_ranges(pack: MotionPack, validation_fraction: float = 0.1) -> List[Tuple[int, int]]:
    """Each file's training part as absolute [start, end) frames: its first (1 − fraction), as in
    `split_windows`."""
    ranges = []
    for i in range(len(pack.files)):
        a, b = pack.file_frames(i)
        ranges.append((a, a + int(round((b - a) * (1.0 - validation_fraction)))))
    return ranges


def split_windows(pack: MotionPack, length: int = 50, offset: int = 20, validation_fraction: float = 0.1,
                  validation_length: int = 65, validation_offset: int = 40) -> Tuple[np.ndarray, np.ndarray]:
    """Training windows from the first (1 − fraction) of each file, validation windows from its tail.

    Returns absolute start frames into the pack's flat arrays. Choices (presets, steps) are made on the
    validation windows, never on subject 5."""
    train, val = [], []
    for i in range(len(pack.files)):
        a, b = pack.file_frames(i)
        cut = a + int(round((b - a) * (1.0 - validation_fraction)))
        train += [a + s for s in windows(cut - a, length, offset)]
        if not pack.is_augmented(i):  # a time-scaled copy's tail is the same motion as its original's
            val += [cut + s for s in windows(b - cut, validation_length, validation_offset)]
    return np.asarray(train, dtype=np.int64), np.asarray(val, dtype=np.int64)


__all__ = ["MotionPack", "prepare", "load_pack", "save_pack", "windows", "split_windows", "training_ranges",
           "TRAIN_SUBJECTS", "TEST_SUBJECTS", "subject_of"]
