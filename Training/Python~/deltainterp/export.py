"""ONNX export of a trained Δ-Interpolator (Documentation~/model-contract.md).

Three graphs per model, all opset 15, legacy TorchScript exporter, a dynamic batch axis B on every input
and output (contract version 2: one row per transition, so a runtime runs many characters at once) and
dynamic frame axes:
- `<name>.onnx`: the whole transition (key features + frame indices → deltas of the query frames);
- `<name>.keys.onnx`: keys → `key_memory` [B, R, 2, K, D] (per block, the cross-attention keys/values);
- `<name>.frame.onnx`: `key_memory` + query frames → deltas (lazy decoding, one frame at a time if wanted).
Each also returns the constant outputs `contract_version`, `joint_count`, `key_feature_size`, and carries
`metadata_props` (`contract_version`, `deltainterp` JSON). Export refuses graphs with operators outside
`operators.ALLOWED` and checks every graph numerically against torch with a numpy ONNX evaluator.
"""
from __future__ import annotations

import inspect
import io
import json
import math
import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Optional, Tuple

import numpy as np
import torch
from torch import nn

from . import contract as C, safe_output
from .checkpoint import LoadedModel
from .model import DeltaInterpolator
from .onnx_reference import run_model
from .operators import check_operators

Tensor = torch.Tensor
OPSET = 15

TRAINING_PAST = (10, 10)      # TransitionSampler defaults used by `train` (past keys, gap range); the
                              # lower end of the past range comes from the run's --min-past
TRAINING_FUTURE = (1, 1)
TRAINING_MISSING = (5, 39)     # the paper's gaps; a run's --min-gap/--max-gap replace it


def _constants(model: DeltaInterpolator) -> Tuple[Tensor, Tensor, Tensor]:
    j = model.config.joints
    return (torch.tensor([C.CONTRACT_VERSION], dtype=torch.int64), torch.tensor([j], dtype=torch.int64),
            torch.tensor([C.FEATURES_PER_JOINT * j], dtype=torch.int64))


class WholeGraph(nn.Module):
    """Contract version 2: every input has a batch axis B (one row per transition, rows may differ in
    gap length and frame indices but share K and N). `batched=False` is the version 1 layout (indices
    [K]/[N], gap [1], batch 1), kept to read the weights of files exported before version 2."""

    def __init__(self, model: DeltaInterpolator, batched: bool = True) -> None:
        super().__init__()
        self.model = model
        self.batched = batched

    def forward(self, key_features: Tensor, key_frame_indices: Tensor, query_frame_indices: Tensor,
                gap_length: Tensor, query_features: Optional[Tensor] = None):
        gap = gap_length.unsqueeze(1) if self.batched else gap_length  # [B] → [B, 1]: broadcasts over tokens
        outputs = self.model(key_features, key_frame_indices, query_frame_indices, gap, query_features,
                             with_contacts=self.model.has_contacts)
        return tuple(outputs) + _constants(self.model)


class KeysGraph(nn.Module):
    def __init__(self, model: DeltaInterpolator, batched: bool = True) -> None:
        super().__init__()
        self.model = model
        self.batched = batched

    def forward(self, key_features: Tensor, key_frame_indices: Tensor, gap_length: Tensor):
        if not self.batched:
            _, memory = self.model.encode_keys(key_features, key_frame_indices, gap_length)
            # batch 1: (1, K, D) keys and values → (2, K, D) per block → (R, 2, K, D)
            return (torch.stack([torch.cat((k, v), 0) for k, v in memory], 0),) + _constants(self.model)
        _, memory = self.model.encode_keys(key_features, key_frame_indices, gap_length.unsqueeze(1))
        # (B, K, D) keys and values → (B, 2, K, D) per block → (B, R, 2, K, D): one row per transition,
        # contiguous, so a runtime gathers and scatters whole rows
        key_memory = torch.stack([torch.stack((k, v), 1) for k, v in memory], 1)
        return (key_memory,) + _constants(self.model)


class FrameGraph(nn.Module):
    def __init__(self, model: DeltaInterpolator, batched: bool = True) -> None:
        super().__init__()
        self.model = model
        self.batched = batched

    def forward(self, key_memory: Tensor, query_frame_indices: Tensor, gap_length: Tensor,
                query_features: Optional[Tensor] = None):
        if self.batched:
            # (B, R, 2, K, D) → (B, 2R, K, D), sliced into (B, 1, K, D) keys and values per block, attended
            # with Mul/ReduceSum (attend_rows): no per-head transposes of every row's memory, so a batch of
            # rows costs little more than its dense layers
            b, blocks = key_memory.shape[0], len(self.model.blocks)
            rows = key_memory.reshape(b, 2 * blocks, key_memory.shape[3], key_memory.shape[4])
            memory = [(rows[:, 2 * i:2 * i + 1], rows[:, 2 * i + 1:2 * i + 2]) for i in range(blocks)]
            tokens = self.model.decode_queries(memory, query_frame_indices, gap_length.unsqueeze(1), query_features,
                                               rows=True)
        else:
            memory = [(key_memory[i, 0:1], key_memory[i, 1:2]) for i in range(len(self.model.blocks))]
            tokens = self.model.decode_queries(memory, query_frame_indices, gap_length, query_features)
        root, rotation = self.model.heads(tokens)
        contacts = (self.model.contacts(tokens, memory, rows=self.batched),) if self.model.has_contacts else ()
        return (root, rotation) + contacts + _constants(self.model)


class ExportCheckError(ValueError):
    """A written graph does not compute what the torch model computes (or breaks the contract)."""


@dataclass
class GraphSpec:
    kind: str                       # whole | keys | frame
    module: nn.Module
    input_names: List[str]
    output_names: List[str]
    dynamic_axes: Dict[str, Dict[int, str]]


def example_inputs(model: DeltaInterpolator, kind: str, keys: int = 11, queries: int = 5, gap=5,
                   seed: int = 0, batched: bool = True) -> Dict[str, Tensor]:
    """Inputs of the given graph kind for K keys and N queries (frame indices laid out as the contract's).
    `gap` is one gap length or, batched, a list of them (one row each: B = len(gap)); each row's query
    frames are its first N missing frames. `batched=False`: the version 1 layout (B = 1)."""
    g = torch.Generator().manual_seed(seed)
    gaps = list(gap) if isinstance(gap, (list, tuple)) else [gap]
    if not batched and len(gaps) != 1:
        raise ValueError("the version 1 layout has batch 1")
    b, j = len(gaps), model.config.joints
    feats = torch.randn(b, keys, C.FEATURES_PER_JOINT * j, generator=g) * 0.3
    key_idx, query_idx, gap_t = (torch.from_numpy(a) for a in C.example_frame_indices(keys, queries, gaps, batched))
    if kind == "keys":
        return {C.KEY_FEATURES: feats, C.KEY_FRAME_INDICES: key_idx, C.GAP_LENGTH: gap_t}
    inputs = {C.KEY_FEATURES: feats, C.KEY_FRAME_INDICES: key_idx, C.QUERY_FRAME_INDICES: query_idx,
              C.GAP_LENGTH: gap_t}
    if model.config.input_delta_mode == "none":
        inputs[C.QUERY_FEATURES] = torch.randn(b, queries, C.FEATURES_PER_JOINT * j, generator=g) * 0.3
    if kind == "frame":
        with torch.no_grad():
            inputs = {C.KEY_MEMORY: KeysGraph(model, batched)(feats, key_idx, gap_t)[0],
                      C.QUERY_FRAME_INDICES: query_idx, C.GAP_LENGTH: gap_t,
                      **({C.QUERY_FEATURES: inputs[C.QUERY_FEATURES]} if C.QUERY_FEATURES in inputs else {})}
    return inputs


def graph_specs(model: DeltaInterpolator, batched: bool = True) -> List[GraphSpec]:
    """The three graphs; `batched=False` is the version 1 layout (only to read old files' weights)."""
    consts = list(C.CONSTANT_OUTPUTS)
    # contract version 3: the whole and frame graphs of a model with a contact head also emit foot_contacts
    deltas = [C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA] + ([C.FOOT_CONTACTS] if model.has_contacts else [])
    qf = [C.QUERY_FEATURES] if model.config.input_delta_mode == "none" else []
    if not batched:
        qf_axes = {C.QUERY_FEATURES: {1: "N"}} if qf else {}
        out_axes = {name: {1: "N"} for name in deltas}
        return [
            GraphSpec("whole", WholeGraph(model, False),
                      [C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.QUERY_FRAME_INDICES, C.GAP_LENGTH] + qf,
                      deltas + consts,
                      {C.KEY_FEATURES: {1: "K"}, C.KEY_FRAME_INDICES: {0: "K"}, C.QUERY_FRAME_INDICES: {0: "N"},
                       **qf_axes, **out_axes}),
            GraphSpec("keys", KeysGraph(model, False), [C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.GAP_LENGTH],
                      [C.KEY_MEMORY] + consts,
                      {C.KEY_FEATURES: {1: "K"}, C.KEY_FRAME_INDICES: {0: "K"}, C.KEY_MEMORY: {2: "K"}}),
            GraphSpec("frame", FrameGraph(model, False), [C.KEY_MEMORY, C.QUERY_FRAME_INDICES, C.GAP_LENGTH] + qf,
                      deltas + consts,
                      {C.KEY_MEMORY: {2: "K"}, C.QUERY_FRAME_INDICES: {0: "N"}, **qf_axes, **out_axes}),
        ]
    qf_axes = {C.QUERY_FEATURES: {0: "B", 1: "N"}} if qf else {}
    out_axes = {name: {0: "B", 1: "N"} for name in deltas}
    return [
        GraphSpec("whole", WholeGraph(model),
                  [C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.QUERY_FRAME_INDICES, C.GAP_LENGTH] + qf,
                  deltas + consts,
                  {C.KEY_FEATURES: {0: "B", 1: "K"}, C.KEY_FRAME_INDICES: {0: "B", 1: "K"},
                   C.QUERY_FRAME_INDICES: {0: "B", 1: "N"}, C.GAP_LENGTH: {0: "B"}, **qf_axes, **out_axes}),
        GraphSpec("keys", KeysGraph(model), [C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.GAP_LENGTH],
                  [C.KEY_MEMORY] + consts,
                  {C.KEY_FEATURES: {0: "B", 1: "K"}, C.KEY_FRAME_INDICES: {0: "B", 1: "K"}, C.GAP_LENGTH: {0: "B"},
                   C.KEY_MEMORY: {0: "B", 3: "K"}}),
        GraphSpec("frame", FrameGraph(model), [C.KEY_MEMORY, C.QUERY_FRAME_INDICES, C.GAP_LENGTH] + qf,
                  deltas + consts,
                  {C.KEY_MEMORY: {0: "B", 3: "K"}, C.QUERY_FRAME_INDICES: {0: "B", 1: "N"}, C.GAP_LENGTH: {0: "B"},
                   **qf_axes, **out_axes}),
    ]


def metadata(loaded: LoadedModel, kind: str, name: str) -> Dict:
    cfg = loaded.config
    contacts = {}
    if loaded.model.has_contacts:
        # which model joint each foot_contacts channel is, and where a frame counts as planted (p ≥ threshold,
        # chosen on validation); every graph of the model carries them, the keys graph too (one metadata per model)
        contacts = {"contact_joints": list(C.CONTACT_JOINTS), "contact_threshold": float(loaded.contact_threshold)}
    architecture = {"width": cfg.width, "blocks": cfg.blocks, "heads": cfg.heads,
                    "embedding_dim": cfg.embedding_dim, "embedding_size": cfg.embedding_size,
                    "parameters": loaded.model.parameter_count()}
    if loaded.model.has_contacts:
        architecture["contact_head"] = cfg.contact_head
        if cfg.contact_head in ("mlp", "block"):
            architecture["contact_hidden"] = cfg.contact_hidden
    return {
        "contract_version": C.CONTRACT_VERSION,
        "name": name,
        "graph": kind,
        "skeleton": loaded.skeleton.to_json(),
        "unit_scale": loaded.unit_scale,
        "up_axis": [0, 1, 0],
        "facing_local_axis": [float(v) for v in loaded.facing_local_axis],
        "facing_target_axis": [float(v) for v in loaded.facing_target_axis],
        "rotation_6d": "rows",
        "quaternion_order": "wxyz",
        "output_delta_mode": cfg.output_delta_mode,
        "input_delta_mode": cfg.input_delta_mode,
        "training": {"past_frames": [int(loaded.train_config.get("min_past", TRAINING_PAST[0])), TRAINING_PAST[1]],
                     "future_frames": list(TRAINING_FUTURE),
                     "missing_frames": [int(loaded.train_config.get("min_gap", TRAINING_MISSING[0])),
                                        int(loaded.train_config.get("max_gap", TRAINING_MISSING[1]))], "fps": loaded.fps,
                     "data": loaded.data_description or "not recorded"},
        "max_frame_index": C.MAX_FRAME_INDEX,
        "architecture": architecture,
        **contacts,
    }


def _torch_onnx_export(module: nn.Module, args: Tuple, f, spec: GraphSpec) -> None:
    kwargs = dict(input_names=spec.input_names, output_names=spec.output_names,
                  dynamic_axes=spec.dynamic_axes, opset_version=OPSET, do_constant_folding=True)
    if "dynamo" in inspect.signature(torch.onnx.export).parameters:
        kwargs["dynamo"] = False  # torch ≥ 2.5: keep the TorchScript exporter, whose output the contract describes
    torch.onnx.export(module, args, f, **kwargs)


def _output_from_initializer_to_node(model) -> None:
    """Constant folding can turn a constant output into an initializer that is ALSO a graph output;
    some importers only look for node outputs, so route such outputs through an Identity node."""
    import onnx
    inits = {i.name for i in model.graph.initializer}
    for out in model.graph.output:
        if out.name in inits:
            src = out.name + "_constant"
            for i in model.graph.initializer:
                if i.name == out.name:
                    i.name = src
            model.graph.node.append(onnx.helper.make_node("Identity", [src], [out.name], name=out.name + "_id"))


def _declare_output_shapes(proto, loaded: LoadedModel, spec: GraphSpec) -> None:
    """The exporter names the output dims after internal nodes ('Reshaperotation_6d_delta_dim_2');
    state the contract's shapes instead, so that a runtime inspecting the model sees [1, N, J, 6]."""
    cfg = loaded.config
    shapes = {C.ROOT_POSITION_DELTA: ["B", "N", 3], C.ROTATION_6D_DELTA: ["B", "N", cfg.joints, 6],
              C.FOOT_CONTACTS: ["B", "N", len(C.CONTACT_JOINTS)],
              C.KEY_MEMORY: ["B", cfg.blocks, 2, "K", cfg.width], **{c: [1] for c in C.CONSTANT_OUTPUTS}}
    for out in proto.graph.output:
        dims = out.type.tensor_type.shape.dim
        want = shapes[out.name]
        del dims[:]
        for d in want:
            dim = dims.add()
            if isinstance(d, str):
                dim.dim_param = d
            else:
                dim.dim_value = d


def export_graph(loaded: LoadedModel, spec: GraphSpec, name: str):
    """Trace one graph → onnx.ModelProto with metadata; raises OperatorError on forbidden operators."""
    import onnx
    model = loaded.model.eval()
    if model.has_contacts:
        names = list(loaded.skeleton.names)
        lacking = [j for j in C.CONTACT_JOINTS if j not in names]
        if lacking:
            raise ExportCheckError(f"{name}: a contact head, but the skeleton has no joint {lacking[0]}; expected "
                                   f"the joints {', '.join(C.CONTACT_JOINTS)} (the foot_contacts channels)")
        if not (math.isfinite(loaded.contact_threshold) and 0.0 < loaded.contact_threshold < 1.0):
            raise ExportCheckError(f"{name}: contact threshold {loaded.contact_threshold}; expected a number "
                                   "between 0 and 1")
    # traced with two rows of different gap lengths, so nothing about one row becomes a constant
    inputs = example_inputs(model, spec.kind, gap=[5, 7])
    args = tuple(inputs[n] for n in spec.input_names)
    buffer = io.BytesIO()
    with torch.no_grad(), warnings.catch_warnings():
        warnings.simplefilter("ignore", torch.jit.TracerWarning)
        _torch_onnx_export(spec.module.eval(), args, buffer, spec)
    proto = onnx.load_from_string(buffer.getvalue())
    _output_from_initializer_to_node(proto)
    _declare_output_shapes(proto, loaded, spec)
    proto.producer_name = "deltainterp"
    del proto.metadata_props[:]
    for key, value in (("contract_version", str(C.CONTRACT_VERSION)),
                       ("deltainterp", json.dumps(metadata(loaded, spec.kind, name), sort_keys=False))):
        entry = proto.metadata_props.add()
        entry.key, entry.value = key, value
    onnx.checker.check_model(proto)
    check_operators(proto, f"{name} ({spec.kind} graph)")
    return proto


def graph_paths(out: str | Path) -> Dict[str, Path]:
    out = Path(out)
    if out.suffix != ".onnx":
        raise ValueError(f"--out must end in .onnx (got {out})")
    stem = out.with_suffix("")
    return {"whole": out, "keys": Path(f"{stem}.keys.onnx"), "frame": Path(f"{stem}.frame.onnx")}


def verify(loaded: LoadedModel, protos: Dict[str, object], tolerance: float = 1e-5,
           shapes: Tuple = ((11, 5, 5), (11, 30, 30), (6, 1, 17), (11, 1, (5, 30, 12)), (3, 4, (9, 4)))) -> float:
    """Evaluate every graph with the numpy reference evaluator on several (K, N, n) and compare with
    torch; also whole == keys + frame. A tuple n is a batch of rows with those gap lengths. Returns the largest difference; raises ExportCheckError above
    `tolerance`."""
    model = loaded.model.eval()
    worst = 0.0
    for keys, queries, gap in shapes:
        whole_in = example_inputs(model, "whole", keys, queries, gap, seed=keys * 100 + queries)
        with torch.no_grad():
            expected = WholeGraph(model)(*whole_in.values())  # deltas, contacts when the model has them, constants
            memory = KeysGraph(model)(whole_in[C.KEY_FEATURES], whole_in[C.KEY_FRAME_INDICES],
                                      whole_in[C.GAP_LENGTH])[0]
        np_in = {k: v.numpy() for k, v in whole_in.items()}
        got_whole = run_model(protos["whole"], np_in)
        got_keys = run_model(protos["keys"], {k: np_in[k] for k in (C.KEY_FEATURES, C.KEY_FRAME_INDICES,
                                                                     C.GAP_LENGTH)})
        frame_in = {C.KEY_MEMORY: got_keys[C.KEY_MEMORY], C.QUERY_FRAME_INDICES: np_in[C.QUERY_FRAME_INDICES],
                    C.GAP_LENGTH: np_in[C.GAP_LENGTH]}
        if C.QUERY_FEATURES in np_in:
            frame_in[C.QUERY_FEATURES] = np_in[C.QUERY_FEATURES]
        got_frame = run_model(protos["frame"], frame_in)
        pairs = [(got_keys[C.KEY_MEMORY], memory.numpy(), "keys graph vs torch")]
        outputs = (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA) + ((C.FOOT_CONTACTS,) if model.has_contacts else ())
        for i, out_name in enumerate(outputs):
            pairs.append((got_whole[out_name], expected[i].numpy(), f"whole {out_name} vs torch"))
            pairs.append((got_frame[out_name], expected[i].numpy(), f"keys+frame {out_name} vs torch"))
        for got, want, what in pairs:
            if got.shape != want.shape:
                raise ExportCheckError(f"{what}: shape {got.shape} != {want.shape} (K={keys}, N={queries})")
            diff = float(np.abs(got - want).max()) if got.size else 0.0
            if not np.isfinite(diff):
                raise ExportCheckError(f"{what}: non-finite outputs (K={keys}, N={queries}); expected finite ones")
            worst = max(worst, diff)
            if diff > tolerance:
                raise ExportCheckError(f"{what}: max |diff| {diff:.3g} > {tolerance} (K={keys}, N={queries})")
        for kind in ("whole", "keys", "frame"):
            got = run_model(protos[kind], np_in if kind == "whole" else
                            (frame_in if kind == "frame" else {k: np_in[k] for k in (
                                C.KEY_FEATURES, C.KEY_FRAME_INDICES, C.GAP_LENGTH)}))
            consts = [int(got[c][0]) for c in C.CONSTANT_OUTPUTS]
            if consts != [C.CONTRACT_VERSION, model.config.joints, C.FEATURES_PER_JOINT * model.config.joints]:
                raise ExportCheckError(f"{kind} graph constant outputs {consts} are wrong")
    return worst


@dataclass
class ExportReport:
    paths: Dict[str, Path]
    sizes: Dict[str, int]
    operators: Dict[str, List[str]]
    max_difference: float
    parameters: int


def export_model(loaded: LoadedModel, out: str | Path, name: str = "DeltaInterpolator",
                 check: bool = True) -> ExportReport:
    """Export the three graphs next to each other, verify them, and write them (only if all pass)."""
    import onnx
    paths = graph_paths(out)
    protos = {spec.kind: export_graph(loaded, spec, name) for spec in graph_specs(loaded.model)}
    worst = verify(loaded, protos) if check else float("nan")
    sizes, ops = {}, {}
    for kind, proto in protos.items():
        data = proto.SerializeToString()
        safe_output.write_bytes(paths[kind], data)  # temporary file + rename (the CLI checked the paths)
        sizes[kind] = len(data)
        ops[kind] = check_operators(proto, kind)
    _ = onnx
    return ExportReport(paths, sizes, ops, worst, loaded.model.parameter_count())
