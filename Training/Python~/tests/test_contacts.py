"""Contract version 3's foot contacts: the label rule, the contact head on a frozen trunk (training, resume,
export, motion unchanged), precision/recall counting, golden vectors, and refusals of hostile files and options."""
from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import onnx
import pytest
import torch

from deltainterp import contacts as K
from deltainterp import contract as C
from deltainterp.checkpoint import CheckpointError, load_checkpoint, read_checkpoint, save_checkpoint_file
from deltainterp.export import example_inputs, export_model
from deltainterp.fixtures import check_golden_against_onnx
from deltainterp.onnx_reference import run_model
from deltainterp.warm_start import WarmStartError, load_exported_model

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "Tests" / "Fixtures~"
PYTHONPATH = str(REPO / "Training" / "Python~")


def _cli(*args):
    return subprocess.run([sys.executable, "-m", "deltainterp", *args], capture_output=True, text=True,
                          env={"PYTHONPATH": PYTHONPATH, "OPENBLAS_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"}, cwd=REPO)


# -- the label rule ----------------------------------------------------------------------------------------
def test_planted_follows_the_skating_measures_rule_with_a_ground_level_per_joint():
    leg, dt = 100.0, 1.0 / 30.0
    frames = 6
    feet = np.zeros((frames, 4, 3))
    t = np.arange(frames)
    feet[:, 1, 1] = 8.0                  # an ankle a heel's height (8 % of a leg) above the toes' floor ...
    feet[4:, 1, 1] = 11.5                # ... lifted 3.5 % of a leg above its own level on the last two frames
    feet[:, 2, 0] = 0.6 * t              # 18 leg-% per second: faster than 15 %
    feet[:, 3, 0] = 0.4 * t              # 12 % per second: slow enough
    feet[:, 3, 1] = 2.9                  # and inside the height band
    got = K.planted(feet, dt, leg)
    assert got[:, 0].all() and not got[:, 2].any() and got[:, 3].all()
    # each joint from its own ground level: the ankle stands on its floor until it lifts (the skating measure's
    # one level, the lowest joint's, would never plant it)
    assert got[:, 1].tolist() == [True, True, True, True, False, False]
    assert K.ground_levels(feet).tolist() == [0.0, 8.0, 0.0, 2.9]
    # a clip standing on a raised floor is labelled the same
    assert (K.planted(feet + np.array([0.0, 40.0, 0.0]), dt, leg) == got).all()
    # one frame lifted: that frame alone stops being planted (its neighbours' central speeds stay small)
    lifted = feet.copy()
    lifted[3, 0, 1] = 10.0
    assert K.planted(lifted, dt, leg)[:, 0].tolist() == [True, True, True, False, True, True]


def test_the_label_rules_golden_vectors_are_what_the_rule_gives_today():
    """Tests/Fixtures~/contact-labels.json (C# `FootSkating.ContactLabels` replays it) is the rule's output now."""
    stored = json.loads((FIXTURES / "contact-labels.json").read_text())
    assert stored == json.loads(json.dumps(K.contact_label_vectors()))
    walk = next(c for c in stored["cases"] if c["name"] == "walk")
    flags = np.array(walk["planted"]).reshape(-1, 4)
    assert 0.2 < flags.mean() < 0.8 and flags[:, 0].any() and flags[:, 1].any()  # both joints of a foot plant


def test_counts_give_precision_and_recall_per_joint():
    counts = K.ContactCounts.empty((0.5,))
    p = np.array([[0.9, 0.1, 0.6, np.nan], [0.2, 0.8, 0.7, np.nan], [np.nan] * 4])
    truth = np.array([[True, True, False, True], [False, True, True, True], [True, True, True, True]])
    counts.add(p, truth, (0.5,))
    assert counts.frames == 2  # NaN rows are keys: not scored
    assert counts.precision()[0].tolist()[:3] == [1.0, 1.0, 0.5]
    assert counts.recall()[0].tolist()[:3] == [1.0, 0.5, 1.0]


# -- the head on a frozen trunk ----------------------------------------------------------------------------
@pytest.fixture(scope="module")
def contact_run(tmp_path_factory, synthetic_pack_path):
    out = tmp_path_factory.mktemp("contacts") / "run"
    cfg = K.ContactTrainConfig(data=str(synthetic_pack_path), out=str(out), init_from=str(FIXTURES / "tiny-model.pt"),
                               hidden=16, steps=30, batch_size=8, checkpoint_every=10, every=(15, 30))
    K.train_contact_head(cfg, progress=False)
    return cfg, out


def test_training_the_head_leaves_every_other_weight_alone_and_resumes(contact_run, tmp_path):
    cfg, out = contact_run
    trained = load_checkpoint(out / "checkpoint.pt")
    start = load_checkpoint(FIXTURES / "tiny-model.pt")
    assert trained.config.contact_head == "mlp" and trained.model.has_contacts
    assert 0 < trained.contact_threshold < 1
    base = start.model.state_dict()
    for name, value in trained.model.state_dict().items():
        if name.startswith("contact_head."):
            continue
        assert torch.equal(value, base[name]), name
    state = read_checkpoint(out / "checkpoint.pt")
    assert state["step"] == 30 and "every_15_LeftFoot_precision" in state["validation"]
    # resuming to 40 steps continues from step 30 (the head moves, the trunk still does not)
    cfg2 = K.ContactTrainConfig(**{**cfg.__dict__, "steps": 40})
    K.train_contact_head(cfg2, progress=False)
    again = load_checkpoint(out / "checkpoint.pt")
    assert read_checkpoint(out / "checkpoint.pt")["step"] == 40
    head = [k for k in base if False] or [k for k in again.model.state_dict() if k.startswith("contact_head.")]
    assert any(not torch.equal(again.model.state_dict()[k], trained.model.state_dict()[k]) for k in head)
    with pytest.raises(ValueError, match="--lr|lr 0.5 but the run used"):
        K.train_contact_head(K.ContactTrainConfig(**{**cfg.__dict__, "steps": 40, "lr": 0.5}), progress=False)


def test_export_emits_contacts_and_the_motion_is_the_trunks(contact_run, tmp_path):
    _, out = contact_run
    loaded = load_checkpoint(out / "checkpoint.pt")
    report = export_model(loaded, tmp_path / "m.onnx", name="contacts-test")
    whole, keys, frame = (onnx.load(str(report.paths[k])) for k in ("whole", "keys", "frame"))
    assert [o.name for o in whole.graph.output][:3] == [C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA, C.FOOT_CONTACTS]
    assert C.FOOT_CONTACTS in [o.name for o in frame.graph.output]
    assert C.FOOT_CONTACTS not in [o.name for o in keys.graph.output]
    dims = [d.dim_param or d.dim_value for d in
            next(o for o in whole.graph.output if o.name == C.FOOT_CONTACTS).type.tensor_type.shape.dim]
    assert dims == ["B", "N", 4]
    meta = json.loads({p.key: p.value for p in whole.metadata_props}["deltainterp"])
    assert meta["contact_joints"] == ["LeftFoot", "LeftToe", "RightFoot", "RightToe"]
    assert meta["contact_threshold"] == loaded.contact_threshold and meta["contract_version"] == 3
    # the motion outputs are those of the model it started from, to float rounding
    before = onnx.load(str(FIXTURES / "tiny-model.onnx"))
    feeds = {k: v.numpy() for k, v in example_inputs(loaded.model, "whole", 11, 17, [17, 25]).items()}
    a, b = run_model(before, feeds), run_model(whole, feeds)
    for name in (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA):
        assert float(np.abs(a[name] - b[name]).max()) <= 1e-6
    p = b[C.FOOT_CONTACTS]
    assert p.shape == (2, 17, 4) and np.isfinite(p).all() and (p >= 0).all() and (p <= 1).all()
    # and the file reads back with its head and threshold
    back = load_exported_model(report.paths["whole"])
    assert back.model.has_contacts and back.contact_threshold == loaded.contact_threshold


def test_golden_contacts_replay_through_whole_and_lazy_graphs():
    doc = json.loads((FIXTURES / "golden-contacts.json").read_text())
    assert doc["contact_joints"] == list(C.CONTACT_JOINTS) and doc["contact_threshold"] == 0.4
    assert check_golden_against_onnx(doc, FIXTURES / "tiny-model-contacts.onnx") <= 1e-5
    keys, frame = (onnx.load(str(FIXTURES / f"tiny-model-contacts.{k}.onnx")) for k in ("keys", "frame"))
    for case in doc["cases"]:
        inp = case["inputs"]
        k = len(inp[C.KEY_FRAME_INDICES])
        feats = np.asarray(inp[C.KEY_FEATURES], np.float32).reshape(1, k, -1)
        memory = run_model(keys, {C.KEY_FEATURES: feats, C.KEY_FRAME_INDICES: np.asarray([inp[C.KEY_FRAME_INDICES]]),
                                  C.GAP_LENGTH: np.asarray(inp[C.GAP_LENGTH])})[C.KEY_MEMORY]
        want = np.asarray(case["outputs"][C.FOOT_CONTACTS]).reshape(1, -1, 4)
        # one frame at a time, as the lazy runtime decodes
        for i, q in enumerate(inp[C.QUERY_FRAME_INDICES]):
            got = run_model(frame, {C.KEY_MEMORY: memory, C.QUERY_FRAME_INDICES: np.asarray([[q]]),
                                    C.GAP_LENGTH: np.asarray(inp[C.GAP_LENGTH])})[C.FOOT_CONTACTS]
            assert np.abs(got[0, 0] - want[0, i]).max() <= 1e-5
    # the model without a head writes no contacts into its golden document
    plain = json.loads((FIXTURES / "golden.json").read_text())
    assert all(C.FOOT_CONTACTS not in c["outputs"] for c in plain["cases"])


def test_a_version_2_file_still_loads_without_contacts():
    loaded = load_exported_model(FIXTURES / "tiny-model-v2.onnx")
    assert not loaded.model.has_contacts
    assert "foot_contacts" not in [o.name for o in onnx.load(str(FIXTURES / "tiny-model-v2.onnx")).graph.output]


# -- hostile files and options -----------------------------------------------------------------------------
def _contacts_proto():
    return onnx.load(str(FIXTURES / "tiny-model-contacts.onnx"))


def _refused(proto, tmp_path, match):
    path = tmp_path / "hostile.onnx"
    path.write_bytes(proto.SerializeToString())
    with pytest.raises(WarmStartError, match=match) as e:
        load_exported_model(path)
    assert "\n" not in str(e.value) and str(e.value).startswith(str(path)) and "expected" in str(e.value)


def test_a_contact_output_of_the_wrong_shape_is_refused(tmp_path):
    proto = _contacts_proto()
    out = next(o for o in proto.graph.output if o.name == C.FOOT_CONTACTS)
    out.type.tensor_type.shape.dim[2].dim_value = 3
    _refused(proto, tmp_path, "foot_contacts has shape")
    proto = _contacts_proto()
    out = next(o for o in proto.graph.output if o.name == C.FOOT_CONTACTS)
    del out.type.tensor_type.shape.dim[2]
    _refused(proto, tmp_path, "foot_contacts has shape")


def test_a_contact_head_that_computes_another_shape_is_refused(tmp_path):
    """The declared shape is right but the graph's head has 3 channels: its outputs do not fit the network."""
    proto = _contacts_proto()
    last = [i for i in proto.graph.initializer if list(i.dims) == [16, 4]]
    assert last, "the tiny contact head's last MatMul weight (16 × 4)"
    w = onnx.numpy_helper.to_array(last[0])[:, :3].copy()
    last[0].CopyFrom(onnx.numpy_helper.from_array(w, last[0].name))
    _refused(proto, tmp_path, "contact_head|foot_contacts|shape")


def test_non_finite_contact_values_are_refused(tmp_path):
    proto = _contacts_proto()
    bias = [i for i in proto.graph.initializer if list(i.dims) == [4] and i.data_type == onnx.TensorProto.FLOAT]
    assert bias, "the tiny contact head's last bias (4)"
    for init in bias:
        init.CopyFrom(onnx.numpy_helper.from_array(np.full(4, np.nan, np.float32), init.name))
    _refused(proto, tmp_path, "non-finite")


@pytest.mark.parametrize("field,value,match", [
    ("contact_threshold", 1.5, "contact_threshold"), ("contact_threshold", "NaN", "contact_threshold"),
    ("contact_threshold", None, "contact_threshold"),
    ("contact_joints", ["LeftFoot", "LeftToe", "RightToe", "RightFoot"], "contact_joints"),
])
def test_bad_contact_metadata_is_refused(tmp_path, field, value, match):
    proto = _contacts_proto()
    entry = next(p for p in proto.metadata_props if p.key == "deltainterp")
    meta = json.loads(entry.value)
    meta[field] = float("nan") if value == "NaN" else value
    entry.value = json.dumps(meta)
    _refused(proto, tmp_path, match)


def test_a_checkpoint_with_a_bad_threshold_is_refused(tmp_path):
    state = read_checkpoint(FIXTURES / "tiny-model-contacts.pt")
    for bad in (float("nan"), 0.0, 1.0, "0.5"):
        state["contact_threshold"] = bad
        save_checkpoint_file(state, tmp_path / "bad.pt")
        with pytest.raises(CheckpointError, match="contact threshold"):
            load_checkpoint(tmp_path / "bad.pt")


@pytest.mark.parametrize("option,value", [
    ("--head", "cubic"), ("--head", "none"), ("--hidden", "0"), ("--steps", "0"), ("--batch-size", "0"),
    ("--lr", "0"), ("--lr", "nan"), ("--chained-share", "1.5"), ("--chained-share", "nan"),
    ("--checkpoint-every", "0"), ("--max-minutes", "-1"), ("--max-minutes", "inf"), ("--every", "1"),
    ("--validate-every", "-1"), ("--decay-at", "0"), ("--decay-at", "nan"),
])
def test_train_contacts_refuses_bad_options(tmp_path, synthetic_pack_path, option, value):
    r = _cli("train-contacts", "--data", str(synthetic_pack_path), "--init-from", str(FIXTURES / "tiny-model.pt"),
             "--out", str(tmp_path / "run"), option, value)
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0] and "expected" in lines[0]
    assert not (tmp_path / "run").exists()  # refused before any work


@pytest.mark.parametrize("option,value", [("--threshold", "1"), ("--threshold", "nan"), ("--every", "1")])
def test_contacts_refuses_bad_options(tmp_path, synthetic_pack_path, option, value):
    r = _cli("contacts", "--data", str(synthetic_pack_path), "--model", str(FIXTURES / "tiny-model-contacts.onnx"),
             option, value)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and option in r.stderr


def test_contacts_refuses_a_model_without_a_head(synthetic_pack_path):
    r = _cli("contacts", "--data", str(synthetic_pack_path), "--model", str(FIXTURES / "tiny-model.onnx"))
    assert r.returncode == 2 and "no foot_contacts output" in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_contacts_prints_precision_and_recall(synthetic_pack_path, tmp_path):
    r = _cli("contacts", "--data", str(synthetic_pack_path), "--model", str(FIXTURES / "tiny-model-contacts.onnx"),
             "--every", "15", "--json", str(tmp_path / "c.json"))
    assert r.returncode == 0, r.stderr
    assert "planted where p >= 0.4" in r.stdout and "LeftToe P" in r.stdout
    report = json.loads((tmp_path / "c.json").read_text())
    assert report["threshold"] == 0.4 and set(report["every"]["15"]) >= set(C.CONTACT_JOINTS)
    assert set(report["rule_on_baked_motion"]["15"]) == set(C.CONTACT_JOINTS)
    assert "applied to the baked motion itself" in r.stdout


def test_the_rule_on_the_baked_motion_is_counted_against_the_truths_labels(synthetic_pack_path):
    """The motion-labelled contacts are scored on the same frames against the same truth labels as the predicted ones."""
    from deltainterp.data import load_pack
    pack = load_pack(str(synthetic_pack_path))
    loaded = load_exported_model(FIXTURES / "tiny-model-contacts.onnx")
    motion = {}
    counts = K.contact_scores(loaded, pack, (15,), "validation", (0.5,), motion)
    assert counts[15].frames == motion[15].frames > 0
    assert (motion[15].actual == counts[15].actual).all()


def test_motion_difference_is_zero_for_the_same_trunk_and_sees_a_changed_one(tmp_path):
    same = K.motion_difference(FIXTURES / "tiny-model-contacts.onnx", FIXTURES / "tiny-model.onnx")
    assert set(same) >= {"whole root_position_delta", "keys key_memory", "frame rotation_6d_delta"}
    assert max(same.values()) <= 1e-6
    # the same files with one motion weight nudged: the whole and frame graphs differ, the keys graph not
    for suffix in ("", ".keys", ".frame"):
        proto = onnx.load(str(FIXTURES / f"tiny-model{suffix}.onnx"))
        for init in proto.graph.initializer:
            if list(init.dims) == [3] and init.data_type == onnx.TensorProto.FLOAT:  # the root head's bias
                init.CopyFrom(onnx.numpy_helper.from_array(onnx.numpy_helper.to_array(init) + 0.01, init.name))
        (tmp_path / f"nudged{suffix}.onnx").write_bytes(proto.SerializeToString())
    moved = K.motion_difference(FIXTURES / "tiny-model-contacts.onnx", tmp_path / "nudged.onnx")
    assert moved["whole root_position_delta"] > 0.005 and moved["frame root_position_delta"] > 0.005


def test_a_block_head_exports_reads_back_and_leaves_the_motion(tmp_path, synthetic_pack_path):
    out = tmp_path / "run"
    K.train_contact_head(K.ContactTrainConfig(data=str(synthetic_pack_path), out=str(out), head="block", hidden=8,
                                              init_from=str(FIXTURES / "tiny-model.pt"), steps=5, batch_size=4,
                                              every=(15,)), progress=False)
    loaded = load_checkpoint(out / "checkpoint.pt")
    assert loaded.config.contact_head == "block"
    report = export_model(loaded, tmp_path / "b.onnx", name="block-test")  # whole == keys + frame, checked
    back = load_exported_model(report.paths["whole"])
    assert back.config.contact_head == "block" and back.config.contact_hidden == 8
    assert max(K.motion_difference(report.paths["whole"], FIXTURES / "tiny-model.onnx").values()) <= 1e-6
