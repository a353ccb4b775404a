"""Calibration weights and weighted percentiles (sass_tui/model/population/targets.py),
checked against direct computations with numpy."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.population.targets import (
    CUT_PERCENTILES,
    TargetError,
    _features,
    calibrate,
    kish_effective_n,
    weighted_percentile,
)

finite = st.floats(-1e6, 1e6, allow_nan=False)


@given(st.lists(finite, min_size=1, max_size=60), st.lists(st.floats(0, 100), max_size=5))
def test_equal_weights_are_numpys_percentiles(values, percentiles):
    """Unweighted populations keep their figures: equal weights are np.percentile."""
    got = weighted_percentile(values, np.full(len(values), 2.5), percentiles)
    assert np.allclose(got, np.percentile(values, percentiles), rtol=1e-12, atol=1e-9)


@given(
    st.lists(st.tuples(finite, st.floats(0.01, 100)), min_size=2, max_size=60),
    st.floats(0, 100),
    st.floats(0, 100),
)
def test_weighted_percentiles_stay_in_range_and_in_order(pairs, p, q):
    values, weights = zip(*pairs)
    low, high = sorted((p, q))
    a, b = weighted_percentile(values, weights, [low, high])
    assert min(values) <= a <= b <= max(values)


def test_a_heavy_weight_pulls_the_median():
    values = np.arange(1.0, 11.0)
    weights = np.ones(10)
    weights[-1] = 100.0  # the largest value holds almost all the weight
    assert weighted_percentile(values, weights, [50])[0] > 9.0  # 5.5 unweighted


def test_kish_effective_size():
    assert kish_effective_n(np.ones(50)) == pytest.approx(50)
    assert kish_effective_n([1.0, 0.0, 0.0]) == pytest.approx(1)
    assert kish_effective_n([3.0, 1.0]) == pytest.approx(16 / 10)


def _base_and_sample(shift: float, n: int = 4000, rows: int = 3000):
    rng = np.random.default_rng(7)
    cov = np.array([[40.0, 30.0], [30.0, 120.0]])
    base = rng.multivariate_normal([163.0, 68.0], cov, n)
    sample = rng.multivariate_normal([163.0 - shift, 68.0 + 2 * shift], cov * 1.2, rows)
    return base, sample


def test_the_weighted_people_have_the_samples_moments_and_shares():
    base, sample = _base_and_sample(shift=2.5)
    w = calibrate(["stature", "mass"], base, sample).weights
    mean = w @ base / w.sum()
    assert np.allclose(mean, sample.mean(axis=0), atol=1e-5)
    cov = ((base - mean) * w[:, None]).T @ (base - mean) / w.sum()
    assert np.allclose(cov, np.cov(sample.T, bias=True), rtol=1e-5)
    for i in range(2):
        for cut in np.percentile(sample[:, i], CUT_PERCENTILES):
            share = w[base[:, i] <= cut].sum() / w.sum()
            assert share == pytest.approx(np.mean(sample[:, i] <= cut), abs=1e-5)
    for q in (25, 50, 75):
        a, b = np.percentile(sample, q, axis=0)
        share = w[(base[:, 0] <= a) & (base[:, 1] <= b)].sum() / w.sum()
        assert share == pytest.approx(np.mean((sample[:, 0] <= a) & (sample[:, 1] <= b)), abs=1e-5)


def test_people_lacking_a_value_weigh_nothing():
    base, sample = _base_and_sample(shift=1.0)
    base[::10, 1] = np.nan
    weighting = calibrate(["stature", "mass"], base, sample)
    assert (weighting.weights[::10] == 0).all()
    assert weighting.people == len(base) - len(base[::10])
    assert 0 < weighting.effective_n <= weighting.people


def test_the_same_people_need_no_weighting():
    base, _ = _base_and_sample(shift=0)
    weighting = calibrate(["stature", "mass"], base, base)
    assert np.allclose(weighting.weights, 1.0, atol=1e-6)
    assert weighting.warnings() == []


@settings(deadline=None, max_examples=20)
@given(st.floats(-40, 40))
def test_a_target_is_matched_or_refused(shift):
    """Whatever the shift: the weights match the sample's mean, or nothing is made."""
    base, sample = _base_and_sample(shift=shift, n=800, rows=200)
    try:
        weighting = calibrate(["stature", "mass"], base, sample)
    except TargetError as exc:
        assert "outside the people" in str(exc)
        return
    w = weighting.weights
    assert np.allclose(w @ base / w.sum(), sample.mean(axis=0), atol=1e-4)


@pytest.mark.parametrize("shift", [8, 30])
def test_a_target_far_outside_is_refused(shift):
    """8: weights exist, but ~16 people would stand for everybody; 30: none exist."""
    base, sample = _base_and_sample(shift=shift)
    with pytest.raises(TargetError, match="outside the people"):
        calibrate(["stature", "mass"], base, sample)


def test_a_target_largely_outside_is_made_with_a_warning():
    base, sample = _base_and_sample(shift=6)
    weighting = calibrate(["stature", "mass"], base, sample)
    assert weighting.effective_n < 0.1 * weighting.people
    assert any("effective sample size" in w for w in weighting.warnings())


def test_too_few_rows_are_refused():
    base, sample = _base_and_sample(shift=1)
    with pytest.raises(TargetError, match="at least 30"):
        calibrate(["stature", "mass"], base, sample[:29], where="s.csv")


def test_cuts_made_fewer_by_very_unequal_weights_still_give_features():
    """A 60-row sample whose survey weights differ by 10^12 makes quartiles
    coincide, np.unique leaves two cuts of five, and the pair's joint shares
    raised IndexError; they are asked of the cuts both fields still have."""
    x = np.random.default_rng(3).normal(170, 8, (50, 2))
    cuts = [np.array([160.0, 175.0]), np.array([150.0, 160.0, 170.0, 180.0, 190.0])]
    g = _features(x, x.mean(axis=0), x.std(axis=0), cuts)
    # 2 z, 3 products, 2 + 5 cuts, the pair below both of cut 1 (the only shared quartile)
    assert g.shape == (50, 2 + 3 + 7 + 1)
    assert np.array_equal(g[:, -1], ((x[:, 0] <= 175.0) & (x[:, 1] <= 160.0)).astype(float))
