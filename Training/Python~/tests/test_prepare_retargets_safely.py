"""`prepare`'s retargeting: a data file whose name looks like an option is still a file (class 22); the cache is
keyed by the file's content and the tool's version (3); a manifest's map is refused by its size before it is read
(8); a backtracking `groups` regex is refused within seconds (5); SIGTERM, SIGHUP and SIGINT end the
`inbetween retarget` children and leave no temporary file (19) (issue 31)."""
from __future__ import annotations

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from deltainterp import datasets
from deltainterp.data import load_pack

from conftest import REPO, TRAINING
from refusals import bvh, one_line, run_cli

CLIP = REPO / "Samples~" / "Demo" / "cmu_01_01_jumps_turn.bvh"
CLIP_HEAD = next(i for i, line in enumerate(CLIP.read_text().splitlines()) if line.startswith("Frame Time")) + 1


def _needs_the_tool():
    if shutil.which("dotnet") is None or not (REPO / "Tools~" / "inbetween").exists():
        pytest.skip("dotnet is not installed: the retargeting runs in the C# tool")


# 22 and 3, on the real tool: a file named like an option is prepared; a corrected file of equal size whose time
#    was kept is retargeted again, not packed from the old entry.
def test_a_file_named_like_an_option_is_prepared_and_its_corrected_content_repacked(tmp_path, capsys, monkeypatch):
    _needs_the_tool()
    monkeypatch.delenv("INBETWEEN", raising=False)
    text = "".join(CLIP.read_text().splitlines(keepends=True)[:CLIP_HEAD + 200])
    text = re.sub(r"Frames:\s*\d+", "Frames: 200", text)
    control = tmp_path / "control"
    control.mkdir()
    (control / "plain.bvh").write_text(text)
    code, _, err = run_cli(capsys, ["prepare", "--data", control, "--out", tmp_path / "control.npz", "--cache",
                                    tmp_path / "control-cache"])
    assert code == 0, err
    plain = load_pack(str(tmp_path / "control.npz"))
    data = tmp_path / "data"
    data.mkdir()
    clip = data / "--from-frame=5.bvh"
    clip.write_text(text)
    monkeypatch.chdir(data)
    argv = ["prepare", "--data", ".", "--out", tmp_path / "pack.npz", "--cache", tmp_path / "cache", "--force"]
    code, out, err = run_cli(capsys, argv)
    assert code == 0, err
    first = load_pack(str(tmp_path / "pack.npz"))
    assert first.files[0].endswith("--from-frame=5.bvh"), first.files
    # The whole file, as the plainly named copy: no option took 5 frames off it.
    assert len(first.root_positions) == len(plain.root_positions)
    assert np.allclose(first.local_quaternions, plain.local_quaternions)

    stat = clip.stat()
    body = clip.read_text().splitlines(keepends=True)
    body[CLIP_HEAD + 40], body[CLIP_HEAD + 120] = body[CLIP_HEAD + 120], body[CLIP_HEAD + 40]  # equal size, other motion
    clip.write_text("".join(body))
    os.utime(clip, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert clip.stat().st_size == stat.st_size and clip.stat().st_mtime_ns == stat.st_mtime_ns
    code, _, err = run_cli(capsys, argv)
    assert code == 0, err
    second = load_pack(str(tmp_path / "pack.npz"))
    assert not np.allclose(first.local_quaternions, second.local_quaternions)


def test_the_cache_entry_follows_the_content_and_the_tool_version(tmp_path):
    clip = tmp_path / "take.bvh"
    clip.write_text(bvh(5))
    plan = datasets.FilePlan(clip, "take.bvh", str(tmp_path))
    args = datasets._retarget_args(plan, Path("OUT"), None)
    key = datasets._cache_key(plan, args, "tool 1")
    moved = tmp_path / "elsewhere.bvh"
    shutil.copy(clip, moved)
    assert datasets._cache_key(datasets.FilePlan(moved, "elsewhere.bvh", str(tmp_path)),
                               datasets._retarget_args(datasets.FilePlan(moved, "e", ""), Path("OUT"), None),
                               "tool 1") == key  # the content, not the path
    stat = clip.stat()
    clip.write_text(bvh(5).replace("0.10 90 0", "0.20 90 0"))
    os.utime(clip, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert clip.stat().st_size == stat.st_size and datasets._cache_key(plan, args, "tool 1") != key
    clip.write_text(bvh(5))
    assert datasets._cache_key(plan, args, "tool 1") == key and datasets._cache_key(plan, args, "tool 2") != key
    one, two = tmp_path / "one", tmp_path / "two"
    one.write_text("#!/bin/sh\n")
    two.write_text("#!/bin/sh\n# rebuilt\n")
    assert datasets.tool_version([str(one)]) != datasets.tool_version([str(two)])


# 8. A manifest's map was read whole to hash it before the size limit refused it (a sparse 2 GB map: 2.3 GB).
def test_an_oversized_map_is_refused_before_it_is_read(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("INBETWEEN", "/bin/false")
    data = tmp_path / "data"
    data.mkdir()
    (data / "take.bvh").write_text(bvh(5))
    with open(data / "huge.json", "wb") as f:
        f.truncate(256 << 20)  # sparse: no disk, but reading it whole costs 256 MB
    (data / "inbetween-data.json").write_text(json.dumps({"defaults": {"map": "huge.json"}}))
    started = time.monotonic()
    code, _, err = run_cli(capsys, ["prepare", "--data", data, "--out", tmp_path / "p.npz", "--cache", tmp_path / "c"])
    line = one_line(code, err, "is 268,435,456 bytes or more; expected a JSON joint map of at most 1,048,576 bytes")
    assert str(data / "huge.json") in line and time.monotonic() - started < 20


# 5. `groups` was applied with Python `re` unbounded: ^(a|aa)+$ on a 200-character name never finished. The
#    manifest reader refuses the repeated-group shape from the text; this pattern (no repeated group) slips past
#    such a scan and backtracks polynomially (C(70, 10) paths), so only the time bound stops it.
SLOW_GROUPS = "^(x?)" + "a*" * 10 + "$"


def test_a_backtracking_groups_regex_is_refused_within_seconds(tmp_path):
    data = tmp_path / "data"
    data.mkdir()
    name = "a" * 60 + "b"
    (data / f"{name}.bvh").write_text(bvh(5))
    (data / "02_01.bvh").write_text(bvh(5))
    (data / "inbetween-data.json").write_text(json.dumps({"groups": SLOW_GROUPS}))
    env = dict(os.environ, PYTHONPATH=str(TRAINING), INBETWEEN="/bin/false")
    started = time.monotonic()
    r = subprocess.run([sys.executable, "-m", "deltainterp", "prepare", "--data", str(data), "--out",
                        str(tmp_path / "p.npz"), "--cache", str(tmp_path / "c")], capture_output=True, text=True,
                       env=env, timeout=60)
    line = one_line(r.returncode, r.stderr, f'inbetween-data.json: "groups" took over 1 s on "{name}.bvh"; '
                                            "expected a pattern that does not backtrack catastrophically")
    assert time.monotonic() - started < 30
    assert datasets.subject_groups(r"^(\d+)_", ["02_01.bvh", "x.bvh", "13_7.bvh"], "m.json") == ["02", "", "13"]


# 19. SIGTERM/SIGHUP killed prepare at once; its `inbetween retarget` children ran on and left .tmp.bvh files.
SLOW_TOOL = r"""
import os, sys, time
args = sys.argv[1:]
out = args[args.index("--out") + 1]
with open(out, "w") as f:
    f.write("HIERARCHY\n")  # a half-written output, as a tool interrupted mid-write leaves it
with open(os.path.join(os.environ["MARKERS"], str(os.getpid())), "w") as f:
    f.write(out)
time.sleep(120)
"""


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    with open(f"/proc/{pid}/stat") as f:  # a zombie (ended, not yet reaped by init) counts as ended
        return f.read().split(")")[-1].split()[0] != "Z"


def _default_signal_dispositions() -> None:
    """The child starts with the default SIGHUP/SIGTERM/SIGINT dispositions whatever this run inherited: under `nohup`
    (SIGHUP ignored) prepare rightly keeps an ignored SIGHUP ignored, which is not what this test asks about."""
    for sig in (signal.SIGHUP, signal.SIGTERM, signal.SIGINT):
        signal.signal(sig, signal.SIG_DFL)


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP, signal.SIGINT], ids=lambda s: s.name)
def test_a_signal_ends_the_retargeting_children_and_removes_their_files(sig, tmp_path):
    data, cache, markers = tmp_path / "data", tmp_path / "cache", tmp_path / "markers"
    for folder in (data, markers):
        folder.mkdir()
    for name in ("a", "b", "c"):
        (data / f"{name}.bvh").write_text(bvh(5 + ord(name)))
    tool = tmp_path / "slow_retarget.py"
    tool.write_text(SLOW_TOOL)
    env = dict(os.environ, PYTHONPATH=str(TRAINING), INBETWEEN=f"{sys.executable} {tool}", MARKERS=str(markers))
    prepare = subprocess.Popen([sys.executable, "-m", "deltainterp", "prepare", "--data", str(data), "--out",
                                str(tmp_path / "p.npz"), "--cache", str(cache), "--jobs", "2"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                               preexec_fn=_default_signal_dispositions)
    try:
        deadline = time.monotonic() + 60
        while len(list(markers.iterdir())) < 2 and time.monotonic() < deadline and prepare.poll() is None:
            time.sleep(0.1)
        children = [int(p.name) for p in markers.iterdir()]
        assert len(children) == 2 and list(cache.glob(".*.tmp.bvh")), prepare.stderr.read() if prepare.poll() else ""
        prepare.send_signal(sig)
        prepare.wait(30)
        time.sleep(0.5)
        assert not [pid for pid in children if _alive(pid)], "the retarget children run on"
        assert sorted(p.name for p in cache.iterdir()) == [], "temporary files were left in the cache"
        assert prepare.returncode != 0 and not (tmp_path / "p.npz").exists()
    finally:
        if prepare.poll() is None:
            prepare.kill()
        for p in markers.iterdir():
            try:
                os.kill(int(p.name), signal.SIGKILL)
            except ProcessLookupError:
                pass
