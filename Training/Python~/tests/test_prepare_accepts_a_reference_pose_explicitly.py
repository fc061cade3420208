"""Issue 30: `prepare --accept-reference-pose`, the explicit override of the 25° humanoid rule (as on `retarget`,
`bake` and `score`; the manifest's "accept_reference_pose" does it per file): refused without it naming the way
out, kept with it, and what it let through reported in every output — the console (a warning per file, also on a
cache hit) and the pack's description. Hostile values are refused in one line.

The bundled CMU clip's frame 1 is a crouch whose legs and spine point 26-30° from the model's standing pose, so
`--reference-frame 1` is the reference pose the rule refuses."""
from __future__ import annotations

import json
import shutil

import pytest

from conftest import REPO
from refusals import one_line, run_cli

from deltainterp.data import load_pack
from deltainterp.datasets import ACCEPTED, accepted_note

CLIP = REPO / "Samples~" / "Demo" / "cmu_01_01_jumps_turn.bvh"
needs_tool = pytest.mark.skipif(shutil.which("dotnet") is None, reason="dotnet is not installed: prepare retargets in the C# tool")


def _folder(tmp_path, manifest=None):
    folder = tmp_path / "data"
    folder.mkdir()
    shutil.copy(CLIP, folder / "crouch.bvh")
    if manifest is not None:
        (folder / "inbetween-data.json").write_text(json.dumps(manifest))
    return folder


@needs_tool
def test_the_flag_keeps_a_refused_reference_pose_and_every_output_says_so(tmp_path, capsys):
    data = _folder(tmp_path)
    args = ["prepare", "--data", data, "--reference-frame", "1", "--cache", tmp_path / "cache", "--jobs", "1"]
    code, _, err = run_cli(capsys, args + ["--out", tmp_path / "refused.npz"])
    line = one_line(code, err, "--accept-reference-pose")
    assert "--reference-frame" in line and line.count("; expected") == 1
    assert not (tmp_path / "refused.npz").exists()

    for attempt in ("retargeted", "from the cache"):
        out_path = tmp_path / f"pack-{attempt.split()[0]}.npz"
        code, out, err = run_cli(capsys, args + ["--accept-reference-pose", "--out", out_path])
        assert code == 0, err
        warnings = [w for w in out.splitlines() if w.startswith("warning: ")]
        assert len(warnings) == 1, out
        assert warnings[0].startswith(f"warning: {data / 'crouch.bvh'}: {ACCEPTED} although 5 bone(s)"), attempt
        assert "Spine (Spine1)" in warnings[0] and "LeftUpLeg (LeftUpLeg)" in warnings[0]
        description = load_pack(str(out_path)).description
        assert "1 reference pose(s) kept by --accept-reference-pose that the 25° humanoid rule refuses: crouch.bvh: although 5 bone(s)" in description, description


@needs_tool
def test_the_manifest_key_is_reported_the_same_way(tmp_path, capsys):
    data = _folder(tmp_path, {"files": {"crouch.bvh": {"reference_frame": 1, "accept_reference_pose": True}}})
    code, out, err = run_cli(capsys, ["prepare", "--data", data, "--out", tmp_path / "p.npz", "--cache", tmp_path / "c"])
    assert code == 0, err
    assert f"warning: {data / 'crouch.bvh'}: {ACCEPTED}" in out
    assert "kept by --accept-reference-pose" in load_pack(str(tmp_path / "p.npz")).description


def test_a_standing_reference_pose_needs_no_report():
    assert accepted_note("╭──╮\n│ Wrote │ x.bvh │\n╰──╯\n") == ""
    wrapped = "│ Wrote │ x │\nwarning: x.bvh: reference pose accepted by \n--accept-reference-pose although 1 bone(s) point\nmore than 25°: Spine (Spine) 40°\n"
    assert accepted_note(wrapped) == f"{ACCEPTED} although 1 bone(s) point more than 25°: Spine (Spine) 40°"


@pytest.mark.parametrize("value", ["yes", "1", "\x1b[2J"])
def test_a_value_given_to_the_flag_is_refused_in_one_line(value, tmp_path, capsys):
    data = _folder(tmp_path)
    code, _, err = run_cli(capsys, ["prepare", "--data", data, f"--accept-reference-pose={value}", "--out", tmp_path / "o.npz"])
    line = one_line(code, err, "--accept-reference-pose")
    assert "\x1b" not in err and line.count("; expected") == 1
    assert not (tmp_path / "o.npz").exists()
