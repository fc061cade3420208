"""Warm start: recover a network's weights from an exported whole graph (`.onnx`).

The exporter folds each Linear weight's transpose into an anonymous initializer (`onnx::MatMul_558`), so
ONNX names alone do not say which parameter a tensor is. We find out by exporting a network of the same
architecture whose every parameter is filled with its own index: element [r, c] of parameter i holds
1000·(i+1) + r, so an initializer of that probe export names its parameter by its values' thousands and
says whether it was transposed by the axis along which they vary (shape alone cannot tell for square
matrices). The same
exporter on the same architecture lays the graph out identically, so the mapping carries over to the real
file. `load_onnx_weights` checks the result by running both the file and the rebuilt network on the same
inputs (numpy reference evaluator) and refuses a mismatch.
"""
from __future__ import annotations

import io
import json
import math
import warnings
from pathlib import Path
from typing import Dict, Tuple

import numpy as np
import torch

from . import contract as C
from .checkpoint import LoadedModel
from .export import WholeGraph, _torch_onnx_export, example_inputs, graph_specs
from .safe_input import InputPathError, load_onnx
from .model import DeltaInterpolator, ModelConfig
from .onnx_reference import run_model
from .skeleton import Skeleton


class WarmStartError(ValueError):
    """The ONNX file does not hold a network of the requested architecture."""


def _probe_mapping(config: ModelConfig, batched: bool = True) -> Dict[Tuple[str, int], Tuple[str, bool]]:
    """(node name, input position) → (parameter name, transposed) for the whole graph of this architecture.

    Keyed by where a tensor is USED rather than by initializer name: the exporter merges initializers
    with equal values (an untrained network's LayerNorm gains are all ones), so one initializer of a
    real file may stand for several parameters, but every use still names its own."""
    import onnx
    from onnx import numpy_helper

    model = DeltaInterpolator(config).eval()
    names = [n for n, _ in model.named_parameters()]
    with torch.no_grad():
        for i, (_, p) in enumerate(model.named_parameters()):
            rows = torch.arange(p.shape[0], dtype=p.dtype).reshape(-1, *([1] * (p.dim() - 1)))
            p.copy_((1000.0 * (i + 1) + rows).expand_as(p))
    # the same layout as the file's (contract version 1: batch 1; 2: a batch axis), as export traces it
    spec = next(s for s in graph_specs(model, batched) if s.kind == "whole")
    inputs = example_inputs(model, "whole", gap=[5, 7] if batched else 5, batched=batched)
    buffer = io.BytesIO()
    with torch.no_grad(), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        _torch_onnx_export(WholeGraph(model, batched).eval(), tuple(inputs[n] for n in spec.input_names), buffer, spec)
    proto = onnx.load_from_string(buffer.getvalue())
    shapes = dict((n, tuple(p.shape)) for n, p in model.named_parameters())
    by_initializer: Dict[str, Tuple[str, bool]] = {}
    for init in proto.graph.initializer:
        values = numpy_helper.to_array(init)
        if values.dtype != np.float32 or values.size == 0:
            continue
        index = np.floor(values / 1000.0)
        first = int(index.flat[0])
        if not np.all(index == first) or not 1 <= first <= len(names):
            continue
        name = names[first - 1]
        rows = values - 1000.0 * first
        dims = tuple(values.shape)
        if dims == shapes[name] and (values.ndim == 1 or np.all(rows == rows[:, :1])):
            by_initializer[init.name] = (name, False)
        elif values.ndim == 2 and dims == shapes[name][::-1] and np.all(rows == rows[:1, :]):
            by_initializer[init.name] = (name, True)
    # Only scoped nodes ("/model/blocks.0/mlp/layers.0/MatMul"): their names come from the module tree and
    # are stable; numbered ones (Identity_12) shift when the exporter merges initializers.
    return {(node.name, i): by_initializer[x] for node in proto.graph.node if node.name.startswith("/")
            for i, x in enumerate(node.input) if x in by_initializer}


def _load(path: Path):
    """The model at `path`: a regular file only (a named pipe would block), no external data (an initializer
    at `../../dev/zero` reads forever, one at `/etc/passwd` reads a file outside the model's folder)."""
    try:
        return load_onnx(path)
    except InputPathError as e:
        raise WarmStartError(str(e)) from None


def load_onnx_weights(path: str | Path, config: ModelConfig, tolerance: float = 1e-5) -> Dict[str, torch.Tensor]:
    """The state dict of `config`'s network as stored in the whole graph at `path`, checked by running both."""
    import onnx
    from onnx import numpy_helper

    path = Path(path)
    proto = _load(path)
    batched = _is_batched(proto)
    mapping = _probe_mapping(config, batched)
    model = DeltaInterpolator(config).eval()
    state = {k: v.clone() for k, v in model.state_dict().items()}
    found = set()
    initializers = {init.name: init for init in proto.graph.initializer}
    aliases = {node.output[0]: node.input[0] for node in proto.graph.node if node.op_type == "Identity"}
    for node in proto.graph.node:
        for position, tensor_name in enumerate(node.input):
            while tensor_name in aliases and tensor_name not in initializers:  # merged weights pass an Identity
                tensor_name = aliases[tensor_name]
            if (node.name, position) not in mapping or tensor_name not in initializers:
                continue
            name, transposed = mapping[(node.name, position)]
            values = torch.from_numpy(numpy_helper.to_array(initializers[tensor_name]).copy())
            values = values.t() if transposed else values
            if tuple(values.shape) != tuple(state[name].shape):
                raise WarmStartError(f"{path}: {name} has shape {tuple(values.shape)}; "
                                     f"expected {tuple(state[name].shape)}")
            state[name] = values.contiguous()
            found.add(name)
    missing = sorted(set(state) - found)
    if missing:
        raise WarmStartError(f"{path}: {len(missing)} parameters not found (e.g. {missing[:3]}); "
                             f"expected a whole graph of width {config.width}, {config.blocks} blocks")
    model.load_state_dict(state)
    for keys, queries, gap in ((11, 5, 5), (2, 17, 17)):
        feeds = example_inputs(model, "whole", keys, queries, gap, seed=keys + queries, batched=batched)
        with torch.no_grad():
            want = WholeGraph(model, batched)(*feeds.values())
        got = run_model(proto, {k: v.numpy() for k, v in feeds.items()})
        outputs = (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA) + ((C.FOOT_CONTACTS,) if model.has_contacts else ())
        for i, out in enumerate(outputs):
            if out not in got:
                raise WarmStartError(f"{path}: no output {out}; expected the outputs of a whole graph "
                                     f"({', '.join(outputs)})")
            if got[out].shape != tuple(want[i].shape):
                raise WarmStartError(f"{path}: output {out} has shape {list(got[out].shape)} for {list(want[i].shape)[:2]} "
                                     f"(batch, query frames); expected {list(want[i].shape)}")
            if not np.isfinite(got[out]).all():
                raise WarmStartError(f"{path}: output {out} holds non-finite values (NaN or infinity); expected "
                                     "finite outputs")
            diff = float(np.abs(got[out] - want[i].numpy()).max())
            if not diff <= tolerance:
                raise WarmStartError(f"{path}: rebuilt network differs from the file by {diff:.3g} in {out}; "
                                     f"expected ≤ {tolerance} (another architecture?)")
    return state


def _is_batched(proto) -> bool:
    """True for a contract version ≥ 2 graph (a batch axis: `gap_length` is [B], key frame indices [B, K])."""
    for value in proto.graph.input:
        if value.name == C.KEY_FRAME_INDICES:
            return len(value.type.tensor_type.shape.dim) == 2
    return True


def load_exported_model(path: str | Path):
    """An exported whole graph → a `LoadedModel` (network, skeleton, unit scale, axes from its metadata),
    so `evaluate` can score a shipped `.onnx` through the same torch path as a checkpoint."""
    import onnx

    path = Path(path)
    proto = _load(path)
    entries = {p.key: p.value for p in proto.metadata_props}
    if "deltainterp" not in entries:
        raise WarmStartError(f"{path}: no 'deltainterp' metadata; expected a graph written by `export`")
    try:
        meta = json.loads(entries["deltainterp"])
        skeleton = Skeleton.from_json(meta["skeleton"])
        arch = meta["architecture"]
        sizes = {k: arch[k] for k in ("width", "blocks", "heads", "embedding_dim", "embedding_size")}
        for key, value in sizes.items():
            if not isinstance(value, int) or isinstance(value, bool) or not 1 <= value <= 1 << 16:
                raise ValueError(f"architecture.{key} is {str(value)[:40]}")
        if sizes["width"] % sizes["heads"]:
            raise ValueError(f"architecture.width {sizes['width']} is not a multiple of heads {sizes['heads']}")
        contact_head, contact_hidden, threshold = _contact_metadata(proto, meta, skeleton)
        config = ModelConfig(joints=skeleton.joint_count, width=sizes["width"], blocks=sizes["blocks"],
                             heads=sizes["heads"], embedding_dim=sizes["embedding_dim"],
                             embedding_size=sizes["embedding_size"],
                             output_delta_mode=meta["output_delta_mode"], input_delta_mode=meta["input_delta_mode"],
                             contact_head=contact_head, contact_hidden=contact_hidden)
        training = meta.get("training", {})
        min_past = int(training.get("past_frames", [10, 10])[0])
        fps = float(training.get("fps", 30.0))
        unit_scale = float(meta["unit_scale"])
        axes = tuple(meta["facing_local_axis"]), tuple(meta["facing_target_axis"])
        data = str(training.get("data", ""))
    except (KeyError, TypeError, ValueError, IndexError, AttributeError, RecursionError, AssertionError) as e:
        detail = " ".join(str(e).split())[:120] if not isinstance(e, RecursionError) else "nested too deeply"
        raise WarmStartError(f"{path}: its 'deltainterp' metadata is not what `export` writes ({type(e).__name__}: "
                             f"{detail}); expected a graph written by `python3 -m deltainterp export`") from None
    model = DeltaInterpolator(config)
    model.load_state_dict(load_onnx_weights(path, config))
    model.eval()
    name = str(meta.get("name", ""))[:100]
    return LoadedModel(model, skeleton, unit_scale, 0, {"min_past": min_past}, {}, axes[0], axes[1], fps, data, name,
                       contact_threshold=threshold)


def _contact_metadata(proto, meta: dict, skeleton) -> Tuple[str, int, float]:
    """(contact head, its hidden size, threshold) of a whole graph: ("none", 128, 0.5) without a `foot_contacts`
    output (contract version 2, or 3 without contacts). With one, its declared shape must be [B, N, 4] and the
    metadata must name the contract's contact joints (all in the skeleton), a threshold in (0, 1) and the head;
    ValueError (reported by the caller as the file's metadata) otherwise."""
    output = next((o for o in proto.graph.output if o.name == C.FOOT_CONTACTS), None)
    arch = meta.get("architecture", {})
    if output is None:
        if "contact_head" in arch or "contact_joints" in meta:
            raise ValueError(f"the metadata describes a contact head but the graph has no {C.FOOT_CONTACTS} output")
        return "none", 128, 0.5
    dims = output.type.tensor_type.shape.dim
    if len(dims) != 3 or not dims[2].HasField("dim_value") or dims[2].dim_value != len(C.CONTACT_JOINTS):
        shown = [d.dim_value if d.HasField("dim_value") else (d.dim_param or "?") for d in dims][:6]
        raise ValueError(f"output {C.FOOT_CONTACTS} has shape {shown}, expected [B, N, {len(C.CONTACT_JOINTS)}]")
    joints = meta.get("contact_joints")
    if joints != list(C.CONTACT_JOINTS):
        raise ValueError(f"contact_joints {str(joints)[:80]}, expected {list(C.CONTACT_JOINTS)}")
    lacking = [j for j in joints if j not in skeleton.names]
    if lacking:
        raise ValueError(f"contact joint {lacking[0]} is not a joint of the skeleton")
    threshold = meta.get("contact_threshold")
    if isinstance(threshold, bool) or not isinstance(threshold, (int, float)) or not (
            math.isfinite(threshold) and 0 < threshold < 1):
        raise ValueError(f"contact_threshold {str(threshold)[:40]}, expected a number between 0 and 1")
    head = arch.get("contact_head")
    if head not in ("linear", "mlp", "block"):
        raise ValueError(f"architecture.contact_head {str(head)[:40]}, expected 'linear', 'mlp' or 'block'")
    hidden = arch.get("contact_hidden", 128)
    if not isinstance(hidden, int) or isinstance(hidden, bool) or not 1 <= hidden <= 4096:
        raise ValueError(f"architecture.contact_hidden {str(hidden)[:40]}")
    return head, hidden, float(threshold)
