"""Issue 30: `export` names a model after its run (or an exported model's own name), never after a data set it was
not trained on, and the same for its data description."""
from __future__ import annotations

import json
from pathlib import Path

import onnx

from deltainterp.checkpoint import save_checkpoint_file
from deltainterp.cli import main
from deltainterp.fixtures import checkpoint_state


def _metadata(path: Path) -> dict:
    props = {p.key: p.value for p in onnx.load(str(path), load_external_data=False).metadata_props}
    return json.loads(props["deltainterp"])


def _checkpoint(folder: Path, tiny, **extra) -> Path:
    folder.mkdir(parents=True)
    state = checkpoint_state(tiny)
    state["data_description"] = ""  # a run that recorded none, as train.py's checkpoints
    state.update(extra)
    path = folder / "checkpoint.pt"
    save_checkpoint_file(state, path)
    return path


def test_a_run_without_a_name_is_named_after_its_folder_and_says_its_data_is_unknown(tmp_path, tiny, capsys):
    ckpt = _checkpoint(tmp_path / "runs" / "my fine-tune", tiny, train_config={"data": str(tmp_path / "gone.npz")})
    out = tmp_path / "m.onnx"
    assert main(["export", "--checkpoint", str(ckpt), "--out", str(out)]) == 0
    meta = _metadata(out)
    assert meta["name"] == "DeltaInterpolator-my-fine-tune"
    assert "LaFAN1" not in meta["training"]["data"] and "not recorded" in meta["training"]["data"]
    assert "gone.npz" in meta["training"]["data"]
    printed = capsys.readouterr().out
    assert printed.startswith("DeltaInterpolator-my-fine-tune (trained on: not recorded")


def test_a_lafan1_pack_is_described_by_the_subjects_it_holds(tmp_path, tiny):
    import numpy as np
    pack = tmp_path / "pack.npz"
    np.savez(pack, files=np.array(["walk1_subject5.bvh", "run1_subject2.bvh"]), frame_time=np.float64(1 / 30))
    ckpt = _checkpoint(tmp_path / "runs" / "r", tiny, train_config={"data": str(pack)})
    out = tmp_path / "m.onnx"
    assert main(["export", "--checkpoint", str(ckpt), "--out", str(out), "--name", "Mine"]) == 0
    meta = _metadata(out)
    assert meta["name"] == "Mine" and meta["training"]["data"] == "LaFAN1 subjects 2, 5 (2 files)"


def test_a_re_export_keeps_the_models_own_name_and_data(tmp_path, tiny):
    ckpt = _checkpoint(tmp_path / "runs" / "first", tiny)
    first = tmp_path / "first.onnx"
    assert main(["export", "--checkpoint", str(ckpt), "--out", str(first), "--name", "Keep-Me"]) == 0
    again = tmp_path / "again.onnx"
    assert main(["export", "--checkpoint", str(first), "--out", str(again)]) == 0
    assert _metadata(again)["name"] == "Keep-Me"
    assert _metadata(again)["training"]["data"] == _metadata(first)["training"]["data"]


def test_a_hostile_name_is_refused_in_one_line(tmp_path, tiny, capsys):
    ckpt = _checkpoint(tmp_path / "runs" / "x", tiny)
    for bad in ["", "a\nb", "\x1b[2J", "n" * 101]:
        out = tmp_path / "m.onnx"
        code = main(["export", "--checkpoint", str(ckpt), "--out", str(out), "--name", bad])
        err = capsys.readouterr().err.strip()
        assert code == 2 and "--name" in err and "expected" in err and "\n" not in err and "\x1b" not in err
        assert not out.exists()
