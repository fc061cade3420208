"""Hostile inputs, second review (issue 16): each test failed (or hung) before its fix. The class number of the
issue is in each test's comment."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest
import torch

from deltainterp import safe_output
from deltainterp.checkpoint import FORMAT, FORMAT_VERSION
from deltainterp.cli import main
from deltainterp.data import MotionPack, save_pack
from deltainterp.warm_start import WarmStartError, load_exported_model

from conftest import REPO, TRAINING, synthetic_motion

FIXTURES = REPO / "Tests" / "Fixtures~"
HEADER = ("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition Zrotation "
          "Yrotation Xrotation\n  End Site\n  {\n    OFFSET 0 1 0\n  }\n}\nMOTION\n")
STATS = {"x_mean": [0.0] * 3, "x_std": [1.0] * 3, "offsets": []}  # one joint, as HEADER


def bvh(frames: int = 3, root: str = "0") -> str:
    rows = [f"{root if f == 1 else '0'} 90 0 0 0 0" for f in range(frames)]
    return HEADER + f"Frames: {frames}\nFrame Time: 0.0333333\n" + "\n".join(rows) + "\n"


def run_cli(capsys, argv, seconds: float = 120):
    """main(argv) in a thread → (exit code, stdout, stderr); fails instead of hanging (a FIFO blocks an open)."""
    result = {}

    def target():
        try:
            result["code"] = main([str(a) for a in argv])
        except BaseException as e:  # noqa: BLE001 - reported below
            result["error"] = e

    thread = threading.Thread(target=target, daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"{argv[0]} did not finish within {seconds} s (blocked on a named pipe?)"
    if "error" in result:
        raise result["error"]
    out, err = capsys.readouterr()
    return result["code"], out, err


def one_line(code, err, phrase=None):
    assert code == 2, err
    lines = [line for line in err.replace("\r", "\n").splitlines() if line.strip() and "%|" not in line]
    assert len(lines) == 1, f"expected one line on stderr, got:\n{err}"
    assert lines[0].startswith("error: ") and "Traceback" not in err and "expected" in lines[0], lines[0]
    if phrase is not None:
        assert phrase in lines[0], lines[0]
    return lines[0]


def lafan1_folder(tmp_path: Path, text: str = None) -> Path:
    data = tmp_path / "data"
    data.mkdir()
    (data / "walk1_subject1.bvh").write_text(text or bvh())
    (data / "walk1_subject5.bvh").write_text(bvh())
    (tmp_path / "stats.json").write_text(json.dumps(STATS))
    return data


# 2. prepare --out and evaluate --json were not checked against the --data BVH files.
def test_outputs_never_replace_a_data_bvh(tmp_path, capsys):
    data = lafan1_folder(tmp_path)
    target = data / "walk1_subject1.bvh"
    before = target.read_bytes()
    code, _, err = run_cli(capsys, ["prepare", "--data", data, "--stats", tmp_path / "stats.json", "--out", target,
                                    "--force"])
    one_line(code, err, "is also an input")
    code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--json", data / "walk1_subject5.bvh", "--force"])
    one_line(code, err, "is also an input")
    assert target.read_bytes() == before and (data / "walk1_subject5.bvh").read_text() == bvh()


# 8. ONNX external data was followed out of the model's folder (/etc/passwd read, ../../dev/zero forever).
def model_with_external_data(tmp_path: Path, location: str) -> Path:
    import onnx
    proto = onnx.load(str(FIXTURES / "tiny-model.onnx"))
    tensor = max(proto.graph.initializer, key=lambda t: len(t.raw_data))
    length = len(tensor.raw_data)
    tensor.ClearField("raw_data")
    tensor.data_location = onnx.TensorProto.EXTERNAL
    for key, value in (("location", location), ("offset", "0"), ("length", str(length))):
        entry = tensor.external_data.add()
        entry.key, entry.value = key, value
    folder = tmp_path / "models"
    folder.mkdir(exist_ok=True)
    path = folder / "external.onnx"
    path.write_bytes(proto.SerializeToString())
    return path


def test_onnx_external_data_is_refused(tmp_path, capsys):
    secret = tmp_path / "secret.bin"
    secret.write_bytes(os.urandom(1 << 16))
    model = model_with_external_data(tmp_path, "../secret.bin")
    with pytest.raises(WarmStartError, match="another file"):
        load_exported_model(model)
    code, _, err = run_cli(capsys, ["evaluate", "--data", tmp_path, "--checkpoint", model, "--json", tmp_path / "b.json"])
    one_line(code, err, str(model))
    from deltainterp.warm_start import load_onnx_weights
    from deltainterp.checkpoint import load_checkpoint
    with pytest.raises(WarmStartError, match="another file"):
        load_onnx_weights(model, load_checkpoint(FIXTURES / "tiny-model.pt").config)
    if Path("/dev/zero").exists():
        endless = model_with_external_data(tmp_path, "../../../../../../../../dev/zero")
        with pytest.raises(WarmStartError, match="another file"):
            load_exported_model(endless)


# 10. and 23. Tracebacks (and JSON errors without the file name) for hostile .onnx metadata.
def model_with_metadata(tmp_path: Path, name: str, edit) -> Path:
    import onnx
    proto = onnx.load(str(FIXTURES / "tiny-model.onnx"))
    entry = next(p for p in proto.metadata_props if p.key == "deltainterp")
    entry.value = edit(json.loads(entry.value))
    path = tmp_path / f"{name}.onnx"
    path.write_bytes(proto.SerializeToString())
    return path


HOSTILE_METADATA = {
    "list": lambda m: "[]",
    "heads-0": lambda m: json.dumps({**m, "architecture": {**m["architecture"], "heads": 0}}),
    "deep": lambda m: "[" * 100_000 + "]" * 100_000,
    "no-architecture": lambda m: json.dumps({k: v for k, v in m.items() if k != "architecture"}),
    "not-json": lambda m: "{not json",
}


@pytest.mark.parametrize("kind", sorted(HOSTILE_METADATA))
def test_hostile_onnx_metadata_gives_one_line_naming_the_file(kind, tmp_path, capsys):
    model = model_with_metadata(tmp_path, kind, HOSTILE_METADATA[kind])
    code, _, err = run_cli(capsys, ["evaluate", "--data", tmp_path, "--checkpoint", model, "--json", tmp_path / "b.json"])
    one_line(code, err, str(model))
    assert not (tmp_path / "b.json").exists()


def test_a_checkpoint_with_deeply_nested_json_gives_one_line(tmp_path, capsys):
    path = tmp_path / "deep.pt"
    torch.save({"format": FORMAT, "version": FORMAT_VERSION, "meta": "[" * 3000 + "]" * 3000, "tensors": [],
                "model": {}}, path)
    code, _, err = run_cli(capsys, ["export", "--checkpoint", path, "--out", tmp_path / "m.onnx"])
    one_line(code, err, str(path))


def test_train_on_a_small_pack_trains_without_validation(tmp_path, capsys, skeleton):
    roots, quats = [], []
    for seed in (3, 4):
        r, q = synthetic_motion(200, skeleton.joint_count, seed)
        roots.append(r)
        quats.append(q)
    pack = MotionPack(skeleton, ["a.bvh", "b.bvh"], np.array([0, 200, 400]), np.concatenate(roots),
                      np.concatenate(quats), 1 / 30)
    pack_path = tmp_path / "small.npz"
    save_pack(pack, str(pack_path))
    run = tmp_path / "run"
    code, out, err = run_cli(capsys, ["train", "--data", pack_path, "--out", run, "--preset", "tiny", "--steps", 3,
                                      "--batch-size", 2, "--warmup", 1, "--validate-every", 1,
                                      "--checkpoint-every", 1000])
    assert code == 0, err
    assert (run / "checkpoint.pt").exists()
    assert "training without validation" in out + err


# 16. prepare and evaluate blocked on a named pipe *.bvh in --data or a named pipe --checkpoint.
@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are a Unix feature")
def test_named_pipes_are_refused_without_blocking(tmp_path, capsys):
    data = lafan1_folder(tmp_path)
    os.mkfifo(data / "run1_subject1.bvh")
    code, _, err = run_cli(capsys, ["prepare", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--out", tmp_path / "p.npz"], seconds=60)
    one_line(code, err, "named pipe")
    os.unlink(data / "run1_subject1.bvh")
    os.mkfifo(data / "run1_subject5.bvh")
    code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--json", tmp_path / "b.json"], seconds=60)
    one_line(code, err, "named pipe")
    for name in ("pipe.onnx", "pipe.pt"):
        os.mkfifo(tmp_path / name)
        code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--checkpoint", tmp_path / name,
                                        "--json", tmp_path / "b.json"], seconds=60)
        one_line(code, err, name)
    os.mkfifo(tmp_path / "stats-pipe.json")
    code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats-pipe.json",
                                    "--json", tmp_path / "b.json"], seconds=60)
    one_line(code, err, "named pipe")


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


# 22. A BVH not named *_subjectK gave "invalid literal for int() … 'foo'".
def test_a_file_name_without_a_subject_is_named(tmp_path, capsys):
    data = lafan1_folder(tmp_path)
    (data / "foo.bvh").write_text(bvh())
    code, _, err = run_cli(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--json", tmp_path / "b.json"])
    line = one_line(code, err, "foo.bvh")
    assert "invalid literal" not in line


# 24. prepare packed NaN motion (and 1e308, infinite as float32) that train then rejected as "not a pack".
@pytest.mark.parametrize("value", ["nan", "1e308", "inf"])
def test_prepare_refuses_non_finite_motion(value, tmp_path, capsys):
    data = lafan1_folder(tmp_path, bvh(root=value))
    out = tmp_path / "p.npz"
    code, _, err = run_cli(capsys, ["prepare", "--data", data, "--stats", tmp_path / "stats.json", "--out", out])
    one_line(code, err, "walk1_subject1.bvh")
    assert not out.exists()
