"""Percentile interpolation: the two-piece normal model of spec §2.

From the stored 5th/50th/95th percentile values of a measurement,
    v(p) = v50 + z(p) * s,   s = (v50 - v5)/z95 below the median, (v95 - v50)/z95 above,
where z(p) is the standard normal quantile and z95 = z(95) = 1.64485...  The
inverse uses the same pieces.  Rows may run either way (a lower joint limit
grows more negative with the percentile).

The model is written once, for one cell in plain floats (`cell_value_at`,
`cell_percentile_of`): the TUI's first screen is computed with them before
numpy is imported, to start sooner.  `value_at` and `percentile_of` apply them
over numpy arrays whose last axis holds (v5, v50, v95), with broadcasting:
they are model/population/percentile_arrays.py, which imports numpy at its top (off the
first screen, sass_tui/startup.py).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from statistics import NormalDist

from sass_tui.model.errors import SassError
from sass_tui.model.floats import divide

# One cell's stored (v5, v50, v95), and a group's (rows, 3 axes) cells in
# plain floats, before numpy is wanted.
Cell = tuple[float, float, float]
Grid = list[list[float]]

MIN_PERCENTILE = 0.5
MAX_PERCENTILE = 99.5
_STANDARD = NormalDist()
# The spec writes 1.6449; the exact quantile keeps v(5) and v(95) equal to the
# stored values to the last bit instead of to 1e-5.
Z95 = _STANDARD.inv_cdf(0.95)


class PercentileError(ValueError, SassError):
    """A percentile outside 0.5-99.5, or not a number."""


def _refuse(p: float) -> PercentileError:
    return PercentileError(f"percentile {p:g} is outside {MIN_PERCENTILE:g}-{MAX_PERCENTILE:g}")


def check_percentile(p: float) -> float:
    """One percentile (an edit's, an option's), in plain floats: 0.5-99.5,
    else PercentileError (NaN too).  Over an array: percentile_arrays.py."""
    if not MIN_PERCENTILE <= p <= MAX_PERCENTILE:
        raise _refuse(float(p))
    return p


def cell_value_at(v5: float, v50: float, v95: float, p: float) -> float:
    """The value at percentile p (0.5-99.5, checked by the caller) of one
    cell; NaN (no value) stays NaN."""
    # Exact at the stored percentiles, whatever rounding the arithmetic does.
    if p == 5.0:
        return v5
    if p == 50.0:
        return v50
    if p == 95.0:
        return v95
    z = _STANDARD.inv_cdf(p / 100.0)
    spread = (v50 - v5 if z < 0 else v95 - v50) / Z95
    return v50 + z * spread


def cell_percentile_of(v5: float, v50: float, v95: float, value: float) -> float:
    """The percentile of one value against one cell's statistics (the inverse
    of cell_value_at).

    Not clipped to 0.5-99.5: a real person can lie outside it (the sheet
    shows `>99.5` or `<0.5`).  NaN where it is undefined: no stored value, or
    a degenerate row (all three equal) with a value other than that one.  A
    degenerate row's own value is at the 50th (the sheet shows no percentile
    for it: `has_spread`).
    """
    # Exact at the stored percentiles (the 95th first, as a row whose 5th
    # and 95th are equal has always given).
    if value == v95 and v95 != v50:
        return 95.0
    if value == v5 and v5 != v50:
        return 5.0
    if math.isnan(v50) or math.isnan(value):
        return math.nan
    diff = value - v50
    if diff == 0:
        return 50.0
    # The piece on which the value lies: z <= 0 on the lower, z >= 0 on the
    # upper piece.  Either can serve a non-monotonic row; prefer the lower.
    z_lower = divide(diff, (v50 - v5) / Z95)
    z_upper = divide(diff, (v95 - v50) / Z95)
    if math.isfinite(z_lower) and z_lower <= 0:
        z = z_lower
    elif math.isfinite(z_upper) and z_upper >= 0:
        z = z_upper
    else:
        return math.nan
    return _STANDARD.cdf(z) * 100.0


def has_spread(v5: float, v50: float, v95: float) -> bool:
    """Whether a cell's values differ by percentile: a cell whose 5th, 50th
    and 95th are equal (the shipped eyes' 2.2/2.2/2.2, a center of mass on
    the segment's axis) has no percentile to show."""
    return not v5 == v50 == v95


def plausible_range(v5: float, v50: float, v95: float) -> tuple[float, float]:
    """The values of one cell's 0.5th and 99.5th percentiles, lower first:
    a typed value outside them is accepted with a warning naming them."""
    ends = cell_value_at(v5, v50, v95, MIN_PERCENTILE), cell_value_at(v5, v50, v95, MAX_PERCENTILE)
    return min(ends), max(ends)


def grid_at(cells: Callable[[int, int], Cell], rows: int, p: float) -> tuple[Grid, Grid]:
    """A group of `rows` rows at percentile p, cell by cell in plain floats
    (`cells(row, axis)` gives a cell's stored values): the values, and each
    value's percentile (p; NaN where there is no value)."""
    values = [[cell_value_at(*cells(row, axis), p) for axis in range(3)] for row in range(rows)]
    return values, [[math.nan if math.isnan(v) else p for v in row] for row in values]
