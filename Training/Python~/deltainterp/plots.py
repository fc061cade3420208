"""PNG plots of a training run's CSV log and validation curves."""
from __future__ import annotations

import csv
import json
from pathlib import Path

from . import safe_output


def plot_training(run_dir: str | Path) -> Path:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    run = Path(run_dir)
    with open(run / "log.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    steps = [int(r["step"]) for r in rows]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for key in ("total", "quat", "pos", "key_quat", "key_pos"):
        if rows and key in rows[0]:
            axes[0].plot(steps, [float(r[key]) for r in rows], label=key)
    axes[0].set_yscale("log")
    axes[0].set_xlabel("step")
    axes[0].set_title("training loss (L1 terms; total includes the ×10 scales)")
    axes[0].legend()
    val_path = run / "validation.jsonl"
    if val_path.exists():
        with open(val_path) as f:
            vals = [json.loads(line) for line in f if line.strip()]
        vs = [v["step"] for v in vals]
        for n, color in zip((5, 15, 30), ("tab:blue", "tab:orange", "tab:green")):
            axes[1].plot(vs, [v[f"model_l2q_{n}"] for v in vals], color=color, label=f"model L2Q n={n}")
            if f"slerp_l2q_{n}" in vals[0]:
                axes[1].axhline(vals[0][f"slerp_l2q_{n}"], color=color, ls="--", lw=1, label=f"SLERP n={n}")
        axes[1].set_xlabel("step")
        axes[1].set_title("validation L2Q (held-out tails of training files)")
        axes[1].legend(fontsize=8)
    fig.tight_layout()
    out = run / "curves.png"  # the run's own file: replaced on every call, through a temporary file
    try:
        safe_output.write(out, lambda f: fig.savefig(f, format="png", dpi=110))
    finally:
        plt.close(fig)
    return out


def plot_benchmark(report: dict, out: str | Path) -> Path:
    """Bars of L2Q, L2P and NPSS per transition length, one colour per method, from an `evaluate` (or
    C# `benchmark --json`) report — the table at a glance."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    results = report["results"]
    methods = list(results)
    lengths = list(next(iter(results.values()))["l2q"])
    titles = {"l2q": "L2Q (global quaternions)", "l2p": "L2P (global positions, standardised)",
              "npss": "NPSS (power spectrum)"}
    labels = {"zerovel": "zero-velocity", "slerp": "SLERP", "model": "Δ-Interpolator (ours)"}
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    width = 0.8 / len(methods)
    for ax, metric in zip(axes, ("l2q", "l2p", "npss")):
        for i, method in enumerate(methods):
            values = [results[method][metric][n] for n in lengths]
            xs = [j + (i - (len(methods) - 1) / 2) * width for j in range(len(lengths))]
            ax.bar(xs, values, width, label=labels.get(method, method))
        ax.set_xticks(range(len(lengths)))
        ax.set_xticklabels([f"n={n}" for n in lengths])
        ax.set_title(titles[metric])
    axes[0].legend(fontsize=8)
    fig.suptitle(f"LaFAN1 benchmark, {report.get('windows', '?')} windows of {report.get('window', '?')} "
                 f"frames every {report.get('offset', '?')} (lower is better)")
    fig.tight_layout()
    out = Path(out)  # the caller checked it (safe_output.check) before the benchmark ran
    try:
        safe_output.write(out, lambda f: fig.savefig(f, format="png", dpi=110))
    finally:
        plt.close(fig)
    return out
