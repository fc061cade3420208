"""Command line: python3 -m deltainterp prepare|train|evaluate|export|quantize|fixtures|train-contacts|contacts
(see --help of each)."""
from __future__ import annotations

import argparse
import errno
import json
import math
import os
import re
import sys
from pathlib import Path
from typing import List, Optional

from . import safe_output
from .plots import plot_benchmark
from .terminal_text import LINE_LENGTH, SafeStream, safe


def shown(path) -> str:
    """A path or name as a message shows it: escaped (terminal_text.safe), clipped only beyond a line's length."""
    return safe(path, LINE_LENGTH)

DEFAULT_DATA = "../shared/data/lafan1"
DEFAULT_STATS = "../shared/data/lafan1/train_stats_official.json"
DEFAULT_PACK = "Training/.data/lafan1-train.npz"


def _prepare(sub) -> None:
    p = sub.add_parser("prepare", help="retarget BVH folders of any humanoid onto the model's skeleton and pack them",
                       formatter_class=argparse.RawDescriptionHelpFormatter,
                       description="Reads every BVH file in the --data folders (recursively), moves each onto the "
                                   "model's skeleton and frame rate\nwith `inbetween retarget` (the C# tool: one "
                                   "implementation of joint maps, synthesized joints, root scale\nand resampling), "
                                   "and writes one compact .npz that `train` reads. Per-file facts (true frame "
                                   "rate,\nframes to drop, reference frame, joint map) come from a manifest "
                                   "(inbetween-data.json in the folder,\nor a NAME.json given to --data; format in "
                                   "deltainterp/datasets.py and Training/README.md) or from\nthe options below.\n\n"
                                   "A single LaFAN1 folder (<theme><take>_subject<k>.bvh beside train_stats_official.json, "
                                   "no manifest,\nno --holdout) is packed as before: subjects 1-4, the statistics "
                                   "file's offsets.\n\nExample (the shipped CMU model's data, subjects 02, 09, 13 and 38 "
                                   "held out):\n  PYTHONPATH=Training/Python~ python3 -m deltainterp prepare --data "
                                   "Training/Python~/datasets/cmu.json Training/Python~/datasets/cmu-more.json \\\n"
                                   "      --holdout '02_*' '09_*' '13_*' '38_*' --out Training/.data/cmu-train.npz")
    p.add_argument("--data", nargs="+", default=[DEFAULT_DATA],
                   help=f"folders of .bvh files or data manifests (default {DEFAULT_DATA})")
    p.add_argument("--stats", default=DEFAULT_STATS,
                   help="LaFAN1 only: official statistics JSON; its bone offsets become the model's skeleton offsets")
    p.add_argument("--out", default=DEFAULT_PACK, help=f"output .npz (default {DEFAULT_PACK})")
    p.add_argument("--holdout", nargs="*", default=[], metavar="GLOB",
                   help="leave out files whose name or path (relative to their folder) matches, e.g. '02_*' "
                        "(held-out subjects: never trained on, never used to choose anything)")
    p.add_argument("--from-frame", type=int, help="drop the frames before K in every file (manifest default)")
    p.add_argument("--reference-frame", type=int, help="the frame whose pose is the reference (manifest default)")
    p.add_argument("--input-fps", type=float, help="every file's true frame rate (manifest default)")
    p.add_argument("--map", help="a JSON joint map for every file (manifest default; the format `inbetween retarget --map` reads)")
    p.add_argument("--up", help="every file's up axis: auto, y or z (manifest default \"up\"; `inbetween retarget --up`)")
    p.add_argument("--accept-reference-pose", action="store_true",
                   help="keep every file's reference pose even where its spine, neck or leg bones point more than 25° "
                        "from the model's standing pose (refused by default; the manifest's \"accept_reference_pose\" "
                        "does it per file). What it let through is printed per file and written into the pack's "
                        "description; prefer --reference-frame naming a standing frame, or a joint map fix")
    p.add_argument("--time-scales", default="",
                   help="augment with time-scaled copies, e.g. 0.8,1.25 (1.25 = played 25%% slower); trained on, never validated on")
    p.add_argument("--model", help="the .onnx whose skeleton and frame rate are the target (default: the tool's)")
    p.add_argument("--jobs", type=int, default=2, help="retargeting processes at once (default 2)")
    p.add_argument("--cache", default="Training/.data/retargeted",
                   help="folder for retargeted files, reused by later runs (default Training/.data/retargeted)")
    p.add_argument("--force", action="store_true", help="replace an existing --out file")


def _is_lafan1_folder(args) -> bool:
    if len(args.data) != 1 or args.holdout or args.accept_reference_pose or any(
            getattr(args, k) is not None for k in ("from_frame", "reference_frame", "input_fps", "map", "up")):
        return False
    folder = Path(args.data[0])
    if not folder.is_dir() or (folder / "inbetween-data.json").exists():
        return False
    names = [f.name for f in folder.glob("*.bvh")]
    return bool(names) and all(re.fullmatch(r"[A-Za-z]+\d*_subject\d+\.bvh", n) for n in names)


def _export_name(given, checkpoint: str, exported: str) -> str:
    """The exported model's name: --name, else an exported model's own, else after the run (its folder);
    never a data set's it was not trained on (the default was once DeltaInterpolator-LaFAN1 for any run)."""
    if given is not None:
        if not given.strip() or len(given) > 100 or any(ord(c) < 32 or ord(c) == 127 for c in given):
            raise ValueError(f"--name {given[:40]!r}; expected a model name of 1 to 100 printable characters")
        return given
    if exported:
        return exported
    run = re.sub(r"[^A-Za-z0-9._-]+", "-", Path(checkpoint).resolve().parent.name).strip("-.")
    if not run:
        raise ValueError(f"{checkpoint}: no run folder to name the model after; expected --name NAME")
    return f"DeltaInterpolator-{run}"


def _run_prepare(args) -> int:
    # Before any data is read: the output (existing without --force, or one of the named inputs: --force
    # replaces an output, never an input such as a folder's own manifest) ...
    safe_output.check(args.out, args.force, _named_inputs(args))
    # ... then statistics the user named (the LaFAN1 default is read only by the LaFAN1 path below).
    if args.stats and args.stats != DEFAULT_STATS:
        from .lafan1_statistics import load_statistics
        load_statistics(args.stats)
    if _is_lafan1_folder(args):
        from .data import prepare
        safe_output.check(args.out, args.force, [args.stats, *_bvh_files(args.data[0])])  # before reading any BVH
        pack = prepare(args.data[0], args.out, args.stats)
        print(f"wrote {shown(args.out)}: {len(pack.files)} files, {len(pack.root_positions)} frames, "
              f"{pack.skeleton.joint_count} joints")
        return 0
    from .datasets import open_source, plan_files, prepare_any
    scales = []
    for v in [t for t in args.time_scales.split(",") if t.strip()]:
        try:
            scales.append(float(v))
        except ValueError:
            raise ValueError(f"--time-scales: {v!r} is not a number; expected e.g. 0.8,1.25") from None
        if not (0.25 <= scales[-1] <= 4):
            raise ValueError(f"--time-scales: {v}; expected factors from 0.25 to 4")
    if args.jobs < 1 or args.jobs > 64:
        raise ValueError(f"--jobs {args.jobs}; expected 1 to 64")
    from .datasets import UP_AXES
    if args.up is not None and args.up not in UP_AXES:
        raise ValueError(f"--up {args.up[:40]!r}; expected auto, y or z")
    options = {"from_frame": args.from_frame, "reference_frame": args.reference_frame, "fps": args.input_fps,
               "map": args.map, "up": args.up, "accept_reference_pose": True if args.accept_reference_pose else None}
    inputs = _named_inputs(args)
    for source in [open_source(d) for d in args.data]:  # nor one of the BVH files, manifests or maps they name
        plans = plan_files(source, options, args.holdout, [])
        inputs += [str(p.path) for p in plans] + [str(p.map) for p in plans if p.map is not None]
        inputs += [str(source.manifest)] if source.manifest is not None else []
    safe_output.check(args.out, args.force, inputs)
    pack, plans, sources = prepare_any(args.data, args.out, args.holdout, options, scales, args.cache,
                                       args.model, args.jobs)
    originals = [p for p in plans if p.time_scale == 1.0]
    seconds = sum(int(pack.starts[i + 1] - pack.starts[i]) for i in range(len(pack.files))
                  if not pack.is_augmented(i)) * pack.frame_time
    for s in sources:
        n = sum(1 for p in originals if p.folder == str(s.folder))
        print(f"  {shown(s.folder)}: {n} files" + (f" (manifest {shown(s.manifest)})" if s.manifest else ""))
    if args.holdout:
        print(f"  held out: files matching {safe(' '.join(args.holdout), LINE_LENGTH)}")
    for p in originals:  # the explicit override is never silent (as retarget, bake and score report it)
        if p.accepted:
            print(f"warning: {shown(p.path)}: {p.accepted}")
    print(f"wrote {shown(args.out)}: {len(originals)} files ({seconds / 60:.1f} min at {1 / pack.frame_time:.0f} fps)"
          + (f" + {len(plans) - len(originals)} time-scaled copies" if len(plans) > len(originals) else "")
          + f", {len(pack.root_positions)} frames, {pack.skeleton.joint_count} joints")
    return 0


def _train(sub) -> None:
    p = sub.add_parser("train", help="train a model (resumes automatically from OUT/checkpoint.pt)",
                       description="Trains the Δ-Interpolator on a prepared pack. Writes OUT/checkpoint.pt "
                                   "(exact resume: rerun the same command), OUT/log.csv, OUT/validation.jsonl "
                                   "and OUT/curves.png. Under torchrun it trains with DistributedDataParallel. "
                                   "These four files are the run's own: they are replaced (through a temporary "
                                   "file) as the run goes, without --force. OUT must be new, empty or a run "
                                   "folder; resuming refuses other settings or another architecture (naming "
                                   "the difference) and warns about another --steps. Example (after `prepare`): "
                                   "PYTHONPATH=Training/Python~ python3 -m deltainterp train --preset tiny --steps 20 "
                                   "--out Training/runs/try")
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
    p.add_argument("--foot-contact-weight", type=float, default=0.0,
                   help="weight of a loss on the predicted foot joints' horizontal speed (model units per second) on "
                        "missing frames where the truth's feet are planted (default 0: off)")
    p.add_argument("--mirror", action="store_true", help="augment with left/right mirrored windows")
    p.add_argument("--random-yaw", action="store_true", help="augment with a random rotation about Y")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--min-past", type=int, default=10,
                   help="train over past-key counts P from this to 10 (default 10: the benchmark's layout only)")
    p.add_argument("--uniform-past", action="store_true",
                   help="with --min-past < 10: every past-key count equally often (instead of --longest-past-share)")
    p.add_argument("--longest-past-share", type=float, default=0.4,
                   help="with --min-past < 10: share of batches with P = 10; half the rest has P = min-past, "
                        "the rest spread between (default 0.4)")
    p.add_argument("--min-gap", type=int, default=5,
                   help="shortest gap n (missing frames) trained on; n is drawn with p(n) ∝ 1/n (default 5, the paper)")
    p.add_argument("--max-gap", type=int, default=39,
                   help="longest gap trained on (default 39, the paper); raise it for keys further apart, e.g. "
                        "119 for a key every 4 s at 30 fps (longer layouts come from windows of their own length)")
    p.add_argument("--chained-share", type=float, default=0.0,
                   help="share of batches whose past frames are the network's own output for the gap before (as a "
                        "bake feeds them; default 0)")
    p.add_argument("--init-from", default="",
                   help="start a new run from these weights (an exported .onnx or a checkpoint.pt) instead of random")
    p.add_argument("--average-from", type=int, default=0,
                   help="from this step on, the run's weights (checkpoint, validation, export) are the mean of every "
                        "later step's (stochastic weight averaging; default 0: off)")
    p.add_argument("--threads", type=int, default=1,
                   help="torch intra-op threads (default 1: measured fastest on a 2-core CPU, see model card; at most "
                        "the processors of this machine)")
    p.add_argument("--checkpoint-every", type=int, default=250)
    p.add_argument("--validate-every", type=int, default=500)
    p.add_argument("--max-minutes", type=float, default=0.0,
                   help="stop cleanly (with a checkpoint) after this many minutes; rerun to resume")


def _lengths(text: str) -> List[int]:
    try:
        values = [int(v) for v in text.split(",") if v.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"--lengths wants comma-separated integers, got {text!r}")
    if not values or any(v < 1 for v in values):
        raise argparse.ArgumentTypeError(f"--lengths wants positive integers, got {text!r}")
    return values


def _evaluate_export_fixtures(sub) -> None:
    p = sub.add_parser(
        "evaluate", help="the official LaFAN1 benchmark: zero-velocity, SLERP and (optionally) a model",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Runs the official LaFAN1 in-betweening benchmark (Harvey et al. 2020) on the subject-5 "
                    "BVH files in --data:\nwindows of --window frames every --offset frames, XZ-centred and "
                    "turned to face +X at frame 9,\n10 past frames, a transition of n frames, the target at "
                    "frame 10+n; L2Q, L2P (normalised\nwith --stats) and NPSS over the missing frames.\n\n"
                    "Without --checkpoint it scores the two baselines; with it, a 'model' row as well.\n"
                    "Example:\n  PYTHONPATH=Training/Python~ python3 -m deltainterp evaluate "
                    "--checkpoint Training/runs/runtime/checkpoint.pt --json out/benchmark.json")
    p.add_argument("--data", default=DEFAULT_DATA, help=f"folder of LaFAN1 .bvh files (default {DEFAULT_DATA})")
    p.add_argument("--stats", default=DEFAULT_STATS,
                   help="official statistics JSON (x_mean, x_std, offsets); default " + DEFAULT_STATS)
    p.add_argument("--window", type=int, default=65, help="window length in frames (official: 65)")
    p.add_argument("--offset", type=int, default=40, help="frames between window starts (official: 40)")
    p.add_argument("--lengths", type=_lengths, default=[5, 15, 30, 45],
                   help="transition lengths n, comma-separated (default 5,15,30,45)")
    p.add_argument("--checkpoint", help="a checkpoint.pt from `train` (or tiny-model.pt), or an exported whole "
                                        "graph .onnx, to score as 'model'")
    p.add_argument("--past-frames", type=int, default=10,
                   help="the model sees only the last P of the 10 past frames (same windows and target frame; "
                        "SLERP and zero-velocity are unchanged). Default 10, the official layout")
    p.add_argument("--past-policy", choices=["feed", "repeat"], default="feed",
                   help="with --past-frames < 10: feed the P frames as they are (key indices 0..P-1), or repeat "
                        "the earliest to fill 10 (for models trained with 10 past frames only)")
    p.add_argument("--batch-size", type=int, default=64, help="windows per network call (default 64)")
    p.add_argument("--threads", type=int, default=1,
                   help="torch intra-op threads (default 1; at most the processors of this machine)")
    p.add_argument("--json", required=True, help="where to write the results JSON")
    p.add_argument("--plot", help="also draw the table as bar charts into this PNG")
    p.add_argument("--force", action="store_true", help="replace existing --json/--plot files")

    p = sub.add_parser(
        "export", help="export a checkpoint to ONNX: whole graph + lazy keys/frame graphs",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Writes OUT (the whole transition) and, beside it, .keys.onnx and .frame.onnx graphs "
                    "(lazy decoding;\nout/m.onnx → out/m.keys.onnx, out/m.frame.onnx), opset 15, a batch axis, dynamic frame axes, with the contract's constant outputs and "
                    "metadata\n(Documentation~/model-contract.md). Fails when a graph holds an operator that "
                    "Sentis 2.x or\nBarracuda cannot import (deltainterp/operators.py), or when the numpy "
                    "evaluation of a written\ngraph differs from torch by more than 1e-5.\n"
                    "Example:\n  PYTHONPATH=Training/Python~ python3 -m deltainterp export "
                    "--checkpoint Training/runs/runtime/checkpoint.pt --out out/runtime.onnx\n"
                    "Re-export a shipped model in the current contract (weights read back from its whole graph):\n"
                    "  PYTHONPATH=Training/Python~ python3 -m deltainterp export --checkpoint "
                    "Samples~/LaFAN1Model/DeltaInterpolator-LaFAN1.onnx --out /tmp/m.onnx --name DeltaInterpolator-LaFAN1")
    p.add_argument("--checkpoint", required=True,
                   help="checkpoint.pt from `train`, or an exported whole graph (.onnx, any contract version)")
    p.add_argument("--out", required=True, help="output path ending in .onnx")
    p.add_argument("--name", help="model name in the metadata (default: an exported model's own name, else "
                                    "DeltaInterpolator-RUN after the checkpoint's run folder Training/runs/RUN)")
    p.add_argument("--force", action="store_true", help="replace existing OUT, .keys.onnx and .frame.onnx files")

    p = sub.add_parser(
        "chained", help="validation of chained bakes: the pack's validation tails filled gap after gap",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Bakes the validation tails of a prepared pack (the last 10 %% of every file that is not a "
                    "time-scaled copy)\nas `inbetween bake` does: keys every K frames, each gap's past frames the "
                    "previous gap's output,\nand prints the mean joint position error and L2Q over the non-key "
                    "frames, model and SLERP.\nWhat `train`'s one-gap validation cannot see; choose long-gap "
                    "models by it, never by held-out subjects.\n"
                    "Example:\n  PYTHONPATH=Training/Python~ python3 -m deltainterp chained --data "
                    "Training/.data/cmu-train.npz --checkpoint Training/runs/cmu/checkpoint.pt --every 15 30 60")
    p.add_argument("--data", required=True, help="the prepared pack (.npz) the model was trained on")
    p.add_argument("--checkpoint", required=True, action="append",
                   help="checkpoint.pt or exported .onnx (repeat to compare models side by side)")
    p.add_argument("--every", type=int, nargs="+", default=[15, 30, 60], help="key spacings in model frames (default 15 30 60)")

    p = sub.add_parser(
        "fixtures", help="write the tiny test model and golden vectors for the C# tests",
        description="Writes tiny-model.pt, tiny-model.onnx (+ .keys.onnx, .frame.onnx) and golden.json "
                    "into --out. Deterministic: the same bytes on every run. Regenerating replaces them by "
                    "design (no --force; each through a temporary file + rename).")
    p.add_argument("--out", default="Tests/Fixtures~", help="output folder (default Tests/Fixtures~)")
    p.add_argument("--data", default=DEFAULT_DATA,
                   help="LaFAN1 folder for the skeleton (optional: a built-in copy is used without it)")


def _contacts(sub) -> None:
    p = sub.add_parser(
        "train-contacts", help="a foot-contact head (contract version 3's foot_contacts) on a model's frozen trunk",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Starts from a model (--init-from: an exported .onnx or a checkpoint), adds a contact head on the "
                    "query tokens\nafter the last block and trains only it (the trunk is frozen: the motion outputs "
                    "stay what they were),\nwith the skating measure's contact rule on the ground truth as labels. "
                    "Resumes from OUT/checkpoint.pt.\nAt the end it chooses the threshold on the validation tails "
                    "(chained bakes, keys every --every frames)\nand stores it in the checkpoint; `export` writes "
                    "it into the model's metadata.\n"
                    "Example:\n  PYTHONPATH=Training/Python~ python3 -m deltainterp train-contacts --data "
                    "Training/.data/cmu-train.npz \\\n      --init-from Runtime/Models/DeltaInterpolator-CMU.onnx "
                    "--out Training/runs/cmu-contacts --steps 6000")
    p.add_argument("--data", required=True, help="the prepared pack (.npz) the model was trained on")
    p.add_argument("--init-from", required=True, help="the model whose trunk is kept (.onnx or checkpoint.pt)")
    p.add_argument("--out", required=True, help="run folder (checkpoint.pt, contacts-log.csv, validation.jsonl)")
    p.add_argument("--head", default="mlp", help="contact head: linear or mlp (default mlp)")
    p.add_argument("--hidden", type=int, default=128, help="the mlp head's hidden units (default 128)")
    p.add_argument("--steps", type=int, default=6000, help="training steps (default 6000)")
    p.add_argument("--batch-size", type=int, default=64, help="transitions per step (default 64)")
    p.add_argument("--lr", type=float, default=1e-3, help="Adam learning rate (default 1e-3)")
    p.add_argument("--chained-share", type=float, default=0.5,
                   help="share of batches whose past frames are the network's own fill (default 0.5)")
    p.add_argument("--no-mirror", action="store_true", help="no left-right mirrored batches")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--checkpoint-every", type=int, default=250)
    p.add_argument("--validate-every", type=int, default=0,
                   help="also choose and log the threshold on validation every N steps (0: only at the end)")
    p.add_argument("--decay-at", type=float, default=0.8, help="the learning rate drops x0.1 after this share of the steps")
    p.add_argument("--max-minutes", type=float, default=0.0, help="stop with a checkpoint after M minutes (0: no limit)")
    p.add_argument("--every", type=int, nargs="+", default=[15, 30],
                   help="key spacings (model frames) the threshold is chosen for (default 15 30)")
    p.add_argument("--threads", type=int, default=1, help="torch intra-op threads (default 1)")

    p = sub.add_parser(
        "contacts", help="precision and recall of a model's predicted foot contacts in bakes",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Bakes clips of a prepared pack gap after gap (keys every --every model frames, each gap's past "
                    "frames the\nprevious output, as `inbetween bake`) and counts, over every non-key frame and each "
                    "foot joint\n(LeftFoot, LeftToe, RightFoot, RightToe), the precision and recall of planted frames "
                    "(p ≥ the model's\nthreshold, or --threshold) against the truth's labels (the skating measure's "
                    "contact rule).\n--split validation: the last 10 % of each file that is not a time-scaled copy "
                    "(the training pack's\nvalidation tails); --split all: every file whole (a pack of held-out "
                    "subjects).\n"
                    "Example:\n  PYTHONPATH=Training/Python~ python3 -m deltainterp contacts --data "
                    "Training/.data/cmu-heldout.npz --split all \\\n      --model Runtime/Models/DeltaInterpolator-CMU.onnx "
                    "--every 15 30")
    p.add_argument("--data", required=True, help="a prepared pack (.npz) on the model's skeleton")
    p.add_argument("--model", required=True, help="an exported whole graph (.onnx) or checkpoint.pt with a contact head")
    p.add_argument("--split", choices=["validation", "all"], default="validation")
    p.add_argument("--every", type=int, nargs="+", default=[15, 30], help="key spacings in model frames (default 15 30)")
    p.add_argument("--threshold", type=float, help="planted where p ≥ this (default: the model's own)")
    p.add_argument("--json", help="also write the counts and scores here")
    p.add_argument("--force", action="store_true", help="replace an existing --json file")
    p.add_argument("--same-motion-as", metavar="OTHER.onnx",
                   help="first print the largest difference between --model's motion outputs (whole, keys and frame "
                        "graphs) and OTHER's on the same inputs: a contact head on a frozen trunk gives ~0")


def _run_contacts(args) -> int:
    import torch
    from . import contacts as K
    torch.set_num_threads(max(1, args.threads) if hasattr(args, "threads") else 1)
    if args.verb == "train-contacts":
        if args.threads < 1:
            raise ValueError(f"--threads {args.threads}; expected ≥ 1")
        cfg = K.ContactTrainConfig(data=args.data, out=args.out, init_from=args.init_from, head=args.head,
                                   hidden=args.hidden, steps=args.steps, batch_size=args.batch_size, lr=args.lr,
                                   chained_share=args.chained_share, mirror=not args.no_mirror, seed=args.seed,
                                   checkpoint_every=args.checkpoint_every, max_minutes=args.max_minutes,
                                   validate_every=args.validate_every, decay_at=args.decay_at,
                                   every=tuple(args.every))
        print(f"checkpoint: {K.train_contact_head(cfg)}")
        return 0
    from .checkpoint import load_checkpoint
    from .data import load_pack
    from .warm_start import load_exported_model
    if any(not 2 <= k <= 200 for k in args.every):
        raise ValueError(f"--every {args.every}; expected key spacings of 2..200 model frames")
    if args.threshold is not None and not (math.isfinite(args.threshold) and 0 < args.threshold < 1):
        raise ValueError(f"--threshold {args.threshold}; expected a number between 0 and 1")
    if args.json:
        safe_output.check(args.json, args.force, [args.data, args.model])
    loaded = load_exported_model(args.model) if args.model.endswith(".onnx") else load_checkpoint(args.model)
    if not loaded.model.has_contacts:
        raise ValueError(f"{args.model}: has no foot_contacts output; expected a model with a contact head "
                         "(`train-contacts`, contract version 3)")
    if args.same_motion_as:
        if not (args.model.endswith(".onnx") and args.same_motion_as.endswith(".onnx")):
            raise ValueError(f"--same-motion-as {args.same_motion_as}: compares two exported models; expected --model "
                             "and OTHER to be .onnx files")
        for what, d in K.motion_difference(args.model, args.same_motion_as).items():
            print(f"  {what}: max |{args.model} - {args.same_motion_as}| = {d:.3g}")
    pack = load_pack(args.data)
    if list(pack.skeleton.names) != list(loaded.skeleton.names):
        raise ValueError(f"{args.data}: its skeleton is not the model's; expected a pack prepared for {args.model}")
    threshold = loaded.contact_threshold if args.threshold is None else args.threshold
    thresholds = tuple(sorted(set(K.THRESHOLDS) | {threshold}))
    from_motion: dict = {}
    counts = K.contact_scores(loaded, pack, args.every, args.split, thresholds, from_motion)
    print(f"{args.model} on {args.data} ({args.split}), planted where p >= {threshold}:")
    for line in K.format_scores(counts, threshold, thresholds):
        print("  " + line)
    print("the same rule applied to the baked motion itself (contacts labelled from the filled frames), for comparison:")
    for line in K.format_scores(from_motion, threshold, thresholds):
        print("  " + line)
    if args.json:
        i = thresholds.index(threshold)
        report = {"model": args.model, "data": args.data, "split": args.split, "threshold": threshold,
                  "every": {str(k): {"frames": c.frames, **{j: {"precision": float(c.precision()[i, n]),
                                                                 "recall": float(c.recall()[i, n]),
                                                                 "planted": int(c.actual[n])}
                                                              for n, j in enumerate(K.C.CONTACT_JOINTS)}}
                            for k, c in counts.items()},
                  "rule_on_baked_motion": {str(k): {j: {"precision": float(c.precision()[i, n]),
                                                        "recall": float(c.recall()[i, n])}
                                                    for n, j in enumerate(K.C.CONTACT_JOINTS)}
                                           for k, c in from_motion.items()}}
        safe_output.write_text(args.json, json.dumps(report, indent=2) + "\n")
        print(f"wrote {args.json}")
    return 0


def _quantize(sub) -> None:
    from .quantize import DEFAULT_MIN_WEIGHTS, FORMS
    p = sub.add_parser(
        "quantize", help="dynamic int8 copy of an exported model, for ONNX Runtime only (not Sentis)",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        description="Rewrites every MatMul with a constant weight of the whole graph MODEL and, beside it, its "
                    ".keys.onnx and .frame.onnx\ninto dynamically quantized products (activations uint8 per "
                    "tensor at run time, weights int8 per\noutput column) and writes them to OUT, OUT's "
                    ".keys.onnx and .frame.onnx with the same inputs, outputs and\nmetadata (plus a "
                    "'quantization' entry). ONNX Runtime only: Unity Sentis cannot import these operators.\n"
                    "Prints each graph's largest output difference to float (relative to the output's largest "
                    "value,\nnumpy reference evaluator). Measure with `inbetween benchmark` and `inbetween speed` "
                    "before using\nit (Documentation~/int8.md).\n"
                    "Example:\n  PYTHONPATH=Training/Python~ python3 -m deltainterp quantize "
                    "--model Runtime/Models/DeltaInterpolator-CMU.onnx --out out/DeltaInterpolator-CMU.int8.onnx")
    p.add_argument("--model", required=True, help="the float whole graph NAME.onnx (its lazy graphs are found beside it)")
    p.add_argument("--out", required=True, help="output path ending in .onnx (e.g. NAME.int8.onnx)")
    p.add_argument("--form", choices=FORMS, default="fused",
                   help="fused: com.microsoft DynamicQuantizeMatMul nodes; integer: standard DynamicQuantizeLinear "
                        "→ MatMulInteger → Cast → Mul (default fused)")
    p.add_argument("--min-weights", type=int, default=DEFAULT_MIN_WEIGHTS,
                   help=f"quantize only weights of at least this many elements (default {DEFAULT_MIN_WEIGHTS})")
    p.add_argument("--force", action="store_true", help="replace existing output files")


def _run_quantize(args) -> int:
    from .quantize import quantize_model
    report = quantize_model(args.model, args.out, args.form, args.min_weights, args.force)
    for kind, path in report.paths.items():
        g = report.graphs[kind]
        before, after = report.sizes[kind]
        print(f"  {kind:<5} {shown(path)}  {_size(before)} → {_size(after)}  {len(g.quantized)} MatMuls int8, "
              f"{len(g.kept)} float; max |int8 − float| / max |float| = {report.relative_difference[kind]:.2%}")
    return 0


def _named_inputs(args) -> List[str]:
    """What `prepare` reads that the command line names: --stats, --map, --model, every --data manifest and
    each --data folder's own manifest (read even when absent now: a path it may be created at is still
    refused). The BVH files and manifest maps are added once the sources are opened."""
    from .datasets import MANIFEST_NAME
    named = [args.stats, args.map, args.model]
    for d in args.data:
        named.append(str(Path(d) / MANIFEST_NAME) if Path(d).is_dir() else d)
    return [str(x) for x in named if x]


def processors() -> int:
    """The processors this process may run on (its affinity), as `speed`/`benchmark` cap --threads."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def _refuse_option(name: str, value, expected: str) -> None:
    raise ValueError(f"{name} {value}; expected {expected}")


def _check_whole(name: str, value: Optional[int], low: int, high: int, what: str) -> None:
    if value is not None and not low <= value <= high:
        _refuse_option(name, value, f"{what} from {low} to {high}")


def _check_real(name: str, value: Optional[float], low: float, high: float, what: str, open_low: bool = False) -> None:
    if value is None:
        return
    if not (math.isfinite(value) and (value > low if open_low else value >= low) and value <= high):
        _refuse_option(name, value, f"{what} {'above' if open_low else 'from'} {low:g}" +
                       (f" to {high:g}" if math.isfinite(high) else ""))


def check_threads(value: int) -> None:
    """--threads from 1 to the processors: more only compete for the same cores (500 took 19 s to start, 2^31
    ended in std::bad_alloc blamed on the model)."""
    if value is not None and not 1 <= value <= processors():
        _refuse_option("--threads", value, f"1 to {processors()} threads (the processors of this machine; more only "
                                           "compete for the same cores)")


def check_train_options(args) -> None:
    """Every `train` number refused in one line (`--OPTION VALUE; expected ...`) before anything is read; a zero
    batch, block or head count, or a checkpoint every 0 steps, ended in tracebacks of 12 to 42 lines."""
    check_threads(args.threads)
    _check_whole("--batch-size", args.batch_size, 1, 1 << 16, "windows per step")
    _check_whole("--steps", args.steps, 1, 1 << 40, "optimizer steps")
    _check_whole("--checkpoint-every", args.checkpoint_every, 1, 1 << 40, "steps between checkpoints")
    _check_whole("--validate-every", args.validate_every, 1, 1 << 40, "steps between validations")
    _check_whole("--warmup", args.warmup, 0, 1 << 40, "warm-up steps")
    _check_whole("--average-from", args.average_from, 0, 1 << 40, "a step (0: no averaging)")
    _check_whole("--seed", args.seed, 0, (1 << 32) - 1, "a seed")
    _check_whole("--width", args.width, 2, 1 << 14, "a network width")
    _check_whole("--blocks", args.blocks, 1, 64, "a number of blocks")
    _check_whole("--heads", args.heads, 1, 1 << 10, "a number of attention heads")
    _check_whole("--min-past", args.min_past, 1, 10, "past keys")
    _check_whole("--min-gap", args.min_gap, 1, 1 << 16, "missing frames")
    _check_whole("--max-gap", args.max_gap, args.min_gap if args.min_gap >= 1 else 1, 1 << 16,
                 "missing frames (at least --min-gap)")
    _check_real("--lr", args.lr, 0.0, 1.0, "a learning rate", open_low=True)
    _check_real("--decay-at", args.decay_at, 0.0, math.inf, "a fraction of --steps", open_low=True)
    _check_real("--dropout", args.dropout, 0.0, 0.99, "a dropout probability")
    _check_real("--reconstruction-scale", args.reconstruction_scale, 0.0, math.inf, "a weight")
    _check_real("--foot-contact-weight", args.foot_contact_weight, 0.0, math.inf, "a weight (0: off)")
    _check_real("--longest-past-share", args.longest_past_share, 0.0, 1.0, "a share", open_low=True)
    _check_real("--chained-share", args.chained_share, 0.0, 1.0, "a share")
    _check_real("--max-minutes", args.max_minutes, 0.0, math.inf, "minutes (0: no limit)")
    if args.width is not None or args.heads is not None:
        from .model import preset
        sizes = {**preset(args.preset, joints=1).to_dict(), **{k: getattr(args, k) for k in ("width", "heads")
                                                                 if getattr(args, k) is not None}}
        if sizes["width"] % sizes["heads"]:
            _refuse_option("--width", sizes["width"], f"a multiple of the {sizes['heads']} heads")


def check_evaluate_options(args) -> None:
    """`evaluate`'s numbers, as `train`'s."""
    check_threads(args.threads)
    _check_whole("--batch-size", args.batch_size, 1, 1 << 16, "windows per network call")
    _check_whole("--window", args.window, 2, 1 << 20, "frames")
    _check_whole("--offset", args.offset, 1, 1 << 20, "frames between windows")


def _bvh_files(folder) -> List[str]:
    """The *.bvh files of a --data folder (none for anything else): inputs no output may replace."""
    return [str(p) for p in Path(folder).glob("*.bvh")] if folder and Path(folder).is_dir() else []


def _refuse_non_finite(report: dict, data) -> None:
    """A NaN or infinity in the results is an error (exit 2), never a number in a table or a file."""
    for method, metrics in report.get("results", {}).items():
        for metric, values in metrics.items():
            for n, value in values.items():
                if not math.isfinite(value):
                    raise ValueError(f"{data}: the benchmark gave {metric.upper()} = {value} for {method} at n={n}; "
                                     "expected finite results (a file with huge or broken motion values?)")


def _size(n: int) -> str:
    return f"{n / 1024:.1f} KiB" if n < 1 << 20 else f"{n / (1 << 20):.2f} MiB"


def _run_evaluate_export_fixtures(args) -> int:
    import torch
    if args.verb == "evaluate":
        from .benchmark import format_table, run_benchmark
        from .checkpoint import load_checkpoint
        check_evaluate_options(args)
        torch.set_num_threads(args.threads)
        inputs = [args.checkpoint, args.stats, *_bvh_files(args.data)]  # an output never replaces a --data BVH
        safe_output.check(args.json, args.force, inputs)  # before the benchmark runs, not after
        if args.plot:
            safe_output.check(args.plot, args.force, inputs + [args.json])
        if args.checkpoint and args.checkpoint.endswith(".onnx"):
            from .warm_start import load_exported_model
            loaded = load_exported_model(args.checkpoint)
        else:
            loaded = load_checkpoint(args.checkpoint) if args.checkpoint else None
        report = run_benchmark(args.data, args.stats, args.window, args.offset, args.lengths, loaded,
                               args.batch_size, past_frames=args.past_frames, past_policy=args.past_policy)
        if loaded is not None:
            report["checkpoint"] = {"path": args.checkpoint, "step": loaded.step,
                                    "parameters": loaded.model.parameter_count(), **loaded.config.to_dict()}
        _refuse_non_finite(report, args.data)
        safe_output.write_text(args.json, json.dumps(report, indent=2, allow_nan=False) + "\n")
        print(format_table(report))
        print(f"\nwrote {shown(args.json)}")
        if args.plot:
            print(f"wrote {shown(plot_benchmark(report, args.plot))}")
        return 0
    if args.verb == "export":
        from .checkpoint import load_checkpoint
        from .export import export_model, graph_paths
        torch.set_num_threads(1)
        for path in graph_paths(args.out).values():
            safe_output.check(path, args.force, [args.checkpoint])
        if args.checkpoint.endswith(".onnx"):
            from .warm_start import load_exported_model
            loaded = load_exported_model(args.checkpoint)
        else:
            loaded = load_checkpoint(args.checkpoint)
        name = _export_name(args.name, args.checkpoint, loaded.name)
        report = export_model(loaded, args.out, name)
        print(f"{shown(name)} (trained on: {shown(loaded.data_description or 'not recorded')}): {report.parameters:,} parameters, opset 15, checked against torch "
              f"(max |diff| {report.max_difference:.2g})")
        for kind, path in report.paths.items():
            print(f"  {kind:<5} {shown(path)}  {_size(report.sizes[kind])}  ops: {', '.join(report.operators[kind])}")
        return 0
    if args.verb == "chained":
        from .chained import chained_metrics
        from .checkpoint import load_checkpoint
        from .data import load_pack
        from .warm_start import load_exported_model
        torch.set_num_threads(1)
        pack = load_pack(args.data)
        for path in args.checkpoint:
            loaded = load_exported_model(path) if path.endswith(".onnx") else load_checkpoint(path)
            skeleton = loaded.skeleton_tensors(torch.float32)
            for k in args.every:
                if k < 2:
                    raise ValueError(f"--every {k}: expected at least 2 frames between keys")
                r = chained_metrics(loaded.model, pack, skeleton, k)
                if r.get("tails", 0) == 0:
                    print(f"{shown(path)}  every {k}: no validation tail of {k + 1} frames or more")
                    continue
                print(f"{shown(path)}  every {k}: {r['tails']} tails, {r['gaps']} gaps, {r['frames']} frames  "
                      f"position {r['model_position']:.4f} vs SLERP {r['slerp_position']:.4f} (x{r['position_vs_slerp']:.3f})  "
                      f"L2Q {r['model_l2q']:.4f} vs {r['slerp_l2q']:.4f} (x{r['l2q_vs_slerp']:.3f})")
        return 0
    if args.verb == "fixtures":
        from .fixtures import write_fixtures
        torch.set_num_threads(1)
        data = args.data if args.data and Path(args.data).exists() else None
        paths = write_fixtures(args.out, data)
        for what, path in paths.items():
            print(f"  {what:<10} {shown(path)}  {_size(Path(path).stat().st_size)}")
        print("skeleton from " + (shown(data) if data else "the built-in LaFAN1 copy"))
        return 0
    raise ValueError(f"unknown verb {args.verb}")


class UsageError(ValueError):
    """A command line argparse cannot read (an unknown option, a flag given a value, a bad choice): refused in
    the one-line form like every other bad input, not argparse's wrapped usage block and a second line."""


class OneLineArgumentParser(argparse.ArgumentParser):
    """argparse with its refusals in the refusal contract's form (Documentation~/refusal-contract.md):
    `error: PROG: what; expected …` on one line, exit 2 (main prints it); --help is unchanged."""

    def error(self, message: str):  # argparse calls this for every unreadable command line
        raise UsageError(f"{self.prog}: {message.replace(';', ',')}; expected what '{self.prog} --help' lists")


def build_parser() -> argparse.ArgumentParser:
    parser = OneLineArgumentParser(prog="python3 -m deltainterp",
                                     description="Train, evaluate and export the Δ-Interpolator. A full recipe: "
                                                 "prepare → train → evaluate → export (see README).")
    sub = parser.add_subparsers(dest="verb", required=True, metavar="VERB")
    _prepare(sub)
    _train(sub)
    _evaluate_export_fixtures(sub)
    _quantize(sub)
    _contacts(sub)
    return parser


def main(argv: Optional[List[str]] = None) -> int:
    """Runs one verb with stdout and stderr escaping terminal control characters (a file name with ESC in it
    cannot rewrite the terminal through any module's message); refusals are one line, exit 2."""
    streams = sys.stdout, sys.stderr
    sys.stdout, sys.stderr = SafeStream(sys.stdout), SafeStream(sys.stderr)
    try:
        return _main(argv)
    finally:
        sys.stdout, sys.stderr = streams


def _close_progress_bars() -> None:
    """Ends any progress bar a failing verb left open (e.g. train's, when a checkpoint cannot be written), so the
    error starts a line of its own instead of trailing the bar."""
    tqdm = sys.modules.get("tqdm")
    for bar in list(getattr(getattr(tqdm, "tqdm", None), "_instances", None) or []):
        try:
            bar.close()
        except Exception:  # noqa: BLE001 - a bar that cannot close must not hide the error
            pass


def _main(argv: Optional[List[str]]) -> int:
    try:
        args = build_parser().parse_args(argv)
        if args.verb == "prepare":
            return _run_prepare(args)
        if args.verb == "train":
            check_train_options(args)
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
                              max_minutes=args.max_minutes, threads=args.threads, min_past=args.min_past,
                              longest_past_share=args.longest_past_share, uniform_past=args.uniform_past,
                              init_from=args.init_from, min_gap=args.min_gap, max_gap=args.max_gap,
                              chained_share=args.chained_share, average_from=args.average_from,
                              foot_contact_weight=args.foot_contact_weight)
            path = train(cfg)
            print(f"checkpoint: {shown(path)}")
            return 0
        if args.verb == "quantize":
            return _run_quantize(args)
        if args.verb in ("train-contacts", "contacts"):
            return _run_contacts(args)
        return _run_evaluate_export_fixtures(args)
    except ValueError as e:  # CheckpointError, OutputPathError, bad data: `FILE: what; expected`
        _close_progress_bars()
        print(f"error: {safe(e, LINE_LENGTH)}", file=sys.stderr)  # one line, whatever the names in it hold
        return 2
    except OSError as e:  # unreadable or unwritable files the checks above could not foresee
        _close_progress_bars()
        if e.filename is None:
            print(f"error: {safe(e, LINE_LENGTH)}", file=sys.stderr)
        else:
            full = e.errno in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG)
            print(f"error: {safe(e.filename, LINE_LENGTH)}: {e.strerror or type(e).__name__}; expected "
                  + ("room for it on its disk" if full else "a readable file or a writable place"), file=sys.stderr)
        return 2
