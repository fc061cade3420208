"""`deltainterp quantize`: the reference evaluator's int8 operators against the ONNX specification, the
rewritten tiny model close to float (and a damaged one caught), metadata kept, and the output rules."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import onnx
import pytest
from onnx import numpy_helper

from deltainterp import contract as C
from deltainterp.onnx_reference import OPS, run_model
from deltainterp.quantize import (QuantizeError, quantize_graph, quantize_model, quantize_weight,
                                  relative_differences)
from deltainterp.safe_output import OutputPathError

REPO = Path(__file__).resolve().parents[3]
TINY = REPO / "Tests" / "Fixtures~" / "tiny-model.onnx"
TOLERANCE = 0.03   # max |int8 − float| / max |float| per graph; the tiny model measures 1.1–1.4 %


@pytest.fixture()
def tiny_copy(tmp_path):
    for suffix in ("", ".keys", ".frame"):
        shutil.copy(TINY.with_name(f"tiny-model{suffix}.onnx"), tmp_path / f"tiny{suffix}.onnx")
    return tmp_path / "tiny.onnx"


def _load_three(whole: Path):
    stem = str(whole)[:-len(".onnx")]
    return {k: onnx.load(p) for k, p in (("whole", whole), ("keys", f"{stem}.keys.onnx"),
                                         ("frame", f"{stem}.frame.onnx"))}


def test_dynamic_quantize_linear_follows_the_specification():
    # the worked example of the ONNX operator documentation (DynamicQuantizeLinear, opset 11)
    x = np.array([0, 2, -3, -2.5, 1.34, 0.5], dtype=np.float32)
    y, scale, zero = OPS["DynamicQuantizeLinear"]([x], {})
    assert np.isclose(scale, 0.0196078438)
    assert zero == 153
    assert y.tolist() == [153, 255, 0, 26, 221, 179]
    y, scale, zero = OPS["DynamicQuantizeLinear"]([np.array([-1, -2.1, -1.3, -2.5, -3.34, -4], np.float32)], {})
    assert zero == 255 and y.tolist() == [191, 121, 172, 96, 42, 0]  # the range widened to hold 0


def test_matmul_integer_subtracts_zero_points():
    a = np.array([[11, 7, 3], [10, 6, 2]], dtype=np.uint8)
    b = np.array([[1, 4], [2, 5], [3, 6]], dtype=np.int8)
    got = OPS["MatMulInteger"]([a, b, np.uint8(12)], {})
    assert got.dtype == np.int32
    assert got.tolist() == (((a.astype(np.int32) - 12) @ b.astype(np.int32))).tolist()


def test_weights_are_symmetric_int8_per_output_column():
    w = np.array([[0.5, -2.0, 0.0], [-1.0, 1.0, 0.0]], dtype=np.float32)
    q, scale = quantize_weight(w)
    assert q.dtype == np.int8 and scale.tolist() == pytest.approx([1 / 127, 2 / 127, 1.0])
    assert q[:, 0].tolist() == [64, -127] and q[:, 1].tolist() == [-127, 64] and q[:, 2].tolist() == [0, 0]


@pytest.mark.parametrize("form", ["fused", "integer"])
def test_tiny_model_stays_close_to_float(tiny_copy, tmp_path, form):
    out = tmp_path / "tiny.int8.onnx"
    report = quantize_model(tiny_copy, out, form, min_weights=1)
    assert set(report.paths) == {"whole", "keys", "frame"}
    assert all(len(g.quantized) > 0 for g in report.graphs.values())
    for kind, difference in report.relative_difference.items():
        assert difference < TOLERANCE, f"{kind}: {difference:.2%}"
    floats, quantized = _load_three(tiny_copy), _load_three(out)
    ops = {n.op_type for n in quantized["frame"].graph.node}
    assert ({"DynamicQuantizeMatMul"} if form == "fused" else {"DynamicQuantizeLinear", "MatMulInteger"}) <= ops
    for kind in floats:
        before = {e.key: e.value for e in floats[kind].metadata_props}
        after = {e.key: e.value for e in quantized[kind].metadata_props}
        assert after["contract_version"] == before["contract_version"]
        meta_before, meta_after = json.loads(before["deltainterp"]), json.loads(after["deltainterp"])
        assert meta_after.pop("quantization")["form"] == form
        assert meta_after == meta_before  # every field of the contract is kept
        assert [i.name for i in quantized[kind].graph.input] == [i.name for i in floats[kind].graph.input]
        assert [o.name for o in quantized[kind].graph.output] == [o.name for o in floats[kind].graph.output]


def test_the_two_forms_compute_the_same(tiny_copy, tmp_path):
    fused = _load_three(quantize_model(tiny_copy, tmp_path / "f.onnx", "fused", 1).paths["whole"])
    integer = _load_three(quantize_model(tiny_copy, tmp_path / "i.onnx", "integer", 1).paths["whole"])
    meta = json.loads(next(e.value for e in fused["whole"].metadata_props if e.key == "deltainterp"))
    from deltainterp.quantize import probe_inputs
    feeds = probe_inputs(meta, "whole")
    a, b = run_model(fused["whole"], feeds), run_model(integer["whole"], feeds)
    assert np.abs(a[C.ROTATION_6D_DELTA] - b[C.ROTATION_6D_DELTA]).max() < 1e-5


def test_a_damaged_quantization_is_caught(tiny_copy):
    # the check above must be able to fail: one weight column's scale 30 % off is far outside the tolerance
    floats = _load_three(tiny_copy)
    quantized = {k: quantize_graph(p, "fused", 1)[0] for k, p in floats.items()}
    graph = quantized["frame"].graph
    scale = next(i for i in graph.initializer if i.name.endswith("_weight_scale") and "rotation_head" in i.name)
    values = numpy_helper.to_array(scale).copy()
    values *= 1.3
    scale.CopyFrom(numpy_helper.from_array(values, scale.name))
    assert relative_differences(floats, quantized)["frame"] > TOLERANCE


def test_output_rules(tiny_copy, tmp_path):
    with pytest.raises(OutputPathError, match="also an input"):
        quantize_model(tiny_copy, tiny_copy, force=True)
    out = tmp_path / "q.onnx"
    quantize_model(tiny_copy, out, min_weights=1)
    with pytest.raises(OutputPathError, match="already exists"):
        quantize_model(tiny_copy, out, min_weights=1)
    with pytest.raises(QuantizeError, match="quantized already"):
        quantize_model(out, tmp_path / "qq.onnx", min_weights=1)
    with pytest.raises(QuantizeError, match="'keys' graph"):
        quantize_model(tiny_copy.with_name("tiny.keys.onnx"), tmp_path / "k.onnx", min_weights=1)


def test_the_csharp_fixture_is_what_quantize_writes(tiny_copy, tmp_path):
    # Tests/Runtime/OnnxRuntime/QuantizedModelTests runs these files on the real ONNX Runtime
    out = quantize_model(tiny_copy, tmp_path / "tiny-model.int8.onnx", "fused", 1).paths
    for kind, path in out.items():
        committed = REPO / "Tests" / "Fixtures~" / path.name
        assert committed.read_bytes() == path.read_bytes(), (
            f"{committed.name} is stale; run PYTHONPATH=Training/Python~ python3 -m deltainterp quantize --model "
            "Tests/Fixtures~/tiny-model.onnx --out Tests/Fixtures~/tiny-model.int8.onnx --min-weights 1 --force")
