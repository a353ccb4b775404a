"""Units: the typed forms of spec §2, conversions, and refusals."""

from __future__ import annotations

import math
import subprocess
import sys
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import GIRTH
from sass_tui.model.units import (
    _ALIASES,
    BASE_FACTORS,
    UnitError,
    _factor,
    convert,
    finite_number,
    parse_quantity,
    per_minute,
)


@cache
def registry():
    """pint, given the unit definitions BASE_FACTORS writes out (pint is a
    test dependency: sass itself converts by the table)."""
    pint = pytest.importorskip("pint")
    return pint.UnitRegistry(str(Path(__file__).with_name("units.txt")), cache_folder=None)


def pint_factor(from_unit: str, to_unit: str) -> float:
    """pint's factor, or UnitError across dimensions (as the table's)."""
    import pint

    try:
        return float(registry().Quantity(1.0, from_unit).to(to_unit).magnitude)
    except pint.DimensionalityError:
        raise UnitError(f"{from_unit} -> {to_unit}") from None


@pytest.mark.parametrize(
    "text,unit,expected",
    [
        ("12", "cm", 12.0),
        ("12in", "cm", 30.48),
        ("12 in", "cm", 30.48),
        ("30deg", "rad", np.pi / 6),
        ("0.5 rad", "deg", 28.64788975654116),
        ("17.98 ft-lb", "N_m", 24.377606711),
        ("24 N-m", "N_m", 24.0),
        ("24 N·m", "ft_lb", 24 / 1.3558179483314004),
        ("24 Nm", "N_m", 24.0),
        ("17.98 ft·lbf", "ft_lb", 17.98),
        ("-3.5e1 cm", "cm", -35.0),
        ("176 lb", "kg", 79.83225712),
    ],
)
def test_typed_quantities(text, unit, expected):
    assert parse_quantity(text, unit) == pytest.approx(expected, rel=1e-7)


@pytest.mark.parametrize(
    "text,unit,message",
    [
        ("12 kg", "cm", "kg is not a unit of length"),
        ("30 deg", "cm", "deg is not a unit of length"),
        ("12 furlongs", "cm", "unknown unit 'furlongs'"),
        ("twelve", "cm", "expected a number"),
        ("", "cm", "expected a number"),
        ("5 cm", "N_m", "cm is not a unit of torque"),
    ],
)
def test_bad_quantities(text, unit, message):
    with pytest.raises(UnitError, match=message):
        parse_quantity(text, unit)


def test_whole_group_round_trip_cm_in():
    values = Figure.default().groups[GIRTH].values
    inches = convert(values, "cm", "in")
    assert inches[0, 2] == pytest.approx(22.7 / 2.54)
    np.testing.assert_allclose(convert(inches, "in", "cm"), values, rtol=1e-12)


def test_degrees_radians_round_trip_keeps_no_value():
    values = Figure.default().groups["joint_limits"].values
    back = convert(convert(values, "deg", "rad"), "rad", "deg")
    np.testing.assert_allclose(back, values, rtol=1e-12)
    assert np.isnan(back).sum() == np.isnan(values).sum() > 0


@pytest.mark.parametrize(
    "text", ["1e400", "-1e400 cm", "1e400 in", "1e16", "nan", "inf", "inf cm", "-inf", "NaN cm"]
)
def test_non_finite_and_absurd_numbers_are_refused(text):
    with pytest.raises(UnitError):
        parse_quantity(text, "cm")


def test_a_number_too_large_to_convert_is_refused():
    with pytest.raises(UnitError, match="usable number"):
        parse_quantity("1e308 ft", "mm")


@pytest.mark.parametrize("text", ["nan", "inf", "-inf", "1e309", "1e16", "x"])
def test_finite_number_refuses(text):
    with pytest.raises(UnitError):
        finite_number(text)


def test_finite_number_accepts_ordinary_numbers():
    assert finite_number(" -3.5e2 ") == -350.0
    assert finite_number("1e15") == 1e15


def test_the_unit_table_agrees_with_pint():
    # Every pair of units a user can type, table against pint (units.txt).
    names = sorted(set(_ALIASES.values()))
    assert set(names) == set(BASE_FACTORS)
    for a in names:
        for b in names:
            table_dimension = BASE_FACTORS[a][0] == BASE_FACTORS[b][0]
            try:
                expected = pint_factor(a, b)
            except UnitError:
                assert not table_dimension, (a, b)
                continue
            assert table_dimension, (a, b)
            assert _factor(a, b) == pytest.approx(expected, rel=1e-14), (a, b)


def test_common_conversions_do_not_import_pint():
    code = (
        "import sys\n"
        "from sass_tui.model.units import parse_quantity, convert\n"
        "assert abs(parse_quantity('70 in', 'cm') - 177.8) < 1e-9\n"
        "assert abs(parse_quantity('17.98 ft-lb', 'N_m') - 24.377606711) < 1e-6\n"
        "convert(1.0, 'deg', 'rad')\n"
        "print('pint' in sys.modules)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "False"


def test_a_pasted_page_is_not_a_quantity():
    with pytest.raises(UnitError, match="at most 200"):
        parse_quantity("12in" * 1000, "cm")


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("2", 2.0),
        ("2/min", 2.0),
        (" 120 / h ", 2.0),
        ("30/hr", 0.5),
        ("60 per hour", 1.0),
        ("1 per s", 60.0),
        ("0.5 per minute", 0.5),
        ("3/mins", 3.0),
        ("0", 0.0),
    ],
)
def test_a_rate_is_read_per_minute(text, expected):
    assert per_minute(text) == pytest.approx(expected)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("-1", "is negative"),
        ("nan", "not a usable number"),
        ("1e400/h", "not a usable number"),
        ("2/day", "'day' is no time unit"),
        ("2 apples", "expected a number per minute"),
        ("/min", "expected a number per minute"),
        ("", "expected a number per minute"),
    ],
)
def test_a_rate_that_is_no_rate_is_refused(text, message):
    with pytest.raises(UnitError, match=message):
        per_minute(text)


@given(
    st.floats(0, 1e6, allow_nan=False),
    st.sampled_from([("", 1.0), ("/min", 1.0), ("/h", 60.0), (" per hour", 60.0), ("/s", 1 / 60)]),
)
def test_any_rate_with_its_unit_is_that_many_per_unit(value, unit):
    spelled, minutes = unit
    assert per_minute(f"{value!r}{spelled}") == pytest.approx(value / minutes, rel=1e-12)


@given(st.text(max_size=40))
def test_any_text_is_a_rate_or_a_unit_error(text):
    try:
        rate = per_minute(text)
    except UnitError:
        return
    assert math.isfinite(rate) and rate >= 0
