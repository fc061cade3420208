"""Issue 29: bakes the CMU training pack's spans with a contact-head checkpoint (chained, keys every 15 and 30),
fits `contact_features.ContactClassifier` on the training parts, chooses the threshold on the validation tails and
prints precision / recall beside the head's and the label rule applied to the filled motion. Held-out: only with
--heldout PACK, once, after the choice (the classifier and threshold are then fixed in --out).

  OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=2 nice -n 19 python3 Training/Python~/tools/contact_features_run.py \
      --model Training/runs/block-head.pt --data Training/.data/cmu-train.npz --out Training/runs/features
"""
import argparse
import json
import pickle
import sys
import time
from pathlib import Path

import numpy as np
import torch

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from deltainterp import contact_features as F  # noqa: E402
from deltainterp.checkpoint import load_checkpoint  # noqa: E402
from deltainterp.contacts import choose_threshold, format_scores, pack_leg_length  # noqa: E402
from deltainterp.data import load_pack  # noqa: E402


def records(loaded, pack, part, every, path: Path):
    if path.exists():  # resumable: each part's bakes are kept
        return pickle.loads(path.read_bytes())
    r = F.bake_records(loaded, pack, part, every)
    tmp = path.with_suffix(".tmp")
    tmp.write_bytes(pickle.dumps(r))
    tmp.rename(path)
    return r


def heldout(args, loaded, leg, dt, bakes: Path, out: Path) -> int:
    """Scores the classifiers in --out, each at its own validation threshold, on the held-out pack (once)."""
    held = load_pack(args.heldout)
    recs = records(loaded, held, "all", args.every, bakes / "records-heldout.pkl")
    for name in ("classifier", "classifier-head"):
        saved = torch.load(out / f"{name}.pt")
        F.OFFSETS = tuple(saved["offsets"]) if "offsets" in saved else tuple(args.offsets)
        model = F.ContactClassifier(saved["inputs"], saved["hidden"])
        model.load_state_dict(saved["state"])
        counts = F.score(model.eval(), recs, leg, dt, saved["with_head"])
        print(f"held out, {name} (offsets {list(F.OFFSETS)}) at its validation threshold {saved['threshold']}:")
        for line in format_scores(counts, saved["threshold"]):
            print("  " + line)
    for name, counts, th in (("rule on the filled motion", F.rule_counts(recs, leg, dt), 0.5),
                             ("contact head", F.head_counts(recs), 0.3)):
        print(f"held out, {name} (threshold {th}):")
        for line in format_scores(counts, th):
            print("  " + line)
    return 0


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--model", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--every", type=int, nargs="+", default=[15, 30])
    ap.add_argument("--bakes", default=None, help="folder of the cached bakes (default: --out)")
    ap.add_argument("--hidden", type=int, default=64)
    ap.add_argument("--epochs", type=int, default=30)
    ap.add_argument("--offsets", type=int, nargs="+", default=list(F.OFFSETS),
                    help="frames around the scored one whose motion the classifier reads")
    ap.add_argument("--score-only", action="store_true",
                    help="fit nothing: score the classifiers already in --out (with --heldout: the held-out pack only)")
    ap.add_argument("--heldout", default=None, help="held-out pack, scored once with the fixed classifier")
    args = ap.parse_args()
    torch.set_num_threads(1)
    F.OFFSETS = tuple(args.offsets)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    loaded = load_checkpoint(args.model)
    pack = load_pack(args.data)
    leg, dt = pack_leg_length(pack), float(pack.frame_time)
    t = time.time()
    bakes = Path(args.bakes or args.out)
    bakes.mkdir(parents=True, exist_ok=True)
    if args.score_only and args.heldout:
        return heldout(args, loaded, leg, dt, bakes, out)
    train = records(loaded, pack, "train", args.every, bakes / "records-train.pkl")
    val = records(loaded, pack, "validation", args.every, bakes / "records-validation.pkl")
    print(f"bakes ready ({time.time() - t:.0f} s)", flush=True)
    results = {}
    for name, counts in (("rule on the filled motion", F.rule_counts(val, leg, dt)), ("contact head", F.head_counts(val))):
        th, worst = choose_threshold(counts)
        results[name] = (th, worst)
        print(f"{name}: threshold {th}, worst {worst:.3f}")
        for line in format_scores(counts, th):
            print("  " + line)
    for with_head in (False, True):
        x, y = zip(*(F.features(r, leg, dt, with_head) for recs in train.values() for r in recs))
        x, y = np.concatenate(x), np.concatenate(y)
        print(f"fit with_head={with_head}: {len(y)} samples, planted share {y.mean():.3f}", flush=True)
        model = F.fit(x, y, hidden=args.hidden, epochs=args.epochs)
        counts = F.score(model, val, leg, dt, with_head)
        th, worst = choose_threshold(counts)
        name = f"classifier{' + head' if with_head else ''}"
        results[name] = (th, worst)
        print(f"{name}: threshold {th}, worst validation precision/recall {worst:.3f}")
        for line in format_scores(counts, th):
            print("  " + line, flush=True)
        torch.save({"state": model.state_dict(), "inputs": x.shape[1], "offsets": list(F.OFFSETS), "hidden": args.hidden, "threshold": th,
                    "with_head": with_head, "worst": worst}, out / f"classifier{'-head' if with_head else ''}.pt")
    (out / "validation.json").write_text(json.dumps(results, indent=1))
    if args.heldout:
        heldout(args, loaded, leg, dt, bakes, out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
