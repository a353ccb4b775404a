"""How the spreadsheet shows values and percentiles (999 blank, as SASS did),
and text from files made safe for the terminal."""

from __future__ import annotations

import math

from sass_tui.model.population.percentile import MAX_PERCENTILE, MIN_PERCENTILE
from sass_tui.model.text import printable

DECIMALS = {"cm": 2, "in": 2, "deg": 1, "rad": 3}


def format_value(value: float, unit: str) -> str:
    """999 (NaN) is shown blank, as SASS did."""
    if value is None or math.isnan(value):
        return ""
    return f"{value:.{DECIMALS.get(unit, 2)}f}"


def format_percentile(p: float) -> str:
    """One decimal; beyond the 0.5th-99.5th percentile model's range (a real
    person, a typed value) `>99.5` or `<0.5`, never a rounded `100.0`."""
    if p is None or math.isnan(p):
        return ""
    if p > MAX_PERCENTILE:
        return f">{MAX_PERCENTILE:g}"
    if p < MIN_PERCENTILE:
        return f"<{MIN_PERCENTILE:g}"
    return f"{p:.1f}"


NO_PERCENTILE = "—"


def format_cell_percentile(value: float, p: float) -> str:
    """A value without a percentile (its row has no spread: 5th, 50th and
    95th equal, and the value is another) shows "—", not a blank that looks
    like a missing value."""
    if not math.isnan(value) and math.isnan(p):
        return NO_PERCENTILE
    return format_percentile(p)


def printable_lines(text: str) -> str:
    """`printable` line by line: a message may span lines, and keeps them."""
    return "\n".join(printable(line) for line in text.split("\n"))
