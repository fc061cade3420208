"""Loading a training checkpoint (`train.py` writes it) for evaluation, export and fixtures."""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Dict, Tuple

import torch

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

    @property
    def config(self) -> ModelConfig:
        return self.model.config

    def skeleton_tensors(self, dtype: torch.dtype = torch.float64) -> SkeletonTensors:
        """The skeleton as the training objective sees it: offsets in MODEL units."""
        return SkeletonTensors(list(self.skeleton.parents),
                               torch.tensor(self.skeleton.offsets * self.unit_scale, dtype=dtype),
                               self.unit_scale, self.facing_local_axis, self.facing_target_axis)


REQUIRED_KEYS = ("model", "model_config", "skeleton", "unit_scale")


def load_checkpoint(path: str | Path) -> LoadedModel:
    """A checkpoint written by `train` (or `fixtures`) → the network in eval mode and its skeleton.

    Raises FileNotFoundError / ValueError with what is missing, so the CLI can print it."""
    path = Path(path)
    if not path.exists():
        raise FileNotFoundError(f"checkpoint {path} not found (train writes RUN/checkpoint.pt)")
    # Our own files hold RNG states and configs besides tensors; torch ≥ 2.6 would refuse them by default.
    state = torch.load(path, map_location="cpu", weights_only=False)
    missing = [k for k in REQUIRED_KEYS if k not in state]
    if missing:
        raise ValueError(f"{path} is not a deltainterp checkpoint: it lacks {missing}")
    config = ModelConfig(**state["model_config"])
    model = DeltaInterpolator(config)
    model.load_state_dict(state["model"])
    model.eval()
    skeleton = Skeleton.from_json(state["skeleton"])
    if skeleton.joint_count != config.joints:
        raise ValueError(f"{path}: skeleton has {skeleton.joint_count} joints, the network {config.joints}")
    train_config = dict(state.get("train_config", {}))
    fps, description = float(state.get("fps", 30.0)), str(state.get("data_description", ""))
    if not description:
        fps, description = _describe_training_data(train_config.get("data"), fps)
    return LoadedModel(model, skeleton, float(state["unit_scale"]), int(state.get("step", 0)),
                       train_config, dict(state.get("validation", {})),
                       tuple(state.get("facing_local_axis", DEFAULT_FACING_LOCAL_AXIS)),
                       tuple(state.get("facing_target_axis", DEFAULT_FACING_TARGET_AXIS)),
                       fps, description)


def _describe_training_data(pack_path, fps: float) -> Tuple[float, str]:
    """'LaFAN1 subjects 1-4 (24 files)' and the frame rate, from the training pack when it is at hand
    (train.py does not store them in the checkpoint)."""
    description = "LaFAN1 subjects 1-4"
    if pack_path and Path(pack_path).exists():
        import numpy as np
        with np.load(pack_path, allow_pickle=False) as z:
            description += f" ({len(z['files'])} files)"
            fps = round(1.0 / float(z["frame_time"]), 3)
    return fps, description
