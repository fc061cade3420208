"""An output never replaces an input, even with --force; a new output path is claimed exclusively, so a second run
writing it meanwhile is refused instead of silently replaced; a full disk is one line naming the file, with no
temporary file and no garbage-collector traceback left behind (issue 31, classes 1, 2 and 20)."""
from __future__ import annotations

import json
import os
import resource
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from deltainterp import safe_output

from conftest import REPO, TRAINING
from refusals import bvh, lafan1_folder, one_line, run_cli

FIXTURES = REPO / "Tests" / "Fixtures~"
APPEARED = "appeared while this command ran"


def leftovers(folder: Path):
    return sorted(p.name for p in folder.rglob(".*.tmp"))


# 1. `prepare --out DIR/inbetween-data.json --force` replaced the folder's manifest; a manifest's map likewise.
def test_prepare_never_replaces_a_manifest_or_map_it_reads_even_with_force(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("INBETWEEN", "/bin/false")  # nothing may get as far as retargeting
    data = tmp_path / "rig"
    data.mkdir()
    (data / "take.bvh").write_text(bvh(5))
    names = tmp_path / "names.json"
    names.write_text(json.dumps({"Hips": "Hips"}))
    manifest = data / "inbetween-data.json"
    manifest.write_text(json.dumps({"defaults": {"from_frame": 1, "map": "../names.json"}}))
    shipped = tmp_path / "rig.json"
    shipped.write_text(json.dumps({"folder": "rig", "defaults": {"map": "names.json"}}))
    before = {p: p.read_bytes() for p in (manifest, names, shipped)}
    for source, target in ((data, manifest), (data, names), (shipped, names), (shipped, shipped),
                           (data, data / "." / "inbetween-data.json")):
        code, _, err = run_cli(capsys, ["prepare", "--data", source, "--out", target, "--force",
                                        "--cache", tmp_path / "cache"])
        one_line(code, err, "is also an input")
    assert {p: p.read_bytes() for p in before} == before
    # A folder without a manifest yet: the pack must not become the manifest a later run reads.
    bare = tmp_path / "bare"
    bare.mkdir()
    (bare / "take.bvh").write_text(bvh(5))
    code, _, err = run_cli(capsys, ["prepare", "--data", bare, "--out", bare / "inbetween-data.json",
                                    "--cache", tmp_path / "cache"])
    one_line(code, err, "is also an input")
    assert not (bare / "inbetween-data.json").exists()


# 2. Two runs without --force to one new path both exited 0; the second silently replaced the first's file.
def test_a_new_output_that_another_run_wrote_meanwhile_is_kept(tmp_path):
    for force in (False, True):  # --force allows replacing a file that existed when checked, not one that appeared
        target = tmp_path / f"new-{force}.json"
        safe_output.check(target, force)
        target.write_text("the other run's")
        with pytest.raises(safe_output.OutputPathError, match=APPEARED):
            safe_output.write_text(target, "ours")
        assert target.read_text() == "the other run's" and leftovers(tmp_path) == []
    existing = tmp_path / "old.json"
    existing.write_text("old")
    safe_output.check(existing, True)
    safe_output.write_text(existing, "new")  # an existing file checked with --force is still replaced
    assert existing.read_text() == "new"
    fresh = tmp_path / "fresh.json"
    safe_output.check(fresh, False)
    safe_output.write_text(fresh, "ours")  # and a new one is written when nobody else did
    assert fresh.read_text() == "ours" and leftovers(tmp_path) == []


def _other_run_writes(path: Path, real):
    """`real`, after another run has written `path` (what a second process does between our check and write)."""
    def wrapped(*args, **kwargs):
        Path(path).write_text("the other run's")
        return real(*args, **kwargs)
    return wrapped


def test_every_trainer_writer_refuses_a_path_another_run_claimed(tmp_path, capsys, monkeypatch):
    import deltainterp.benchmark as benchmark
    import deltainterp.data as data_module
    import deltainterp.quantize as quantize

    data = lafan1_folder(tmp_path, frames=40)
    stats = tmp_path / "stats.json"
    out = tmp_path / "pack.npz"
    monkeypatch.setattr(data_module, "save_pack", _other_run_writes(out, data_module.save_pack))
    code, _, err = run_cli(capsys, ["prepare", "--data", data, "--stats", stats, "--out", out])
    one_line(code, err, APPEARED)
    assert out.read_text() == "the other run's"

    report = tmp_path / "benchmark.json"
    monkeypatch.setattr(benchmark, "run_benchmark", _other_run_writes(report, benchmark.run_benchmark))
    code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", stats, "--window", "25", "--offset", "5",
                                    "--lengths", "5", "--json", report])
    one_line(code, err, APPEARED)
    assert report.read_text() == "the other run's"

    int8 = tmp_path / "m.int8.onnx"
    monkeypatch.setattr(quantize, "relative_differences", _other_run_writes(int8, quantize.relative_differences))
    code, _, err = run_cli(capsys, ["quantize", "--model", FIXTURES / "tiny-model.onnx", "--out", int8])
    one_line(code, err, APPEARED)
    assert int8.read_text() == "the other run's"

    import deltainterp.export as export
    exported = tmp_path / "e.onnx"
    monkeypatch.setattr(export, "export_model", _other_run_writes(exported, export.export_model))
    code, _, err = run_cli(capsys, ["export", "--checkpoint", FIXTURES / "tiny-model.pt", "--out", exported])
    one_line(code, err, APPEARED)
    assert exported.read_text() == "the other run's" and not (tmp_path / "e.keys.onnx").exists()
    assert leftovers(tmp_path) == []


# 20. A full disk printed "[Errno 28] No space left on device" without the file, plus an
#     "Exception ignored in: <function ZipFile.__del__>" traceback (numpy's half-written .npz).
def _prepare_on_a_small_disk(tmp_path: Path, out: Path, limit_bytes=None):
    data = lafan1_folder(tmp_path, frames=2000)
    out.write_bytes(b"old pack")

    def small_files():  # a real write error from the kernel, without root: files may not grow past the limit
        if limit_bytes is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # EFBIG instead of the signal that ends the process
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit_bytes, limit_bytes))

    env = dict(os.environ, PYTHONPATH=str(TRAINING), PYTHONDONTWRITEBYTECODE="1")
    return subprocess.run([sys.executable, "-m", "deltainterp", "prepare", "--data", str(data), "--stats",
                           str(tmp_path / "stats.json"), "--out", str(out), "--force"], capture_output=True,
                          text=True, env=env, preexec_fn=small_files, timeout=300)


def _assert_named_in_one_line(r, out: Path):
    line = one_line(r.returncode, r.stderr)
    assert str(out) in line and "Exception ignored" not in r.stderr, r.stderr
    assert out.read_bytes() == b"old pack" and leftovers(out.parent) == []


def test_a_write_past_what_the_disk_allows_is_one_line_naming_the_file(tmp_path):
    out = tmp_path / "pack.npz"
    _assert_named_in_one_line(_prepare_on_a_small_disk(tmp_path, out, limit_bytes=4096), out)


def test_a_full_disk_is_one_line_naming_the_file(tmp_path):
    disk = tmp_path / "disk"
    disk.mkdir()
    if os.geteuid() != 0 or shutil.which("mount") is None or subprocess.run(
            ["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(disk)], capture_output=True).returncode != 0:
        pytest.skip("mounting a 64 KiB tmpfs needs root (the RLIMIT_FSIZE test covers the same path)")
    try:
        out = disk / "pack.npz"
        (disk / "filler").write_bytes(bytes(48 << 10))  # what is left is less than the pack needs
        _assert_named_in_one_line(_prepare_on_a_small_disk(tmp_path, out), out)
    finally:
        subprocess.run(["umount", str(disk)], check=False)


def test_a_checkpoint_past_what_the_disk_allows_is_one_line_naming_it(tmp_path, synthetic_pack_path):
    def small_files():  # log.csv and validation.jsonl fit; the tiny model's checkpoint (~200 KB) does not
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (32 << 10, 32 << 10))

    run = tmp_path / "run"
    env = dict(os.environ, PYTHONPATH=str(TRAINING), PYTHONDONTWRITEBYTECODE="1")
    r = subprocess.run([sys.executable, "-m", "deltainterp", "train", "--data", str(synthetic_pack_path), "--out",
                        str(run), "--preset", "tiny", "--steps", "2", "--warmup", "1", "--batch-size", "2",
                        "--validate-every", "100", "--checkpoint-every", "100"], capture_output=True, text=True,
                       env=env, preexec_fn=small_files, timeout=300)
    line = one_line(r.returncode, r.stderr)
    assert f"{run / 'checkpoint.pt'}: File too large; expected room for it on its disk" in line, r.stderr
    assert "Traceback" not in r.stderr and "Exception ignored" not in r.stderr, r.stderr
    assert not (run / "checkpoint.pt").exists() and leftovers(run) == []
