"""Hostile inputs (issue 8): no file the tools read runs code, user errors are one line and exit 2, every
output goes through a temporary file (an interrupted write leaves the old file byte-identical), existing
outputs are replaced only with --force, output paths are checked before any work, non-finite results are
errors, and `train --out` refuses folders and settings that are not its run's."""
from __future__ import annotations

import json
import os
import pickle
from pathlib import Path

import numpy as np
import pytest
import torch

from deltainterp import safe_output
from deltainterp.checkpoint import CheckpointError, load_checkpoint, read_checkpoint, save_checkpoint_file
from deltainterp.cli import main
from deltainterp.data import load_pack, save_pack
from deltainterp.fixtures import checkpoint_state, write_fixtures
from deltainterp.train import TrainConfig, train

from conftest import LAFAN1, STATS


# -- helpers -----------------------------------------------------------------------------------------
def run_cli(capsys, argv):
    """main(argv) in-process → (exit code, stdout, stderr)."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def assert_one_line_error(code, err, path=None):
    assert code == 2, err
    lines = [line for line in err.replace("\r", "\n").splitlines() if line.strip() and "%|" not in line]  # tqdm bars
    assert len(lines) == 1, f"expected one line on stderr, got:\n{err}"
    assert lines[0].startswith("error: ") and "Traceback" not in err
    assert "expected" in lines[0], lines[0]
    if path is not None:
        assert f"error: {path}" in lines[0], lines[0]
    return lines[0]


@pytest.fixture
def failing_rename(monkeypatch):
    """Every safe_output rename fails after the temporary file was written in full: what an interrupted
    or failing write leaves behind. Records the temporary files it saw."""
    seen = []

    def fail(temporary, target):
        assert Path(temporary).exists() and Path(temporary).parent == Path(target).parent
        seen.append(Path(temporary))
        raise OSError(28, "No space left on device (simulated)", str(target))

    monkeypatch.setattr(safe_output, "_rename", fail)
    return seen


def no_temporaries(folder: Path):
    left = [p.name for p in folder.iterdir() if p.name.endswith(".tmp") or "write-probe" in p.name]
    assert not left, f"temporary files left behind: {left}"


def run_config(pack: Path, out: Path, steps: int, **kw) -> TrainConfig:
    base = dict(data=str(pack), out=str(out), preset="tiny", batch_size=4, steps=steps, peak_lr=3e-3,
                warmup_steps=2, decay_at=1.0, checkpoint_every=1000, validate_every=1000, threads=1)
    base.update(kw)
    return TrainConfig(**base)


def train_argv(pack: Path, out: Path, steps: int, *extra):
    return ["train", "--data", pack, "--out", out, "--preset", "tiny", "--steps", steps, "--batch-size", 4,
            "--warmup", 2, "--validate-every", 1000, "--checkpoint-every", 1000, *extra]


@pytest.fixture(scope="module")
def tiny_checkpoint(tmp_path_factory, tiny) -> Path:
    path = tmp_path_factory.mktemp("ckpt") / "tiny.pt"
    save_checkpoint_file(checkpoint_state(tiny), path)
    return path


# -- safe_output -------------------------------------------------------------------------------------
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


# -- checkpoints never run code ----------------------------------------------------------------------
class _Payload:
    """Unpickling this would create the marker file (os.system through __reduce__)."""

    def __init__(self, marker: Path):
        self.marker = marker

    def __reduce__(self):
        return os.system, (f"touch {self.marker}",)


def crafted_checkpoints(folder: Path, marker: Path):
    """A torch zip without floats (torch's weights-only unpickler sees the global), one with a float before
    the payload (on torch 1.13 that goes through our restricted unpickler), and a raw pickle file."""
    evil = _Payload(marker)
    paths = {}
    paths["zip"] = folder / "zip.pt"
    torch.save({"model": evil, "model_config": {}}, paths["zip"])
    paths["zip-with-floats"] = folder / "floats.pt"
    torch.save({"unit_scale": 0.01, "model": {}, "payload": evil}, paths["zip-with-floats"])
    paths["raw-pickle"] = folder / "raw.pt"
    paths["raw-pickle"].write_bytes(pickle.dumps({"unit_scale": 0.01, "payload": evil}, protocol=2))
    return paths


@pytest.mark.parametrize("kind", ["zip", "zip-with-floats", "raw-pickle"])
def test_a_crafted_pickle_is_refused_without_running(kind, tmp_path, capsys, synthetic_pack_path):
    marker = tmp_path / "marker"
    path = crafted_checkpoints(tmp_path, marker)[kind]
    with pytest.raises(CheckpointError) as e:
        read_checkpoint(path)
    assert not marker.exists(), "the crafted checkpoint ran code"
    assert str(e.value).startswith(f"{path}: ")
    if kind != "raw-pickle":
        assert "posix.system" in str(e.value) or "os.system" in str(e.value)
    for argv in (["evaluate", "--checkpoint", path, "--json", tmp_path / "b.json", "--data", tmp_path],
                 ["export", "--checkpoint", path, "--out", tmp_path / "m.onnx"]):
        code, _, err = run_cli(capsys, argv)
        assert_one_line_error(code, err, path)
        assert not marker.exists(), f"{argv[0]} ran code from the crafted checkpoint"
    run = tmp_path / "run"
    run.mkdir()
    (run / "checkpoint.pt").write_bytes(path.read_bytes())
    code, _, err = run_cli(capsys, ["train", "--out", run, "--data", tmp_path / "none.npz", "--preset", "tiny"])
    assert_one_line_error(code, err, run / "checkpoint.pt")
    assert not marker.exists(), "train ran code from the crafted checkpoint"
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, tmp_path / "fresh", 3, "--init-from", path))
    assert_one_line_error(code, err, path)
    assert not marker.exists(), "train --init-from ran code from the crafted checkpoint"
    assert not (tmp_path / "b.json").exists() and not (tmp_path / "m.onnx").exists()


def test_a_version_1_checkpoint_still_loads_and_resumes_exactly(synthetic_pack_path, tmp_path):
    """Checkpoints written before this change (a pickled dict with floats, tuples and RNG dicts, as train.py
    and fixtures wrote them): the run in progress and Tests/Fixtures~/tiny-model.pt of older trees."""
    straight = read_checkpoint(train(run_config(synthetic_pack_path, tmp_path / "a", 9), progress=False))
    train(run_config(synthetic_pack_path, tmp_path / "b", 4), progress=False)
    ckpt = tmp_path / "b" / "checkpoint.pt"
    state = read_checkpoint(ckpt)
    assert isinstance(state["python_rng"], tuple) and isinstance(state["rng"][0]["state"]["state"], int)
    torch.save(state, ckpt)  # exactly what the old train.py wrote: torch.save of the logical dict
    assert "format" not in read_checkpoint(ckpt)  # read as version 1
    resumed = read_checkpoint(train(run_config(synthetic_pack_path, tmp_path / "b", 9), progress=False))
    assert resumed["step"] == straight["step"] == 9
    for name, w in straight["model"].items():
        assert torch.equal(w, resumed["model"][name]), f"{name} differs after resuming a version-1 checkpoint"
    assert resumed["rng"] == straight["rng"] and resumed["python_rng"] == straight["python_rng"]


def test_the_new_format_loads_with_torch_weights_only(tiny_checkpoint):
    raw = torch.load(tiny_checkpoint, map_location="cpu", weights_only=True)  # torch's own safe unpickler
    assert raw["format"] == "deltainterp-checkpoint" and raw["version"] == 2
    assert isinstance(raw["meta"], str)


def test_the_committed_fixture_checkpoint_loads():
    fixture = Path(__file__).resolve().parents[3] / "Tests" / "Fixtures~" / "tiny-model.pt"
    loaded = load_checkpoint(fixture)
    assert loaded.config.joints == 22 and loaded.unit_scale == pytest.approx(0.01)


# -- bad checkpoints: one line, exit 2 ---------------------------------------------------------------
def bad_checkpoint(kind: str, folder: Path, good: Path) -> Path:
    path = folder / f"{kind}.pt"
    data = good.read_bytes()
    if kind == "zero-byte":
        path.write_bytes(b"")
    elif kind == "random":
        path.write_bytes(np.random.default_rng(1).bytes(4096))
    elif kind == "truncated":
        path.write_bytes(data[: len(data) // 2])
    elif kind == "directory":
        path.mkdir()
    elif kind == "missing":
        pass
    elif kind == "fifo":
        os.mkfifo(path)
    else:
        state = read_checkpoint(good)
        if kind == "wrong-shape":
            name = next(iter(state["model"]))
            state["model"][name] = torch.zeros(3, 5)
        elif kind == "wrong-architecture":
            state["model_config"] = {**state["model_config"], "width": state["model_config"]["width"] * 2}
        elif kind == "unknown-config":
            state["model_config"] = {**state["model_config"], "colour": "blue"}
        elif kind == "nan-weights":
            name = next(k for k, v in state["model"].items() if v.is_floating_point())
            state["model"][name] = torch.full_like(state["model"][name], float("nan"))
        elif kind == "not-ours":
            torch.save({"weights": torch.zeros(3), "scale": 0.5}, path)
            return path
        elif kind == "a-list":
            torch.save([torch.zeros(3)], path)
            return path
        save_checkpoint_file(state, path)
    return path


BAD_CHECKPOINTS = ["zero-byte", "random", "truncated", "directory", "missing", "fifo", "wrong-shape",
                   "wrong-architecture", "unknown-config", "nan-weights", "not-ours", "a-list"]


@pytest.mark.parametrize("kind", BAD_CHECKPOINTS)
@pytest.mark.parametrize("verb", ["evaluate", "export"])
def test_bad_checkpoints_give_one_line(verb, kind, tmp_path, tiny_checkpoint, capsys):
    path = bad_checkpoint(kind, tmp_path, tiny_checkpoint)
    argv = (["evaluate", "--checkpoint", path, "--json", tmp_path / "b.json", "--data", tmp_path / "nodata"]
            if verb == "evaluate" else ["export", "--checkpoint", path, "--out", tmp_path / "m.onnx"])
    code, _, err = run_cli(capsys, argv)
    line = assert_one_line_error(code, err, path)
    assert "nodata" not in line, "the checkpoint is checked before the data is read"
    assert not (tmp_path / "b.json").exists() and not (tmp_path / "m.onnx").exists()


# -- outputs: --force, checked before work, never an input ----------------------------------------------
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


def test_export_refuses_a_network_with_non_finite_outputs(tmp_path, tiny_checkpoint):
    from deltainterp.export import ExportCheckError, export_model
    loaded = load_checkpoint(tiny_checkpoint)  # load_checkpoint refuses NaN weights; here they come later
    with torch.no_grad():
        next(p for p in loaded.model.parameters() if p.dim() == 2).fill_(float("inf"))
    with pytest.raises(ExportCheckError, match="non-finite"):
        export_model(loaded, tmp_path / "m.onnx")
    assert not (tmp_path / "m.onnx").exists()


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


# -- non-finite results --------------------------------------------------------------------------------
def test_non_finite_benchmark_results_are_an_error():
    from deltainterp.cli import _refuse_non_finite
    report = {"results": {"model": {"l2p": {"5": float("nan")}}}}
    with pytest.raises(ValueError, match=r"DATA: the benchmark gave L2P = nan for model at n=5; expected finite"):
        _refuse_non_finite(report, "DATA")
    _refuse_non_finite({"results": {"model": {"l2p": {"5": 0.5}}}}, "DATA")


def needs_lafan1():
    if not (LAFAN1 / "ground1_subject5.bvh").exists() or not STATS.exists():
        pytest.skip(f"LaFAN1 data not found at {LAFAN1}; the evaluate write tests need one subject-5 file")


def one_file_data(tmp_path: Path, huge: bool = False) -> Path:
    """A --data folder with one real subject-5 file (optionally with one value set to 1e308, which the
    reader accepts as finite and which turns L2P into NaN)."""
    data = tmp_path / "data"
    data.mkdir()
    source = LAFAN1 / "ground1_subject5.bvh"
    if not huge:
        os.symlink(source, data / source.name)
        return data
    lines = source.read_text().splitlines(keepends=True)
    first = next(i for i, line in enumerate(lines) if line.startswith("Frame Time")) + 1
    values = lines[first + 12].split()
    values[0] = "1e308"
    lines[first + 12] = " ".join(values) + "\n"
    (data / source.name).write_text("".join(lines))
    return data


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


def test_evaluate_refuses_a_nan_result(tmp_path, capsys):
    needs_lafan1()
    data = one_file_data(tmp_path, huge=True)
    out = tmp_path / "b.json"
    code, stdout, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", STATS, "--lengths", "5",
                                         "--offset", "40", "--json", out])
    line = assert_one_line_error(code, err, data)
    assert ("= nan" in line or "= inf" in line) and not out.exists() and "| nan" not in stdout.lower()


# -- train --out and resuming --------------------------------------------------------------------------
def test_train_refuses_folders_that_are_not_its_runs(synthetic_pack_path, tmp_path, capsys, tiny_checkpoint):
    regular = tmp_path / "file"
    regular.write_text("x")
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, regular, 3))
    assert "is a file" in assert_one_line_error(code, err, regular)
    other = tmp_path / "other"
    other.mkdir()
    (other / "log.csv").write_text("time,value\n1,2\n")
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, other, 3))
    assert "no checkpoint.pt" in assert_one_line_error(code, err, other)
    assert (other / "log.csv").read_text() == "time,value\n1,2\n" and len(list(other.iterdir())) == 1
    for kind in ("zero-byte", "random", "truncated", "directory"):
        run = tmp_path / f"run-{kind}"
        run.mkdir()
        src = bad_checkpoint(kind, tmp_path, tiny_checkpoint)
        if kind == "directory":
            (run / "checkpoint.pt").mkdir()
        else:
            (run / "checkpoint.pt").write_bytes(src.read_bytes())
        code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 3))
        assert_one_line_error(code, err, run / "checkpoint.pt")
    run = tmp_path / "fixture-as-run"  # a checkpoint for evaluation only: no optimizer state to resume
    run.mkdir()
    (run / "checkpoint.pt").write_bytes(tiny_checkpoint.read_bytes())
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 3))
    assert "lacks 'optimizer'" in assert_one_line_error(code, err, run / "checkpoint.pt")


@pytest.mark.parametrize("kind", ["missing", "zero-byte", "random", "directory", "not-a-pack"])
def test_train_bad_packs_give_one_line(kind, tmp_path, capsys):
    pack = tmp_path / "pack.npz"
    if kind == "zero-byte":
        pack.write_bytes(b"")
    elif kind == "random":
        pack.write_bytes(np.random.default_rng(2).bytes(1000))
    elif kind == "directory":
        pack.mkdir()
    elif kind == "not-a-pack":
        np.savez(pack, something=np.zeros(3))
    code, _, err = run_cli(capsys, train_argv(pack, tmp_path / "run", 3))
    assert_one_line_error(code, err, pack)
    assert not (tmp_path / "run").exists() or not any((tmp_path / "run").iterdir())


def test_resuming_refuses_other_settings_and_warns_about_other_steps(synthetic_pack_path, tmp_path, capsys):
    run = tmp_path / "run"
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 4, "--lr", "0.0003"))
    assert code == 0, err
    before = (run / "checkpoint.pt").read_bytes()
    refusals = [(["--lr", "0.001"], "resuming with --lr 0.001 but the run used 0.0003; expected the same settings"),
                (["--lr", "0.0003", "--seed", "7"], "--seed 7 but the run used 0"),
                (["--lr", "0.0003", "--width", "64"], "resuming another architecture: width 64 but the run used 32"),
                (["--lr", "0.0003", "--mirror"], "--mirror True but the run used False")]
    for extra, message in refusals:
        code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 6, *extra))
        assert message in assert_one_line_error(code, err, run / "checkpoint.pt")
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 2, "--lr", "0.0003"))
    assert "already at step 4, past --steps 2; expected --steps ≥ 4" in assert_one_line_error(code, err)
    assert (run / "checkpoint.pt").read_bytes() == before, "a refused resume must not touch the run"
    code, out, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 4, "--lr", "0.0003"))
    assert code == 0 and "complete at step 4" in out, out + err
    code, out, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 6, "--lr", "0.0003"))
    assert code == 0, err
    assert "warning:" in out and "--steps 6 but the run used 4" in out
    assert read_checkpoint(run / "checkpoint.pt")["step"] == 6


def test_a_diverging_run_stops_with_one_line_and_no_nan_in_its_files(synthetic_pack_path, tmp_path, capsys,
                                                                    monkeypatch):
    from deltainterp import train as train_module
    real_loss = train_module.loss
    calls = {"n": 0}

    def diverging(*args, **kw):
        terms = real_loss(*args, **kw)
        calls["n"] += 1
        if calls["n"] >= 3:
            terms["total"] = terms["total"] * float("nan")
        return terms

    monkeypatch.setattr(train_module, "loss", diverging)
    run = tmp_path / "run"
    code, _, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 6, "--checkpoint-every", "2"))
    assert "non-finite at step 3" in assert_one_line_error(code, err)
    state = read_checkpoint(run / "checkpoint.pt")
    assert state["step"] == 2 and all(torch.isfinite(v).all() for v in state["model"].values()
                                      if v.is_floating_point())


def test_interrupted_checkpoint_and_log_writes_leave_the_old_files(synthetic_pack_path, tmp_path, monkeypatch):
    cfg = run_config(synthetic_pack_path, tmp_path / "run", 50, validate_every=50)
    train(cfg, progress=False)
    run = tmp_path / "run"
    old = {n: (run / n).read_bytes() for n in ("checkpoint.pt", "log.csv", "validation.jsonl")}

    def fail(temporary, target):
        raise OSError(28, "No space left on device (simulated)", str(target))

    for name in old:
        old[name] = (run / name).read_bytes()  # an earlier round's successful appends changed the logs
        monkeypatch.setattr(safe_output, "_rename",
                            lambda t, p, name=name: fail(t, p) if Path(p).name == name else os.replace(t, p))
        with pytest.raises(OSError, match="simulated"):
            train(run_config(synthetic_pack_path, run, 100, validate_every=50), progress=False)
        monkeypatch.undo()
        assert (run / name).read_bytes() == old[name], f"{name} changed by a failed write"
        no_temporaries(run)


# -- other bad inputs name their file ------------------------------------------------------------------
BVH_HEADER = ("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation "
              "Yrotation Xrotation\n  End Site\n  {\n    OFFSET 0 1 0\n  }\n}\nMOTION\nFrames: 2\n"
              "Frame Time: 0.0333333\n")
BAD_BVHS = {"not-a-number": BVH_HEADER + "0 0 0 0 0 0\n0 0 abc 0 0 0\n",
            "short-frame": BVH_HEADER + "0 0 0 0 0 0\n0 0\n",
            "empty": "",
            "not-utf8": None}


@pytest.mark.parametrize("kind", sorted(BAD_BVHS))
def test_a_bad_bvh_gives_one_line_naming_it(kind, tmp_path, capsys):
    data = tmp_path / "data"
    data.mkdir()
    bvh = data / "walk1_subject5.bvh"
    if BAD_BVHS[kind] is None:
        bvh.write_bytes(BVH_HEADER.encode() + b"0 0 0 \xff\xfe 0 0\n")
    else:
        bvh.write_text(BAD_BVHS[kind])
    stats = tmp_path / "stats.json"
    stats.write_text(json.dumps({"x_mean": [0.0] * 6, "x_std": [1.0] * 6, "offsets": [[0.0, 1.0, 0.0]]}))
    code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", stats, "--json", tmp_path / "b.json"])
    assert_one_line_error(code, err, bvh)
    assert not (tmp_path / "b.json").exists()


@pytest.mark.parametrize("content", ["", "not json {", "[1, 2]", '{"x_mean": []}'])
def test_a_bad_statistics_file_gives_one_line_naming_it(content, tmp_path, capsys):
    stats = tmp_path / "stats.json"
    stats.write_text(content)
    for verb in ("evaluate", "prepare"):
        argv = [verb, "--data", tmp_path, "--stats", stats] + (
            ["--json", tmp_path / "b.json"] if verb == "evaluate" else ["--out", tmp_path / "p.npz"])
        code, _, err = run_cli(capsys, argv)
        assert_one_line_error(code, err, stats)


def test_resuming_drops_log_records_written_after_the_checkpoint(synthetic_pack_path, tmp_path, capsys):
    """A run stopped between a log row and its next checkpoint redoes those steps: their records must not
    appear twice."""
    run = tmp_path / "run"
    train(run_config(synthetic_pack_path, run, 50, validate_every=50), progress=False)
    log, val = run / "log.csv", run / "validation.jsonl"
    log.write_text(log.read_text() + "100,0.001,9,9,9,9,9,9.0\n")  # records of steps the checkpoint lacks
    val.write_text(val.read_text() + json.dumps({"step": 100, "model_l2q_5": 9.0}) + "\n")
    code, out, err = run_cli(capsys, train_argv(synthetic_pack_path, run, 100, "--lr", "0.003", "--warmup", 2,
                                                "--decay-at", 1.0, "--validate-every", 50))
    assert code == 0, err
    assert "dropped 2 log record(s)" in out
    steps = [int(line.split(",")[0]) for line in log.read_text().splitlines()[1:]]
    assert steps == [50, 100] and "9,9,9" not in log.read_text()
    assert [json.loads(line)["step"] for line in val.read_text().splitlines()] == [50, 100]
