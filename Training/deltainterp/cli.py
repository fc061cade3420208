"""Command line: python3 -m deltainterp prepare|train|evaluate|export|fixtures (see --help of each)."""
from __future__ import annotations

import argparse
import sys
from typing import List, Optional

DEFAULT_DATA = "../shared/data/lafan1"
DEFAULT_STATS = "../shared/data/lafan1/train_stats_official.json"
DEFAULT_PACK = "Training/.data/lafan1-train.npz"


def _prepare(sub) -> None:
    p = sub.add_parser("prepare", help="read the LaFAN1 training BVH files once and pack them into one .npz",
                       description="Reads every training-subject BVH (subjects 1-4) in --data, applies the "
                                   "quaternion continuity fix per file, and writes one compact .npz that "
                                   "`train` reads (and that can travel to a remote GPU machine).")
    p.add_argument("--data", default=DEFAULT_DATA, help=f"folder of LaFAN1 .bvh files (default {DEFAULT_DATA})")
    p.add_argument("--stats", default=DEFAULT_STATS,
                   help="official statistics JSON; its bone offsets become the model's skeleton offsets")
    p.add_argument("--out", default=DEFAULT_PACK, help=f"output .npz (default {DEFAULT_PACK})")


def _train(sub) -> None:
    p = sub.add_parser("train", help="train a model (resumes automatically from OUT/checkpoint.pt)",
                       description="Trains the Δ-Interpolator on a prepared pack. Writes OUT/checkpoint.pt "
                                   "(exact resume: rerun the same command), OUT/log.csv, OUT/validation.jsonl "
                                   "and OUT/curves.png. Under torchrun it trains with DistributedDataParallel.")
    p.add_argument("--data", default=DEFAULT_PACK, help="pack written by `prepare`")
    p.add_argument("--out", default="Training/runs/runtime", help="run folder (checkpoint, logs, plots)")
    p.add_argument("--preset", default="runtime", choices=["runtime", "paper", "tiny"],
                   help="architecture: runtime (256 wide, 4 blocks, 8 heads), paper (1024/6/8), tiny (tests)")
    p.add_argument("--width", type=int, help="override the preset's width")
    p.add_argument("--blocks", type=int, help="override the preset's number of blocks")
    p.add_argument("--heads", type=int, help="override the preset's number of heads")
    p.add_argument("--dropout", type=float, help="override the preset's dropout")
    p.add_argument("--output-delta-mode", default="slerp", choices=["slerp", "last_pose", "none"],
                   help="what the output deltas are added to (paper ablation)")
    p.add_argument("--input-delta-mode", default="last_pose", choices=["last_pose", "none"],
                   help="whether key features are relative to the last past key (paper ablation)")
    p.add_argument("--steps", type=int, default=20000, help="optimizer steps (default 20000)")
    p.add_argument("--batch-size", type=int, default=64)
    p.add_argument("--lr", type=float, default=4e-4, help="peak learning rate after warm-up")
    p.add_argument("--warmup", type=int, default=500, help="linear warm-up steps")
    p.add_argument("--decay-at", type=float, default=0.8, help="fraction of --steps after which lr ×0.1")
    p.add_argument("--reconstruction-scale", type=float, default=1.0, help="weight of the key-frame loss")
    p.add_argument("--mirror", action="store_true", help="augment with left/right mirrored windows")
    p.add_argument("--random-yaw", action="store_true", help="augment with a random rotation about Y")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--threads", type=int, default=1,
                   help="torch intra-op threads (default 1: measured fastest on a 2-core CPU, see model card)")
    p.add_argument("--checkpoint-every", type=int, default=250)
    p.add_argument("--validate-every", type=int, default=500)
    p.add_argument("--max-minutes", type=float, default=0.0,
                   help="stop cleanly (with a checkpoint) after this many minutes; rerun to resume")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="python3 -m deltainterp",
                                     description="Train, evaluate and export the Δ-Interpolator. A full recipe: "
                                                 "prepare → train → evaluate → export (see README).")
    sub = parser.add_subparsers(dest="verb", required=True, metavar="VERB")
    _prepare(sub)
    _train(sub)
    try:
        from . import cli_more
    except ModuleNotFoundError as e:  # optional module; any OTHER missing import must surface
        if e.name != f"{__package__}.cli_more":
            raise
    else:
        cli_more.add_verbs(sub)
    return parser


def main(argv: Optional[List[str]] = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        if args.verb == "prepare":
            from .data import prepare
            pack = prepare(args.data, args.out, args.stats)
            print(f"wrote {args.out}: {len(pack.files)} files, {len(pack.root_positions)} frames, "
                  f"{pack.skeleton.joint_count} joints")
            return 0
        if args.verb == "train":
            from .train import TrainConfig, train
            overrides = {k: getattr(args, k) for k in ("width", "blocks", "heads", "dropout")
                         if getattr(args, k) is not None}
            overrides["output_delta_mode"] = args.output_delta_mode
            overrides["input_delta_mode"] = args.input_delta_mode
            cfg = TrainConfig(data=args.data, out=args.out, preset=args.preset, model_overrides=overrides,
                              batch_size=args.batch_size, steps=args.steps, peak_lr=args.lr,
                              warmup_steps=args.warmup, decay_at=args.decay_at,
                              reconstruction_scale=args.reconstruction_scale, seed=args.seed,
                              mirror=args.mirror, random_yaw=args.random_yaw,
                              checkpoint_every=args.checkpoint_every, validate_every=args.validate_every,
                              max_minutes=args.max_minutes, threads=args.threads)
            path = train(cfg)
            print(f"checkpoint: {path}")
            return 0
        from . import cli_more
        return cli_more.run(args)
    except (FileNotFoundError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
