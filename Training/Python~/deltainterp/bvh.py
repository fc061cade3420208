"""BVH reading with Core's conventions (mirrors `Runtime/Core/Bvh/BvhReader.cs`).

Euler angles are intrinsic in each joint's CHANNELS order, in degrees; End Sites are not joints; joints
may have 3 or 6 channels in any order. Errors name the file and line.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import List, Tuple

import numpy as np
import torch

from . import quaternions
from .safe_input import check_regular
from .skeleton import Skeleton


class BvhFormatError(ValueError):
    def __init__(self, path: str, line: int, message: str) -> None:
        super().__init__(f"{path}:{line}: {message}")
        self.path, self.line = path, line


@dataclass
class Motion:
    skeleton: Skeleton
    root_positions: np.ndarray    # (T, 3) data units
    local_quaternions: np.ndarray  # (T, J, 4) (w,x,y,z), continuity-fixed along time
    frame_time: float

    @property
    def frame_count(self) -> int:
        return self.root_positions.shape[0]


_CHANNELS = {"xposition", "yposition", "zposition", "xrotation", "yrotation", "zrotation"}


def read_bvh(path: str | Path, fix_continuity: bool = True) -> Motion:
    check_regular(path, "a BVH motion file")  # a named pipe would block the reader, /dev/zero never ends
    try:
        return _read_bvh(path, fix_continuity)
    except BvhFormatError:
        raise
    except (ValueError, IndexError, UnicodeDecodeError) as e:  # float('x'), a short line, bytes not UTF-8
        detail = " ".join(str(e).split())[:120]
        raise ValueError(f"{path}: not a readable BVH file ({type(e).__name__}: {detail}); "
                         "expected a BVH motion file (HIERARCHY, MOTION, one frame of numbers per line)") from None


def _read_bvh(path: str | Path, fix_continuity: bool = True) -> Motion:
    path = str(path)
    with open(path, "r", encoding="utf-8") as f:
        lines = f.read().splitlines()
    if not lines:
        raise BvhFormatError(path, 1, "empty file; expected 'HIERARCHY'")
    names: List[str] = []
    parents: List[int] = []
    offsets: List[List[float]] = []
    channels: List[List[str]] = []
    stack: List[int] = []
    in_end_site = False
    i = 0
    while i < len(lines) and not lines[i].strip():
        i += 1
    if i >= len(lines) or lines[i].strip() != "HIERARCHY":
        raise BvhFormatError(path, i + 1, "expected 'HIERARCHY'")
    i += 1
    pending_parent = -1
    while i < len(lines):
        tok = lines[i].split()
        i += 1
        if not tok:
            continue
        key = tok[0]
        if key in ("ROOT", "JOINT"):
            if len(tok) < 2:
                raise BvhFormatError(path, i, f"{key} without a name")
            if tok[1] in names:
                raise BvhFormatError(path, i, f"duplicate joint name '{tok[1]}'")
            pending_parent = stack[-1] if stack else -1
            names.append(tok[1])
            parents.append(pending_parent)
            offsets.append([0.0, 0.0, 0.0])
            channels.append([])
        elif key == "End":
            in_end_site = True
        elif key == "{":
            stack.append(-2 if in_end_site else len(names) - 1)
        elif key == "}":
            if not stack:
                raise BvhFormatError(path, i, "unbalanced '}'")
            if stack.pop() == -2:
                in_end_site = False
        elif key == "OFFSET":
            if not in_end_site:
                offsets[-1] = [float(v) for v in tok[1:4]]
        elif key == "CHANNELS":
            n = int(tok[1])
            ch = [c.lower() for c in tok[2:2 + n]]
            for c in ch:
                if c not in _CHANNELS:
                    raise BvhFormatError(path, i, f"unknown channel '{c}'")
            channels[-1] = ch
        elif key == "MOTION":
            break
        else:
            raise BvhFormatError(path, i, f"unexpected '{key}'")
    else:
        raise BvhFormatError(path, i, "expected 'MOTION'")
    if stack:
        raise BvhFormatError(path, i, "unbalanced braces before MOTION")
    frames = int(lines[i].split(":")[1])
    frame_time = float(lines[i + 1].split(":")[1])
    body = " ".join(lines[i + 2:i + 2 + frames])
    values = np.array(body.split(), dtype=np.float64)
    width = sum(len(c) for c in channels)
    if values.size != frames * width:
        raise BvhFormatError(path, i + 2, f"expected {frames} motion lines of {width} values")
    values = values.reshape(frames, width)

    j = len(names)
    skeleton = Skeleton(names, parents, np.asarray(offsets, dtype=np.float64))
    root = np.repeat(skeleton.offsets[:1], frames, axis=0).copy()
    quats = np.zeros((frames, j, 4))
    col = 0
    for joint, ch in enumerate(channels):
        rot_cols, order = [], ""
        for c in ch:
            if c.endswith("position"):
                if joint == 0:
                    root[:, "xyz".index(c[0])] = values[:, col]
            else:
                rot_cols.append(col)
                order += c[0]
            col += 1
        if len(order) == 3:
            q = quaternions.from_euler(torch.from_numpy(np.radians(values[:, rot_cols])), order)
            quats[:, joint] = q.numpy()
        else:
            quats[:, joint, 0] = 1.0
    if fix_continuity:
        quats = quaternions.remove_discontinuities(torch.from_numpy(quats), dim=0).numpy()
    return Motion(skeleton, root, quats, frame_time)


def subject_of(path: str | Path) -> int:
    """LaFAN1 file names are <theme><take>_subject<k>.bvh."""
    stem = Path(path).stem
    tail = stem.split("_")[-1]
    if not (tail.startswith("subject") and tail[len("subject"):].isdigit()):
        raise ValueError(f"{path}: the name does not end in _subject<k>; expected LaFAN1 names "
                         "<theme><take>_subject<k>.bvh here (`prepare` takes any humanoid BVH folder or a data manifest)")
    return int(tail[len("subject"):])


def lafan1_files(data_dir: str | Path, subjects: Tuple[int, ...]) -> List[Path]:
    files = sorted(p for p in Path(data_dir).glob("*.bvh") if subject_of(p) in subjects)
    if not files:
        raise FileNotFoundError(f"{data_dir}: no LaFAN1 BVH files of subjects {subjects}; expected a folder of "
                                "<theme><take>_subject<k>.bvh files (LaFAN1)")
    return files
