"""The two-piece normal model (spec §2), both ways."""

from __future__ import annotations

import numpy as np
import pytest
from _paths import DATASETS
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import GIRTH
from sass_tui.model.population.percentile import Z95, PercentileError, has_spread, plausible_range
from sass_tui.model.population.percentile_arrays import percentile_of, value_at

percentiles = st.floats(min_value=0.5, max_value=99.5, allow_nan=False)
values = st.floats(min_value=-500, max_value=500, allow_nan=False)
spreads = st.floats(min_value=0.01, max_value=100, allow_nan=False)


def test_exact_at_the_stored_percentiles_for_a_whole_group():
    stats = read_population_file(DATASETS / "girth.dat", GIRTH).stats("male")
    for column, p in enumerate((5, 50, 95)):
        np.testing.assert_array_equal(value_at(stats, p), stats[..., column])


def test_hand_computed_value():
    # right upper arm length: 33.7 / 36.6 / 39.4 cm; 75th percentile
    z75 = 0.6744897501960817
    assert value_at(np.array([33.7, 36.6, 39.4]), 75) == pytest.approx(36.6 + z75 * 2.8 / Z95)
    assert value_at(np.array([33.7, 36.6, 39.4]), 25) == pytest.approx(36.6 - z75 * 2.9 / Z95)


def test_vectorised_per_cell_percentiles():
    stats = np.array([[1.0, 2.0, 3.0], [10.0, 20.0, 40.0]])
    out = value_at(stats, np.array([5.0, 95.0]))
    np.testing.assert_array_equal(out, [1.0, 40.0])


@pytest.mark.parametrize("bad", [0.4, 99.6, 120, -1, float("nan")])
def test_out_of_range_percentiles_are_refused(bad):
    with pytest.raises(PercentileError, match="outside 0.5-99.5"):
        value_at(np.array([1.0, 2.0, 3.0]), bad)


def test_degenerate_rows_and_no_value():
    assert value_at(np.array([1.0, 1.0, 1.0]), 77) == 1.0
    assert percentile_of(np.array([1.0, 1.0, 1.0]), 1.0) == 50.0
    assert np.isnan(percentile_of(np.array([1.0, 1.0, 1.0]), 2.0))
    assert np.isnan(value_at(np.array([np.nan, np.nan, np.nan]), 30))


@settings(max_examples=200, deadline=None)
@given(
    v50=values, below=spreads, above=spreads, p=percentiles, q=percentiles, decreasing=st.booleans()
)
def test_monotonic_either_way(v50, below, above, p, q, decreasing):
    sign = -1.0 if decreasing else 1.0
    stats = np.array([v50 - sign * below, v50, v50 + sign * above])
    a, b = float(value_at(stats, min(p, q))), float(value_at(stats, max(p, q)))
    if decreasing:
        assert a >= b
    else:
        assert a <= b


@settings(max_examples=200, deadline=None)
@given(v50=values, below=spreads, above=spreads, p=percentiles, decreasing=st.booleans())
def test_round_trip(v50, below, above, p, decreasing):
    sign = -1.0 if decreasing else 1.0
    stats = np.array([v50 - sign * below, v50, v50 + sign * above])
    assert float(percentile_of(stats, value_at(stats, p))) == pytest.approx(p, abs=1e-6)


@settings(max_examples=100, deadline=None)
@given(v50=values, below=spreads, above=spreads, decreasing=st.booleans())
def test_the_plausible_range_is_the_05th_to_995th_percentile(v50, below, above, decreasing):
    sign = -1.0 if decreasing else 1.0
    stats = (v50 - sign * below, v50, v50 + sign * above)
    low, high = plausible_range(*stats)
    ends = sorted(float(value_at(np.array(stats), p)) for p in (0.5, 99.5))
    assert (low, high) == pytest.approx(ends)
    assert has_spread(*stats) == (below > 0 or above > 0)
    assert not has_spread(2.2, 2.2, 2.2)
