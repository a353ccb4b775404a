"""Units: the typed forms of spec §2, conversions, and refusals."""

from __future__ import annotations

import numpy as np
import pytest

from sass_tui.model.figure import Figure
from sass_tui.model.names import GIRTH
from sass_tui.model.units import UnitError, convert, parse_quantity, registry


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


def test_one_registry():
    assert registry() is registry()


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
