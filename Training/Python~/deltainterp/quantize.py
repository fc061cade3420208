"""Dynamic int8 quantization of an exported model, for ONNX Runtime only (issue 19).

ONNX Runtime's own Python quantizer is not installable here (no onnxruntime wheel), so this is a graph
rewrite with the `onnx` package. Every MatMul (and plain Gemm) whose weight is a constant 2-D initializer
of at least `min_weights` elements becomes a dynamically quantized product:
- the activation is quantized per tensor at run time (DynamicQuantizeLinear: uint8, asymmetric), because
  its range changes with every request;
- the weight is quantized once, per output column, symmetric int8 (zero point 0, scale max|w|/127), the
  type ONNX Runtime's u8×s8 kernels take (VNNI on current x86; 127 rather than 128 keeps -w representable);
- the int32 product is rescaled to float (activation scale × column scale) and the bias added as before.
Two spellings of the same arithmetic (`form`):
- `fused`: one com.microsoft `DynamicQuantizeMatMul` node (with the following bias Add folded in);
- `integer`: the standard-domain chain DynamicQuantizeLinear → MatMulInteger → Cast → Mul, which ONNX
  Runtime's optimizer fuses into the same kernel at its default level.
Attention's activation × activation MatMuls and small weights (the 3-wide root head) stay float.

Unity Sentis 2.x imports neither DynamicQuantizeLinear nor MatMulInteger (nor the com.microsoft domain), so
a quantized file is for the ONNX Runtime backend only; its `deltainterp` metadata says so in a
`quantization` object, and it keeps every other metadata field, inputs and outputs of the float file.
"""
from __future__ import annotations

import copy
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Tuple

import numpy as np

from . import contract as C, safe_output
from .onnx_reference import run_model
from .safe_input import load_onnx

FORMS = ("fused", "integer")
MICROSOFT = "com.microsoft"
DEFAULT_MIN_WEIGHTS = 4096   # 32×256 embeddings projections and up; the 256×3 root head stays float
INT8_LIMIT = 127.0


class QuantizeError(ValueError):
    """An input that cannot be quantized (not one of our exports, already quantized, ...)."""


@dataclass
class GraphQuantization:
    quantized: List[str] = field(default_factory=list)   # node names rewritten
    kept: List[str] = field(default_factory=list)        # MatMul/Gemm nodes left in float, with why
    weight_bytes_before: int = 0
    weight_bytes_after: int = 0


def quantize_weight(w: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """[K, N] float → (int8 [K, N], float32 scale [N]): symmetric per output column."""
    w = np.asarray(w, dtype=np.float32)
    peak = np.abs(w).max(axis=0)
    scale = np.where(peak > 0, peak / INT8_LIMIT, 1.0).astype(np.float32)  # an all-zero column stays zero
    q = np.clip(np.rint(w / scale), -INT8_LIMIT, INT8_LIMIT).astype(np.int8)
    return q, scale


def _consumers(graph) -> Dict[str, List]:
    users: Dict[str, List] = {}
    for node in graph.node:
        for name in node.input:
            users.setdefault(name, []).append(node)
    return users


def _bias_add(node, users, inits, outputs, columns: int):
    """The Add right after a MatMul that adds a constant [N] bias (and is the product's only user)."""
    out = node.output[0]
    if out in outputs or len(users.get(out, [])) != 1:
        return None, None
    add = users[out][0]
    if add.op_type != "Add" or len(add.input) != 2:
        return None, None
    other = add.input[1] if add.input[0] == out else add.input[0]
    bias = inits.get(other)
    if bias is None or list(bias.dims) != [columns] or bias.data_type != 1:
        return None, None
    return add, other


def _weight_of(node, inits, attrs) -> Tuple[Optional[np.ndarray], Optional[str], str]:
    """(weight as [K, N], bias initializer name or None, why not) for a MatMul or a plain Gemm. `inits` maps
    names to initializers, including the outputs of Identity nodes of an initializer."""
    from onnx import numpy_helper
    if len(node.input) < 2 or node.input[1] not in inits:
        return None, None, "its second input is not a constant (attention)"
    w = numpy_helper.to_array(inits[node.input[1]])
    if w.dtype != np.float32 or w.ndim != 2:
        return None, None, f"weight of type {w.dtype} rank {w.ndim}"
    if node.op_type == "MatMul":
        return w, None, ""
    # Gemm: only Y = A·B(ᵀ) + c with alpha = beta = 1, A not transposed, c a [N] initializer
    if attrs.get("transA", 0) or attrs.get("alpha", 1.0) != 1.0 or attrs.get("beta", 1.0) != 1.0:
        return None, None, "a Gemm with transA/alpha/beta"
    if attrs.get("transB", 0):
        w = w.T
    bias = node.input[2] if len(node.input) > 2 and node.input[2] else None
    if bias is not None and (bias not in inits or list(inits[bias].dims) != [w.shape[1]]):
        return None, None, "a Gemm whose C is not a constant [N] bias"
    return w, bias, ""


def quantize_graph(proto, form: str = "fused", min_weights: int = DEFAULT_MIN_WEIGHTS):
    """A quantized copy of one ModelProto (the input is not changed) and what was done."""
    import onnx
    from onnx import helper, numpy_helper
    if form not in FORMS:
        raise QuantizeError(f"form {form!r}; expected one of {', '.join(FORMS)}")
    if any(n.op_type in ("DynamicQuantizeMatMul", "MatMulInteger", "DynamicQuantizeLinear") for n in proto.graph.node):
        raise QuantizeError("the graph is quantized already; expected a float export")
    model = copy.deepcopy(proto)
    graph = model.graph
    inits = {i.name: i for i in graph.initializer}
    outputs = {o.name for o in graph.output}
    # The exporter gives a weight used twice (the whole graph runs a block's layers on key and on query
    # tokens) to its second user through an Identity node; see through it, or the float copy stays.
    for node in graph.node:
        if node.op_type == "Identity" and node.input[0] in inits and node.output[0] not in outputs:
            inits[node.output[0]] = inits[node.input[0]]
    users = _consumers(graph)
    report = GraphQuantization()
    new_nodes, drop, new_inits, dead_inits = [], set(), [], set()
    done: Dict[Tuple[str, bool], Tuple[str, str]] = {}  # one int8 copy per weight (the whole graph shares some)
    for node in graph.node:
        if id(node) in drop:
            continue
        if node.op_type not in ("MatMul", "Gemm"):
            new_nodes.append(node)
            continue
        attrs = {a.name: helper.get_attribute_value(a) for a in node.attribute}
        w, bias, why = _weight_of(node, inits, attrs)
        if w is None or w.size < min_weights:
            report.kept.append(f"{node.name}: {why or f'{w.size} weights < {min_weights}'}")
            new_nodes.append(node)
            continue
        tag = node.name.strip("/").replace("/", "_") or f"matmul{len(report.quantized)}"
        weight_key = (inits[node.input[1]].name, bool(node.op_type == "Gemm" and attrs.get("transB", 0)))
        if weight_key not in done:
            q, scale = quantize_weight(w)
            done[weight_key] = (f"{tag}_weight_int8", f"{tag}_weight_scale")
            new_inits += [numpy_helper.from_array(q, done[weight_key][0]),
                          numpy_helper.from_array(scale, done[weight_key][1])]
            report.weight_bytes_before += w.size * 4
            report.weight_bytes_after += q.size + scale.size * 4
        qw, sw = done[weight_key]
        dead_inits.add(inits[node.input[1]].name)
        out = node.output[0]
        add = None
        if bias is None and node.op_type == "MatMul":
            add, bias = _bias_add(node, users, inits, outputs, w.shape[1])
        if form == "fused":
            target = add.output[0] if add is not None else out
            if add is not None:
                drop.add(id(add))
            new_nodes.append(helper.make_node("DynamicQuantizeMatMul",
                                              [node.input[0], qw, sw, "", bias or ""][:5 if bias else 3],
                                              [target], name=f"{node.name}_int8", domain=MICROSOFT))
        else:
            a_q, a_s, a_z = f"{tag}_x_uint8", f"{tag}_x_scale", f"{tag}_x_zero_point"
            new_nodes += [
                helper.make_node("DynamicQuantizeLinear", [node.input[0]], [a_q, a_s, a_z], name=f"{tag}_quantize"),
                helper.make_node("MatMulInteger", [a_q, qw, a_z], [f"{tag}_int32"], name=f"{tag}_matmul_integer"),
                helper.make_node("Cast", [f"{tag}_int32"], [f"{tag}_float"], name=f"{tag}_cast",
                                 to=onnx.TensorProto.FLOAT),
                # activation scale × column scales first, then the product: the pattern ONNX Runtime fuses
                helper.make_node("Mul", [a_s, sw], [f"{tag}_scale"], name=f"{tag}_scale"),
            ]
            if node.op_type == "Gemm" and bias:
                new_nodes += [helper.make_node("Mul", [f"{tag}_float", f"{tag}_scale"], [f"{tag}_product"],
                                               name=f"{tag}_rescale"),
                              helper.make_node("Add", [f"{tag}_product", bias], [out], name=f"{tag}_bias")]
            else:
                new_nodes.append(helper.make_node("Mul", [f"{tag}_float", f"{tag}_scale"], [out], name=f"{tag}_rescale"))
        report.quantized.append(node.name)
    if not report.quantized:
        raise QuantizeError(f"no MatMul/Gemm with a constant weight of at least {min_weights} elements; nothing to quantize")
    still_used = {name for n in new_nodes for name in n.input}
    # Identity nodes that only passed a now-quantized weight on
    new_nodes = [n for n in new_nodes if not (n.op_type == "Identity" and n.output[0] not in still_used
                                               and n.output[0] not in outputs)]
    still_used = {name for n in new_nodes for name in n.input}
    kept_inits = [i for i in graph.initializer if i.name not in dead_inits or i.name in still_used]
    del graph.node[:]
    graph.node.extend(new_nodes)
    del graph.initializer[:]
    graph.initializer.extend(kept_inits + new_inits)
    if form == "fused" and not any(o.domain == MICROSOFT for o in model.opset_import):
        model.opset_import.append(helper.make_opsetid(MICROSOFT, 1))
    _mark_metadata(model, form, min_weights, report)
    onnx.checker.check_model(model)  # the com.microsoft node is not schema-checked (unknown domain to onnx)
    return model, report


def _mark_metadata(model, form: str, min_weights: int, report: GraphQuantization) -> None:
    entries = {e.key: e for e in model.metadata_props}
    if "deltainterp" not in entries:
        raise QuantizeError("no 'deltainterp' metadata; expected a graph written by `deltainterp export`")
    meta = json.loads(entries["deltainterp"].value)
    meta["quantization"] = {
        "method": "dynamic int8",
        "form": form,
        "weights": "int8, symmetric, per output column",
        "activations": "uint8, per tensor, computed at run time",
        "min_weights": min_weights,
        "quantized_matmuls": len(report.quantized),
        "float_matmuls": len(report.kept),
        "runtime": "ONNX Runtime only (Unity Sentis 2.x imports neither DynamicQuantizeLinear nor MatMulInteger)",
    }
    entries["deltainterp"].value = json.dumps(meta, sort_keys=False)


# ---------------------------------------------------------------------------------------------------- files

def sibling_paths(whole: str | Path) -> Dict[str, Path]:
    """NAME.onnx → its three graphs (the runtime's rule: NAME.keys.onnx and NAME.frame.onnx beside it)."""
    from .export import graph_paths
    return graph_paths(whole)


def probe_inputs(meta: Dict, kind: str, keys: int = 11, queries: int = 8, gaps=(7, 20), seed: int = 0,
                 key_memory: Optional[np.ndarray] = None) -> Dict[str, np.ndarray]:
    """Contract-shaped inputs for one graph from its metadata: two rows of different gap lengths, or in the
    version 1 layout (no batch axis: indices [K]/[N], gap [1]) one row with the first gap."""
    rng = np.random.default_rng(seed)
    batched = int(meta.get("contract_version", C.CONTRACT_VERSION)) >= 2
    gaps = list(gaps) if batched else [gaps[0]]
    j = len(meta["skeleton"]["names"])
    feats = (rng.standard_normal((len(gaps), keys, C.FEATURES_PER_JOINT * j)) * 0.3).astype(np.float32)
    key_idx, query_idx, gap = C.example_frame_indices(keys, queries, gaps, batched)
    if kind == "keys":
        return {C.KEY_FEATURES: feats, C.KEY_FRAME_INDICES: key_idx, C.GAP_LENGTH: gap}
    if kind == "frame":
        return {C.KEY_MEMORY: key_memory, C.QUERY_FRAME_INDICES: query_idx, C.GAP_LENGTH: gap}
    return {C.KEY_FEATURES: feats, C.KEY_FRAME_INDICES: key_idx, C.QUERY_FRAME_INDICES: query_idx,
            C.GAP_LENGTH: gap}


def relative_differences(float_protos: Dict[str, object], quantized: Dict[str, object]) -> Dict[str, float]:
    """max |int8 − float| / max |float| of each graph's float outputs on probe inputs, evaluated with the
    numpy reference evaluator (which implements the quantized operators by their specifications)."""
    meta = json.loads(next(e.value for e in float_protos["whole"].metadata_props if e.key == "deltainterp"))
    if meta.get("input_delta_mode") == "none":
        raise QuantizeError("input delta mode 'none' (an ablation) is not supported here")
    result: Dict[str, float] = {}
    memory = None
    for kind in ("whole", "keys", "frame"):
        if kind not in quantized:
            continue
        if kind == "frame" and memory is None:
            memory = run_model(float_protos["keys"], probe_inputs(meta, "keys"))[C.KEY_MEMORY]
        feeds = probe_inputs(meta, kind, key_memory=memory)
        want, got = run_model(float_protos[kind], feeds), run_model(quantized[kind], feeds)
        if kind == "keys":
            memory = want[C.KEY_MEMORY]
        names = [C.KEY_MEMORY] if kind == "keys" else [C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA]
        result[kind] = max(float(np.abs(got[n] - want[n]).max() / max(np.abs(want[n]).max(), 1e-12)) for n in names)
    return result


@dataclass
class QuantizeReport:
    paths: Dict[str, Path]
    sizes: Dict[str, Tuple[int, int]]            # kind → (float bytes, int8 bytes)
    graphs: Dict[str, GraphQuantization]
    relative_difference: Dict[str, float]


def quantize_model(source: str | Path, out: str | Path, form: str = "fused",
                   min_weights: int = DEFAULT_MIN_WEIGHTS, force: bool = False) -> QuantizeReport:
    """Quantize NAME.onnx and, when beside it, NAME.keys.onnx and NAME.frame.onnx into OUT's three paths.
    Checks every output path before any work; writes nothing unless every graph was rewritten and checked."""
    inputs, targets = sibling_paths(source), sibling_paths(out)
    kinds = ["whole"] + [k for k in ("keys", "frame") if inputs[k].exists()]
    if len(kinds) == 2:
        raise QuantizeError(f"{source}: only one of its .keys.onnx/.frame.onnx is beside it; expected both or neither")
    for kind in kinds:
        safe_output.check(targets[kind], force, [str(p) for p in inputs.values()])
    float_protos, quantized, graphs = {}, {}, {}
    for kind in kinds:
        float_protos[kind] = load_onnx(inputs[kind], "an exported graph (.onnx)")
        graph_kind = json.loads(next((e.value for e in float_protos[kind].metadata_props if e.key == "deltainterp"),
                                     "{}")).get("graph")
        if graph_kind != kind:
            raise QuantizeError(f"{inputs[kind]}: holds the {graph_kind!r} graph; expected the {kind!r} graph "
                                "(pass NAME.onnx, the whole graph of an export)")
        quantized[kind], graphs[kind] = quantize_graph(float_protos[kind], form, min_weights)
    differences = relative_differences(float_protos, quantized)
    sizes = {}
    for kind in kinds:
        data = quantized[kind].SerializeToString()
        safe_output.write_bytes(targets[kind], data)
        sizes[kind] = (inputs[kind].stat().st_size, len(data))
    return QuantizeReport({k: targets[k] for k in kinds}, sizes, graphs, differences)


__all__ = ["FORMS", "DEFAULT_MIN_WEIGHTS", "QuantizeError", "GraphQuantization", "QuantizeReport",
           "quantize_weight", "quantize_graph", "quantize_model", "relative_differences", "probe_inputs"]
