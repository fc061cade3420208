"""The official LaFAN1 in-betweening benchmark (Harvey et al. 2020; method-spec §1), re-implemented.

Semantics follow `ubisoft/ubisoft-laforge-animation-dataset` lafan1/{extract,utils,benchmarks}.py:
- test files = subject 5; windows start at 0, offset, … while start + window < frames (§1.4);
- the quaternion continuity fix runs once per FILE before windowing (§1.5);
- each window is XZ-centred on the mean root XZ over ALL its frames (§1.6), then turned about +Y so that
  the hips' local +Y axis at frame 9 (projected on XZ) points to +X (§1.7);
- ground truth and baselines use the statistics file's bone offsets, not the test file's (§1.9);
- zero-velocity copies frame 9; interpolation LERPs the root and SLERPs every local quaternion between
  frame 9 and frame 10+n with weights k/(n+1) (§1.10);
- L2Q: norm over the 88-vector of global quaternions, L2P: norm over the 66 standardised global
  coordinates, NPSS: real part of the full FFT, per-feature normalised CDF, L1 EMD, GT-power weights,
  no epsilon (§1.11). Means run over (window, missing frame).

Everything is float64. The model row runs the SAME path as training and the runtime (`make_batch`:
localize at the last past key → key features → network → `decode_outputs` → `unlocalize`).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np
import torch

from . import quaternions
from .baseline import interpolation_weights, slerp_baseline
from .bvh import lafan1_files, read_bvh
from .data import TEST_SUBJECTS, windows
from .facing import yaw_toward
from .kinematics import forward_kinematics
from .localize import unlocalize
from .objective import make_batch, predict
from .progress import Progress, each
from .lafan1_statistics import Statistics, load_statistics
from .sampler import TransitionSampler

Tensor = torch.Tensor

PAST = 10            # past context frames (n_past)
FUTURE = 10          # frames after the target that the official code keeps (n_future); only the first is used
FACING_FRAME = PAST - 1
DEFAULT_LENGTHS = (5, 15, 30, 45)
METRICS = ("l2q", "l2p", "npss")
METHOD_LABELS = {"zerovel": "Zero-V", "slerp": "Interp. (SLERP)", "model": "Model"}


@dataclass
class BenchmarkWindows:
    names: List[str]          # joint names (from the BVH)
    parents: List[int]
    files: List[str]          # source file of each window
    starts: List[int]         # start frame of each window in its file
    root_positions: Tensor    # (W, T, 3) float64, centred and facing-normalised, cm
    local_quaternions: Tensor  # (W, T, J, 4) float64

    @property
    def count(self) -> int:
        return int(self.root_positions.shape[0])


def normalise_windows(root_positions: Tensor, local_quaternions: Tensor, facing_frame: int = FACING_FRAME
                      ) -> Tuple[Tensor, Tensor]:
    """Official XZ centring (mean over all window frames) then the +Y-about rotation at `facing_frame`
    that makes the hips' local +Y face +X. Non-root local quaternions are unchanged by a global turn (the
    official code's FK → rotate → IK round trip returns them up to round-off)."""
    mean_xz = root_positions[:, :, [0, 2]].mean(dim=1, keepdim=True)
    centred = root_positions.clone()
    centred[:, :, [0, 2]] -= mean_xz
    # `yaw_toward` returns rotation(forward → +X) = the inverse of the official yrot; a zero forward
    # (hips pointing straight up) gives the identity instead of the official zero quaternion.
    yaw = yaw_toward(local_quaternions[:, facing_frame, 0], (0.0, 1.0, 0.0), (1.0, 0.0, 0.0))
    yaw_t = yaw[:, None].expand(centred.shape[:-1] + (4,))
    positions = quaternions.apply(yaw_t, centred)
    rotations = local_quaternions.clone()
    rotations[:, :, 0] = quaternions.multiply(yaw_t, local_quaternions[:, :, 0])
    return positions, rotations


def load_windows(data_dir: str | Path, window: int = 65, offset: int = 40,
                 subjects: Sequence[int] = TEST_SUBJECTS, progress: bool = True) -> BenchmarkWindows:
    files = lafan1_files(data_dir, tuple(subjects))
    iterator = each(files, len(files), "reading test BVH", "file", progress)
    roots, quats, names_of, starts_of = [], [], [], []
    names: Optional[List[str]] = None
    parents: Optional[List[int]] = None
    for f in iterator:
        motion = read_bvh(f, fix_continuity=True)  # continuity fix over the whole file, before windowing
        if names is None:
            names, parents = motion.skeleton.names, motion.skeleton.parents
        elif motion.skeleton.names != names:
            raise ValueError(f"{f}: joints differ from those of {files[0]}")
        r = torch.from_numpy(motion.root_positions)
        q = torch.from_numpy(motion.local_quaternions)
        for s in windows(motion.frame_count, window, offset):
            roots.append(r[s:s + window])
            quats.append(q[s:s + window])
            names_of.append(f.name)
            starts_of.append(s)
    if not roots:
        raise ValueError(f"no {window}-frame windows in the subject {tuple(subjects)} files of {data_dir}")
    positions, rotations = normalise_windows(torch.stack(roots), torch.stack(quats))
    assert names is not None and parents is not None
    return BenchmarkWindows(list(names), list(parents), names_of, starts_of, positions, rotations)


# -- metrics -----------------------------------------------------------------------------------------
def l2q(pred_global_quaternions: Tensor, gt_global_quaternions: Tensor) -> float:
    """Mean over (window, frame) of the norm of the (J·4)-vector difference; no hemisphere alignment."""
    d = (pred_global_quaternions - gt_global_quaternions).flatten(2)
    return float(d.norm(dim=-1).mean())


def l2p(pred_global_positions: Tensor, gt_global_positions: Tensor, stats: Statistics) -> float:
    """Mean over (window, frame) of the norm of the standardised (J·3)-vector difference."""
    std = torch.as_tensor(stats.x_std, dtype=pred_global_positions.dtype)
    mean = torch.as_tensor(stats.x_mean, dtype=pred_global_positions.dtype)
    p = (pred_global_positions.flatten(2) - mean) / std
    g = (gt_global_positions.flatten(2) - mean) / std
    return float((p - g).norm(dim=-1).mean())


def npss(gt: np.ndarray, pred: np.ndarray) -> float:
    """NPSS on (B, T, D) sequences, as the official `fast_npss` (real part of the full FFT over time)."""
    gt_power = np.square(np.real(np.fft.fft(gt, axis=1)))
    pred_power = np.square(np.real(np.fft.fft(pred, axis=1)))
    gt_total = gt_power.sum(axis=1)
    pred_total = pred_power.sum(axis=1)
    gt_cdf = np.cumsum(gt_power / gt_total[:, None, :], axis=1)
    pred_cdf = np.cumsum(pred_power / pred_total[:, None, :], axis=1)
    emd = np.abs(pred_cdf - gt_cdf).sum(axis=1)
    return float(np.average(emd, weights=gt_total))


def score(pred_rotations: Tensor, pred_roots: Tensor, gt_global: Tuple[Tensor, Tensor], offsets: Tensor,
          parents: Sequence[int], stats: Statistics) -> Dict[str, float]:
    """FK of a prediction (local quats (W, n, J, 4), root positions (W, n, 3), cm) against GT globals."""
    gq, gp = gt_global
    pq, pp = forward_kinematics(pred_rotations, pred_roots, offsets, parents)
    return {"l2q": l2q(pq, gq), "l2p": l2p(pp, gp, stats),
            "npss": npss(gq.flatten(2).numpy(), pq.flatten(2).numpy())}


# -- baselines -----------------------------------------------------------------------------------
def zero_velocity(roots: Tensor, rotations: Tensor, n: int) -> Tuple[Tensor, Tensor]:
    last = PAST - 1
    return (roots[:, last:last + 1].expand(-1, n, -1),
            rotations[:, last:last + 1].expand(-1, n, -1, -1))


def interpolation(roots: Tensor, rotations: Tensor, n: int) -> Tuple[Tensor, Tensor]:
    last, target = PAST - 1, PAST + n
    weights = interpolation_weights(torch.arange(PAST, PAST + n), last, n)
    return slerp_baseline(roots[:, last], roots[:, target], rotations[:, last], rotations[:, target], weights)


# -- the model row -------------------------------------------------------------------------------
PAST_POLICIES = ("feed", "repeat")


def context_frames(past_frames: int, n: int, policy: str = "feed") -> List[int]:
    """Window frames the network sees for a request with only the last `past_frames` of the 10 context
    frames known: the keys, then the n missing frames, then the target at 10+n.

    `feed` gives the network exactly those P frames (key frame indices 0..P-1, target P+n); `repeat`
    pads them to 10 by repeating the earliest known frame (indices 0..9, target 10+n), for a model trained
    with 10 past frames only."""
    if not 1 <= past_frames <= PAST:
        raise ValueError(f"--past-frames {past_frames} is outside 1..{PAST}; expected 1 to {PAST}")
    if policy not in PAST_POLICIES:
        raise ValueError(f"past policy {policy!r}; expected one of {PAST_POLICIES}")
    first = PAST - past_frames
    known = list(range(first, PAST))
    keys = known if policy == "feed" else [first] * first + known
    return keys + list(range(PAST, PAST + n + 1))


def model_predictions(loaded, roots: Tensor, rotations: Tensor, n: int, batch_size: int = 64,
                      bar=None, past_frames: int = PAST, past_policy: str = "feed") -> Tuple[Tensor, Tensor]:
    """Run the network on every window: keys = frames 0..9 and 10+n, exactly as a runtime request (or
    only the last `past_frames` of the context, see `context_frames`).

    Returns world (benchmark-frame) root positions (W, n, 3) cm and local quaternions (W, n, J, 4)."""

    frames = torch.tensor(context_frames(past_frames, n, past_policy))
    past = len(frames) - n - 1
    layout = TransitionSampler(past=past).layout(n)
    skeleton = loaded.skeleton_tensors(torch.float64)
    cfg = loaded.config
    out_roots, out_rots = [], []
    with torch.no_grad():
        for b in range(0, roots.shape[0], batch_size):
            r = roots[b:b + batch_size][:, frames]
            q = rotations[b:b + batch_size][:, frames]
            batch = make_batch(r, q, layout, skeleton, cfg.output_delta_mode, cfg.input_delta_mode)
            root, rot, _, _ = predict(loaded.model, batch, with_keys=False)
            root, rot = unlocalize(root, rot, batch.localization, loaded.unit_scale)
            out_roots.append(root)
            out_rots.append(rot)
            if bar is not None:
                bar.update(int(r.shape[0]))
    return torch.cat(out_roots), torch.cat(out_rots)


def run_benchmark(data_dir: str | Path, stats_path: str | Path, window: int = 65, offset: int = 40,
                  lengths: Sequence[int] = DEFAULT_LENGTHS, loaded=None, batch_size: int = 64,
                  progress: bool = True, past_frames: int = PAST, past_policy: str = "feed") -> Dict:
    """The whole benchmark → the JSON-ready result dictionary (see `evaluate --help`)."""
    context_frames(past_frames, 1, past_policy)  # refuses a bad P or policy before any work
    for n in lengths:
        if n < 1 or n + PAST + FUTURE > window:
            raise ValueError(f"transition length {n} needs {n + PAST + FUTURE} frames (10 past, n, 10 future "
                             f"as the official benchmark crops them) but windows have {window}")
    stats = load_statistics(stats_path)
    data = load_windows(data_dir, window, offset, progress=progress)
    if len(data.names) != len(stats.offsets):
        raise ValueError(f"{stats.path} has {len(stats.offsets)} joints, the BVH files {len(data.names)}")
    if loaded is not None and loaded.skeleton.names != data.names:
        raise ValueError("the checkpoint's skeleton joints differ from the benchmark BVH joints")
    offsets = torch.from_numpy(stats.offsets)
    parents = data.parents
    results: Dict[str, Dict[str, Dict[str, float]]] = {m: {k: {} for k in METRICS} for m in
                                                        (["zerovel", "slerp"] + (["model"] if loaded else []))}
    bar = Progress(data.count * len(lengths), "model", "window") if progress and loaded is not None else None
    for n in lengths:
        missing = slice(PAST, PAST + n)
        gt = forward_kinematics(data.local_quaternions[:, missing], data.root_positions[:, missing], offsets,
                                parents)
        rows = {"zerovel": zero_velocity(data.root_positions, data.local_quaternions, n),
                "slerp": interpolation(data.root_positions, data.local_quaternions, n)}
        if loaded is not None:
            rows["model"] = model_predictions(loaded, data.root_positions, data.local_quaternions, n,
                                              batch_size, bar, past_frames, past_policy)
        for method, (roots, rots) in rows.items():
            for metric, value in score(rots, roots, gt, offsets, parents, stats).items():
                results[method][metric][str(n)] = value
    if bar is not None:
        bar.close()
    report = {"windows": data.count, "window": window, "offset": offset, "stats": str(stats_path),
              "files": sorted(set(data.files)), "lengths": list(lengths), "results": results}
    if past_frames != PAST:  # the official layout writes exactly the keys it always wrote
        report.update(past_frames=past_frames, past_policy=past_policy)
    return report


def format_table(report: Dict) -> str:
    """Methods × lengths for each metric, like the official printout (more digits)."""
    lengths = [str(n) for n in report["lengths"]]
    digits = {"l2q": 4, "l2p": 4, "npss": 5}
    titles = {"l2q": "L2Q (global quaternions)", "l2p": "L2P (global positions, standardised)",
              "npss": "NPSS (global quaternions)"}
    lines = [f"LaFAN1 benchmark: {report['windows']} windows of {report['window']} frames every "
             f"{report['offset']} ({', '.join(report['files'])})"]
    if "past_frames" in report:
        lines.append(f"model sees the last {report['past_frames']} of the 10 past frames "
                     f"({report['past_policy']}); SLERP and zero-velocity are unchanged")
    for metric in METRICS:
        lines.append("")
        lines.append(f"=== {titles[metric]} ===")
        lines.append(f"{'length':<16}" + "".join(f"{n:>10}" for n in lengths))
        for method, table in report["results"].items():
            vals = table[metric]
            lines.append(f"{METHOD_LABELS.get(method, method):<16}"
                         + "".join(f"{vals[n]:>10.{digits[metric]}f}" for n in lengths))
    return "\n".join(lines)
