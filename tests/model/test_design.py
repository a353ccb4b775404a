"""The design solver (model/population/design.py) against brute force over
small populations, and the `?` of the query language and `--split` as parsers."""

from __future__ import annotations

import argparse
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.cli.design import split_argument
from sass_tui.db.query.query import QueryError, parse
from sass_tui.model.population.design import DesignError, LimitSpec, solve

UNKNOWN = math.nan


def share(values: np.ndarray, w: np.ndarray, low: float | None, high: float | None) -> float:
    ok = np.ones(len(values), dtype=bool)
    if low is not None:
        ok &= values >= low
    if high is not None:
        ok &= values <= high
    return float(w[ok].sum() / w.sum())


def test_the_shortest_range_of_a_skewed_population_sits_at_its_dense_end():
    """An exponential sample: the shortest interval holding 90 % starts at
    the smallest values (brute force over every pair of people)."""
    rng = np.random.default_rng(7)
    x = np.round(rng.exponential(10.0, 400), 3)
    w = np.ones_like(x)
    spec = LimitSpec("mass", "kg", UNKNOWN, UNKNOWN)
    design = solve([spec], x[:, None], w, np.ones(len(x), dtype=bool), 90.0, decimals=None)
    (limit,) = design.limits
    assert limit.low is not None and limit.high is not None
    width = limit.high - limit.low
    xs = np.sort(x)
    need = math.ceil(0.9 * len(x))
    brute = min(xs[i + need - 1] - xs[i] for i in range(len(xs) - need + 1))
    assert width == pytest.approx(brute, abs=0.2)
    assert share(x, w, limit.low, limit.high) >= 0.9
    assert limit.excluded_below < limit.excluded_above


def test_two_limits_share_the_exclusion_and_reach_the_joint_share():
    rng = np.random.default_rng(3)
    data = rng.multivariate_normal([170, 75], [[64, 40], [40, 144]], 3000)
    w = rng.uniform(0.5, 2.0, 3000)
    specs = [LimitSpec("stature", "cm", None, UNKNOWN), LimitSpec("mass", "kg", UNKNOWN, None)]
    design = solve(specs, data, w, np.ones(3000, dtype=bool), 95.0, decimals=None)
    high, low = design.limits[0].high, design.limits[1].low
    joint = float(w[(data[:, 0] <= high) & (data[:, 1] >= low)].sum() / w.sum())
    assert joint == pytest.approx(design.share) and 0.95 <= joint < 0.952
    assert design.limits[0].excluded_above == pytest.approx(
        design.limits[1].excluded_below, abs=0.002
    )


def test_shares_of_any_size_split_as_their_proportions():
    """--split 1e308,1e308 added up to infinity: a ZeroDivisionError traceback."""
    rng = np.random.default_rng(3)
    data = rng.multivariate_normal([170, 75], [[64, 40], [40, 144]], 3000)
    w = np.ones(3000)
    specs = [LimitSpec("stature", "cm", None, UNKNOWN), LimitSpec("mass", "kg", None, UNKNOWN)]

    def limits(split: list[float]) -> list[float | None]:
        design = solve(specs, data, w, np.ones(3000, dtype=bool), 95.0, split=split)
        return [limit.high for limit in design.limits]

    assert limits([1e308, 1e308]) == limits([1.0, 1.0])
    assert limits([2e307, 1e307]) == limits([2.0, 1.0])


def test_one_unknown_is_the_weighted_quantile():
    x = np.arange(1.0, 101.0)
    spec = LimitSpec("stature", "cm", None, UNKNOWN)
    design = solve([spec], x[:, None], np.ones(100), np.ones(100, dtype=bool), 95.0, decimals=None)
    assert design.limits[0].high == pytest.approx(np.percentile(x, 95))


def test_fixed_limits_that_exclude_too_many_are_said():
    x = np.arange(1.0, 101.0)
    fixed = x > 20  # the fixed limits alone accommodate 80 %
    spec = LimitSpec("stature", "cm", None, UNKNOWN)
    with pytest.raises(DesignError, match="accommodate 80.0 %"):
        solve([spec], x[:, None], np.ones(100), fixed, 95.0)


LIMIT_FIELDS = st.sampled_from(["stature", "mass", "measure.poplitealheight"])
OPS = st.sampled_from(["<", "<=", ">", ">=", "≤", "≥"])


@given(field=LIMIT_FIELDS, op=OPS, spaces=st.sampled_from(["", " ", "  "]))
@settings(deadline=None)
def test_a_question_mark_is_an_unknown_only_for_design(field, op, spaces):
    text = f"{field}{spaces} {op}{spaces}?"
    (comparison,) = parse(text, unknowns=True).tree.comparisons()
    assert math.isnan(comparison.value)
    with pytest.raises(QueryError, match="sass design"):
        parse(text)


@given(st.text(alphabet="?<>= .,0123456789abcmsteur", max_size=30))
@settings(deadline=None)
def test_any_text_with_question_marks_parses_or_is_one_error(text):
    try:
        parse(text, unknowns=True)
    except QueryError as error:
        assert str(error)


@given(
    st.lists(
        st.tuples(
            st.integers(0, 50), st.one_of(st.none(), st.sampled_from(["1/3", "1/2", "0.25"]))
        ),
        min_size=1,
        max_size=5,
    )
)
def test_split_reads_what_it_is_given(items):
    text = ",".join(f"{w}" if low is None else f"{w}:{low}" for w, low in items)
    shares, below = split_argument(text)
    assert shares == [float(w) for w, _ in items]
    expected = {None: None, "1/3": 1 / 3, "1/2": 0.5, "0.25": 0.25}
    assert below == [expected[low] for _, low in items]


@pytest.mark.parametrize("text", ["1:1/0", "nan", "inf", "-1", "1:2", "a"])
def test_split_refuses_what_is_no_share(text):
    with pytest.raises(argparse.ArgumentTypeError):
        split_argument(text)


@given(st.text(max_size=20))
def test_split_refuses_or_reads_any_text(text):
    try:
        shares, below = split_argument(text)
    except argparse.ArgumentTypeError as error:
        assert str(error)
    else:
        assert all(0 <= s < math.inf for s in shares) and len(shares) == len(below)
