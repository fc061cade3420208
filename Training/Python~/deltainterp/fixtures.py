"""Test fixtures for the C# runtime: a tiny model (checkpoint + three ONNX graphs) and golden vectors.

The tiny model has the `tiny` architecture on the 22-joint LaFAN1 skeleton. Its output heads are set to
seeded random NON-ZERO values, so its output is not plain SLERP and every stage of the pipeline
(localization, key features, network, decoding, un-localization, FK) is visible in the golden numbers.
Requests are synthetic (smooth seeded joint motion) with varied root positions and facings, so that the
fixtures do not depend on LaFAN1 being present. Everything is deterministic: same files on every run.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Optional

import numpy as np
import torch

from . import contract as C
from . import quaternions, safe_output
from .checkpoint import LoadedModel, load_checkpoint, save_checkpoint_file
from .contacts import write_contact_label_vectors
from .export import export_model
from .kinematics import forward_kinematics
from .lafan1 import lafan1_skeleton
from .model import DeltaInterpolator, preset
from .onnx_reference import run_model
from .sampler import TransitionSampler
from .skeleton import Skeleton
from .transition import run_transition
from .export import export_model

Tensor = torch.Tensor
SEED = 1234
HEAD_STD = 0.01          # random head weights: visible deltas (a few degrees, a few cm), sane poses
UNIT_SCALE = 0.01        # cm → m, as the LaFAN1 models
MODEL_NAME = "tiny-model"
SIGNIFICANT_DIGITS = 9   # float32 round-trips exactly; float64 poses keep ~1e-9 relative accuracy
CONTACTS_MODEL_NAME = "tiny-model-contacts"  # the same network with a contact head (contract version 3)
CONTACT_HIDDEN = 16
CONTACT_STD = 0.5        # random contact head: probabilities spread over (0, 1), not all near 0.5
CONTACT_THRESHOLD = 0.4  # not 0.5, so a reader that ignores the metadata's threshold is caught


@dataclass(frozen=True)
class Case:
    name: str
    past: int
    gap: int
    origin_xz: tuple          # world root XZ at the last past key, cm
    facing_deg: float         # facing at the last past key: yaw about +Y applied to +X
    turn_deg: float           # how much the facing turns from the last past key to the target
    speed: float              # cm per frame along the facing
    seed: int
    flip_target_signs: bool = False  # negate some target quaternions (same rotations, other hemisphere)


CASES = (
    Case("n1_facing_plus_x_at_origin", 10, 1, (0.0, 0.0), 0.0, 10.0, 1.0, 1),
    Case("n5_facing_minus_x", 10, 5, (250.0, -130.0), 178.0, -30.0, 2.5, 2),
    Case("n30_far_facing_minus_z_turning", 10, 30, (1234.5, 567.8), 90.0, 120.0, 3.0, 3),
    Case("n15_target_sign_flips", 10, 15, (-80.0, 40.0), -135.0, 45.0, 1.5, 4, True),
    Case("n12_short_history_p4", 4, 12, (35.0, -410.0), 60.0, -75.0, 2.0, 5),
    Case("n8_half_turn", 10, 8, (-620.0, -15.0), -20.0, 200.0, 0.5, 6),
)


def make_tiny_model(skeleton: Skeleton, seed: int = SEED, contacts: bool = False) -> LoadedModel:
    """The tiny fixture network; with `contacts` also a contact head (contract version 3's `foot_contacts`), whose
    trunk and motion heads are the same as without it (the head is built last, from its own generator)."""
    torch.manual_seed(seed)
    extra = dict(contact_head="mlp", contact_hidden=CONTACT_HIDDEN) if contacts else {}
    model = DeltaInterpolator(preset("tiny", joints=skeleton.joint_count, **extra))
    g = torch.Generator().manual_seed(seed + 1)
    with torch.no_grad():
        for head in (model.root_head, model.rotation_head):
            head.weight.copy_(torch.randn(head.weight.shape, generator=g) * HEAD_STD)
            head.bias.copy_(torch.randn(head.bias.shape, generator=g) * HEAD_STD)
        if contacts:
            c = torch.Generator().manual_seed(seed + 2)
            for p in model.contact_head.parameters():
                p.copy_(torch.randn(p.shape, generator=c) * CONTACT_STD)
    model.eval()
    return LoadedModel(model, skeleton, UNIT_SCALE, 0,
                       data_description="none: untrained tiny fixture with random non-zero heads",
                       contact_threshold=CONTACT_THRESHOLD if contacts else 0.5)


def checkpoint_state(loaded: LoadedModel) -> Dict:
    """A checkpoint `load_checkpoint` (hence evaluate/export) accepts."""
    state = {"model": loaded.model.state_dict(), "model_config": loaded.config.to_dict(),
             "skeleton": loaded.skeleton.to_json(), "unit_scale": loaded.unit_scale, "step": loaded.step,
             "train_config": {}, "validation": {}, "fps": loaded.fps,
             "data_description": loaded.data_description}
    if loaded.model.has_contacts:
        state["contact_threshold"] = loaded.contact_threshold
    return state


# -- synthetic requests ------------------------------------------------------------------------------
_HIPS_FACING_PLUS_X = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
# columns: LaFAN1 hips local +X (spine) → world +Y, local +Y (forward) → world +X, local +Z (left) → −Z


def _axis_angle_to_quat(v: np.ndarray) -> np.ndarray:
    angle = np.linalg.norm(v, axis=-1, keepdims=True)
    axis = v / np.maximum(angle, 1e-12)
    return np.concatenate((np.cos(angle / 2), np.sin(angle / 2) * axis), axis=-1)


def synthetic_request(case: Case, joints: int):
    """World root positions (L, 3) cm and local quaternions (L, J, 4) for frames 0..P+n (the missing
    frames are included for convenience only; golden requests never expose them)."""
    rng = np.random.default_rng(case.seed)
    length = case.past + case.gap + 1
    r = case.past - 1
    t = np.arange(length, dtype=np.float64)
    progress = (t - r) / (case.gap + 1)
    yaw = np.radians(case.facing_deg + case.turn_deg * progress)
    yaw_q = np.stack((np.cos(yaw / 2), 0 * yaw, np.sin(yaw / 2), 0 * yaw), -1)
    base = quaternions.from_matrix(torch.from_numpy(_HIPS_FACING_PLUS_X)).numpy()
    wobble = _axis_angle_to_quat(0.08 * np.sin(0.3 * t[:, None] + rng.uniform(0, 6.3, 3)))
    root_q = quaternions.multiply(torch.from_numpy(yaw_q), quaternions.multiply(
        torch.from_numpy(base).expand(length, 4), torch.from_numpy(wobble))).numpy()
    amplitude = rng.uniform(0.05, 0.45, (1, joints, 3))
    omega = rng.uniform(0.05, 0.35, (1, joints, 3))
    phase = rng.uniform(0, 2 * math.pi, (1, joints, 3))
    rest = rng.uniform(-0.3, 0.3, (1, joints, 3))
    local = _axis_angle_to_quat(rest + amplitude * np.sin(omega * t[:, None, None] + phase))
    local[:, 0] = root_q
    heading = np.stack((np.cos(yaw), 0 * yaw, -np.sin(yaw)), -1)  # yaw about +Y applied to +X
    step = np.cumsum(np.concatenate(([0.0], np.ones(length - 1))) * case.speed)[:, None] * heading
    step = step - step[r]
    root = step + np.array([case.origin_xz[0], 0.0, case.origin_xz[1]])
    root[:, 1] = 88.0 + 3.0 * np.sin(0.4 * t + rng.uniform(0, 6.3))
    if case.flip_target_signs:
        local[-1, ::2] *= -1.0  # every other joint's target in the opposite hemisphere
    return root, local


def _round(x) -> object:
    if isinstance(x, (list, tuple)):
        return [_round(v) for v in x]
    v = float(x)
    return float(f"{v:.{SIGNIFICANT_DIGITS}g}") if v != 0.0 else 0.0


def _tolist(t) -> list:
    return _round(np.asarray(t, dtype=np.float64).tolist())


def golden_case(loaded: LoadedModel, case: Case) -> Dict:
    root, local = synthetic_request(case, loaded.config.joints)
    p, n = case.past, case.gap
    result = run_transition(loaded, torch.from_numpy(root[None, :p]), torch.from_numpy(local[None, :p]),
                            torch.from_numpy(root[None, -1]), torch.from_numpy(local[None, -1]), n)
    batch, world_root, world_rot = result.batch, result.root_positions, result.local_quaternions
    features = batch.key_features.float()  # what the runtime feeds the float32 graph
    layout = TransitionSampler(past=p, min_gap=1, max_gap=n).layout(n)
    root_delta, rot_delta = result.root_delta, result.rotation_delta
    offsets = torch.from_numpy(loaded.skeleton.offsets)
    _, world_pos = forward_kinematics(world_rot, world_root, offsets, loaded.skeleton.parents)
    return {
        "name": case.name, "past_frames": p, "gap": n,
        "past_root_positions": _tolist(root[:p]),
        "past_local_quaternions": _tolist(local[:p]),
        "target_root_position": _tolist(root[-1]),
        "target_local_quaternions": _tolist(local[-1]),
        "localization": {"yaw": _tolist(batch.localization.yaw[0]),
                         "origin": _tolist(batch.localization.origin[0])},
        "inputs": {C.KEY_FEATURES: _tolist(features.reshape(-1)), C.KEY_FRAME_INDICES: layout.key_frames,
                   C.QUERY_FRAME_INDICES: layout.query_frames, C.GAP_LENGTH: [n]},
        "outputs": {C.ROOT_POSITION_DELTA: _tolist(root_delta.reshape(-1)),
                    C.ROTATION_6D_DELTA: _tolist(rot_delta.reshape(-1)),
                    **({C.FOOT_CONTACTS: _tolist(result.foot_contacts.reshape(-1))}
                       if result.foot_contacts is not None else {})},
        "result": {"root_positions": _tolist(world_root[0]), "local_quaternions": _tolist(world_rot[0]),
                   "global_positions": _tolist(world_pos[0])},
    }


def golden_document(loaded: LoadedModel, cases=CASES, model_name: str = MODEL_NAME) -> Dict:
    doc = {"contract_version": C.CONTRACT_VERSION, "model": f"{model_name}.onnx"}
    if loaded.model.has_contacts:
        doc.update(contact_joints=list(C.CONTACT_JOINTS), contact_threshold=loaded.contact_threshold)
    doc["cases"] = [golden_case(loaded, c) for c in cases]
    return doc


def dump_golden(doc: Dict) -> str:
    """Compact JSON with one case per line: small, and diffs stay readable case by case."""
    head = {k: v for k, v in doc.items() if k != "cases"}
    body = ",\n".join(json.dumps(c, separators=(",", ":")) for c in doc["cases"])
    return json.dumps(head, separators=(",", ":"))[:-1] + ',"cases":[\n' + body + "\n]}\n"


def check_golden_against_onnx(doc: Dict, onnx_path: Path, tolerance: float = 1e-5) -> float:
    """Feed every golden case's inputs to the exported whole graph (numpy evaluator); compare outputs."""
    import onnx
    proto = onnx.load(str(onnx_path))
    worst = 0.0
    for case in doc["cases"]:
        inp = case["inputs"]
        k = len(inp[C.KEY_FRAME_INDICES])
        feeds = {C.KEY_FEATURES: np.asarray(inp[C.KEY_FEATURES], np.float32).reshape(1, k, -1),
                 C.KEY_FRAME_INDICES: np.asarray(inp[C.KEY_FRAME_INDICES], np.int64),
                 C.QUERY_FRAME_INDICES: np.asarray(inp[C.QUERY_FRAME_INDICES], np.int64),
                 C.GAP_LENGTH: np.asarray(inp[C.GAP_LENGTH], np.int64)}
        got = run_model(proto, feeds)
        for name in (C.ROOT_POSITION_DELTA, C.ROTATION_6D_DELTA, C.FOOT_CONTACTS):
            if name == C.FOOT_CONTACTS and name not in case["outputs"]:
                if name in got:
                    raise ValueError(f"golden case {case['name']}: ONNX has {name}, the golden document not")
                continue
            d = float(np.abs(got[name].reshape(-1) - np.asarray(case["outputs"][name])).max())
            worst = max(worst, d)
            if d > tolerance:
                raise ValueError(f"golden case {case['name']}: ONNX {name} differs by {d:.3g}")
    return worst


def write_fixtures(out_dir: str | Path, data_dir: Optional[str | Path] = None) -> Dict[str, Path]:
    """tiny-model.pt, tiny-model{,.keys,.frame}.onnx and golden.json in `out_dir` (no contact output), and the
    same network with a contact head: tiny-model-contacts.pt, tiny-model-contacts{,.keys,.frame}.onnx and
    golden-contacts.json (whose outputs also hold `foot_contacts`); contact-labels.json, the contact label rule's
    golden vectors."""
    out = Path(out_dir)
    if out.exists() and not out.is_dir():
        raise ValueError(f"{out}: is a file, not a folder; expected the fixtures folder (Tests/Fixtures~)")
    out.mkdir(parents=True, exist_ok=True)
    skeleton = lafan1_skeleton(data_dir)
    paths = _write_model_fixtures(out, make_tiny_model(skeleton), MODEL_NAME, "golden.json")
    contacts = _write_model_fixtures(out, make_tiny_model(skeleton, contacts=True), CONTACTS_MODEL_NAME,
                                     "golden-contacts.json")
    labels = write_contact_label_vectors(out / "contact-labels.json")
    return {**paths, **{f"contacts_{k}": v for k, v in contacts.items()}, "contact_labels": labels}


def _write_model_fixtures(out: Path, loaded: LoadedModel, name: str, golden_name: str) -> Dict[str, Path]:
    ckpt = out / f"{name}.pt"
    # Regenerating the repository's fixtures replaces them by design (no --force); each file still goes
    # through a temporary file + rename, so a failure leaves the previous set intact.
    save_checkpoint_file(checkpoint_state(loaded), ckpt)
    loaded = load_checkpoint(ckpt)  # everything below goes through what evaluate/export would load
    report = export_model(loaded, out / f"{name}.onnx", name="DeltaInterpolator-tiny-fixture")
    doc = golden_document(loaded, model_name=name)
    check_golden_against_onnx(doc, report.paths["whole"])
    golden = out / golden_name
    safe_output.write_text(golden, dump_golden(doc))
    return {"checkpoint": ckpt, **{f"onnx_{k}": v for k, v in report.paths.items()}, "golden": golden}
