"""The Revised NIOSH Lifting Equation against the Applications Manual (Waters,
Putz-Anderson & Garg 1994, DHHS (NIOSH) Pub. 94-110, revised 2021): every
printed row of Tables 1-5 and 7, the limits of sections 1.3.1-1.3.5, the
special frequency adjustment, Example 4's worksheet, a multi-task composite
index by the manual's formula, and other inputs against the equations as
written out here (metric and U.S.)."""

from __future__ import annotations

import math
from decimal import ROUND_HALF_UP, Decimal

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.strength.niosh import (
    Lift,
    Point,
    TaskIndices,
    assess_lift,
    asymmetric_multiplier,
    composite_lifting_index,
    coupling_multiplier,
    distance_multiplier,
    form,
    frequency_multiplier,
    horizontal_multiplier,
    lifting_index,
    special_frequency,
    task_indices,
    vertical_multiplier,
)

METRIC, US = form("metric"), form("us")

# The manual's tables as printed (pp. 8-18), typed again here.
TABLE_1_US = {10: 1.00, 11: .91, 12: .83, 13: .77, 14: .71, 15: .67, 16: .63, 17: .59, 18: .56,
              19: .53, 20: .50, 21: .48, 22: .46, 23: .44, 24: .42, 25: .40}  # fmt: skip
TABLE_1_METRIC = {25: 1.00, 28: .89, 30: .83, 32: .78, 34: .74, 36: .69, 38: .66, 40: .63,
                  42: .60, 44: .57, 46: .54, 48: .52, 50: .50, 52: .48, 54: .46, 56: .45,
                  58: .43, 60: .42, 63: .40}  # fmt: skip
TABLE_2_US = {0: .78, 5: .81, 10: .85, 15: .89, 20: .93, 25: .96, 30: 1.00, 35: .96, 40: .93,
              45: .89, 50: .85, 55: .81, 60: .78, 65: .74, 70: .70}  # fmt: skip
TABLE_2_METRIC = {0: .78, 10: .81, 20: .84, 30: .87, 40: .90, 50: .93, 60: .96, 70: .99,
                  80: .99, 90: .96, 100: .93, 110: .90, 120: .87, 130: .84, 140: .81,
                  150: .78, 160: .75, 170: .72, 175: .70}  # fmt: skip
TABLE_3_US = {10: 1.00, 15: .94, 20: .91, 25: .89, 30: .88, 35: .87, 40: .87, 45: .86,
              50: .86, 55: .85, 60: .85, 70: .85}  # fmt: skip
TABLE_3_METRIC = {25: 1.00, 40: .93, 55: .90, 70: .88, 85: .87, 100: .87, 115: .86, 130: .86,
                  145: .85, 160: .85, 175: .85}  # fmt: skip
TABLE_4 = {0: 1.00, 15: .95, 30: .90, 45: .86, 60: .81, 75: .76, 90: .71, 105: .66, 120: .62,
           135: .57}  # fmt: skip
# Rows the formula rounds differently from the print (the formula governs, p. 7).
MISPRINTS = {("HM", "us", 22), ("HM", "us", 23), ("DM", "metric", 130)}

TABLE_5_F = (0.2, 0.5, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)
# (duration, V < 30 in) -> the column, top to bottom
TABLE_5 = {
    ("short", True): (1.00, .97, .94, .91, .88, .84, .80, .75, .70, .60, .52, .45, .41, .37, 0, 0, 0),
    ("short", False): (1.00, .97, .94, .91, .88, .84, .80, .75, .70, .60, .52, .45, .41, .37, .34, .31, .28),
    ("moderate", True): (.95, .92, .88, .84, .79, .72, .60, .50, .42, .35, .30, .26, 0, 0, 0, 0, 0),
    ("moderate", False): (.95, .92, .88, .84, .79, .72, .60, .50, .42, .35, .30, .26, .23, .21, 0, 0, 0),
    ("long", True): (.85, .81, .75, .65, .55, .45, .35, .27, .22, .18, 0, 0, 0, 0, 0, 0, 0),
    ("long", False): (.85, .81, .75, .65, .55, .45, .35, .27, .22, .18, .15, .13, 0, 0, 0, 0, 0),
}  # fmt: skip
TABLE_7 = {("good", True): 1.00, ("good", False): 1.00, ("fair", True): 0.95,
           ("fair", False): 1.00, ("poor", True): 0.90, ("poor", False): 0.90}  # fmt: skip


def printed(value: float) -> float:
    """Two decimals, half away from zero (how the tables round, p. 7)."""
    return float(Decimal(f"{value:.9f}").quantize(Decimal("0.01"), rounding=ROUND_HALF_UP))


@pytest.mark.parametrize(
    ("name", "multiplier", "of", "table"),
    [
        ("HM", horizontal_multiplier, US, TABLE_1_US),
        ("HM", horizontal_multiplier, METRIC, TABLE_1_METRIC),
        ("VM", vertical_multiplier, US, TABLE_2_US),
        ("VM", vertical_multiplier, METRIC, TABLE_2_METRIC),
        ("DM", distance_multiplier, US, TABLE_3_US),
        ("DM", distance_multiplier, METRIC, TABLE_3_METRIC),
    ],
)
def test_tables_1_to_3_every_printed_row(name, multiplier, of, table):
    for x, value in table.items():
        got = multiplier(float(x), of).value
        assert abs(got - value) <= 0.0101, (name, of.name, x)
        if (name, of.name, x) not in MISPRINTS:
            assert printed(got) == value, (name, of.name, x, got)


def test_table_4_asymmetry_every_row_and_either_side():
    for a, value in TABLE_4.items():
        assert printed(asymmetric_multiplier(a).value) == value
        assert asymmetric_multiplier(-a).value == asymmetric_multiplier(a).value


def test_table_5_every_cell_and_column():
    for (duration, low), column in TABLE_5.items():
        for of, v in ((US, 20.0 if low else 40.0), (METRIC, 50.0 if low else 100.0)):
            for f, value in zip(TABLE_5_F, column, strict=True):
                assert frequency_multiplier(f, duration, v, of).value == pytest.approx(value)


def test_table_5_boundary_and_limits():
    # V of 30 in / 75 cm is "at or above"; F below 0.2 counts as 0.2; above 15, 0
    assert frequency_multiplier(13, "short", 30, US).value == pytest.approx(0.34)
    assert frequency_multiplier(13, "short", 74.9, METRIC).value == 0
    low = frequency_multiplier(0.05, "long", 100, METRIC)
    assert low.value == pytest.approx(0.85) and "taken as 0.2" in low.limit
    assert frequency_multiplier(16, "short", 100, METRIC).value == 0
    # Example 7 interpolates between the rows for 2 and 3 lifts a minute (F = 2.4)
    assert frequency_multiplier(2.4, "short", 100, METRIC).value == pytest.approx(0.898)


def test_table_7_coupling():
    for (coupling, low), value in TABLE_7.items():
        assert coupling_multiplier(coupling, 29.9 if low else 30.0, US).value == value
        assert coupling_multiplier(coupling, 74.0 if low else 75.0, METRIC).value == value


@pytest.mark.parametrize(
    ("multiplier", "x", "of", "value", "words"),
    [
        (horizontal_multiplier, 20, METRIC, 1.0, "taken as 25 cm"),
        (horizontal_multiplier, 64, METRIC, 0.0, "beyond 63 cm"),
        (horizontal_multiplier, 8, US, 1.0, "taken as 10 in"),
        (horizontal_multiplier, 26, US, 0.0, "beyond 25 in"),
        (vertical_multiplier, 176, METRIC, 0.0, "175 cm"),
        (vertical_multiplier, 71, US, 0.0, "70 in"),
        (distance_multiplier, 10, METRIC, 1.0, "taken as 25 cm"),
        (distance_multiplier, 176, METRIC, 0.0, "beyond 175 cm"),
        (distance_multiplier, 71, US, 0.0, "beyond 70 in"),
    ],
)
def test_each_limit_applied_and_named(multiplier, x, of, value, words):
    found = multiplier(float(x), of)
    assert found.value == value
    assert words in found.limit


def test_asymmetry_beyond_135_degrees_is_no_load():
    assert asymmetric_multiplier(136).value == 0 and "135" in asymmetric_multiplier(136).limit


def test_special_frequency_adjustment():
    # p. 16: 10 lifts a minute for 8 minutes of the 15-minute sample
    assert special_frequency(10, 8) == pytest.approx(80 / 15)
    with pytest.raises(ValueError, match="at most 15 lifts"):
        special_frequency(16, 5)


def test_example_4_package_inspection():
    # Figure 14, p. 46: 26 lb, H 10 -> 20 in, V 22 -> 59 in, A 0, F 3/min, <= 1 h,
    # fair coupling, significant control at the destination.  The worksheet
    # multiplies rounded multipliers: RWL 34.9 lb at the origin, 15.2 at the
    # destination, LI 0.7 and 1.7.
    lift = Lift(US, Point(10, 22, 0, "fair"), 37, 3, "short", 26, Point(20, 59, 0, "fair"))
    answer = assess_lift(lift)
    assert answer.origin.rwl == pytest.approx(34.9, rel=0.01)
    assert answer.destination is not None
    assert answer.destination.rwl == pytest.approx(15.2, rel=0.01)
    assert answer.destination.multipliers["CM"].value == 1.0  # V 59 in, fair
    assert answer.origin.multipliers["CM"].value == 0.95  # V 22 in, fair
    assert round(lifting_index(26, answer.origin.rwl), 1) == 0.7
    assert round(lifting_index(26, answer.rwl), 1) == 1.7


def test_rwl_of_zero_is_no_load():
    lift = Lift(METRIC, Point(70, 50), 40, 1, "long", 5)
    assert assess_lift(lift).rwl == 0 and lifting_index(5, 0) == math.inf


def reference_rwl(h, v, d, a, f_column_value, coupling_value, metric):
    """The manual's formulas (p. 7), written out apart from sass's."""
    if metric:
        hm = 1.0 if h <= 25 else (25 / h if h <= 63 else 0.0)
        vm = 1 - 0.003 * abs(v - 75) if v <= 175 else 0.0
        dm = 1.0 if d <= 25 else (0.82 + 4.5 / d if d <= 175 else 0.0)
        lc = 23
    else:
        hm = 1.0 if h <= 10 else (10 / h if h <= 25 else 0.0)
        vm = 1 - 0.0075 * abs(v - 30) if v <= 70 else 0.0
        dm = 1.0 if d <= 10 else (0.82 + 1.8 / d if d <= 70 else 0.0)
        lc = 51
    am = 1 - 0.0032 * a if a <= 135 else 0.0
    return lc * hm * vm * dm * am * f_column_value * coupling_value


@settings(max_examples=200, deadline=None)
@given(
    metric=st.booleans(),
    h=st.floats(0, 1),
    v=st.floats(0, 1),
    d=st.floats(0, 1),
    a=st.floats(0, 150),
    row=st.integers(0, 16),
    duration=st.sampled_from(["short", "moderate", "long"]),
    coupling=st.sampled_from(["good", "fair", "poor"]),
)
def test_hidden_cases_against_the_formulas(metric, h, v, d, a, row, duration, coupling):
    scale = 70.0 if metric else 28.0  # past each upper limit of the form
    of = METRIC if metric else US
    h, v, d = h * scale, v * scale * 2.6, d * scale * 2.6
    low = v < (75 if metric else 30)
    fm = TABLE_5[(duration, low)][row]
    cm = TABLE_7[(coupling, low)]
    lift = Lift(of, Point(h, v, a, coupling), d, TABLE_5_F[row], duration)
    expected = reference_rwl(h, v, d, a, fm, cm, metric)
    assert assess_lift(lift).rwl == pytest.approx(expected, rel=0.01, abs=1e-9)


def test_composite_lifting_index_by_the_manual_formula():
    # Three tasks (section 2.4.5): FILI, STLI and F given; renumbered by STLI,
    # CLI = STLI1 + FILI2 (1/FM1,2 - 1/FM1) + FILI3 (1/FM1,2,3 - 1/FM1,2), each
    # FM from Table 5 (long duration, V >= 75 cm) at the summed frequency.
    tasks = [
        TaskIndices("b", 2.0, 100, 10, 8, 1.0, 1.3),
        TaskIndices("a", 1.0, 100, 10, 8, 1.2, 1.6),
        TaskIndices("c", 1.0, 100, 10, 8, 0.8, 1.3),
    ]
    answer = composite_lifting_index(tasks, "long", METRIC)
    # FM at 1, 3 and 4 lifts a minute: 0.75, 0.55, 0.45; task b before c (same
    # STLI, the higher frequency first)
    expected = 1.6 + 1.0 * (1 / 0.55 - 1 / 0.75) + 0.8 * (1 / 0.45 - 1 / 0.55)
    assert [t.name for t in answer.tasks] == ["a", "b", "c"]
    assert answer.cli == pytest.approx(expected)


def test_task_indices_use_the_heaviest_load_for_fili():
    lift = Lift(METRIC, Point(25, 75), 25, 1, "long", 10, None, 15)
    indices = task_indices("t", lift)
    assert indices.firwl == pytest.approx(23.0)  # fair coupling at V 75 cm: CM 1
    assert indices.fili == pytest.approx(15 / indices.firwl)
    assert indices.stli == pytest.approx(10 / (indices.firwl * 0.75))


def test_an_index_is_printed_with_two_decimals_or_in_words():
    from sass_tui.model.strength.niosh import index_words

    assert index_words(1.6155) == "1.62"
    assert index_words(None) == "-"
    assert index_words(lifting_index(5.0, 0.0)) == "infinite"
