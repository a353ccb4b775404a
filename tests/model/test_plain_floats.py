"""The first screen's numbers in plain floats equal numpy's.

The TUI computes the default figure before numpy is imported: population
files are read into plain floats and the percentile model runs cell by cell.
Here the same numbers come from numpy's array arithmetic (the vectorised
two-piece normal model written out independently), and must agree to the
last bit.
"""

from __future__ import annotations

import math
from statistics import NormalDist

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model import datasets
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.floats import divide, median
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, JOINT_LIMITS, ROWS
from sass_tui.model.population.percentile import Z95, cell_percentile_of, cell_value_at
from sass_tui.model.session import Session

STANDARD = NormalDist()


def numpy_value_at(stats: np.ndarray, p: float) -> np.ndarray:
    """Spec §2 over arrays: v50 + z(p) * (v50 - v5 or v95 - v50) / z95."""
    v5, v50, v95 = stats[..., 0], stats[..., 1], stats[..., 2]
    z = STANDARD.inv_cdf(p / 100.0)
    out = v50 + z * (np.where(z < 0, v50 - v5, v95 - v50) / Z95)
    out = np.where(p == 5.0, v5, out)
    out = np.where(p == 50.0, v50, out)
    return np.where(p == 95.0, v95, out)


def numpy_percentile_of(stats: np.ndarray, value: np.ndarray) -> np.ndarray:
    v5, v50, v95 = stats[..., 0], stats[..., 1], stats[..., 2]
    diff = value - v50
    with np.errstate(divide="ignore", invalid="ignore"):
        z_lower, z_upper = diff / ((v50 - v5) / Z95), diff / ((v95 - v50) / Z95)
    z = np.where(
        np.isfinite(z_lower) & (z_lower <= 0),
        z_lower,
        np.where(np.isfinite(z_upper) & (z_upper >= 0), z_upper, np.nan),
    )
    z = np.where(diff == 0, 0.0, z)
    z = np.where(np.isnan(v50) | np.isnan(value), np.nan, z)
    out = np.array([STANDARD.cdf(v) * 100.0 if np.isfinite(v) else np.nan for v in z.flat])
    out = out.reshape(z.shape)
    out = np.where((value == v5) & (v5 != v50), 5.0, out)
    return np.where((value == v95) & (v95 != v50), 95.0, out)


PERCENTILES = (0.5, 1.0, 5.0, 12.5, 25.0, 50.0, 63.2, 75.0, 95.0, 97.5, 99.5)


@pytest.mark.parametrize("gender", ["male", "female"])
def test_the_default_figure_at_every_percentile_is_numpys(gender):
    figure = Figure.default(gender)
    for group in (GIRTH, JOINT_LIMITS, CENTER_OF_MASS):
        stats = read_population_file(datasets.path(datasets.FILES[group]), group).stats(gender)
        for p in PERCENTILES:
            figure.set_group_percentile(group, p)
            state = figure.groups[group]
            assert isinstance(state._values, list)  # computed in plain floats
            expected = numpy_value_at(stats, p)
            cells = np.array([[state.cell(r, a)[0] for a in range(3)] for r in range(len(stats))])
            np.testing.assert_array_equal(cells, expected, strict=True)
            np.testing.assert_array_equal(state.values, expected)  # the array, once asked
            np.testing.assert_array_equal(
                state.percentiles, np.where(np.isnan(expected), np.nan, p)
            )


@pytest.mark.parametrize("gender", ["male", "female"])
def test_mass_and_stature_both_ways_are_numpys(gender):
    figure = Figure.default(gender)
    stats = read_population_file(datasets.path("global.dat"), GLOBAL).stats(gender)
    rows = [row.name for row in ROWS[GLOBAL]]
    mass, stature = stats[rows.index("mass"), 0], stats[rows.index("stature"), 0]
    for p in PERCENTILES:
        figure.set_mass_percentile(p)
        figure.set_stature_percentile(p)
        assert figure.mass == numpy_value_at(mass, p)
        assert figure.stature == numpy_value_at(stature, p)
    for kg, cm in ((45.0, 150.0), (82.2, 175.5), (140.0, 205.0)):
        figure.set_mass(kg)
        figure.set_stature(cm)
        assert figure.mass_percentile == numpy_percentile_of(mass, np.float64(kg))
        assert figure.stature_percentile == numpy_percentile_of(stature, np.float64(cm))


finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False)
cells = st.one_of(finite, st.just(0.0), st.just(math.nan), st.sampled_from([1.0, -1.0, 5.0]))


@pytest.mark.slow
@settings(max_examples=500, deadline=None)
@given(v5=cells, v50=cells, v95=cells, p=st.floats(min_value=0.5, max_value=99.5), value=cells)
def test_one_cell_either_way_is_numpys(v5, v50, v95, p, value):
    stats = np.array([v5, v50, v95])
    with np.errstate(all="ignore"):
        expected_value = numpy_value_at(stats, p)
        expected_percentile = numpy_percentile_of(stats, np.float64(value))
    np.testing.assert_array_equal(cell_value_at(v5, v50, v95, p), expected_value)
    np.testing.assert_array_equal(cell_percentile_of(v5, v50, v95, value), expected_percentile)


@settings(max_examples=300, deadline=None)
@given(a=cells, b=cells)
def test_divide_is_ieee_division(a, b):
    with np.errstate(all="ignore"):
        expected = np.float64(a) / np.float64(b)
    np.testing.assert_array_equal(divide(a, b), expected)


@settings(max_examples=300, deadline=None)
@given(st.lists(finite, max_size=9))
def test_median_is_numpys(values):
    if values:
        assert median(values) == np.median(values)
    else:
        assert math.isnan(median(values))


def test_a_file_read_is_plain_floats_until_its_array_is_asked_for():
    data = read_population_file(datasets.path(datasets.FILES[GIRTH]), GIRTH)
    assert isinstance(data.sections["male"], list)
    cell = data.cell("male", 4, 2)
    array = data.stats("male")
    assert array is data.stats("male")  # made once
    assert isinstance(data.sections["male"], list)  # cells go on reading the floats
    assert cell == tuple(array[4, 2]) == data.cell("male", 4, 2)


class Made:
    """A strength_later that counts its calls."""

    def __init__(self, sheet: object) -> None:
        self.sheet, self.calls = sheet, 0

    def __call__(self):
        self.calls += 1
        return self.sheet


def test_a_strength_sheet_made_later_is_made_once_when_first_asked_for():
    from sass_tui.model.strength.strength import StrengthSheet, read_strength_file

    population = Figure.default()
    sheet = StrengthSheet(read_strength_file(), Figure.default("female"))
    later = Made(sheet)
    session = Session(population, strength_later=later)
    assert session.strength_sheets.made() is None and later.calls == 0
    assert not session.can_undo()  # the journal does not make it either
    assert later.calls == 0
    assert session.strength_sheet is sheet and later.calls == 1
    assert sheet.figure is population  # as a sheet given at once
    assert session.strength_sheets.population is sheet and later.calls == 1
    session.set_angle(0, 0, "10")
    assert session.undo() and later.calls == 1


def test_a_strength_sheet_set_before_it_is_made_stays():
    # Input Data for strength before anything asked: the file's sheet, not the
    # default made over it afterwards.
    from sass_tui.model.strength.strength import read_strength_file

    later = Made(None)
    session = Session(Figure.default(), strength_later=later)
    sheet = session.load_strength(read_strength_file())
    assert later.calls == 1
    assert session.strength_sheet is sheet and session.strength_sheets.population is sheet
    assert later.calls == 1


def test_undo_restores_cells_held_either_way():
    # The journal copies a group's cells (plain floats or arrays) and shares
    # its population statistics, which no edit changes.
    session = Session(Figure.default())
    state = session.figure.groups[GIRTH]
    before = [[state.cell(r, a) for a in range(3)] for r in range(len(state.rows))]
    session.set_group_percentile(GIRTH, 80.0)  # plain floats
    session.set_value(GIRTH, 4, 2, 30.0)  # an array
    session.set_cell_percentile(GIRTH, 5, 1, 10.0)
    source = session.figure.groups[GIRTH].source
    while session.undo():
        assert session.figure.groups[GIRTH].source is source
    state = session.figure.groups[GIRTH]
    assert [[state.cell(r, a) for a in range(3)] for r in range(len(state.rows))] == before
