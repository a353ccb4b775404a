"""The figure's arithmetic over numpy arrays (model/body/figure.py holds the
figure): a group's cells as an array, a person's percentiles against a
population, the values written out with the population's filling the gaps.

A module of its own because it needs numpy, which the TUI's first screen
goes without (`the first screen`, sass_tui/startup.py): figure.py computes
that screen in plain floats and imports this module the first time an
array is wanted (a cell edit, a person, an export).
"""

from __future__ import annotations

import numpy as np

from sass_tui.model.population.percentile import Grid
from sass_tui.model.population.percentile_arrays import percentile_of, value_at


def array(cells: object) -> np.ndarray:
    """A group's cells (a Grid of plain floats, or an array) as a new float array."""
    return np.array(cells, dtype=float)


def percentiles_against(stats: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Each of a person's values' percentile against the population's
    statistics (rows, 3, 3), in the values' shape."""
    return np.asarray(percentile_of(stats, values), dtype=float).reshape(values.shape)


def filled_values(
    values: np.ndarray | Grid, stats: np.ndarray, percentile: float
) -> tuple[np.ndarray, np.ndarray]:
    """A group's values with each missing one (NaN) the population's at the
    group percentile where the population has one, and the mask of those filled."""
    population = value_at(stats, percentile)
    filled = np.isnan(values) & ~np.isnan(population)
    return np.where(filled, population, values), filled
