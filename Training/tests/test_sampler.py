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
