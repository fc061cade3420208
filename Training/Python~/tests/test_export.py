"""ONNX export: numpy evaluation of the written files == torch, lazy graphs == whole, operator policy,
metadata, and the C# fixtures (contract version, determinism, golden vectors)."""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import onnx
import pytest
import torch
from onnx import TensorProto, helper

from deltainterp import contract as C
from deltainterp.checkpoint import load_checkpoint
from deltainterp.export import (KeysGraph, WholeGraph, example_inputs, export_model, graph_specs, _torch_onnx_export)
from deltainterp.fixtures import checkpoint_state, write_fixtures
from deltainterp.onnx_reference import run_model
from deltainterp.operators import ALLOWED, OperatorError, check_operators

REPO = Path(__file__).resolve().parents[3]
FIXTURES = REPO / "Tests" / "Fixtures~"
CSHARP_CONTRACT = REPO / "Runtime" / "Core" / "Inference" / "ModelContract.cs"


@pytest.fixture(scope="module")
def exported(tiny, tmp_path_factory):
    out = tmp_path_factory.mktemp("export") / "tiny.onnx"
    report = export_model(tiny, out, name="test")
    return tiny, report, {k: onnx.load(str(p)) for k, p in report.paths.items()}


@pytest.mark.parametrize("keys, queries, gap", [(11, 5, 5), (11, 45, 45), (4, 3, 9), (2, 1, 1)])
def test_numpy_onnx_equals_torch(exported, keys, queries, gap):
    tiny, _, protos = exported
    inputs = example_inputs(tiny.model, "whole", keys, queries, gap, seed=99)
    with torch.no_grad():
        want = WholeGraph(tiny.model)(*inputs.values())
    got = run_model(protos["whole"], {k: v.numpy() for k, v in inputs.items()})
    assert got[C.ROOT_POSITION_DELTA].shape == (1, queries, 3)
    assert got[C.ROTATION_6D_DELTA].shape == (1, queries, 22, 6)
    assert np.abs(got[C.ROOT_POSITION_DELTA] - want[0].numpy()).max() < 1e-5
    assert np.abs(got[C.ROTATION_6D_DELTA] - want[1].numpy()).max() < 1e-5
    assert [int(got[c][0]) for c in C.CONSTANT_OUTPUTS] == [C.CONTRACT_VERSION, 22, 198]


def test_lazy_graphs_equal_whole_all_at_once_and_one_at_a_time(exported):
    tiny, _, protos = exported
    inputs = {k: v.numpy() for k, v in example_inputs(tiny.model, "whole", 11, 12, 12, seed=5).items()}
    whole = run_model(protos["whole"], inputs)
    keys = run_model(protos["keys"], {k: inputs[k] for k in (C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.GAP_LENGTH)})
    memory = keys[C.KEY_MEMORY]
    assert memory.shape == (1, tiny.config.blocks, 2, 11, tiny.config.width)
    all_at_once = run_model(protos["frame"], {C.KEY_MEMORY: memory, C.QUERY_FRAME_INDICES: inputs[C.QUERY_FRAME_INDICES],
                                              C.GAP_LENGTH: inputs[C.GAP_LENGTH]})
    for name in (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA):
        assert np.abs(all_at_once[name] - whole[name]).max() < 1e-5
    for i, frame in enumerate(inputs[C.QUERY_FRAME_INDICES][0]):
        one = run_model(protos["frame"], {C.KEY_MEMORY: memory, C.QUERY_FRAME_INDICES: frame.reshape(1, 1),
                                          C.GAP_LENGTH: inputs[C.GAP_LENGTH]})
        for name in (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA):
            assert np.abs(one[name][0, 0] - whole[name][0, i]).max() < 1e-5


def test_graph_interfaces_and_metadata(exported):
    tiny, report, protos = exported
    expected_inputs = {"whole": [C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.QUERY_FRAME_INDICES, C.GAP_LENGTH],
                       "keys": [C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.GAP_LENGTH],
                       "frame": [C.KEY_MEMORY, C.QUERY_FRAME_INDICES, C.GAP_LENGTH]}
    for kind, proto in protos.items():
        assert [o.opset_import[0].version for o in [proto]] == [15]
        assert [i.name for i in proto.graph.input] == expected_inputs[kind]
        outputs = [o.name for o in proto.graph.output]
        assert outputs[-3:] == list(C.CONSTANT_OUTPUTS)
        props = {p.key: p.value for p in proto.metadata_props}
        assert props["contract_version"] == str(C.CONTRACT_VERSION)
        meta = json.loads(props["deltainterp"])
        assert meta["graph"] == kind and meta["contract_version"] == C.CONTRACT_VERSION
        assert meta["skeleton"]["names"][0] == "Hips" and len(meta["skeleton"]["parents"]) == 22
        assert meta["unit_scale"] == 0.01 and meta["rotation_6d"] == "rows" and meta["quaternion_order"] == "wxyz"
        assert meta["facing_local_axis"] == [0.0, 1.0, 0.0] and meta["facing_target_axis"] == [1.0, 0.0, 0.0]
        assert meta["architecture"]["parameters"] == tiny.model.parameter_count()
        assert meta["training"]["missing_frames"] == [5, 39]
        dims = {o.name: [d.dim_param or d.dim_value for d in o.type.tensor_type.shape.dim] for o in proto.graph.output}
        if kind != "keys":
            assert dims[C.ROTATION_6D_DELTA] == ["B", "N", 22, 6] and dims[C.ROOT_POSITION_DELTA] == ["B", "N", 3]
        else:
            assert dims[C.KEY_MEMORY] == ["B", tiny.config.blocks, 2, "K", tiny.config.width]
        ins = {i.name: [d.dim_param or d.dim_value for d in i.type.tensor_type.shape.dim] for i in proto.graph.input}
        assert ins[C.GAP_LENGTH] == ["B"]
        if C.KEY_FRAME_INDICES in ins:
            assert ins[C.KEY_FRAME_INDICES] == ["B", "K"]
        if C.QUERY_FRAME_INDICES in ins:
            assert ins[C.QUERY_FRAME_INDICES] == ["B", "N"]
        ops = check_operators(proto)
        assert not {"LayerNormalization", "Attention", "ScatterND", "If", "Loop"} & set(ops)
        assert set(ops) <= ALLOWED
    assert report.sizes["whole"] < 1 << 20


def _graph_with(op_type: str, **attrs):
    x = helper.make_tensor_value_info("x", TensorProto.FLOAT, [1, 4])
    y = helper.make_tensor_value_info("y", TensorProto.FLOAT, [1, 4])
    inputs = ["x"] + (["s", "b"] if op_type == "LayerNormalization" else [])
    inits = [helper.make_tensor("s", TensorProto.FLOAT, [4], [1.0] * 4),
             helper.make_tensor("b", TensorProto.FLOAT, [4], [0.0] * 4)] if op_type == "LayerNormalization" else []
    node = helper.make_node(op_type, inputs, ["y"], **attrs)
    return helper.make_model(helper.make_graph([node], "g", [x], [y], inits),
                             opset_imports=[helper.make_opsetid("", 17)])


@pytest.mark.parametrize("op, attrs, message", [
    ("LayerNormalization", {}, "LayerNormalization"),
    ("Erf", {}, "not imported by both"),
    ("Softmax", {"axis": 0}, "last axis only"),
])
def test_operator_check_refuses(op, attrs, message):
    with pytest.raises(OperatorError, match=message):
        check_operators(_graph_with(op, **attrs))


def test_export_refuses_a_module_with_scatternd(tiny, tmp_path):
    class InPlace(torch.nn.Module):
        def forward(self, x):
            y = x.clone()
            y[:, 1] = x[:, 0] * 2.0  # index assignment → ScatterND
            return y
    spec = graph_specs(tiny.model)[0]
    spec.input_names, spec.output_names, spec.dynamic_axes = ["x"], ["y"], {}
    path = tmp_path / "bad.onnx"
    _torch_onnx_export(InPlace(), (torch.zeros(1, 3),), str(path), spec)
    with pytest.raises(OperatorError, match="ScatterND"):
        check_operators(onnx.load(str(path)), "bad")


# -- fixtures for the C# side -----------------------------------------------------------------------
def test_contract_version_matches_csharp():
    if not CSHARP_CONTRACT.exists():
        pytest.skip(f"{CSHARP_CONTRACT} does not exist yet (the C# runtime's ModelContract)")
    m = re.search(r"public\s+const\s+int\s+Version\s*=\s*(\d+)\s*;", CSHARP_CONTRACT.read_text())
    assert m, f"no `public const int Version = N;` in {CSHARP_CONTRACT}"
    assert int(m.group(1)) == C.CONTRACT_VERSION


def test_fixtures_are_deterministic_and_up_to_date(tmp_path):
    a = write_fixtures(tmp_path / "a")
    b = write_fixtures(tmp_path / "b")
    for key in a:
        assert a[key].read_bytes() == b[key].read_bytes(), f"{a[key].name} differs between two runs"
    if not (FIXTURES / "golden.json").exists():
        pytest.skip("Tests/Fixtures~ has not been written yet")
    for key, path in a.items():
        committed = FIXTURES / path.name
        stale = f"{committed} is stale: run `PYTHONPATH=Training/Python~ python3 -m deltainterp fixtures`"
        if path.suffix == ".json":
            # Network outputs in float32 differ in their last digits between CPUs (OpenBLAS picks its
            # kernels per CPU model), so golden numbers are compared to 1e-5 (the export check's tolerance; relative above 1), everything else
            # exactly.
            _assert_same_json(json.loads(committed.read_text()), json.loads(path.read_text()), stale)
        else:
            assert committed.read_bytes() == path.read_bytes(), stale


def _assert_same_json(committed, fresh, stale: str, where: str = "") -> None:
    assert type(committed) is type(fresh), f"{stale} (at {where or 'top'})"
    if isinstance(fresh, dict):
        assert list(committed) == list(fresh), f"{stale} (keys at {where or 'top'})"
        for k in fresh:
            _assert_same_json(committed[k], fresh[k], stale, f"{where}.{k}")
    elif isinstance(fresh, list):
        assert len(committed) == len(fresh), f"{stale} (length at {where})"
        for i, (c, f) in enumerate(zip(committed, fresh)):
            _assert_same_json(c, f, stale, f"{where}[{i}]")
    elif isinstance(fresh, float):
        assert abs(committed - fresh) <= 1e-5 * max(1.0, abs(fresh)), f"{stale} ({where}: {committed} != {fresh})"
    else:
        assert committed == fresh, f"{stale} ({where}: {committed!r} != {fresh!r})"


def test_golden_cases_replay_through_the_onnx_file_and_the_checkpoint(tmp_path):
    paths = write_fixtures(tmp_path)
    golden = json.loads(paths["golden"].read_text())
    assert golden["contract_version"] == C.CONTRACT_VERSION and golden["model"] == "tiny-model.onnx"
    assert {c["gap"] for c in golden["cases"]} >= {1, 5, 30}
    loaded = load_checkpoint(paths["checkpoint"])
    facing_minus_x = False
    for case in golden["cases"]:
        p, n = case["past_frames"], case["gap"]
        k = p + 1
        feeds = {C.KEY_FEATURES: np.asarray(case["inputs"][C.KEY_FEATURES], np.float32).reshape(1, k, 198),
                 C.KEY_FRAME_INDICES: np.asarray(case["inputs"][C.KEY_FRAME_INDICES]),
                 C.QUERY_FRAME_INDICES: np.asarray(case["inputs"][C.QUERY_FRAME_INDICES]),
                 C.GAP_LENGTH: np.asarray(case["inputs"][C.GAP_LENGTH])}
        out = run_model(paths["onnx_whole"], feeds)
        rot = np.asarray(case["outputs"][C.ROTATION_6D_DELTA])
        assert np.abs(out[C.ROTATION_6D_DELTA].reshape(-1) - rot).max() < 1e-5
        assert np.abs(rot).max() > 1e-3, "the fixture model must not be plain SLERP"
        assert len(case["result"]["local_quaternions"]) == n and len(case["result"]["global_positions"][0]) == 22
        from deltainterp.transition import run_transition
        t = lambda v: torch.tensor(v, dtype=torch.float64)[None]  # noqa: E731
        res = run_transition(loaded, t(case["past_root_positions"]), t(case["past_local_quaternions"]),
                             t(case["target_root_position"]), t(case["target_local_quaternions"]), n)
        assert np.abs(res.root_positions[0].numpy() - np.asarray(case["result"]["root_positions"])).max() < 1e-5
        assert np.abs(res.local_quaternions[0].numpy() - np.asarray(case["result"]["local_quaternions"])).max() < 1e-6
        yaw = np.asarray(case["localization"]["yaw"])
        facing_minus_x |= abs(yaw[0]) < 0.1  # a ~180° turn about +Y
    assert facing_minus_x, "one golden case must face roughly −X"


def test_fixture_checkpoint_round_trip(tiny, tmp_path):
    torch.save(checkpoint_state(tiny), tmp_path / "c.pt")
    loaded = load_checkpoint(tmp_path / "c.pt")
    assert loaded.skeleton.names == tiny.skeleton.names
    for name, w in tiny.model.state_dict().items():
        assert torch.equal(w, loaded.model.state_dict()[name])
    with pytest.raises(ValueError, match="missing.pt: not found"):
        load_checkpoint(tmp_path / "missing.pt")
    torch.save({"model": {}}, tmp_path / "bad.pt")
    with pytest.raises(ValueError, match="not a deltainterp checkpoint"):
        load_checkpoint(tmp_path / "bad.pt")


def test_keys_graph_torch_module(tiny):
    inputs = example_inputs(tiny.model, "keys", 7, 1, 3)
    memory = KeysGraph(tiny.model)(*inputs.values())[0]
    assert memory.shape == (1, tiny.config.blocks, 2, 7, tiny.config.width)


def test_batch_rows_equal_their_own_runs(exported):
    """Contract version 2: rows of one batched run (different gap lengths, different query frames) equal
    each row run alone, in every graph (a runtime gathers many characters into one run)."""
    tiny, _, protos = exported
    gaps = [5, 30, 12, 1]
    batch = {k: v.numpy() for k, v in example_inputs(tiny.model, "whole", 11, 1, gaps, seed=7).items()}
    batch[C.QUERY_FRAME_INDICES] = np.array([[10], [10 + 29], [10 + 6], [10]], dtype=np.int64)
    keys_in = (C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.GAP_LENGTH)
    whole = run_model(protos["whole"], batch)
    memory = run_model(protos["keys"], {k: batch[k] for k in keys_in})[C.KEY_MEMORY]
    assert memory.shape == (4, tiny.config.blocks, 2, 11, tiny.config.width)
    frame = run_model(protos["frame"], {C.KEY_MEMORY: memory, C.QUERY_FRAME_INDICES: batch[C.QUERY_FRAME_INDICES],
                                        C.GAP_LENGTH: batch[C.GAP_LENGTH]})
    for row in range(len(gaps)):
        one = {k: v[row:row + 1] for k, v in batch.items()}
        alone = run_model(protos["whole"], one)
        alone_memory = run_model(protos["keys"], {k: one[k] for k in keys_in})[C.KEY_MEMORY]
        assert np.abs(alone_memory[0] - memory[row]).max() < 1e-5
        for name in (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA):
            assert np.abs(alone[name][0] - whole[name][row]).max() < 1e-5
            assert np.abs(alone[name][0] - frame[name][row]).max() < 1e-5
