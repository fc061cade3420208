"""Bad input files (issues 8, 16): a broken BVH, statistics file or ONNX model (external data, hostile
metadata), a named pipe where a file is expected, or a LaFAN1 file name without a subject is one line naming
the file, exit 2 — never a traceback, never a blocked read."""
from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from deltainterp.checkpoint import load_checkpoint
from deltainterp.warm_start import WarmStartError, load_exported_model

from cli_checks import run_cli, assert_one_line_error, FIXTURE_FILES, bvh, run_cli_within, one_line, lafan1_folder


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

# 8. ONNX external data was followed out of the model's folder (/etc/passwd read, ../../dev/zero forever).
def model_with_external_data(tmp_path: Path, location: str) -> Path:
    import onnx
    proto = onnx.load(str(FIXTURE_FILES / "tiny-model.onnx"))
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
    code, _, err = run_cli_within(capsys, ["evaluate", "--data", tmp_path, "--checkpoint", model, "--json", tmp_path / "b.json"])
    one_line(code, err, str(model))
    from deltainterp.warm_start import load_onnx_weights
    from deltainterp.checkpoint import load_checkpoint
    with pytest.raises(WarmStartError, match="another file"):
        load_onnx_weights(model, load_checkpoint(FIXTURE_FILES / "tiny-model.pt").config)
    if Path("/dev/zero").exists():
        endless = model_with_external_data(tmp_path, "../../../../../../../../dev/zero")
        with pytest.raises(WarmStartError, match="another file"):
            load_exported_model(endless)

# 10. and 23. Tracebacks (and JSON errors without the file name) for hostile .onnx metadata.
def model_with_metadata(tmp_path: Path, name: str, edit) -> Path:
    import onnx
    proto = onnx.load(str(FIXTURE_FILES / "tiny-model.onnx"))
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
    code, _, err = run_cli_within(capsys, ["evaluate", "--data", tmp_path, "--checkpoint", model, "--json", tmp_path / "b.json"])
    one_line(code, err, str(model))
    assert not (tmp_path / "b.json").exists()

# 16. prepare and evaluate blocked on a named pipe *.bvh in --data or a named pipe --checkpoint.
@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are a Unix feature")
def test_named_pipes_are_refused_without_blocking(tmp_path, capsys):
    data = lafan1_folder(tmp_path)
    os.mkfifo(data / "run1_subject1.bvh")
    code, _, err = run_cli_within(capsys, ["prepare", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--out", tmp_path / "p.npz"], seconds=60)
    one_line(code, err, "named pipe")
    os.unlink(data / "run1_subject1.bvh")
    os.mkfifo(data / "run1_subject5.bvh")
    code, _, err = run_cli_within(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--json", tmp_path / "b.json"], seconds=60)
    one_line(code, err, "named pipe")
    for name in ("pipe.onnx", "pipe.pt"):
        os.mkfifo(tmp_path / name)
        code, _, err = run_cli_within(capsys, ["evaluate", "--data", data, "--checkpoint", tmp_path / name,
                                        "--json", tmp_path / "b.json"], seconds=60)
        one_line(code, err, name)
    os.mkfifo(tmp_path / "stats-pipe.json")
    code, _, err = run_cli_within(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats-pipe.json",
                                    "--json", tmp_path / "b.json"], seconds=60)
    one_line(code, err, "named pipe")

# 22. A BVH not named *_subjectK gave "invalid literal for int() … 'foo'".
def test_a_file_name_without_a_subject_is_named(tmp_path, capsys):
    data = lafan1_folder(tmp_path)
    (data / "foo.bvh").write_text(bvh())
    code, _, err = run_cli_within(capsys, ["evaluate", "--data", data, "--stats", tmp_path / "stats.json",
                                    "--json", tmp_path / "b.json"])
    line = one_line(code, err, "foo.bvh")
    assert "invalid literal" not in line
