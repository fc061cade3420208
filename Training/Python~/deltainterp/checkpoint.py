"""Loading a training checkpoint (`train.py` writes it) for evaluation, export and fixtures."""
from __future__ import annotations

import io
import json
import math
import pickle
import re
import types
import zipfile
from collections import OrderedDict
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Dict, List, Tuple

import numpy as np
import torch
from torch import _weights_only_unpickler, serialization

from . import safe_output
from .model import DeltaInterpolator, ModelConfig
from .objective import SkeletonTensors
from .skeleton import Skeleton

DEFAULT_FACING_LOCAL_AXIS = (0.0, 1.0, 0.0)   # LaFAN1 hips: local +Y points forward (method-spec §1.3)
DEFAULT_FACING_TARGET_AXIS = (1.0, 0.0, 0.0)  # the benchmark turns the character to face +X


@dataclass
class LoadedModel:
    model: DeltaInterpolator       # in eval mode, on the CPU
    skeleton: Skeleton             # offsets in data units
    unit_scale: float              # model units per data unit
    step: int
    train_config: Dict[str, Any] = field(default_factory=dict)
    validation: Dict[str, float] = field(default_factory=dict)
    facing_local_axis: tuple = DEFAULT_FACING_LOCAL_AXIS
    facing_target_axis: tuple = DEFAULT_FACING_TARGET_AXIS
    fps: float = 30.0
    data_description: str = ""
    name: str = ""                 # an exported model's own name (re-export keeps it); "" for a checkpoint
    contact_threshold: float = 0.5  # a model with a contact head: p ≥ this is planted (chosen on validation)

    @property
    def config(self) -> ModelConfig:
        return self.model.config

    def skeleton_tensors(self, dtype: torch.dtype = torch.float64) -> SkeletonTensors:
        """The skeleton as the training objective sees it: offsets in MODEL units."""
        return SkeletonTensors(list(self.skeleton.parents),
                               torch.tensor(self.skeleton.offsets * self.unit_scale, dtype=dtype),
                               self.unit_scale, self.facing_local_axis, self.facing_target_axis)


REQUIRED_KEYS = ("model", "model_config", "skeleton", "unit_scale")
FORMAT = "deltainterp-checkpoint"
FORMAT_VERSION = 2
EXPECTED = "expected a checkpoint.pt written by `train` (or Tests/Fixtures~/tiny-model.pt)"


class CheckpointError(ValueError):
    """A file that is not a checkpoint we can use; the message is `PATH: what; expected`."""

    def __init__(self, path, what: str, expected: str = EXPECTED) -> None:
        super().__init__(f"{path}: {what}; {expected}")
        self.path = str(path)


# -- the file format ---------------------------------------------------------------------------------
# Version 2 (this file's `save_checkpoint_file`) holds only what torch's weights-only unpickler rebuilds on
# every torch since 1.13: {"format", "version", "model": state dict of tensors, "tensors": [tensor, ...],
# "meta": JSON text}. Everything else (step, configs, skeleton, optimizer hyper-parameters, numpy and Python
# RNG states) lives in the JSON, tensors referenced as {"$tensor": i}; torch 1.13's weights-only unpickler
# cannot even read a Python float, hence the JSON. Version 1 (`train` before it, a pickled dict with floats,
# tuples and RNG dicts) still loads: with weights_only=True where torch can, else with `_RestrictedUnpickler`
# (the same allow-list). Neither path can call anything but tensor and dict constructors.

def _encode(value, tensors: List[torch.Tensor]):
    if isinstance(value, torch.Tensor):
        tensors.append(value.detach())
        return {"$tensor": len(tensors) - 1}
    if isinstance(value, dict):
        if all(isinstance(k, str) and not k.startswith("$") for k in value):
            return {k: _encode(v, tensors) for k, v in value.items()}
        return {"$dict": [[_encode(k, tensors), _encode(v, tensors)] for k, v in value.items()]}
    if isinstance(value, tuple):
        return {"$tuple": [_encode(v, tensors) for v in value]}
    if isinstance(value, list):
        return [_encode(v, tensors) for v in value]
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, (np.integer, np.floating, np.bool_)):
        return value.item()
    raise TypeError(f"cannot store a {type(value).__name__} in a checkpoint")


def _decode(value, tensors: List[torch.Tensor]):
    if isinstance(value, list):
        return [_decode(v, tensors) for v in value]
    if isinstance(value, dict):
        if set(value) == {"$tensor"}:
            return tensors[int(value["$tensor"])]
        if set(value) == {"$tuple"}:
            return tuple(_decode(v, tensors) for v in value["$tuple"])
        if set(value) == {"$dict"}:
            return {_decode_key(k, tensors): _decode(v, tensors) for k, v in value["$dict"]}
        return {k: _decode(v, tensors) for k, v in value.items()}
    return value


def _decode_key(key, tensors):
    k = _decode(key, tensors)
    return tuple(k) if isinstance(k, list) else k


def encode_checkpoint(state: Dict[str, Any]) -> Dict[str, Any]:
    """The logical checkpoint dict → what `torch.save` writes (format version 2)."""
    tensors: List[torch.Tensor] = []
    meta = {k: _encode(v, tensors) for k, v in state.items() if k != "model"}
    model = OrderedDict((k, v.detach()) for k, v in state["model"].items())
    return {"format": FORMAT, "version": FORMAT_VERSION, "model": model, "tensors": tensors,
            "meta": json.dumps(meta)}


def save_checkpoint_file(state: Dict[str, Any], path: str | Path) -> Path:
    """Writes `state` (model state dict, step, configs, ...) in format version 2: temporary file beside
    `path`, then rename (safe_output). torch.save into a file object names the zip's records `archive/`,
    so the bytes do not depend on the (random) temporary name."""
    encoded = encode_checkpoint(state)
    return safe_output.write(path, lambda f: torch.save(encoded, f))


class _RestrictedUnpickler(pickle.Unpickler):
    """pickle.Unpickler that resolves only the globals torch's weights-only unpickler allows (tensor,
    storage and OrderedDict rebuilders): a pickle that names anything else (os.system, builtins.eval, ...)
    is refused before anything runs. Used only where torch's own weights-only unpickler cannot read a
    version-1 checkpoint (torch 1.13 lacks the float opcode)."""

    def find_class(self, module: str, name: str):
        allowed = _allowed_globals()
        full = f"{module}.{name}"
        if full in allowed:
            return allowed[full]
        raise pickle.UnpicklingError(f"Unsupported class {full}")


def _allowed_globals() -> Dict[str, Any]:
    return _weights_only_unpickler._get_allowed_globals()


def _restricted_pickle_module():
    module = types.ModuleType("deltainterp_restricted_pickle")
    module.Unpickler = _RestrictedUnpickler
    module.load = lambda f, **kw: _RestrictedUnpickler(f, **kw).load()
    module.loads = lambda b, **kw: _RestrictedUnpickler(io.BytesIO(b), **kw).load()
    module.UnpicklingError = pickle.UnpicklingError
    return module


def _refusal(e: BaseException) -> str:
    """The useful part of a torch.load failure, one short line."""
    text = str(e).replace("\n", " ")
    for marker in ("WeightsUnpickler error:", "error:"):
        if marker in text:
            text = text.split(marker, 1)[1].strip()
            break
    m = re.search(r"Unsupported (?:class|global:?) (?:GLOBAL )?([\w.]+)", text)
    if m:
        return f"it would call {m.group(1)}, which a checkpoint never needs (only tensors and plain values are loaded)"
    text = text.strip() or type(e).__name__
    return f"cannot be read ({type(e).__name__}: {text[:160]})"


def _weights_only_lacks_floats() -> bool:
    return int(torch.__version__.split(".")[0]) < 2


def _torch_load(path: Path) -> Any:
    if zipfile.is_zipfile(path):
        try:
            with zipfile.ZipFile(path) as z:
                names = z.namelist()
        except (zipfile.BadZipFile, OSError, ValueError) as e:
            raise CheckpointError(path, f"is a damaged zip archive ({type(e).__name__})") from None
        if any(n.endswith("constants.pkl") for n in names):
            # torch.load hands TorchScript archives to torch.jit.load, even with weights_only=True
            raise CheckpointError(path, "is a TorchScript archive, not a checkpoint")
    try:
        return torch.load(path, map_location="cpu", weights_only=True)
    except Exception as e:  # noqa: BLE001 - any failure means: not a file we can read safely
        if _weights_only_lacks_floats() and "Unsupported operand" in str(e) and zipfile.is_zipfile(path):
            try:
                return _restricted_load(path)
            except Exception as e2:  # noqa: BLE001
                raise CheckpointError(path, _refusal(e2)) from None
        raise CheckpointError(path, _refusal(e)) from None


def _restricted_load(path: Path) -> Any:
    """torch 1.13 only: its torch.load ignores `pickle_module` unless weights_only=True (which cannot read a
    float), so call its zip loader directly with the restricted unpickler."""
    with serialization._open_zipfile_reader(str(path)) as archive:
        return serialization._load(archive, "cpu", _restricted_pickle_module(), encoding="utf-8")


def read_checkpoint(path: str | Path) -> Dict[str, Any]:
    """The logical dict of a checkpoint file (either format), loaded without running any code from it.
    Raises CheckpointError (`PATH: what; expected`) for a missing, non-regular, empty or unreadable file."""
    path = Path(path)
    if not path.exists():
        raise CheckpointError(path, "not found", EXPECTED + " (train writes RUN/checkpoint.pt)")
    if path.is_dir():
        raise CheckpointError(path, "is a directory", EXPECTED)
    if not path.is_file():
        raise CheckpointError(path, "is not a regular file (a FIFO, device or socket)", EXPECTED)
    if path.stat().st_size == 0:
        raise CheckpointError(path, "is empty (0 bytes)", EXPECTED)
    raw = _torch_load(path)
    if not isinstance(raw, dict):
        raise CheckpointError(path, f"is not a deltainterp checkpoint (it holds a {type(raw).__name__})")
    if raw.get("format") != FORMAT:
        return raw  # version 1: the logical dict itself
    if raw.get("version") != FORMAT_VERSION:
        raise CheckpointError(path, f"is checkpoint format version {raw.get('version')!r}",
                              f"expected version {FORMAT_VERSION} (a newer deltainterp wrote it?)")
    try:
        tensors = list(raw["tensors"])
        state = _decode(json.loads(raw["meta"]), tensors)
        state["model"] = raw["model"]
    except (KeyError, TypeError, ValueError, IndexError, RecursionError) as e:  # RecursionError: 3,000-deep JSON
        raise CheckpointError(path, f"has a damaged header ({type(e).__name__}: {str(e)[:120]})")
    return state


def load_checkpoint(path: str | Path) -> LoadedModel:
    """A checkpoint written by `train` (or `fixtures`) → the network in eval mode and its skeleton.

    Raises CheckpointError with the file and what is wrong, so the CLI can print it in one line."""
    path = Path(path)
    state = read_checkpoint(path)
    missing = [k for k in REQUIRED_KEYS if k not in state]
    if missing:
        raise CheckpointError(path, f"is not a deltainterp checkpoint: it lacks {missing}")
    model = build_model(path, state)
    try:
        skeleton = Skeleton.from_json(state["skeleton"])
        unit_scale = float(state["unit_scale"])
    except (KeyError, TypeError, ValueError, IndexError) as e:
        raise CheckpointError(path, f"has an unreadable skeleton or unit scale ({type(e).__name__}: {str(e)[:120]})")
    config = model.config
    if skeleton.joint_count != config.joints:
        raise CheckpointError(path, f"skeleton has {skeleton.joint_count} joints, the network {config.joints}",
                              "expected the same count")
    if not math.isfinite(unit_scale) or unit_scale <= 0:
        raise CheckpointError(path, f"unit scale {unit_scale}", "expected a positive finite number")
    train_config = dict(state.get("train_config", {}) or {})
    fps, description = float(state.get("fps", 30.0)), str(state.get("data_description", ""))
    if not description:
        fps, description = _describe_training_data(train_config.get("data"), fps)
    threshold = contact_threshold_of(path, state.get("contact_threshold", 0.5))
    return LoadedModel(model, skeleton, unit_scale, int(state.get("step", 0)),
                       train_config, dict(state.get("validation", {}) or {}),
                       tuple(state.get("facing_local_axis", DEFAULT_FACING_LOCAL_AXIS)),
                       tuple(state.get("facing_target_axis", DEFAULT_FACING_TARGET_AXIS)),
                       fps, description, contact_threshold=threshold)


def contact_threshold_of(path, value) -> float:
    """A stored contact threshold, or CheckpointError: a number strictly between 0 and 1 (a probability that
    decides planted frames; 0 or 1 would plant every frame or none)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not (math.isfinite(value) and 0 < value < 1):
        raise CheckpointError(path, f"contact threshold {str(value)[:40]}", "expected a number between 0 and 1")
    return float(value)


def build_model(path: str | Path, state: Dict[str, Any]) -> DeltaInterpolator:
    """The network of a checkpoint's logical dict, in eval mode; CheckpointError for a configuration that
    builds no network, weights of another shape, or non-finite weights (a diverged run)."""
    try:
        config = ModelConfig(**state["model_config"])
        model = DeltaInterpolator(config)
    except Exception as e:  # noqa: BLE001 - a config from a file: any failure is the file's
        raise CheckpointError(path, f"has an unusable model_config ({type(e).__name__}: {str(e)[:120]})")
    weights = state["model"]
    if not isinstance(weights, dict) or not all(isinstance(v, torch.Tensor) for v in weights.values()):
        raise CheckpointError(path, "its 'model' entry is not a state dict of tensors")
    try:
        model.load_state_dict(weights)
    except RuntimeError as e:
        first = str(e).strip().splitlines()
        detail = " ".join(line.strip() for line in first[1:3]) if len(first) > 1 else str(e)
        raise CheckpointError(path, f"weights do not fit its model_config ({detail[:200]})",
                              "expected the weights `train` saved with it")
    for name, w in weights.items():
        if w.is_floating_point() and not bool(torch.isfinite(w).all()):
            raise CheckpointError(path, f"weight {name} holds non-finite values (NaN or infinity)",
                                  "expected a network whose training did not diverge")
    model.eval()
    return model


def _describe_training_data(pack_path, fps: float) -> Tuple[float, str]:
    """What the run was trained on and the frame rate, from the training pack when it is at hand (train.py
    does not store them in the checkpoint): the pack's own description, or, for a LaFAN1 pack (which has none),
    its subjects read from its file names. Never a data set the run was not trained on: without the pack the
    description says so (issue 30: a fine-tune was exported as "LaFAN1 subjects 1-4")."""
    if not pack_path:
        return fps, "not recorded (the checkpoint names no training pack)"
    if not Path(pack_path).exists():
        return fps, f"not recorded (its training pack {Path(pack_path).name} is not at hand)"
    with np.load(pack_path, allow_pickle=False) as z:
        files = [str(f) for f in z["files"]]
        if "description" in z.files and str(z["description"]):
            description = str(z["description"])  # a pack of any humanoid BVH says what it holds
        else:
            subjects = sorted({int(m.group(1)) for f in files for m in [re.search(r"_subject(\d+)", f)] if m})
            what = f"LaFAN1 subjects {', '.join(map(str, subjects))}" if subjects else f"the pack {Path(pack_path).name}"
            description = f"{what} ({len(files)} files)"
        fps = round(1.0 / float(z["frame_time"]), 3)
    return fps, description
