"""Window cutting and counts."""
from __future__ import annotations

import numpy as np
import pytest

from deltainterp.bvh import lafan1_files
from deltainterp.data import load_pack, split_windows, windows


@pytest.mark.parametrize("frames, length, offset, expected", [
    (65, 65, 40, []),                # start + length < frames is strict: a file of exactly one window gives none
    (66, 65, 40, [0]),
    (105, 65, 40, [0]),              # 40 + 65 = 105 is not < 105
    (106, 65, 40, [0, 40]),
    (200, 50, 20, [0, 20, 40, 60, 80, 100, 120, 140]),
    (10, 50, 20, []),
])
def test_windows_follow_the_official_strict_rule(frames, length, offset, expected):
    assert windows(frames, length, offset) == expected


@pytest.mark.parametrize("frames", [66, 105, 106, 1000, 5047])
def test_window_count_formula(frames):
    assert len(windows(frames, 65, 40)) == max(0, (frames - 65 - 1) // 40 + 1)


def _frame_count(path) -> int:
    with open(path) as f:
        for line in f:
            if line.strip().startswith("Frames:"):
                return int(line.split(":")[1])
    raise ValueError(path)


def test_real_lafan1_test_window_count(lafan1_dir):
    files = lafan1_files(lafan1_dir, (5,))
    assert [f.name for f in files] == ["fallAndGetUp1_subject5.bvh", "ground1_subject5.bvh",
                                       "obstacles1_subject5.bvh"]
    assert sum(len(windows(_frame_count(f), 65, 40)) for f in files) == 376


def test_real_lafan1_training_files(lafan1_dir):
    files = lafan1_files(lafan1_dir, (1, 2, 3, 4))
    assert len(files) == 24
    frames = sum(_frame_count(f) for f in files)
    assert frames == 125_493 - 15_180  # SOURCES.md: all 27 files minus the subject-5 ones


def test_split_windows_keep_validation_tails_apart(synthetic_pack_path):
    pack = load_pack(str(synthetic_pack_path))
    train, val = split_windows(pack)
    for i in range(len(pack.files)):
        a, b = pack.file_frames(i)
        cut = a + int(round((b - a) * 0.9))
        t = train[(train >= a) & (train < b)]
        v = val[(val >= a) & (val < b)]
        assert len(t) > 0 and len(v) > 0
        assert np.all(t + 50 <= cut), "a training window reaches into the validation tail"
        assert np.all(v >= cut) and np.all(v + 65 <= b)
