"""Data manifests and file plans for `prepare` on any humanoid BVH (no retargeting runs here)."""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from deltainterp.cli import main
from deltainterp.datasets import open_source, plan_files

REPO = Path(__file__).resolve().parents[3]


def _folder(tmp_path: Path, manifest: dict | None = None) -> Path:
    data = tmp_path / "data"
    (data / "sub").mkdir(parents=True)
    for name in ("01_01.bvh", "02_01.bvh", "60_01.bvh", "sub/13_10.bvh"):
        (data / name).write_text("HIERARCHY\n")
    (data / "notes.txt").write_text("not motion")
    if manifest is not None:
        (data / "inbetween-data.json").write_text(json.dumps(manifest))
    return data


def test_defaults_overrides_holdout_skip_and_time_scales(tmp_path):
    data = _folder(tmp_path, {"defaults": {"from_frame": 1, "reference_frame": 0},
                              "files": {"60_*.bvh": {"fps": 60, "from_frame": 10}, "sub/*": {"skip": True}},
                              "groups": "(\\d+)_\\d+\\.bvh$"})
    plans = plan_files(open_source(str(data)), {}, holdout=["02_*"], time_scales=[0.8, 1.25])
    originals = [p for p in plans if p.time_scale == 1.0]
    assert [p.name for p in originals] == ["01_01.bvh", "60_01.bvh"]
    salsa = next(p for p in originals if p.name == "60_01.bvh")
    assert (salsa.fps, salsa.from_frame, salsa.reference_frame, salsa.group) == (60, 10, 0, "60")
    assert sorted({p.time_scale for p in plans}) == [0.8, 1.0, 1.25] and len(plans) == 6


def test_options_override_manifest_defaults_but_not_per_file_entries(tmp_path):
    data = _folder(tmp_path, {"defaults": {"from_frame": 1}, "files": {"01_*": {"from_frame": 5}}})
    plans = {p.name: p for p in plan_files(open_source(str(data)), {"from_frame": 3}, [], [])}
    assert plans["01_01.bvh"].from_frame == 5 and plans["02_01.bvh"].from_frame == 3


def test_up_reaches_retarget_per_file_and_from_the_command_line(tmp_path):
    """Issue 30: the manifest's "up" (auto, y, z; as score's reader) becomes `retarget --up`; an option overrides the default."""
    from deltainterp.datasets import _retarget_args
    data = _folder(tmp_path, {"defaults": {"up": "auto"}, "files": {"60_*": {"up": "z"}}})
    plans = {p.name: p for p in plan_files(open_source(str(data)), {}, [], [])}
    assert plans["60_01.bvh"].up == "z" and plans["01_01.bvh"].up == "auto"
    args = _retarget_args(plans["60_01.bvh"], tmp_path / "o.bvh", None)
    assert args[args.index("--up") + 1] == "z"
    forced = {p.name: p for p in plan_files(open_source(str(data)), {"up": "y"}, [], [])}
    assert forced["01_01.bvh"].up == "y" and forced["60_01.bvh"].up == "z"
    bare = _folder(tmp_path / "bare")
    assert "--up" not in _retarget_args(plan_files(open_source(str(bare)), {}, [], [])[0], tmp_path / "o.bvh", None)


def test_accept_reference_pose_reaches_retarget_per_file(tmp_path):
    """Issue 30: the manifest's "accept_reference_pose" (as score's reader) becomes `retarget --accept-reference-pose` for that file only."""
    from deltainterp.datasets import _retarget_args
    data = _folder(tmp_path, {"files": {"60_*": {"accept_reference_pose": True}}})
    plans = {p.name: p for p in plan_files(open_source(str(data)), {}, [], [])}
    assert plans["60_01.bvh"].accept_reference_pose and not plans["01_01.bvh"].accept_reference_pose
    assert "--accept-reference-pose" in _retarget_args(plans["60_01.bvh"], tmp_path / "o.bvh", None)
    assert "--accept-reference-pose" not in _retarget_args(plans["01_01.bvh"], tmp_path / "o.bvh", None)


def test_prepare_refuses_a_hostile_up_in_one_line(tmp_path, capsys):
    data = _folder(tmp_path)
    code = main(["prepare", "--data", str(data), "--up", "x\x1b[2J", "--out", str(tmp_path / "o.npz")])
    err = capsys.readouterr().err.strip()
    assert code == 2 and "--up" in err and "expected auto, y or z" in err and "\n" not in err and "\x1b" not in err


def test_a_manifest_file_names_its_folder_relative_to_itself(tmp_path):
    data = _folder(tmp_path)
    manifest = tmp_path / "sets" / "mine.json"
    manifest.parent.mkdir()
    manifest.write_text(json.dumps({"folder": "../data", "defaults": {"map": "rig.json"}}))
    source = open_source(str(manifest))
    assert source.folder == data.resolve()
    plan = plan_files(source, {}, [], [])[0]
    assert plan.map == manifest.parent / "rig.json"


@pytest.mark.parametrize("manifest, phrase", [
    ({"default": {}}, "unknown field"),
    ({"defaults": {"from_frame": -1}}, "from_frame"),
    ({"defaults": {"fps": 0}}, "fps"),
    ({"files": {"x": {"speed": 2}}}, "unknown setting"),
    ({"groups": "("}, "regular expression"),
    ({"defaults": {"skip": "yes"}}, "skip"),
    ({"defaults": {"up": "x"}}, "\"up\""),
    ({"files": {"a*": {"up": "Z; rm -rf /"}}}, "\"up\""),
    ({"defaults": {"up": 1}}, "\"up\""),
    ({"defaults": {"accept_reference_pose": "yes"}}, "\"accept_reference_pose\""),
    ({"files": {"a*": {"accept_reference_pose": 1}}}, "\"accept_reference_pose\""),
])
def test_bad_manifests_are_refused_naming_the_file(tmp_path, manifest, phrase):
    data = _folder(tmp_path, manifest)
    with pytest.raises(ValueError) as e:
        open_source(str(data))
    assert str(e.value).startswith(str(data / "inbetween-data.json") + ": ") and phrase in str(e.value)


def test_the_repository_manifests_read(tmp_path):
    for name in ("cmu.json", "cmu-more.json"):
        path = REPO / "Training" / "Python~" / "datasets" / name
        try:
            source = open_source(str(path))
        except ValueError as e:
            if "is not a folder" in str(e):
                pytest.skip(f"{path}: its data folder is not beside the repository")
            raise
        assert source.licence and "mocap.cs.cmu.edu" in source.licence


def test_prepare_refuses_an_output_that_is_one_of_its_bvh_inputs(tmp_path, capsys):
    data = _folder(tmp_path)
    target = data / "01_01.bvh"
    assert main(["prepare", "--data", str(data), "--out", str(target), "--force"]) == 2
    assert "input" in capsys.readouterr().err
    assert target.read_text() == "HIERARCHY\n"


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
def test_a_fifo_named_bvh_is_refused_not_read(tmp_path):
    data = _folder(tmp_path)
    os.mkfifo(data / "03_01.bvh")
    with pytest.raises(ValueError, match="not a regular file"):
        plan_files(open_source(str(data)), {}, [], [])
