"""One training/validation transition batch and the paper's losses (method-spec §2.10).

Everything a sample goes through here — localization, key features, SLERP baseline, decoding — is the
same code path the exporter's golden vectors and the C# runtime follow.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, Optional, Sequence, Tuple

import torch

from . import quaternions, rotation6d
from .baseline import baseline, interpolation_weights
from .decoding import decode_outputs
from .features import key_features
from .kinematics import forward_kinematics
from .localize import Localization, localize
from .model import DeltaInterpolator
from .sampler import KeyLayout

Tensor = torch.Tensor


@dataclass
class SkeletonTensors:
    parents: Sequence[int]
    offsets: Tensor        # (J, 3) model units
    unit_scale: float
    facing_local_axis: Sequence[float] = (0.0, 1.0, 0.0)
    facing_target_axis: Sequence[float] = (1.0, 0.0, 0.0)


@dataclass
class TransitionBatch:
    layout: KeyLayout
    positions: Tensor       # (B, L, 3) localized root positions, model units
    rotations: Tensor       # (B, L, J, 4) localized local quaternions
    localization: Localization
    key_features: Tensor    # (B, K, 9J)
    query_features: Optional[Tensor]
    base_root: Tensor       # (B, N, 3)
    base_rotations: Tensor  # (B, N, J, 4)


def make_batch(root_positions: Tensor, local_quaternions: Tensor, layout: KeyLayout,
               skeleton: SkeletonTensors, output_delta_mode: str, input_delta_mode: str) -> TransitionBatch:
    r = layout.past - 1
    target = layout.past + layout.gap
    pos, rot, loc = localize(root_positions, local_quaternions, r, skeleton.facing_local_axis,
                             skeleton.facing_target_axis, skeleton.unit_scale)
    keys = torch.tensor(layout.key_frames)
    feats = key_features(pos[:, keys], rot[:, keys], skeleton.offsets, skeleton.parents, layout.reference_key,
                         input_delta_mode)
    weights = interpolation_weights(torch.tensor(layout.query_frames), r, layout.gap)
    base_root, base_rot = baseline(output_delta_mode, pos[:, r], pos[:, target], rot[:, r], rot[:, target], weights)
    query_features = None
    if input_delta_mode == "none":
        slerp_root, slerp_rot = baseline("slerp", pos[:, r], pos[:, target], rot[:, r], rot[:, target], weights)
        r6 = rotation6d.from_matrix(quaternions.to_matrix(slerp_rot))
        p = slerp_root[:, :, None].expand(-1, -1, r6.shape[2], -1)
        query_features = torch.cat((r6, p), -1).reshape(r6.shape[0], r6.shape[1], -1)
    return TransitionBatch(layout, pos, rot, loc, feats, query_features, base_root, base_rot)


def _network_inputs(model, batch: TransitionBatch):
    """The network's inputs for a batch, in the network's precision. The network may run in another
    precision than the geometry (evaluation and fixtures do the localization and decoding in float64, as
    the C# runtime does, around a float32 network)."""
    layout = batch.layout
    net_dtype = next(getattr(model, "module", model).parameters()).dtype
    qfeats = None if batch.query_features is None else batch.query_features.to(net_dtype)
    return (batch.key_features.to(net_dtype), torch.tensor(layout.key_frames), torch.tensor(layout.query_frames),
            torch.tensor([layout.gap]), qfeats)


def query_deltas(model: DeltaInterpolator, batch: TransitionBatch) -> Tuple[Tensor, Tensor]:
    """The raw network outputs for the query frames (root (B, N, 3), 6D (B, N, J, 6)), network dtype."""
    return model(*_network_inputs(model, batch))


def predict(model: DeltaInterpolator, batch: TransitionBatch, with_keys: bool):
    """Run the network and decode: localized root positions and local quaternions for the query frames
    (and, with_keys, for the key frames, against the reference's first/last interpolated baselines)."""
    layout = batch.layout
    mode = getattr(model, "module", model).config.output_delta_mode
    geo_dtype = batch.base_root.dtype
    if with_keys:
        (kr, k6), (qr, q6) = model(*_network_inputs(model, batch), with_keys=True)
        kr, k6 = kr.to(geo_dtype), k6.to(geo_dtype)
    else:
        qr, q6 = query_deltas(model, batch)
    qr, q6 = qr.to(geo_dtype), q6.to(geo_dtype)
    root, rot = decode_outputs(mode, batch.base_root, batch.base_rotations, qr, q6)
    if not with_keys:
        return root, rot, None, None
    p = layout.past
    kb_root = torch.cat((batch.base_root[:, :1].expand(-1, p, -1), batch.base_root[:, -1:]), 1)
    kb_rot = torch.cat((batch.base_rotations[:, :1].expand(-1, p, -1, -1), batch.base_rotations[:, -1:]), 1)
    key_root, key_rot = decode_outputs(mode, kb_root, kb_rot, kr, k6)
    return root, rot, key_root, key_rot


def l1_global(pred_root: Tensor, pred_rot: Tensor, gt_root: Tensor, gt_rot: Tensor,
              skeleton: SkeletonTensors):
    pq, pp = forward_kinematics(pred_rot, pred_root, skeleton.offsets, skeleton.parents)
    gq, gp = forward_kinematics(gt_rot, gt_root, skeleton.offsets, skeleton.parents)
    pq = quaternions.align_hemisphere(pq, gq)
    return (pq - gq).abs().mean(), (pp - gp).abs().mean()


def loss(model: DeltaInterpolator, batch: TransitionBatch, skeleton: SkeletonTensors,
         reconstruction_scale: float = 1.0, quat_scale: float = 10.0, position_scale: float = 10.0
         ) -> Dict[str, Tensor]:
    layout = batch.layout
    root, rot, key_root, key_rot = predict(model, batch, with_keys=reconstruction_scale > 0)
    q_idx = torch.tensor(layout.query_frames)
    lq, lp = l1_global(root, rot, batch.positions[:, q_idx], batch.rotations[:, q_idx], skeleton)
    out = {"quat": lq, "pos": lp}
    total = quat_scale * lq + position_scale * lp
    if key_root is not None:
        k_idx = torch.tensor(layout.key_frames)
        kq, kp = l1_global(key_root, key_rot, batch.positions[:, k_idx], batch.rotations[:, k_idx], skeleton)
        out.update(key_quat=kq, key_pos=kp)
        total = total + reconstruction_scale * (quat_scale * kq + position_scale * kp)
    out["total"] = total
    return out
