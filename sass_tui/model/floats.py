"""Float arithmetic as numpy's arrays do it, for the code that runs before
numpy is imported: the TUI's first screen, drawn sooner without it."""

from __future__ import annotations

import math


def divide(a: float, b: float) -> float:
    """a / b with IEEE results instead of ZeroDivisionError: ±inf for a
    non-zero a over zero, NaN for 0/0 and NaN/0."""
    if b == 0:
        if a == 0 or math.isnan(a):
            return math.nan
        return math.copysign(math.inf, a) * math.copysign(1.0, b)
    return a / b


def median(values: list[float]) -> float:
    """The median of values without NaN (NaN if there are none)."""
    ordered = sorted(values)
    middle = len(ordered) // 2
    if not ordered:
        return math.nan
    if len(ordered) % 2:
        return ordered[middle]
    return (ordered[middle - 1] + ordered[middle]) / 2
