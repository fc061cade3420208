"""Every verb that reads an `.onnx` refuses, in one line and before running anything, a node outside the model
contract (a Loop of 10^12 trips must not start) and an operator the reference evaluator lacks (issue 31,
classes 4 and 17)."""
from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import pytest

from deltainterp.onnx_reference import run_model

from conftest import REPO
from refusals import one_line, run_cli

FIXTURES = REPO / "Tests" / "Fixtures~"


def _whole_graph():
    import onnx
    return onnx.load(str(FIXTURES / "tiny-model.onnx"))


def with_endless_loop(path: Path) -> Path:
    """The tiny model plus a Loop of 10^12 trips whose output feeds nothing: valid ONNX, endless if run."""
    import onnx
    from onnx import TensorProto, helper
    proto = _whole_graph()
    body = helper.make_graph(
        [helper.make_node("Identity", ["cond_in"], ["cond_out"]),
         helper.make_node("Add", ["count_in", "one"], ["count_out"])], "body",
        [helper.make_tensor_value_info("trip", TensorProto.INT64, []),
         helper.make_tensor_value_info("cond_in", TensorProto.BOOL, []),
         helper.make_tensor_value_info("count_in", TensorProto.FLOAT, [])],
        [helper.make_tensor_value_info("cond_out", TensorProto.BOOL, []),
         helper.make_tensor_value_info("count_out", TensorProto.FLOAT, [])],
        [helper.make_tensor("one", TensorProto.FLOAT, [], [1.0])])
    proto.graph.initializer.extend([helper.make_tensor("trips", TensorProto.INT64, [], [10 ** 12]),
                                    helper.make_tensor("go", TensorProto.BOOL, [], [True]),
                                    helper.make_tensor("zero", TensorProto.FLOAT, [], [0.0])])
    proto.graph.node.insert(0, helper.make_node("Loop", ["trips", "go", "zero"], ["loop_count"], name="spin",
                                                body=body))
    onnx.save(proto, str(path))
    return path


def with_unevaluated_operator(path: Path, operator: str = "Floor") -> Path:
    """The tiny model plus a contract operator (both Unity importers read it) that onnx_reference lacks."""
    import onnx
    from onnx import helper
    proto = _whole_graph()
    source = proto.graph.node[-1].output[0]
    proto.graph.node.append(helper.make_node(operator, [source], ["rounded"], name="round_it"))
    onnx.save(proto, str(path))
    return path


@pytest.fixture(params=["loop", "floor"])
def hostile_model(request, tmp_path) -> Path:
    folder = tmp_path / request.param
    folder.mkdir()
    make = with_endless_loop if request.param == "loop" else with_unevaluated_operator
    return make(folder / "m.onnx")


def test_verbs_that_read_an_onnx_refuse_it_in_one_line_before_running(hostile_model, synthetic_pack_path, tmp_path,
                                                                     capsys):
    phrase = "the graph uses the operator Loop (node 'spin') outside the model contract, so nothing was run" \
        if hostile_model.parent.name == "loop" else \
        "the graph uses the operator Floor (node 'round_it'), which the trainer's reference evaluator"
    data = REPO.parent / "shared" / "data" / "lafan1"
    for argv in (["quantize", "--model", hostile_model, "--out", tmp_path / "q.onnx"],
                 ["export", "--checkpoint", hostile_model, "--out", tmp_path / "e.onnx"],
                 ["evaluate", "--checkpoint", hostile_model, "--data", data, "--json", tmp_path / "r.json"],
                 ["train", "--init-from", hostile_model, "--data", synthetic_pack_path, "--out", tmp_path / "run",
                  "--preset", "tiny", "--steps", "2"],
                 ["chained", "--checkpoint", hostile_model, "--data", synthetic_pack_path]):
        started = time.monotonic()
        code, _, err = run_cli(capsys, argv)
        line = one_line(code, err, phrase)
        assert str(hostile_model) in line and time.monotonic() - started < 60, (argv[0], line)
    assert not any(p.suffix == ".onnx" and p != hostile_model for p in tmp_path.rglob("*.onnx"))


def test_the_reference_evaluator_checks_every_node_before_running_the_first(tmp_path):
    from deltainterp.onnx_reference import UnsupportedOperatorError
    model = with_endless_loop(tmp_path / "loop.onnx")
    with pytest.raises(ValueError, match="outside the model contract"):
        run_model(model, {})  # the path form: refused while loading (safe_input.load_onnx)
    with pytest.raises(UnsupportedOperatorError, match="outside the model contract"):
        run_model(_with_loop_last(), {})  # the proto form: the Loop is last, yet nothing before it runs


def _with_loop_last():
    import onnx
    proto = _whole_graph()
    proto.graph.node.append(onnx.helper.make_node("Loop", ["", ""], [], name="spin"))
    return proto
