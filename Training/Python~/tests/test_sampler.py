"""Key layouts: p(n) ∝ 1/n on [5, 39] (method-spec §2.3), frame layout of a transition."""
from __future__ import annotations

import numpy as np
import pytest

from deltainterp.sampler import TransitionSampler


def test_gap_distribution_is_inverse_proportional():
    sampler = TransitionSampler()
    rng = np.random.default_rng(0)
    draws = np.array([sampler.sample(rng).gap for _ in range(20000)])
    gaps = np.arange(5, 40)
    expected = (1.0 / gaps) / (1.0 / gaps).sum()
    assert expected[0] == pytest.approx(0.0922, abs=1e-4) and expected[-1] == pytest.approx(0.0118, abs=1e-4)
    observed = np.array([(draws == g).sum() for g in gaps])
    chi2 = float((((observed - expected * len(draws)) ** 2) / (expected * len(draws))).sum())
    # 34 degrees of freedom: the 99.9% quantile is 65.2; a uniform sampler gives chi2 in the thousands
    assert chi2 < 65.2
    assert draws.min() >= 5 and draws.max() <= 39
    assert draws.mean() == pytest.approx(16.1, abs=0.3)


def test_uniform_option_is_uniform():
    sampler = TransitionSampler(inverse_weighting=False)
    assert np.allclose(sampler.probabilities, 1 / 35)


@pytest.mark.parametrize("past, gap", [(10, 5), (10, 39), (4, 1)])
def test_layout(past, gap):
    layout = TransitionSampler(past=past).layout(gap)
    assert layout.key_frames == list(range(past)) + [past + gap]
    assert layout.query_frames == list(range(past, past + gap))
    assert layout.length == past + gap + 1
    assert layout.key_frames[layout.reference_key] == past - 1


def test_invalid_ranges_are_refused():
    with pytest.raises(ValueError):
        TransitionSampler(min_gap=10, max_gap=5)


def test_past_lengths_follow_their_distribution():
    sampler = TransitionSampler(min_past=1, longest_past_share=0.4)
    assert sampler.past_probabilities.sum() == pytest.approx(1.0)
    assert sampler.past_probabilities[-1] == pytest.approx(0.4) and sampler.past_probabilities[0] == pytest.approx(0.3)
    assert np.allclose(sampler.past_probabilities[1:-1], 0.3 / 8)
    rng = np.random.default_rng(1)
    layouts = [sampler.sample(rng) for _ in range(8000)]
    pasts = np.array([layout.past for layout in layouts])
    assert pasts.min() == 1 and pasts.max() == 10
    assert (pasts == 10).mean() == pytest.approx(0.4, abs=0.02)
    assert (pasts == 1).mean() == pytest.approx(0.3, abs=0.02)
    for layout in layouts[:50]:  # the layout of a short past is the contract's: keys 0..P-1, target P+n
        assert layout.key_frames == list(range(layout.past)) + [layout.past + layout.gap]


def test_a_single_past_length_draws_as_before():
    """Runs with the benchmark's layout only keep their RNG stream (resume and old runs stay exact)."""
    a, b = np.random.default_rng(3), np.random.default_rng(3)
    old = [int(b.choice(np.arange(5, 40), p=TransitionSampler().probabilities)) for _ in range(100)]
    assert [TransitionSampler().sample(a).gap for _ in range(100)] == old


def test_past_range_is_checked():
    with pytest.raises(ValueError):
        TransitionSampler(past=10, min_past=0)
    with pytest.raises(ValueError):
        TransitionSampler(past=5, min_past=6)


def test_uniform_past_lengths():
    sampler = TransitionSampler(min_past=1, uniform_past=True)
    assert np.allclose(sampler.past_probabilities, 0.1)
    rng = np.random.default_rng(2)
    pasts = np.array([sampler.sample(rng).past for _ in range(5000)])
    for p in range(1, 11):
        assert (pasts == p).mean() == pytest.approx(0.1, abs=0.02)
