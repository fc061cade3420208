"""The `evaluate`, `export` and `fixtures` verbs (registered by cli.py through `add_verbs`)."""
from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import List

from .cli import DEFAULT_DATA, DEFAULT_STATS


def _lengths(text: str) -> List[int]:
    try:
        values = [int(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"--lengths wants comma-separated integers, got {text!r}")
    if not values or any(v < 1 for v in values):
        raise argparse.ArgumentTypeError(f"--lengths wants positive integers, got {text!r}")
    return values


def add_verbs(sub) -> None:
    p = sub.add_parser(
        "evaluate", help="the official LaFAN1 benchmark: zero-velocity, SLERP and (optionally) a model",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Runs the official LaFAN1 in-betweening benchmark (Harvey et al. 2020) on the subject-5 "
                    "BVH files in --data:\nwindows of --window frames every --offset frames, XZ-centred and "
                    "turned to face +X at frame 9,\n10 past frames, a transition of n frames, the target at "
                    "frame 10+n; L2Q, L2P (normalised\nwith --stats) and NPSS over the missing frames.\n\n"
                    "Without --checkpoint it scores the two baselines; with it, a 'model' row as well.\n"
                    "Example:\n  PYTHONPATH=Training python3 -m deltainterp evaluate "
                    "--checkpoint Training/runs/runtime/checkpoint.pt --json out/benchmark.json")
    p.add_argument("--data", default=DEFAULT_DATA, help=f"folder of LaFAN1 .bvh files (default {DEFAULT_DATA})")
    p.add_argument("--stats", default=DEFAULT_STATS,
                   help="official statistics JSON (x_mean, x_std, offsets); default " + DEFAULT_STATS)
    p.add_argument("--window", type=int, default=65, help="window length in frames (official: 65)")
    p.add_argument("--offset", type=int, default=40, help="frames between window starts (official: 40)")
    p.add_argument("--lengths", type=_lengths, default=[5, 15, 30, 45],
                   help="transition lengths n, comma-separated (default 5,15,30,45)")
    p.add_argument("--checkpoint", help="a checkpoint.pt from `train` (or tiny-model.pt) to score as 'model'")
    p.add_argument("--batch-size", type=int, default=64, help="windows per network call (default 64)")
    p.add_argument("--threads", type=int, default=1, help="torch intra-op threads (default 1)")
    p.add_argument("--json", required=True, help="where to write the results JSON")

    p = sub.add_parser(
        "export", help="export a checkpoint to ONNX: whole graph + lazy keys/frame graphs",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Writes OUT (the whole transition) and, beside it, .keys.onnx and .frame.onnx graphs "
                    "(lazy decoding;\nout/m.onnx → out/m.keys.onnx, out/m.frame.onnx), opset 15, batch 1, dynamic frame axes, with the contract's constant outputs and "
                    "metadata\n(Documentation~/model-contract.md). Fails when a graph holds an operator that "
                    "Sentis 2.x or\nBarracuda cannot import (deltainterp/operators.py), or when the numpy "
                    "evaluation of a written\ngraph differs from torch by more than 1e-5.\n"
                    "Example:\n  PYTHONPATH=Training python3 -m deltainterp export "
                    "--checkpoint Training/runs/runtime/checkpoint.pt --out out/runtime.onnx")
    p.add_argument("--checkpoint", required=True, help="checkpoint.pt from `train`")
    p.add_argument("--out", required=True, help="output path ending in .onnx")
    p.add_argument("--name", default="DeltaInterpolator-LaFAN1", help="model name in the metadata")

    p = sub.add_parser(
        "fixtures", help="write the tiny test model and golden vectors for the C# tests",
        description="Writes tiny-model.pt, tiny-model.onnx (+ .keys.onnx, .frame.onnx) and golden.json "
                    "into --out. Deterministic: the same bytes on every run.")
    p.add_argument("--out", default="Tests/Fixtures", help="output folder (default Tests/Fixtures)")
    p.add_argument("--data", default=DEFAULT_DATA,
                   help="LaFAN1 folder for the skeleton (optional: a built-in copy is used without it)")


def _size(n: int) -> str:
    return f"{n / 1024:.1f} KiB" if n < 1 << 20 else f"{n / (1 << 20):.2f} MiB"


def run(args) -> int:
    import torch
    if args.verb == "evaluate":
        from .benchmark import format_table, run_benchmark
        from .checkpoint import load_checkpoint
        torch.set_num_threads(args.threads)
        loaded = load_checkpoint(args.checkpoint) if args.checkpoint else None
        report = run_benchmark(args.data, args.stats, args.window, args.offset, args.lengths, loaded,
                               args.batch_size)
        if loaded is not None:
            report["checkpoint"] = {"path": args.checkpoint, "step": loaded.step,
                                    "parameters": loaded.model.parameter_count(), **loaded.config.to_dict()}
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json).write_text(json.dumps(report, indent=2) + "\n")
        print(format_table(report))
        print(f"\nwrote {args.json}")
        return 0
    if args.verb == "export":
        from .checkpoint import load_checkpoint
        from .export import export_model
        torch.set_num_threads(1)
        loaded = load_checkpoint(args.checkpoint)
        report = export_model(loaded, args.out, args.name)
        print(f"{args.name}: {report.parameters:,} parameters, opset 15, checked against torch "
              f"(max |diff| {report.max_difference:.2g})")
        for kind, path in report.paths.items():
            print(f"  {kind:<5} {path}  {_size(report.sizes[kind])}  ops: {', '.join(report.operators[kind])}")
        return 0
    if args.verb == "fixtures":
        from .fixtures import write_fixtures
        torch.set_num_threads(1)
        data = args.data if args.data and Path(args.data).exists() else None
        paths = write_fixtures(args.out, data)
        for what, path in paths.items():
            print(f"  {what:<10} {path}  {_size(Path(path).stat().st_size)}")
        print("skeleton from " + (str(data) if data else "the built-in LaFAN1 copy"))
        return 0
    raise ValueError(f"unknown verb {args.verb}")
