"""The official LaFAN1 benchmark: metric definitions, baselines against the official code's numbers, an
independent re-derivation in the official code's own structure (FK → rotate → IK) for another window
size, and the model row of an untrained network (= SLERP)."""
from __future__ import annotations

import json

import numpy as np
import pytest
import torch

from deltainterp.benchmark import l2p, l2q, load_statistics, npss, run_benchmark
from deltainterp.bvh import lafan1_files, read_bvh
from deltainterp.checkpoint import LoadedModel
from deltainterp.cli import main
from deltainterp.data import windows
from deltainterp.model import DeltaInterpolator, preset

from conftest import STATS

# The official code on the 376 local test windows with the official statistics (method-spec §1.12).
OFFICIAL = {
    "zerovel": {"l2q": [0.4867, 1.0060, 1.4660, 1.7823], "l2p": [1.1992, 2.9213, 5.1748, 7.2551],
                "npss": [0.00387, 0.03991, 0.19049, 0.43772]},
    "slerp": {"l2q": [0.1797, 0.5236, 0.8657, 1.0919], "l2p": [0.2854, 1.0293, 2.0595, 2.9918],
              "npss": [0.00162, 0.02839, 0.15522, 0.37231]},
}
TOLERANCE = {"l2q": 5e-5, "l2p": 5e-5, "npss": 5e-6}  # half a unit of the last printed digit


def test_l2q_is_the_norm_over_all_joints_at_once():
    g = torch.zeros(1, 2, 3, 4, dtype=torch.float64)
    p = g.clone()
    p[0, 0, :, 0] = 1.0   # frame 0: three joints off by 1 in one component → norm √3
    assert l2q(p, g) == pytest.approx(np.sqrt(3) / 2)


def test_l2p_standardises_each_coordinate():
    class S:
        x_mean = np.zeros(6)
        x_std = np.array([1.0, 2.0, 4.0, 1.0, 1.0, 1.0])
    g = torch.zeros(1, 1, 2, 3, dtype=torch.float64)
    p = g.clone()
    p[0, 0, 0] = torch.tensor([3.0, 8.0, 0.0], dtype=torch.float64)
    assert l2p(p, g, S) == pytest.approx(5.0)


def test_npss_matches_its_definition():
    rng = np.random.default_rng(0)
    gt, pred = rng.normal(size=(3, 8, 5)), rng.normal(size=(3, 8, 5))
    emd, weights = [], []
    for s in range(3):
        for d in range(5):
            pg = np.real(np.fft.fft(gt[s, :, d])) ** 2
            pp = np.real(np.fft.fft(pred[s, :, d])) ** 2
            emd.append(np.abs(np.cumsum(pp / pp.sum()) - np.cumsum(pg / pg.sum())).sum())
            weights.append(pg.sum())
    assert npss(gt, pred) == pytest.approx(np.dot(emd, weights) / np.sum(weights), rel=1e-12)
    assert npss(gt, gt) == 0.0


@pytest.fixture(scope="module")
def official_run(lafan1_dir):
    return run_benchmark(lafan1_dir, STATS, progress=False)


def test_baselines_equal_the_official_code(official_run):
    assert official_run["windows"] == 376
    for method, metrics in OFFICIAL.items():
        for metric, values in metrics.items():
            got = [official_run["results"][method][metric][str(n)] for n in (5, 15, 30, 45)]
            assert got == pytest.approx(values, abs=TOLERANCE[metric]), f"{method} {metric}"


# -- an independent re-derivation in the official code's structure ---------------------------------
def _qmul(x, y):
    x0, x1, x2, x3 = np.moveaxis(x, -1, 0)
    y0, y1, y2, y3 = np.moveaxis(y, -1, 0)
    return np.stack([y0 * x0 - y1 * x1 - y2 * x2 - y3 * x3, y0 * x1 + y1 * x0 - y2 * x3 + y3 * x2,
                     y0 * x2 + y1 * x3 + y2 * x0 - y3 * x1, y0 * x3 - y1 * x2 + y2 * x1 + y3 * x0], -1)


def _qrot(q, v):
    t = 2.0 * np.cross(q[..., 1:], v)
    return v + q[..., :1] * t + np.cross(q[..., 1:], t)


def _inv(q):
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def _fk(lq, lp, parents):
    gq, gp = [lq[..., 0, :]], [lp[..., 0, :]]
    for j in range(1, len(parents)):
        gp.append(_qrot(gq[parents[j]], lp[..., j, :]) + gp[parents[j]])
        gq.append(_qmul(gq[parents[j]], lq[..., j, :]))
    return np.stack(gq, -2), np.stack(gp, -2)


def _slerp(x, y, a):
    d = (x * y).sum(-1)
    y = np.where(d[..., None] < 0, -y, y)
    d = np.abs(d)
    linear = (1.0 - d) < 0.01
    om = np.arccos(np.clip(d, -1, 1))
    so = np.where(linear, 1.0, np.sin(om))
    w0 = np.where(linear, 1.0 - a, np.sin((1.0 - a) * om) / so)
    w1 = np.where(linear, a, np.sin(a * om) / so)
    return w0[..., None] * x + w1[..., None] * y


def _official_structure(data_dir, window, offset, lengths):
    stats = json.loads(STATS.read_text())
    mean, std = np.asarray(stats["x_mean"]), np.asarray(stats["x_std"])
    X, Q = [], []
    for f in lafan1_files(data_dir, (5,)):
        m = read_bvh(f)
        pos = np.repeat(m.skeleton.offsets[None], m.frame_count, 0)  # local positions = the FILE's offsets
        pos[:, 0] = m.root_positions
        for s in windows(m.frame_count, window, offset):
            X.append(pos[s:s + window])
            Q.append(m.local_quaternions[s:s + window])
    X, Q = np.array(X), np.array(Q)
    parents = m.skeleton.parents
    X[:, :, 0, [0, 2]] -= X[:, :, 0, [0, 2]].mean(1, keepdims=True)
    gq, gp = _fk(Q, X, parents)                                    # rotate at frame 9 through FK / IK
    fwd = _qrot(gq[:, 9:10, 0:1], np.array([0.0, 1.0, 0.0])) * np.array([1.0, 0.0, 1.0])
    fwd = fwd / (np.linalg.norm(fwd, axis=-1, keepdims=True) + 1e-8)
    x = np.array([1.0, 0.0, 0.0])
    yrot = np.concatenate([np.sqrt((fwd * fwd).sum(-1, keepdims=True)) + (fwd * x).sum(-1, keepdims=True),
                           np.cross(x, fwd)], -1)
    yrot = yrot / (np.linalg.norm(yrot, axis=-1, keepdims=True) + 1e-8)
    gq, gp = _qmul(_inv(yrot), gq), _qrot(_inv(yrot), gp)
    p = np.array(parents[1:])
    Q = np.concatenate([gq[..., :1, :], _qmul(_inv(gq[..., p, :]), gq[..., 1:, :])], -2)
    X = np.concatenate([gp[..., :1, :], _qrot(_inv(gq[..., p, :]), gp[..., 1:, :] - gp[..., p, :])], -2)
    offsets = np.asarray(stats["offsets"])
    out = {}
    for n in lengths:
        def local_poses(roots):
            return np.concatenate([roots[:, :, None], np.broadcast_to(offsets, roots.shape[:2] + (21, 3))], 2)
        gt_q, gt_p = _fk(Q[:, 10:10 + n], local_poses(X[:, 10:10 + n, 0]), parents)
        w = np.linspace(0.0, 1.0, n + 2, dtype=np.float32)[1:-1].astype(np.float64)
        root = X[:, 9:10, 0] + w[None, :, None] * (X[:, 10 + n:11 + n, 0] - X[:, 9:10, 0])
        nq = lambda q: q / (np.linalg.norm(q, axis=-1, keepdims=True) + 1e-8)  # noqa: E731
        rots = np.stack([nq(_slerp(nq(Q[:, 9]), nq(Q[:, 10 + n]), a)) for a in w], 1)
        pq, pp = _fk(rots, local_poses(root), parents)
        l2q_v = np.sqrt(((pq - gt_q) ** 2).sum((2, 3))).mean()
        l2p_v = np.sqrt((((pp - gt_p).reshape(*pp.shape[:2], -1) / std) ** 2).sum(-1)).mean()
        out[n] = (l2q_v, l2p_v, npss(gt_q.reshape(*gt_q.shape[:2], -1), pq.reshape(*pq.shape[:2], -1)))
        _ = mean
    return out


def test_other_window_sizes_agree_with_the_official_structure(lafan1_dir):
    lengths = (5, 15, 30)
    report = run_benchmark(lafan1_dir, STATS, window=50, offset=20, lengths=lengths, progress=False)
    reference = _official_structure(lafan1_dir, 50, 20, lengths)
    assert report["windows"] == len(sum([windows(read_bvh(f).frame_count, 50, 20)
                                         for f in lafan1_files(lafan1_dir, (5,))], []))
    for n in lengths:
        got = [report["results"]["slerp"][m][str(n)] for m in ("l2q", "l2p", "npss")]
        assert got == pytest.approx(list(reference[n]), rel=1e-6), f"n={n}"


def test_untrained_model_row_equals_slerp_and_cli_json(lafan1_dir, skeleton, tmp_path):
    torch.manual_seed(0)
    model = DeltaInterpolator(preset("tiny")).eval()
    ckpt = tmp_path / "untrained.pt"
    torch.save({"model": model.state_dict(), "model_config": model.config.to_dict(),
                "skeleton": skeleton.to_json(), "unit_scale": 0.01}, ckpt)
    out = tmp_path / "bench.json"
    assert main(["evaluate", "--data", str(lafan1_dir), "--stats", str(STATS), "--lengths", "5,30",
                 "--checkpoint", str(ckpt), "--json", str(out)]) == 0
    report = json.loads(out.read_text())
    assert set(report) >= {"windows", "window", "offset", "stats", "results"}
    assert report["window"] == 65 and report["offset"] == 40 and report["windows"] == 376
    for metric in ("l2q", "l2p", "npss"):
        for n in ("5", "30"):
            assert report["results"]["model"][metric][n] == pytest.approx(
                report["results"]["slerp"][metric][n], rel=1e-6, abs=1e-9)


def test_statistics_validation(tmp_path):
    with pytest.raises(FileNotFoundError):
        load_statistics(tmp_path / "none.json")
    (tmp_path / "s.json").write_text(json.dumps({"x_mean": [0] * 66, "x_std": [1] * 66}))
    with pytest.raises(ValueError, match="offsets"):
        load_statistics(tmp_path / "s.json")


def test_transition_longer_than_the_window_is_refused(lafan1_dir):
    with pytest.raises(ValueError, match="needs 66 frames"):
        run_benchmark(lafan1_dir, STATS, lengths=(46,), progress=False)


@pytest.mark.parametrize("past, policy, expected", [
    (10, "feed", list(range(10)) + [10, 11, 12, 13, 14, 15]),
    (1, "feed", [9, 10, 11, 12, 13, 14, 15]),
    (3, "repeat", [7] * 7 + [7, 8, 9] + [10, 11, 12, 13, 14, 15]),
])
def test_context_frames_keep_the_window_and_target(past, policy, expected):
    from deltainterp.benchmark import context_frames
    assert context_frames(past, 5, policy) == expected


def test_context_frames_refuse_bad_requests():
    from deltainterp.benchmark import context_frames
    with pytest.raises(ValueError, match="past-frames 11"):
        context_frames(11, 5)
    with pytest.raises(ValueError, match="policy"):
        context_frames(5, 5, "guess")


def test_fewer_past_frames_change_only_the_model_row(lafan1_dir):
    from conftest import REPO
    from deltainterp.checkpoint import load_checkpoint
    loaded = load_checkpoint(REPO / "Tests" / "Fixtures~" / "tiny-model.pt")
    full = run_benchmark(lafan1_dir, STATS, lengths=(5,), loaded=loaded, progress=False)
    short = run_benchmark(lafan1_dir, STATS, lengths=(5,), loaded=loaded, progress=False, past_frames=3)
    assert short["past_frames"] == 3 and "past_frames" not in full
    for method in ("zerovel", "slerp"):
        assert short["results"][method] == full["results"][method]
    assert short["results"]["model"]["l2p"]["5"] != full["results"]["model"]["l2p"]["5"]
