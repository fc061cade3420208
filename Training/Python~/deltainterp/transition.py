"""One in-betweening request end to end, as the C# runtime runs it (`Runtime/Core/Inference`).

past keys + target key (world, data units) → localize → key features → network → decode → un-localize →
world root positions and local quaternions of the missing frames. The same functions as training
(`objective.make_batch`, `objective.predict`), so a model is served exactly as it was trained.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Tuple

import torch

from .checkpoint import LoadedModel
from .decoding import decode_outputs
from .localize import unlocalize
from .objective import TransitionBatch, _network_inputs, make_batch
from .sampler import TransitionSampler

Tensor = torch.Tensor


@dataclass
class TransitionResult:
    root_positions: Tensor     # (B, n, 3) world, data units
    local_quaternions: Tensor  # (B, n, J, 4)
    batch: TransitionBatch     # localization, key features and baselines
    root_delta: Tensor         # (B, n, 3) raw network output (network dtype)
    rotation_delta: Tensor     # (B, n, J, 6)
    foot_contacts: Optional[Tensor] = None  # (B, n, 4) contact probabilities (contract.CONTACT_JOINTS), or None
                                            # when the model has no contact head


def request_frames(past_roots: Tensor, past_quats: Tensor, target_root: Tensor, target_quats: Tensor,
                   gap: int) -> Tuple[Tensor, Tensor]:
    """(B, P, 3), (B, P, J, 4), (B, 3), (B, J, 4) → the (B, P+n+1) frame track `make_batch` takes. The
    missing frames are unknown to a request: they hold copies of the last past key and are never read."""
    filler_r = past_roots[:, -1:].expand(-1, gap, -1)
    filler_q = past_quats[:, -1:].expand(-1, gap, -1, -1)
    roots = torch.cat((past_roots, filler_r, target_root[:, None]), 1)
    quats = torch.cat((past_quats, filler_q, target_quats[:, None]), 1)
    return roots, quats


def run_transition(loaded: LoadedModel, past_roots: Tensor, past_quats: Tensor, target_root: Tensor,
                   target_quats: Tensor, gap: int) -> TransitionResult:
    """Geometry runs in the dtype of the inputs (float64 recommended); the network in its own dtype."""
    if gap < 1:
        raise ValueError("a transition needs at least one missing frame")
    past = int(past_roots.shape[1])
    layout = TransitionSampler(past=past, min_gap=1, max_gap=gap).layout(gap)
    skeleton = loaded.skeleton_tensors(past_roots.dtype)
    cfg = loaded.config
    roots, quats = request_frames(past_roots, past_quats, target_root, target_quats, gap)
    batch = make_batch(roots, quats, layout, skeleton, cfg.output_delta_mode, cfg.input_delta_mode)
    contacts = None
    with torch.no_grad():
        if loaded.model.has_contacts:
            root_delta, rotation_delta, contacts = loaded.model(*_network_inputs(loaded.model, batch), with_contacts=True)
        else:
            root_delta, rotation_delta = loaded.model(*_network_inputs(loaded.model, batch))
    root, rot = decode_outputs(cfg.output_delta_mode, batch.base_root, batch.base_rotations,
                               root_delta.to(batch.base_root.dtype), rotation_delta.to(batch.base_root.dtype))
    world_root, world_rot = unlocalize(root, rot, batch.localization, loaded.unit_scale)
    return TransitionResult(world_root, world_rot, batch, root_delta, rotation_delta, contacts)
