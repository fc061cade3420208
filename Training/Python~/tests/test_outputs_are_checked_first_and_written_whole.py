"""Outputs (issues 8, 16): checked before any work (an existing one only with --force, never one of the inputs),
written through a temporary file renamed into place, so an interrupted or failing write (or SIGTERM) leaves
the old file byte-identical and no temporary file behind."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from deltainterp import safe_output
from deltainterp.checkpoint import load_checkpoint
from deltainterp.data import load_pack, save_pack
from deltainterp.fixtures import write_fixtures

from conftest import STATS, TRAINING
from cli_checks import (run_cli, assert_one_line_error, no_temporaries, needs_lafan1, one_file_data, bvh,
                        run_cli_within, one_line, lafan1_folder)


def test_check_refuses_what_must_not_be_written(tmp_path):
    existing = tmp_path / "old.json"
    existing.write_text("old")
    with pytest.raises(safe_output.OutputPathError, match="already exists; expected a new path, or --force"):
        safe_output.check(existing, force=False)
    assert safe_output.check(existing, force=True) == existing.resolve()
    with pytest.raises(safe_output.OutputPathError, match="is a directory"):
        safe_output.check(tmp_path, force=True)
    with pytest.raises(safe_output.OutputPathError, match="is also an input"):
        safe_output.check(existing, force=True, inputs=[str(tmp_path / "." / "old.json")])
    with pytest.raises(safe_output.OutputPathError, match="is also an input"):
        os.symlink(existing, tmp_path / "link.json")
        safe_output.check(tmp_path / "link.json", force=True, inputs=[existing])
    with pytest.raises(safe_output.OutputPathError, match="its folder .* is a file"):
        safe_output.check(existing / "x.json", force=False)
    os.mkfifo(tmp_path / "fifo")
    with pytest.raises(safe_output.OutputPathError, match="not a regular file"):
        safe_output.check(tmp_path / "fifo", force=True)
    with pytest.raises(safe_output.OutputPathError, match="cannot write in the folder /proc"):
        safe_output.check("/proc/deltainterp-test.json", force=False)
    assert safe_output.check(tmp_path / "new" / "deeper" / "x.json") == (tmp_path / "new/deeper/x.json")
    assert not (tmp_path / "new").exists(), "check creates nothing"
    no_temporaries(tmp_path)

def test_a_failing_writer_leaves_the_old_file_byte_identical(tmp_path):
    target = tmp_path / "out.bin"
    target.write_bytes(b"old content\n")

    def half_then_fail(f):
        f.write(b"half of the new")
        raise RuntimeError("writer failed half-way")

    with pytest.raises(RuntimeError, match="half-way"):
        safe_output.write(target, half_then_fail)
    assert target.read_bytes() == b"old content\n"
    no_temporaries(tmp_path)
    safe_output.write_text(target, "new\n")
    assert target.read_text() == "new\n"
    safe_output.append_text(target, "more\n")
    assert target.read_text() == "new\nmore\n"
    no_temporaries(tmp_path)

def test_evaluate_checks_its_outputs_before_the_benchmark(tmp_path, tiny_checkpoint, capsys):
    nodata = tmp_path / "nodata"  # the benchmark would fail on it: any error about it means work started
    existing = tmp_path / "old.json"
    existing.write_text("keep me")
    cases = [(["--json", existing], existing, "already exists"),
             (["--json", "/proc/deltainterp-x.json"], "/proc/deltainterp-x.json", "cannot write"),
             (["--json", tmp_path], tmp_path, "is a directory"),
             (["--json", tiny_checkpoint, "--checkpoint", tiny_checkpoint], tiny_checkpoint, "also an input"),
             (["--json", STATS, "--stats", STATS], STATS, "also an input"),
             (["--json", tmp_path / "n.json", "--plot", existing], existing, "already exists")]
    for extra, path, what in cases:
        code, _, err = run_cli(capsys, ["evaluate", "--data", nodata, *extra])
        line = assert_one_line_error(code, err, path)
        assert what in line and "nodata" not in line, line
    assert existing.read_text() == "keep me"
    assert not (tmp_path / "n.json").exists()

def test_export_refuses_existing_outputs_without_force(tmp_path, tiny_checkpoint, capsys):
    out = tmp_path / "m.onnx"
    keys = tmp_path / "m.keys.onnx"
    keys.write_bytes(b"old keys")
    code, _, err = run_cli(capsys, ["export", "--checkpoint", tiny_checkpoint, "--out", out])
    assert_one_line_error(code, err, keys)
    assert keys.read_bytes() == b"old keys" and not out.exists()
    code, out_text, err = run_cli(capsys, ["export", "--checkpoint", tiny_checkpoint, "--out", out, "--force"])
    assert code == 0, err
    assert keys.read_bytes()[:8] != b"old keys" and out.exists() and (tmp_path / "m.frame.onnx").exists()
    no_temporaries(tmp_path)

def test_export_interrupted_leaves_the_old_files(tmp_path, tiny_checkpoint, failing_rename):
    from deltainterp.export import export_model
    paths = [tmp_path / n for n in ("m.onnx", "m.keys.onnx", "m.frame.onnx")]
    for p in paths:
        p.write_bytes(b"old " + p.name.encode())
    with pytest.raises(OSError, match="simulated"):
        export_model(load_checkpoint(tiny_checkpoint), paths[0], check=False)
    assert failing_rename, "export did not write through safe_output"
    for p in paths:
        assert p.read_bytes() == b"old " + p.name.encode()
    no_temporaries(tmp_path)

def test_prepare_checks_its_output_before_reading_any_bvh(tmp_path, capsys):
    existing = tmp_path / "pack.npz"
    existing.write_bytes(b"old pack")
    for extra, path in (([existing], existing), ([STATS, "--stats", STATS], STATS)):
        code, _, err = run_cli(capsys, ["prepare", "--data", tmp_path / "nodata", "--out", *extra])
        assert "nodata" not in assert_one_line_error(code, err, path)
    assert existing.read_bytes() == b"old pack"
    code, _, err = run_cli(capsys, ["prepare", "--data", tmp_path / "nodata", "--stats", "", "--out",
                                    tmp_path / "new.npz"])
    assert_one_line_error(code, err, tmp_path / "nodata")  # a missing data folder: one line too
    code, _, err = run_cli(capsys, ["prepare", "--data", tmp_path / "nodata", "--stats", tmp_path / "none.json",
                                    "--out", tmp_path / "new.npz"])
    assert_one_line_error(code, err, tmp_path / "none.json")  # the statistics are read first

def test_prepare_pack_write_interrupted_leaves_the_old_pack(synthetic_pack_path, tmp_path, failing_rename):
    pack = load_pack(str(synthetic_pack_path))
    target = tmp_path / "pack.npz"
    target.write_bytes(b"old pack")
    with pytest.raises(OSError, match="simulated"):
        save_pack(pack, str(target))
    assert failing_rename and target.read_bytes() == b"old pack"
    no_temporaries(tmp_path)

def test_plots_interrupted_leave_the_old_png(tmp_path, failing_rename):
    from deltainterp.plots import plot_benchmark, plot_training
    report = {"windows": 1, "window": 65, "offset": 40,
              "results": {"slerp": {m: {"5": 0.1} for m in ("l2q", "l2p", "npss")}}}
    png = tmp_path / "bench.png"
    png.write_bytes(b"old png")
    with pytest.raises(OSError, match="simulated"):
        plot_benchmark(report, png)
    assert png.read_bytes() == b"old png"
    run = tmp_path / "run"
    run.mkdir()
    (run / "log.csv").write_text("step,lr,total,quat,pos,key_quat,key_pos,seconds\n50,0.001,1,1,1,1,1,1\n")
    (run / "curves.png").write_bytes(b"old curves")
    with pytest.raises(OSError, match="simulated"):
        plot_training(run)
    assert (run / "curves.png").read_bytes() == b"old curves" and len(failing_rename) == 2
    no_temporaries(tmp_path)
    no_temporaries(run)

def test_fixtures_interrupted_leave_the_old_files(tmp_path, failing_rename):
    (tmp_path / "tiny-model.pt").write_bytes(b"old checkpoint")
    with pytest.raises(OSError, match="simulated"):
        write_fixtures(tmp_path)
    assert (tmp_path / "tiny-model.pt").read_bytes() == b"old checkpoint"
    assert not (tmp_path / "golden.json").exists()
    no_temporaries(tmp_path)

def test_fixtures_refuse_a_file_as_folder(tmp_path, capsys):
    (tmp_path / "f").write_text("x")
    code, _, err = run_cli(capsys, ["fixtures", "--out", tmp_path / "f"])
    assert_one_line_error(code, err, tmp_path / "f")

def test_speed_checks_its_json_first_and_writes_safely(tmp_path, tiny_checkpoint, capsys, monkeypatch):
    from deltainterp import speed
    from deltainterp.export import metadata
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(metadata(load_checkpoint(tiny_checkpoint), "whole", "t")))
    out = tmp_path / "speed.json"
    out.write_text("old")
    argv = ["--config", meta, "--json", out, "--repeats", "2", "--warmup", "1", "--no-paper", "--lengths", "5"]
    assert speed.main([str(a) for a in argv]) == 2
    assert "already exists" in capsys.readouterr().err and out.read_text() == "old"
    assert speed.main([str(a) for a in ["--config", meta, "--json", meta, "--force"]]) == 2
    assert "also an input" in capsys.readouterr().err
    seen = []

    def fail(temporary, target):
        seen.append(temporary)
        raise OSError(28, "No space left on device (simulated)", str(target))

    monkeypatch.setattr(safe_output, "_rename", fail)
    with pytest.raises(OSError, match="simulated"):
        speed.main([str(a) for a in argv + ["--force"]])
    assert seen and out.read_text() == "old"
    monkeypatch.undo()
    assert speed.main([str(a) for a in argv + ["--force"]]) == 0
    assert "transition_ms" in json.loads(out.read_text())
    no_temporaries(tmp_path)

def test_evaluate_json_and_plot_interrupted_or_forced(tmp_path, capsys, monkeypatch):
    needs_lafan1()
    data = one_file_data(tmp_path)
    out, png = tmp_path / "b.json", tmp_path / "b.png"
    out.write_text("old json")
    png.write_bytes(b"old png")
    argv = ["evaluate", "--data", data, "--stats", STATS, "--lengths", "5", "--offset", "400", "--json", out,
            "--plot", png, "--force"]
    seen = []

    def fail(temporary, target):
        seen.append(Path(target).name)
        raise OSError(28, "No space left on device (simulated)", str(target))

    monkeypatch.setattr(safe_output, "_rename", fail)
    code, _, err = run_cli(capsys, argv)
    assert_one_line_error(code, err, out)
    assert seen == ["b.json"] and out.read_text() == "old json" and png.read_bytes() == b"old png"
    monkeypatch.undo()
    code, _, err = run_cli(capsys, argv)
    assert code == 0, err
    assert json.loads(out.read_text())["results"]["slerp"]["l2q"]["5"] > 0
    assert png.read_bytes()[:4] == b"\x89PNG"
    no_temporaries(tmp_path)

# 2. prepare --out and evaluate --json were not checked against the --data BVH files.
def test_outputs_never_replace_a_data_bvh(tmp_path, capsys):
    data = lafan1_folder(tmp_path)
    target = data / "walk1_subject1.bvh"
    before = target.read_bytes()
    code, _, err = run_cli_within(capsys, ["prepare", "--data", data, "--stats", tmp_path / "stats.json", "--out", target,
                                    "--force"])
    one_line(code, err, "is also an input")
    code, _, err = run_cli_within(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--json", data / "walk1_subject5.bvh", "--force"])
    one_line(code, err, "is also an input")
    assert target.read_bytes() == before and (data / "walk1_subject5.bvh").read_text() == bvh()

# 18. SIGTERM during a write left the .NAME.XXXXXXXX.tmp file behind.
@pytest.mark.skipif(not hasattr(signal, "SIGTERM") or os.name == "nt", reason="POSIX signals")
def test_sigterm_during_a_write_leaves_no_temporary_file(tmp_path):
    target = tmp_path / "out.bin"
    target.write_text("old")
    script = (
        "import sys, time\n"
        f"sys.path.insert(0, {str(TRAINING)!r})\n"
        "from deltainterp import safe_output\n"
        "def slow(f):\n"
        "    f.write(b'x' * 1000); f.flush(); print('writing', flush=True); time.sleep(60)\n"
        f"safe_output.write({str(target)!r}, slow)\n")
    process = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "writing"
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")], "the write is under way"
    process.send_signal(signal.SIGTERM)
    assert process.wait(30) == 128 + signal.SIGTERM
    assert not [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")]
    assert target.read_text() == "old"
