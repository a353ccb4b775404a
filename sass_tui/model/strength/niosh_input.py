"""What a user types for the NIOSH lifting equation, read into its form.

Lengths are typed with their units ("40cm", "16 in"); the first length typed
with a unit chooses the form (inches or feet: the manual's U.S. customary
form, LC 51 lb; any metric length: the metric form, LC 23 kg), and every
length is converted to it; a bare number is in the form's unit (cm or in), a
bare load in its load unit (kg or lb).  A multi-task job's file is model/strength/niosh_tasks.py.
"""

from __future__ import annotations

from collections.abc import Iterable

from sass_tui.model.strength.niosh import COUPLINGS, Form, NioshError, form
from sass_tui.model.text import quoted
from sass_tui.model.units import (
    BASE_FACTORS,
    UnitError,
    parse_quantity,
    per_minute,
    quantity_unit,
)

US_LENGTHS = ("in", "ft")


def form_of(lengths: Iterable[str | None]) -> Form:
    """The form the first length typed with a unit asks for; metric if none."""
    for text in lengths:
        if text is None:
            continue
        unit = quantity_unit(text)
        if unit is None:
            continue
        if BASE_FACTORS[unit][0] != "length":
            raise UnitError(f"{quoted(text)} is not a length")
        return form("us" if unit in US_LENGTHS else "metric")
    return form("metric")


def length(text: str, of: Form) -> float:
    value = parse_quantity(text, of.length_unit)
    if value < 0:
        raise NioshError(f"length {quoted(text)} is negative")
    return value


def load(text: str, of: Form) -> float:
    value = parse_quantity(text, of.load_unit)
    if value < 0:
        raise NioshError(f"load {quoted(text)} is negative")
    return value


def angle(text: str) -> float:
    return parse_quantity(text, "deg")


def frequency(text: str) -> float:
    """Lifts per minute: "2", "2/min", "120/h" (model/units.py's per_minute)."""
    try:
        return per_minute(text)
    except UnitError as exc:
        raise NioshError(f"lifts per minute: {exc}") from None


def coupling(text: str) -> str:
    word = text.strip().lower()
    if word not in COUPLINGS:
        raise NioshError(f"coupling {quoted(text)}: expected good, fair or poor")
    return word


def travel(d: str | None, v: float, dest_v: float | None, of: Form) -> float:
    """D: typed, else |V at the destination - V at the origin|."""
    if d is not None:
        return length(d, of)
    if dest_v is None:
        raise NioshError("give the vertical travel distance D (or V at the destination)")
    return abs(dest_v - v)
