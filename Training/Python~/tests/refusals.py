"""Helpers for tests of refusals: run the trainer's CLI in-process and check its one-line `error: ...` (exit 2).
Shared by the behaviour-named test files of issue 31."""
from __future__ import annotations

import json
from pathlib import Path

from deltainterp.cli import main

HEADER = ("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation "
          "Yrotation Xrotation\n  End Site\n  {\n    OFFSET 0 1 0\n  }\n}\nMOTION\n")
ONE_JOINT_STATS = {"x_mean": [0.0] * 3, "x_std": [1.0] * 3, "offsets": []}  # one joint, as HEADER


def bvh(frames: int = 3) -> str:
    """A one-joint BVH of `frames` frames at 30 fps."""
    rows = [f"{f * 0.1:.2f} 90 0 {(7 * f) % 50} {(3 * f) % 40} {f % 30}" for f in range(frames)]  # turning
    return HEADER + f"Frames: {frames}\nFrame Time: 0.0333333\n" + "\n".join(rows) + "\n"


def lafan1_folder(tmp_path: Path, frames: int = 3) -> Path:
    """A folder `prepare` packs the LaFAN1 way (no retargeting): two one-joint files and stats.json beside it."""
    data = tmp_path / "data"
    data.mkdir()
    (data / "walk1_subject1.bvh").write_text(bvh(frames))
    (data / "walk1_subject5.bvh").write_text(bvh(frames))
    (tmp_path / "stats.json").write_text(json.dumps(ONE_JOINT_STATS))
    return data


def run_cli(capsys, argv):
    """main(argv) in-process → (exit code, stdout, stderr)."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def one_line(code, err, phrase=None) -> str:
    """The single `error: ...; expected ...` line of a refusal (exit 2), tqdm bars aside."""
    assert code == 2, err
    lines = [line for line in err.replace("\r", "\n").splitlines() if line.strip() and "%|" not in line]
    assert len(lines) == 1, f"expected one line on stderr, got:\n{err}"
    assert lines[0].startswith("error: ") and "Traceback" not in err and "expected" in lines[0], lines[0]
    if phrase is not None:
        assert phrase in lines[0], lines[0]
    return lines[0]
