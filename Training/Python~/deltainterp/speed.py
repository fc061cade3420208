"""Times the PyTorch eager reference of one in-betweening request, for `inbetween speed --pytorch`.

    PYTHONPATH=Training/Python~ python3 -m deltainterp.speed --config META.json --threads N --json OUT

META.json is the `deltainterp` metadata object of an exported model (Documentation~/model-contract.md):
its architecture, skeleton, unit scale and delta modes rebuild the same network in PyTorch. The weights
are random — they do not change the time. One "transition" is what the C# runtime does per request:
`transition.run_transition` (localize → key features → network → SLERP baseline + deltas → Gram–Schmidt
→ quaternions → un-localize) followed by FK of the missing frames, float64 geometry, float32 network,
batch 1, `torch.no_grad()`, `torch.set_num_threads(N)`. The `paper` preset (1024 wide, 6 blocks) is timed
the same way: what a user of the reference implementation pays per request.

Output JSON: {"threads", "torch", "repeats", "transition_ms": {"5": {"median", "p95"}, ...},
"paper_transition_ms": {...}, "parameters", "paper_parameters"}.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import time
from typing import Dict, List

import numpy as np
import torch

from . import safe_output
from .checkpoint import LoadedModel
from .kinematics import forward_kinematics
from .model import DeltaInterpolator, ModelConfig, preset
from .skeleton import Skeleton
from .terminal_text import LINE_LENGTH, safe
from .transition import run_transition


def build(meta: dict, paper: bool) -> LoadedModel:
    skeleton = Skeleton.from_json(meta["skeleton"])
    arch = meta["architecture"]
    modes = dict(output_delta_mode=meta.get("output_delta_mode", "slerp"),
                 input_delta_mode=meta.get("input_delta_mode", "last_pose"), dropout=0.0)
    if paper:
        config = preset("paper", joints=skeleton.joint_count, **modes)
    else:
        config = ModelConfig(joints=skeleton.joint_count, width=arch["width"], blocks=arch["blocks"],
                             heads=arch["heads"], embedding_dim=arch["embedding_dim"],
                             embedding_size=arch["embedding_size"], **modes)
    torch.manual_seed(0)
    model = DeltaInterpolator(config).eval()
    return LoadedModel(model, skeleton, float(meta["unit_scale"]), 0,
                       facing_local_axis=tuple(meta.get("facing_local_axis", (0.0, 1.0, 0.0))),
                       facing_target_axis=tuple(meta.get("facing_target_axis", (1.0, 0.0, 0.0))))


def request(joints: int, past: int, seed: int = 0):
    """A plausible request (float64): a root walking along +X, small random joint rotations."""
    rng = np.random.default_rng(seed)
    axis_angle = rng.normal(0.0, 0.2, (1, past + 1, joints, 3))
    angle = np.linalg.norm(axis_angle, axis=-1, keepdims=True)
    q = np.concatenate((np.cos(angle / 2), np.sin(angle / 2) * axis_angle / np.maximum(angle, 1e-12)), -1)
    roots = np.zeros((1, past + 1, 3))
    roots[..., 0] = np.arange(past + 1) * 2.0
    roots[..., 1] = 90.0
    q, roots = torch.from_numpy(q), torch.from_numpy(roots)
    return roots[:, :past], q[:, :past], roots[:, past], q[:, past]


def time_transitions(loaded: LoadedModel, lengths: List[int], past: int, warmup: int, repeats: int,
                     budget_s: float) -> Dict[str, Dict[str, float]]:
    offsets = torch.from_numpy(loaded.skeleton.offsets)
    parents = loaded.skeleton.parents
    pr, pq, tr, tq = request(loaded.skeleton.joint_count, past)
    out = {}
    with torch.no_grad():
        for n in lengths:
            def once() -> None:
                result = run_transition(loaded, pr, pq, tr, tq, n)
                forward_kinematics(result.local_quaternions, result.root_positions, offsets, parents)
            for _ in range(warmup):
                once()
            samples = []
            start = time.perf_counter()
            while len(samples) < repeats and (len(samples) < 10 or time.perf_counter() - start < budget_s):
                t0 = time.perf_counter()
                once()
                samples.append((time.perf_counter() - t0) * 1e3)
            s = np.sort(np.asarray(samples))
            out[str(n)] = {"median": float(np.median(s)),
                           "p95": float(s[min(len(s) - 1, int(math.ceil(0.95 * len(s))) - 1)]),
                           "samples": len(s)}
    return out


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python3 -m deltainterp.speed", description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--config", required=True, help="the model's 'deltainterp' metadata JSON (a file)")
    p.add_argument("--threads", type=int, default=1, help="torch intra-op threads (default 1)")
    p.add_argument("--lengths", default="5,15,30", help="transition lengths (default 5,15,30)")
    p.add_argument("--past", type=int, default=10, help="past key frames (default 10)")
    p.add_argument("--warmup", type=int, default=20, help="untimed runs per length (default 20)")
    p.add_argument("--repeats", type=int, default=200, help="timed runs per length (default 200)")
    p.add_argument("--budget", type=float, default=10.0,
                   help="seconds per length after which fewer repeats are accepted (default 10)")
    p.add_argument("--no-paper", action="store_true", help="skip the paper preset")
    p.add_argument("--json", required=True, help="output JSON (refused when it exists, unless --force)")
    p.add_argument("--force", action="store_true", help="replace an existing --json file")
    args = p.parse_args(argv)
    try:
        safe_output.check(args.json, args.force, [args.config])  # before the timing, not after it
        with open(args.config) as f:
            meta = json.load(f)
    except (OSError, ValueError) as e:
        message = f"{e.filename}: {e.strerror}; expected a readable file" if isinstance(e, OSError) and e.filename \
            else (str(e) if isinstance(e, safe_output.OutputPathError) else f"{args.config}: not JSON ({e}); expected "
                  "the model's 'deltainterp' metadata JSON")
        print(f"error: {safe(message, LINE_LENGTH)}", file=sys.stderr)
        return 2
    torch.set_num_threads(args.threads)
    lengths = [int(v) for v in args.lengths.split(",") if v.strip()]
    loaded = build(meta, paper=False)
    result = {"threads": args.threads, "torch": torch.__version__, "repeats": args.repeats,
              "parameters": loaded.model.parameter_count(),
              "transition_ms": time_transitions(loaded, lengths, args.past, args.warmup, args.repeats,
                                                args.budget)}
    if not args.no_paper:
        paper = build(meta, paper=True)
        result["paper_parameters"] = paper.model.parameter_count()
        result["paper_transition_ms"] = time_transitions(paper, lengths, args.past, max(3, args.warmup // 4),
                                                         args.repeats, args.budget)
    safe_output.write_text(args.json, json.dumps(result, indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
