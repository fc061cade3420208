"""One training/validation transition batch and the paper's losses (method-spec §2.10).

Everything a sample goes through here — localization, key features, SLERP baseline, decoding — is the
same code path the exporter's golden vectors and the C# runtime follow.
"""
from __future__ import annotations

import math
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
    foot_joints: Sequence[int] = ()   # ankle and toe of each leg (the foot-contact loss and skating measure)
    leg_length: float = 0.0           # model units (see leg_length below)
    frame_time: float = 1.0 / 30.0    # seconds per frame


# The C# foot-skating measure's contact rule (Runtime/Evaluation/Baking/FootSkating.cs).
CONTACT_HEIGHT = 0.03   # leg lengths above the ground
CONTACT_SPEED = 0.15    # leg lengths per second
FOOT_JOINT_NAMES = ("LeftFoot", "LeftToe", "RightFoot", "RightToe")


def leg_length(names: Sequence[str], offsets) -> float:
    """The root's height above its lowest joint in the model's reference T-pose (C# SkeletonMap.LegLength on
    ReferencePose.ModelTPose), in the offsets' units: thigh + shin straight down, plus the ankle→toe bone,
    which that pose points 30° down (half its length). The small hip→thigh offset is left out (about 2 %
    of a leg); the mean of both legs. 0 when the skeleton lacks the LaFAN1 leg joints."""
    total = []
    for side in ("Left", "Right"):
        try:
            bones = [offsets[list(names).index(side + n)] for n in ("Leg", "Foot", "Toe")]
        except ValueError:
            return 0.0
        lengths = [math.sqrt(sum(float(v) ** 2 for v in b)) for b in bones]
        total.append(lengths[0] + lengths[1] + 0.5 * lengths[2])
    return sum(total) / len(total)


def foot_joint_indices(names: Sequence[str]) -> Tuple[int, ...]:
    """Indices of FOOT_JOINT_NAMES in `names` (empty when any is missing)."""
    if not all(n in names for n in FOOT_JOINT_NAMES):
        return ()
    return tuple(list(names).index(n) for n in FOOT_JOINT_NAMES)


def _horizontal_speed(feet: Tensor, frame_time: float) -> Tensor:
    """(B, F, K, 3) positions of a span (key, filled frames, key) → (B, F - 2, K) horizontal (X, Z) speed
    of the filled frames, central differences, units per second."""
    d = feet[:, 2:] - feet[:, :-2]
    eps = 1e-12  # a finite gradient at zero speed; subtracted back so a still joint scores exactly 0
    return ((d[..., 0] ** 2 + d[..., 2] ** 2 + eps).sqrt() - eps ** 0.5) / (2.0 * frame_time)


def foot_contact(gt_feet: Tensor, leg: float, frame_time: float) -> Tensor:
    """(B, F - 2, K) mask of the filled frames' planted truth foot joints: within CONTACT_HEIGHT leg lengths
    above the span's lowest foot-joint height and slower than CONTACT_SPEED leg lengths per second
    (`gt_feet`: (B, F, K, 3), the span from the key before the gap to the key after it)."""
    ground = gt_feet[..., 1].amin(dim=(1, 2), keepdim=True)
    low = gt_feet[:, 1:-1, :, 1] <= ground + CONTACT_HEIGHT * leg
    slow = _horizontal_speed(gt_feet, frame_time) < CONTACT_SPEED * leg
    return low & slow


def foot_skating(pred_feet: Tensor, gt_feet: Tensor, leg: float, frame_time: float) -> Tuple[Tensor, Tensor]:
    """(sum of the prediction's horizontal speed on the truth's planted samples, their count); speeds in
    units per second. `pred_feet` and `gt_feet`: (B, F, K, 3) over the same span (keys at both ends)."""
    mask = foot_contact(gt_feet, leg, frame_time).to(pred_feet.dtype)
    speed = _horizontal_speed(pred_feet, frame_time)
    return (speed * mask).sum(), mask.sum()


def span_feet(pred_pos: Tensor, gt_pos: Tensor, before: Tensor, after: Tensor, feet: Sequence[int]):
    """Foot-joint global positions (B, N + 2, K, 3) of the span key, filled frames, key: the prediction's
    filled frames between the truth's keys, and the truth's."""
    f = list(feet)
    pred = torch.cat((before[:, None, f], pred_pos[:, :, f], after[:, None, f]), 1)
    gt = torch.cat((before[:, None, f], gt_pos[:, :, f], after[:, None, f]), 1)
    return pred, gt


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
              skeleton: SkeletonTensors, positions: bool = False):
    pq, pp = forward_kinematics(pred_rot, pred_root, skeleton.offsets, skeleton.parents)
    gq, gp = forward_kinematics(gt_rot, gt_root, skeleton.offsets, skeleton.parents)
    pq = quaternions.align_hemisphere(pq, gq)
    if positions:
        return (pq - gq).abs().mean(), (pp - gp).abs().mean(), pp, gp
    return (pq - gq).abs().mean(), (pp - gp).abs().mean()


def loss(model: DeltaInterpolator, batch: TransitionBatch, skeleton: SkeletonTensors,
         reconstruction_scale: float = 1.0, quat_scale: float = 10.0, position_scale: float = 10.0,
         foot_contact_weight: float = 0.0) -> Dict[str, Tensor]:
    """The paper's losses; with foot_contact_weight > 0 also that weight times the mean horizontal speed
    (model units per second) of the predicted foot joints on the missing frames where the truth's are
    planted (the C# foot-skating contact rule), reported as "foot"."""
    layout = batch.layout
    root, rot, key_root, key_rot = predict(model, batch, with_keys=reconstruction_scale > 0)
    q_idx = torch.tensor(layout.query_frames)
    feet_on = foot_contact_weight > 0
    if feet_on and (not skeleton.foot_joints or not skeleton.leg_length > 0):
        raise ValueError("the foot-contact loss needs the skeleton's foot joints (LeftFoot, LeftToe, RightFoot, "
                         "RightToe) and a leg length; expected a LaFAN1-named skeleton")
    lq, lp, *positions = l1_global(root, rot, batch.positions[:, q_idx], batch.rotations[:, q_idx], skeleton,
                                   positions=feet_on)
    out = {"quat": lq, "pos": lp}
    total = quat_scale * lq + position_scale * lp
    if feet_on:
        pp, gp = positions
        r, target = layout.past - 1, layout.past + layout.gap
        ends = torch.tensor([r, target])
        _, kp = forward_kinematics(batch.rotations[:, ends], batch.positions[:, ends], skeleton.offsets,
                                   skeleton.parents)
        kp = kp.to(pp.dtype)
        pred_feet, gt_feet = span_feet(pp, gp, kp[:, 0], kp[:, 1], skeleton.foot_joints)
        speed, count = foot_skating(pred_feet, gt_feet, skeleton.leg_length, skeleton.frame_time)
        foot = speed / count.clamp_min(1.0)
        out["foot"] = foot
        total = total + foot_contact_weight * foot
    if key_root is not None:
        k_idx = torch.tensor(layout.key_frames)
        kq, kp = l1_global(key_root, key_rot, batch.positions[:, k_idx], batch.rotations[:, k_idx], skeleton)
        out.update(key_quat=kq, key_pos=kp)
        total = total + reconstruction_scale * (quat_scale * kq + position_scale * kp)
    out["total"] = total
    return out
