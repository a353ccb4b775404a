"""The figure model: global data, group percentiles, per-cell overrides (undo: test_session)."""

from __future__ import annotations

import numpy as np
import pytest

from sass_tui.model.body.figure import Figure, FigureError
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS, MASS_FRACTIONS, row_index
from sass_tui.model.population.percentile import PercentileError

ARM = row_index(GIRTH, "right_upper_arm")


def test_defaults():
    figure = Figure.default()
    assert (figure.gender, figure.figure_type, figure.strength_type) == (
        "male",
        "skinny",
        "isometric",
    )
    assert figure.population == "NASA Crewmember Trainees"
    assert all(figure.groups[g].percentile == 50 for g in (GIRTH, JOINT_LIMITS, CENTER_OF_MASS))
    assert figure.groups[GIRTH].values[ARM, 2] == 36.6


def test_group_percentile_rescales_that_group_only():
    figure = Figure.default()
    joints = figure.groups[JOINT_LIMITS].values.copy()
    figure.set_group_percentile(GIRTH, 95)
    assert figure.groups[GIRTH].values[ARM, 2] == 39.4
    np.testing.assert_array_equal(figure.groups[JOINT_LIMITS].values, joints)


def test_editing_a_value_sets_its_percentile_and_the_reverse():
    figure = Figure.default()
    figure.set_value(GIRTH, ARM, 2, 39.4)
    assert figure.groups[GIRTH].percentiles[ARM, 2] == 95.0
    figure.set_cell_percentile(GIRTH, ARM, 2, 5)
    assert figure.groups[GIRTH].values[ARM, 2] == 33.7
    assert figure.groups[GIRTH].percentiles[ARM, 0] == 50.0  # other cells untouched


def test_no_motion_cells_cannot_be_edited():
    figure = Figure.default()
    with pytest.raises(FigureError, match="no motion about this axis"):
        figure.set_value(JOINT_LIMITS, row_index(JOINT_LIMITS, "right_elbow_ul"), 0, 10)


def test_gender_switch_reloads_every_group_at_its_percentile():
    figure = Figure.default()
    figure.set_group_percentile(GIRTH, 5)
    figure.set_group_percentile(JOINT_LIMITS, 95)
    figure.set_gender("female")
    assert figure.groups[GIRTH].values[ARM, 2] == 27.2  # appendix C, 5th
    elbow = row_index(JOINT_LIMITS, "right_elbow_ul")
    assert figure.groups[JOINT_LIMITS].values[elbow, 1] == 165.9  # appendix I, 95th
    assert figure.groups[CENTER_OF_MASS].values[0, 2] == 9.0  # L.2 female, 50th
    assert figure.mass == pytest.approx(66.8)


def test_mass_and_stature_by_value_or_percentile():
    figure = Figure.default()
    figure.set_mass(figure.global_stats.stats("male")[1, 0, 2])
    assert figure.mass_percentile == 95.0
    figure.set_stature_percentile(5)
    assert figure.stature == figure.global_stats.stats("male")[0, 0, 0]
    with pytest.raises(PercentileError):
        figure.set_mass_percentile(120)
    with pytest.raises(FigureError):
        figure.set_mass(-3)


def test_segment_masses_sum_to_the_total():
    figure = Figure.default()
    masses = dict(figure.segment_masses())
    assert sum(masses.values()) == pytest.approx(82.2)
    assert len(masses) == len(MASS_FRACTIONS)
    assert masses["ctorsomass"] == pytest.approx(0.138 * 82.2)


def test_refused_edits_change_nothing():
    figure = Figure.default()
    with pytest.raises(FigureError, match="gender must be male or female"):
        figure.set_gender("alien")
    with pytest.raises(PercentileError):
        figure.set_group_percentile(GIRTH, 120)
    assert figure.gender == "male" and figure.groups[GIRTH].percentile == 50
