"""The PNG plots users look at instead of reading tables."""
from __future__ import annotations

import json

from deltainterp.plots import plot_benchmark, plot_training


def _report() -> dict:
    row = lambda s: {m: {str(n): s * n / 100 for n in (5, 15, 30, 45)} for m in ("l2q", "l2p", "npss")}  # noqa: E731
    return {"windows": 3, "window": 65, "offset": 40,
            "results": {"zerovel": row(3.0), "slerp": row(1.0), "model": row(0.5)}}


def test_benchmark_plot_is_a_png(tmp_path):
    out = plot_benchmark(_report(), tmp_path / "sub" / "bench.png")
    data = out.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(data) > 10_000  # three panels with bars, not an empty canvas


def test_training_plot_reads_log_and_validation(tmp_path):
    (tmp_path / "log.csv").write_text("step,lr,total,quat,pos,key_quat,key_pos,seconds\n"
                                      "50,1e-4,2.0,0.1,0.1,0.1,0.1,5\n100,2e-4,1.5,0.08,0.07,0.09,0.08,10\n")
    rows = [{"step": s, **{f"{m}_l2q_{n}": 1.0 / s for m in ("model", "slerp") for n in (5, 15, 30)}}
            for s in (50, 100)]
    (tmp_path / "validation.jsonl").write_text("".join(json.dumps(r) + "\n" for r in rows))
    out = plot_training(tmp_path)
    assert out.read_bytes()[:4] == b"\x89PNG"
