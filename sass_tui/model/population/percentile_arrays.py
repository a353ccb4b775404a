"""The percentile model of model/population/percentile.py over numpy arrays: values and
percentiles of a whole group (stats[..., 0:3] = v5, v50, v95, with
broadcasting), a percentile array checked, normal scores.

A module of its own because it needs numpy, which the TUI's first screen
goes without (`the first screen`, sass_tui/startup.py): that screen is
computed cell by cell in plain floats (percentile.py), and this module is
imported by the modules that work on arrays (the figure's numpy half,
model/body/figure_arrays.py; the humanoid; the strength data).
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from sass_tui.model.population.percentile import (
    _STANDARD,
    MAX_PERCENTILE,
    MIN_PERCENTILE,
    _refuse,
    cell_percentile_of,
    cell_value_at,
    check_percentile,
)


def check_percentiles(p: npt.ArrayLike) -> npt.ArrayLike:
    """Percentile(s) p, a number or an array: each 0.5-99.5, else PercentileError."""
    if isinstance(p, (int, float)):  # the one percentile of an edit
        return check_percentile(p)
    arr = np.asarray(p, dtype=float)
    bad = ~((arr >= MIN_PERCENTILE) & (arr <= MAX_PERCENTILE))
    if np.any(bad):
        raise _refuse(arr[bad].flat[0] if arr.ndim else float(arr))
    return p


def z_score(p: npt.ArrayLike) -> npt.NDArray[np.float64] | np.float64:
    """Standard normal quantile of percentile(s) p (0.5-99.5)."""
    arr = np.asarray(p, dtype=float)
    if arr.ndim == 0:
        return np.float64(_STANDARD.inv_cdf(float(arr) / 100.0))
    return np.asarray(np.frompyfunc(_STANDARD.inv_cdf, 1, 1)(arr / 100.0), dtype=float)


def value_at(stats: npt.NDArray[np.float64], p: npt.ArrayLike) -> npt.NDArray[np.float64]:
    """Values at percentile p over an array.  stats[..., 0:3] = (v5, v50,
    v95); p broadcasts against stats[..., 0]."""
    check_percentiles(p)
    stats = np.asarray(stats, dtype=float)
    # The flags the cells' float arithmetic raises (NaN compared) are not errors.
    with np.errstate(all="ignore"):
        cells = np.frompyfunc(cell_value_at, 4, 1)(stats[..., 0], stats[..., 1], stats[..., 2], p)
    return np.asarray(cells, dtype=float)


def percentile_of(
    stats: npt.NDArray[np.float64], value: npt.ArrayLike
) -> npt.NDArray[np.float64] | np.float64:
    """Percentiles of value(s) against stats, over an array (see
    cell_percentile_of); a 0-d result is a numpy float."""
    stats = np.asarray(stats, dtype=float)
    with np.errstate(all="ignore"):  # as value_at
        cells = np.frompyfunc(cell_percentile_of, 4, 1)(
            stats[..., 0], stats[..., 1], stats[..., 2], np.asarray(value, dtype=float)
        )
    out = np.asarray(cells, dtype=float)
    return out if out.ndim else np.float64(out)
