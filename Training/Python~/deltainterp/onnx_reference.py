"""A small numpy evaluator for the ONNX operator subset our exporter emits.

onnxruntime is not available to the Python side, so the exported FILE is checked by running its nodes
here, one by one, in float32 (as a runtime would) — a stronger check than comparing with a traced torch
module, because it reads exactly what the C# runtime will load. Semantics follow the ONNX operator
specification (opset 13–15 forms: axes of Unsqueeze/Squeeze/ReduceSum as inputs, ReduceMean's `axes`
as an attribute, Softmax over one axis).
"""
from __future__ import annotations

from typing import Callable, Dict, List

import numpy as np

from .operators import ALLOWED, FORBIDDEN

Array = np.ndarray


def _attrs(node) -> Dict[str, object]:
    import onnx
    import onnx.numpy_helper
    return {a.name: onnx.helper.get_attribute_value(a) for a in node.attribute}


def _axes(values, rank: int) -> List[int]:
    return sorted(int(a) + rank if int(a) < 0 else int(a) for a in values)


def _gemm(ins, at):
    a, b = ins[0], ins[1]
    if at.get("transA", 0):
        a = a.T
    if at.get("transB", 0):
        b = b.T
    y = at.get("alpha", 1.0) * (a @ b)
    if len(ins) > 2 and ins[2] is not None:
        y = y + at.get("beta", 1.0) * ins[2]
    return y


def _softmax(ins, at):
    x = ins[0]
    axis = int(at.get("axis", -1))
    e = np.exp(x - x.max(axis=axis, keepdims=True))
    return e / e.sum(axis=axis, keepdims=True)


def _reshape(ins, at):
    x, shape = ins[0], [int(s) for s in ins[1]]
    if not at.get("allowzero", 0):
        shape = [x.shape[i] if s == 0 else s for i, s in enumerate(shape)]
    return x.reshape(shape)


def _slice(ins, at):
    x = ins[0]
    starts, ends = ins[1], ins[2]
    axes = ins[3] if len(ins) > 3 and ins[3] is not None else np.arange(len(starts))
    steps = ins[4] if len(ins) > 4 and ins[4] is not None else np.ones(len(starts), dtype=np.int64)
    index = [slice(None)] * x.ndim
    for s, e, a, st in zip(starts, ends, axes, steps):
        a = int(a) + x.ndim if a < 0 else int(a)
        dim = x.shape[a]
        s, e = int(max(min(s, 2 ** 62), -2 ** 62)), int(max(min(e, 2 ** 62), -2 ** 62))
        index[a] = slice(*slice(s, e, int(st)).indices(dim))
    return x[tuple(index)]


def _unsqueeze(ins, at):
    x = ins[0]
    axes = ins[1] if len(ins) > 1 else at["axes"]
    for a in _axes(axes, x.ndim + len(axes)):
        x = np.expand_dims(x, a)
    return x


def _squeeze(ins, at):
    x = ins[0]
    axes = ins[1] if len(ins) > 1 and ins[1] is not None else at.get("axes")
    if axes is None:
        return np.squeeze(x)
    return np.squeeze(x, axis=tuple(_axes(axes, x.ndim)))


def _reduce(fn):
    def op(ins, at):
        x = ins[0]
        axes = at.get("axes")
        if axes is None and len(ins) > 1 and ins[1] is not None:
            axes = ins[1]
        keep = bool(at.get("keepdims", 1))
        if axes is None or len(axes) == 0:
            return fn(x, axis=None, keepdims=keep)
        return fn(x, axis=tuple(_axes(axes, x.ndim)), keepdims=keep)
    return op


def _cast(ins, at):
    import onnx
    import onnx.numpy_helper
    to_numpy = getattr(onnx.helper, "tensor_dtype_to_np_dtype", None)  # onnx ≥ 1.13; older: onnx.mapping
    return ins[0].astype(to_numpy(at["to"]) if to_numpy else onnx.mapping.TENSOR_TYPE_TO_NP_TYPE[at["to"]])


def _constant(ins, at):
    import onnx
    import onnx.numpy_helper
    if "value" in at:
        return onnx.numpy_helper.to_array(at["value"])
    for key in ("value_float", "value_int"):
        if key in at:
            return np.array(at[key])
    for key in ("value_floats", "value_ints"):
        if key in at:
            return np.array(at[key])
    raise NotImplementedError(f"Constant with attributes {sorted(at)}")


def _dynamic_quantize_linear(ins, at):
    """ONNX DynamicQuantizeLinear (opset 11): uint8, the range widened to hold 0, round half to even."""
    x = ins[0].astype(np.float32)
    low, high = min(0.0, float(x.min())) if x.size else 0.0, max(0.0, float(x.max())) if x.size else 0.0
    scale = np.float32((high - low) / 255.0)
    if scale == 0:  # an all-zero tensor: the specification divides by zero; ONNX Runtime gives zeros
        return (np.zeros(x.shape, np.uint8), np.float32(0), np.uint8(0))
    zero_point = np.uint8(np.clip(np.rint(np.float32(0 - low) / scale), 0, 255))
    y = np.clip(np.rint(x / scale) + zero_point, 0, 255).astype(np.uint8)
    return (y, scale, zero_point)


def _integer_product(a, b, a_zero, b_zero):
    a = a.astype(np.int32) - (np.int32(0) if a_zero is None else a_zero.astype(np.int32))
    b = b.astype(np.int32) - (np.int32(0) if b_zero is None else b_zero.astype(np.int32))
    return np.matmul(a, b).astype(np.int32)


def _matmul_integer(ins, at):
    """ONNX MatMulInteger (opset 10): (A − a_zero) · (B − b_zero) in int32; b_zero scalar or per column."""
    return _integer_product(ins[0], ins[1], ins[2] if len(ins) > 2 else None, ins[3] if len(ins) > 3 else None)


def _dynamic_quantize_matmul(ins, at):
    """com.microsoft DynamicQuantizeMatMul (ONNX Runtime contrib): A quantized as DynamicQuantizeLinear,
    the integer product with B, rescaled by A's scale × b_scale (scalar or per column), plus the bias."""
    a_q, a_scale, a_zero = _dynamic_quantize_linear([ins[0]], at)
    b_zero = ins[3] if len(ins) > 3 else None
    y = _integer_product(a_q, ins[1], a_zero, b_zero).astype(np.float32) * (a_scale * ins[2].astype(np.float32))
    if len(ins) > 4 and ins[4] is not None:
        y = y + ins[4]
    return y.astype(np.float32)


def _keep_dtype(fn):
    """Binary arithmetic in the inputs' dtype (numpy would promote int64 ⊕ float32 etc.)."""
    def op(ins, at):
        out = fn(ins[0], ins[1])
        return out.astype(np.result_type(ins[0].dtype, ins[1].dtype), copy=False)
    return op


OPS: Dict[str, Callable] = {
    "Add": _keep_dtype(np.add),
    "Sub": _keep_dtype(np.subtract),
    "Mul": _keep_dtype(np.multiply),
    "Div": lambda i, a: (i[0] // i[1]) if np.issubdtype(i[0].dtype, np.integer) else i[0] / i[1],
    "Pow": lambda i, a: np.power(i[0], i[1]).astype(i[0].dtype),
    "Neg": lambda i, a: -i[0],
    "Sqrt": lambda i, a: np.sqrt(i[0]),
    "Exp": lambda i, a: np.exp(i[0]),
    "Relu": lambda i, a: np.maximum(i[0], 0).astype(i[0].dtype),
    "LeakyRelu": lambda i, a: np.where(i[0] >= 0, i[0], i[0] * np.float32(a.get("alpha", 0.01))).astype(i[0].dtype),
    "Tanh": lambda i, a: np.tanh(i[0]),
    "Sigmoid": lambda i, a: 1.0 / (1.0 + np.exp(-i[0])),
    "MatMul": lambda i, a: np.matmul(i[0], i[1]),
    "Gemm": _gemm,
    "Softmax": _softmax,
    "ReduceMean": _reduce(np.mean),
    "ReduceSum": _reduce(np.sum),
    "ReduceMax": _reduce(np.max),
    "Reshape": _reshape,
    "Transpose": lambda i, a: np.transpose(i[0], a.get("perm")),
    "Gather": lambda i, a: np.take(i[0], i[1].astype(np.int64), axis=int(a.get("axis", 0))),
    "Concat": lambda i, a: np.concatenate(i, axis=int(a["axis"])),
    "Slice": _slice,
    "Unsqueeze": _unsqueeze,
    "Squeeze": _squeeze,
    "Shape": lambda i, a: np.array(i[0].shape, dtype=np.int64)[a.get("start", 0):a.get("end", None)],
    "Expand": lambda i, a: i[0] * np.ones([int(s) for s in i[1]], dtype=i[0].dtype),
    "Cast": _cast,
    "Constant": _constant,
    "Identity": lambda i, a: i[0],
    "Dropout": lambda i, a: i[0],
    # dynamic int8 quantization (deltainterp quantize; ONNX Runtime only)
    "DynamicQuantizeLinear": _dynamic_quantize_linear,
    "MatMulInteger": _matmul_integer,
    "DynamicQuantizeMatMul": _dynamic_quantize_matmul,
}


# The int8 operators `quantize` writes (ONNX Runtime only); with operators.ALLOWED, what the model contract admits.
QUANTIZED = {"DynamicQuantizeLinear", "MatMulInteger", "com.microsoft::DynamicQuantizeMatMul"}


class UnsupportedOperatorError(ValueError):
    """A graph holds a node this evaluator must not or cannot run; the message is `FILE: what; expected`."""


def _operator(node) -> str:
    return node.op_type if node.domain in ("", "ai.onnx") else f"{node.domain}::{node.op_type}"


def check_runnable(graph, source: str = "model") -> None:
    """Refuses, before any node runs, a graph with a node outside the model contract (operators.ALLOWED and the
    int8 operators of `quantize`) or one this evaluator lacks: a `Loop` of 10^12 trips, an `If`, a subgraph or a
    custom domain never runs, and a missing operator is one line instead of a NotImplementedError traceback."""
    import onnx
    for node in graph.node:
        operator = _operator(node)
        name = operator if len(operator) <= 64 else operator[:64] + "…"
        node_name = f" (node {node.name[:80]!r})" if node.name else ""
        if operator not in ALLOWED and operator not in QUANTIZED:
            # The C# ModelOperators.Check's words, so both languages refuse a graph alike.
            why = FORBIDDEN.get(operator, "not imported by both Sentis 2.x and Barracuda")
            raise UnsupportedOperatorError(
                f"{source}: the graph uses the operator {name}{node_name} outside the model contract, so nothing was "
                f"run ({name}: {why}); expected only the operators listed in Documentation~/model-contract.md "
                "(Operators), as python3 -m deltainterp export writes them")
        if any(a.type in (onnx.AttributeProto.GRAPH, onnx.AttributeProto.GRAPHS) for a in node.attribute):
            raise UnsupportedOperatorError(
                f"{source}: the graph's node {name}{node_name} holds a subgraph, so nothing was run; expected a "
                "graph without control flow, as python3 -m deltainterp export writes it")
        if operator not in RUNNABLE:
            raise UnsupportedOperatorError(
                f"{source}: the graph uses the operator {name}{node_name}, which the trainer's reference evaluator "
                "(deltainterp/onnx_reference.py) lacks, so nothing was run; expected the operators python3 -m "
                "deltainterp export and quantize write")


# What run_graph can evaluate, spelled as _operator spells it (the contrib operator only in its own domain).
RUNNABLE = {op for op in OPS if op != "DynamicQuantizeMatMul"} | {"com.microsoft::DynamicQuantizeMatMul"}


def run_graph(graph, feeds: Dict[str, Array], source: str = "model") -> Dict[str, Array]:
    """Evaluate an onnx.GraphProto on numpy inputs; returns every graph output by name. Every node is checked
    before the first runs (check_runnable)."""
    import onnx
    import onnx.numpy_helper
    check_runnable(graph, source)
    values: Dict[str, Array] = {init.name: onnx.numpy_helper.to_array(init) for init in graph.initializer}
    for inp in graph.input:
        if inp.name in values:
            continue
        if inp.name not in feeds:
            raise KeyError(f"missing input '{inp.name}'")
        values[inp.name] = np.asarray(feeds[inp.name])
    for node in graph.node:
        if node.op_type not in OPS:
            raise NotImplementedError(f"onnx_reference has no '{node.op_type}' (node {node.name})")
        ins = [values[n] if n else None for n in node.input]
        out = OPS[node.op_type](ins, _attrs(node))
        outs = out if isinstance(out, tuple) else (out,)  # DynamicQuantizeLinear has three
        if len(node.output) != len(outs):
            raise NotImplementedError(f"{node.op_type} with {len(node.output)} outputs")
        for name, value in zip(node.output, outs):
            values[name] = np.asarray(value)
    return {o.name: values[o.name] for o in graph.output}


def run_model(model, feeds: Dict[str, Array]) -> Dict[str, Array]:
    """`model`: an onnx.ModelProto or a path."""
    import onnx
    import onnx.numpy_helper
    source = "model"
    if not hasattr(model, "graph"):
        source, model = str(model), onnx.load(str(model))
    return run_graph(model.graph, feeds, source)  # every node checked before the first runs
