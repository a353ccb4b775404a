"""Units: the factors of the units SASS uses.

Users type units the way the report does ("12in", "30deg", "17.98 ft-lb",
"24 N-m"); the spellings are mapped to unit names first (pint, for one,
would read "ft-lb" as feet minus pounds).  Every unit a user can type, and
every unit sass stores, has its factor in `BASE_FACTORS`, so converting
"70 in" costs a multiplication.  The table is checked against pint, and pint
is needed for nothing else: tests/model/test_units.py compares every pair
of units with pint's conversion through the same definitions
(tests/model/units.txt), so pint is a test dependency only.
"""

from __future__ import annotations

import math
import re
from functools import cache
from typing import TYPE_CHECKING, overload

from sass_tui.model.errors import SassError
from sass_tui.model.text import quoted
from sass_tui.model.vocabulary import CENTER_OF_MASS, GIRTH, JOINT_LIMITS, STRENGTH

if TYPE_CHECKING:
    import numpy as np
    import numpy.typing as npt


class UnitError(ValueError, SassError):
    """A value or unit the user typed cannot be used here."""


# Standard gravity (m/s^2, the 3rd CGPM, 1901): the newtons of a kilogram-force.
STANDARD_GRAVITY = 9.80665

# Unit name -> (dimension, factor to the SI unit of that dimension).  The
# values are tests/model/units.txt's definitions written out; a test compares
# each pair's factor with pint's.
BASE_FACTORS: dict[str, tuple[str, float]] = {
    "m": ("length", 1.0),
    "cm": ("length", 1e-2),
    "mm": ("length", 1e-3),
    "in": ("length", 0.0254),
    "ft": ("length", 0.3048),
    "kg": ("mass", 1.0),
    "g": ("mass", 1e-3),
    "lb": ("mass", 0.45359237),
    "rad": ("angle", 1.0),
    "deg": ("angle", math.pi / 180.0),
    "rad/s": ("angular speed", 1.0),
    "deg/s": ("angular speed", math.pi / 180.0),
    "N_m": ("torque", 1.0),
    "ft_lb": ("torque", 0.3048 * 4.4482216152605),
    # Forces: the grip table of HFDS 2003 exhibit 14.5.2.1 (model/strength/published_grip.py).
    "N": ("force", 1.0),
    "lbf": ("force", 4.4482216152605),
    # The Liberty Mutual equations' push and pull forces (model/strength/liberty_mutual.py).
    "kgf": ("force", STANDARD_GRAVITY),
}


@cache
def _factor(from_unit: str, to_unit: str) -> float:
    for unit in (from_unit, to_unit):
        if unit not in BASE_FACTORS:
            raise UnitError(f"unknown unit {unit!r}")
    (from_dimension, from_base), (to_dimension, to_base) = (
        BASE_FACTORS[from_unit],
        BASE_FACTORS[to_unit],
    )
    if from_dimension == to_dimension:
        return from_base / to_base
    raise _wrong_dimension(from_unit, to_unit)


def _wrong_dimension(from_unit: str, to_unit: str) -> UnitError:
    return UnitError(
        f"{DISPLAY.get(from_unit, from_unit)} is not a unit of "
        f"{_dimension_word(to_unit)} (expected e.g. {DISPLAY.get(to_unit, to_unit)})"
    )


# Display spelling -> registry name.  Keys are compared after lower-casing,
# except where case matters (N vs n is unambiguous here, so all are lower-case).
_ALIASES = {
    "cm": "cm",
    "centimeter": "cm",
    "centimeters": "cm",
    "centimetre": "cm",
    "centimetres": "cm",
    "mm": "mm",
    "millimeter": "mm",
    "millimeters": "mm",
    "m": "m",
    "meter": "m",
    "meters": "m",
    "metre": "m",
    "metres": "m",
    "in": "in",
    "inch": "in",
    "inches": "in",
    '"': "in",
    "ft": "ft",
    "foot": "ft",
    "feet": "ft",
    "deg": "deg",
    "degree": "deg",
    "degrees": "deg",
    "°": "deg",
    "rad": "rad",
    "radian": "rad",
    "radians": "rad",
    "kg": "kg",
    "kilogram": "kg",
    "kilograms": "kg",
    "g": "g",
    "gram": "g",
    "grams": "g",
    "lb": "lb",
    "lbs": "lb",
    "pound": "lb",
    "pounds": "lb",
    "ft-lb": "ft_lb",
    "ft-lbf": "ft_lb",
    "ft·lb": "ft_lb",
    "ft·lbf": "ft_lb",
    "ftlb": "ft_lb",
    "ft-lbs": "ft_lb",
    "ft*lbf": "ft_lb",
    "ft*lb": "ft_lb",
    "lbf-ft": "ft_lb",
    "lb-ft": "ft_lb",
    "n-m": "N_m",
    "n·m": "N_m",
    "nm": "N_m",
    "n*m": "N_m",
    "n m": "N_m",
    "n": "N",
    "newton": "N",
    "newtons": "N",
    "lbf": "lbf",
    "pound-force": "lbf",
    "pounds-force": "lbf",
    "kgf": "kgf",
    "kilogram-force": "kgf",
    "kilograms-force": "kgf",
    "kp": "kgf",
    "deg/s": "deg/s",
    "°/s": "deg/s",
    "rad/s": "rad/s",
}

# Registry name -> how the program prints it.
DISPLAY = {
    "cm": "cm",
    "in": "in",
    "deg": "deg",
    "rad": "rad",
    "kg": "kg",
    "lb": "lb",
    "ft_lb": "ft-lb",
    "N_m": "N-m",
    "N": "N",
    "lbf": "lbf",
    "kgf": "kgf",
    "mm": "mm",
    "m": "m",
    "ft": "ft",
    "g": "g",
    "deg/s": "deg/s",
    "rad/s": "rad/s",
}

# Each group's canonical (stored) unit and the one it converts to.
GROUP_UNITS = {
    GIRTH: ("cm", "in"),
    JOINT_LIMITS: ("deg", "rad"),
    CENTER_OF_MASS: ("cm", "in"),
    STRENGTH: ("ft_lb", "N_m"),
}

# Possessive quantifiers: no backtracking through a long run of digits.
_NUMBER = re.compile(r"^\s*([-+]?(?:\d++(?:\.\d*+)?|\.\d++)(?:[eE][-+]?\d++)?)\s*(.*?)\s*$")


def unit_name(text: str) -> str:
    """Map a typed unit spelling to the registry's name, or raise UnitError."""
    key = re.sub(r"\s+", " ", text.strip()).lower()
    if key in _ALIASES:
        return _ALIASES[key]
    raise UnitError(f"unknown unit {quoted(text.strip())}")


def parse_quantity(text: str, unit: str) -> float:
    """Read "12", "12in", "12 in", "0.5 rad", "24 N·m" as a number in `unit`.

    A bare number is taken to be in `unit` already.  A unit of the wrong
    dimension, text that is not a number, or a number too large to hold
    ("1e400", which float() reads as infinity) raises UnitError.
    """
    if len(text) > MAX_QUANTITY_LENGTH:
        raise UnitError(
            f"expected a number with an optional unit, got {len(text)} characters "
            f"(at most {MAX_QUANTITY_LENGTH})"
        )
    match = _NUMBER.match(text)
    if not match:
        raise UnitError(f"expected a number with an optional unit, got {quoted(text.strip())}")
    value = finite_number(match.group(1))
    if not match.group(2):
        return value
    given = unit_name(match.group(2))
    converted = float(convert(value, given, unit))
    if not math.isfinite(converted):
        raise UnitError(f"{quoted(text.strip())} is too large a number")
    return converted


def quantity_unit(text: str) -> str | None:
    """The registry name of the unit typed after a quantity's number ("16 in"
    -> "in"); None for a bare number; UnitError for text that is no quantity."""
    match = _NUMBER.match(text) if len(text) <= MAX_QUANTITY_LENGTH else None
    if not match:
        raise UnitError(f"expected a number with an optional unit, got {quoted(text.strip())}")
    return unit_name(match.group(2)) if match.group(2) else None


# "12.5 cm", "17.98 ft-lb": a quantity is short; a pasted file is not one.
MAX_QUANTITY_LENGTH = 200

# Beyond this magnitude no quantity SASS handles means anything, and squaring
# it (the strength fit, percentiles) would overflow a float.
LARGEST_NUMBER = 1e15


# How many minutes each time unit a rate may be given per holds: the NIOSH
# manual's F (Table 5) and Potvin et al.'s F are per minute, and an observer
# often counts per hour ("120/h") or times one action in seconds.
_MINUTES_IN = {"min": 1.0, "minute": 1.0, "h": 60.0, "hr": 60.0, "hour": 60.0}
_MINUTES_IN |= {"s": 1 / 60, "sec": 1 / 60, "second": 1 / 60}
_RATE = re.compile(r"^\s*([^\s/]+?)\s*(?:(?:/|\bper\b)\s*([A-Za-z]+))?\s*$")


def per_minute(text: str) -> float:
    """Actions per minute from "2", "2/min", "120 / h", "1 per s" or "0.5 per minute";
    a bare number is per minute.  Negative, non-finite or unreadable rates
    raise UnitError."""
    match = _RATE.match(text) if len(text) <= MAX_QUANTITY_LENGTH else None
    if not match:
        raise UnitError(
            f"expected a number per minute (2, 2/min, 120/h), got {quoted(text.strip())}"
        )
    value = finite_number(match.group(1))
    if value < 0:
        raise UnitError(f"{quoted(text.strip())} is negative: expected 0 or more")
    if match.group(2) is None:
        return value
    unit = match.group(2).lower()
    minutes = _MINUTES_IN.get(unit, _MINUTES_IN.get(unit[:-1]) if unit.endswith("s") else None)
    if minutes is None:
        raise UnitError(
            f"{quoted(text.strip())}: per {quoted(match.group(2))} is no time unit (min, h or s)"
        )
    return value / minutes


def finite_number(text: str) -> float:
    """float(text) for a number that is finite and at most LARGEST_NUMBER in size.

    "nan", "inf" and "1e400" (which float() reads as infinity) raise UnitError;
    the caller adds where the text came from.
    """
    try:
        value = float(text)
    except ValueError:
        raise UnitError(f"expected a number, got {quoted(text.strip())}") from None
    if not math.isfinite(value) or abs(value) > LARGEST_NUMBER:
        raise UnitError(
            f"{quoted(text.strip())} is not a usable number (largest {LARGEST_NUMBER:g})"
        )
    return value


@overload
def convert(value: float, from_unit: str, to_unit: str) -> float: ...
@overload
def convert(
    value: npt.NDArray[np.float64], from_unit: str, to_unit: str
) -> npt.NDArray[np.float64]: ...
def convert(
    value: float | npt.NDArray[np.float64], from_unit: str, to_unit: str
) -> float | npt.NDArray[np.float64]:
    """Convert a number or numpy array between registry units (NaN stays NaN)."""
    if from_unit == to_unit:
        return value
    return value * _factor(from_unit, to_unit)


def _dimension_word(unit: str) -> str:
    return {
        "cm": "length",
        "in": "length",
        "mm": "length",
        "m": "length",
        "deg": "angle",
        "rad": "angle",
        "kg": "mass",
        "lb": "mass",
        "ft_lb": "torque",
        "N_m": "torque",
        "N": "force",
        "lbf": "force",
        "deg/s": "angular speed",
    }.get(unit, unit)


def other_unit(group: str, unit: str) -> str:
    """The unit the group's conversion command switches to."""
    a, b = GROUP_UNITS[group]
    return b if unit == a else a
