"""Joint limits are never an inverted or empty range: for every
joint, axis and both genders, lower <= upper at every percentile 0.5-99.5,
in the model, in the .fig and in the HAnim file."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.fig_reader import parse_fig
from sass_tui.model.files.figfile import joint_limit_variable, render_fig
from sass_tui.model.files.hanim_x3d import render_hanim
from sass_tui.model.names import AXES, JOINT_LIMITS, ROWS
from sass_tui.model.population.percentile_arrays import value_at
from sass_tui.model.strength.strength import StrengthError, check_angle

JOINTS = [row.name[: -len("_ul")] for row in ROWS[JOINT_LIMITS] if row.name.endswith("_ul")]
PERCENTILES = st.floats(min_value=0.5, max_value=99.5, allow_nan=False)
FIGURES = {gender: Figure.default(gender) for gender in ("male", "female")}


def _index(name: str) -> int:
    return [row.name for row in ROWS[JOINT_LIMITS]].index(name)


@pytest.mark.parametrize("gender", ["male", "female"])
def test_every_percentile_on_a_fine_grid(gender):
    stats = FIGURES[gender].groups[JOINT_LIMITS].source.stats(gender)
    grid = np.linspace(0.5, 99.5, 397)
    for joint in JOINTS:
        upper = value_at(stats[_index(f"{joint}_ul")][..., None, :], grid)
        lower = value_at(stats[_index(f"{joint}_ll")][..., None, :], grid)
        ok = np.isnan(upper) | np.isnan(lower) | (lower <= upper)
        assert ok.all(), (gender, joint, grid[~ok.all(axis=0)][:3])


@pytest.mark.slow
@settings(max_examples=40, deadline=None)
@given(gender=st.sampled_from(["male", "female"]), p=PERCENTILES)
def test_model_fig_and_hanim(gender, p):
    figure = Figure.default(gender)
    figure.set_group_percentile(JOINT_LIMITS, p)
    values = figure.groups[JOINT_LIMITS].values
    fig = parse_fig(render_fig(figure)).variables
    for joint in JOINTS:
        upper, lower = values[_index(f"{joint}_ul")], values[_index(f"{joint}_ll")]
        for axis, name in enumerate(AXES):
            if np.isnan(upper[axis]):
                continue
            assert lower[axis] <= upper[axis], (joint, name)
            up = fig[joint_limit_variable(f"{joint}_ul", name)][0]
            low = fig[joint_limit_variable(f"{joint}_ll", name)][0]
            assert low <= up, (joint, name, low, up)
    root = ET.fromstring(render_hanim(figure).split("\n", 2)[2])
    for element in root.iter("HAnimJoint"):
        if "ulimit" in element.attrib:
            upper = np.array([float(v) for v in element.get("ulimit").split()])
            lower = np.array([float(v) for v in element.get("llimit").split()])
            assert (lower <= upper).all(), element.get("name")


def test_default_male_fig_shoulder_and_neck():
    """MALE50.FIG wrote right_shoulder_z_llimit = 108.55deg above its 71.50deg
    upper limit; the 95th neck extension limit was +103."""
    figure = Figure.default("male")
    fig = parse_fig(render_fig(figure)).variables
    assert fig["right_shoulder_z_llimit"][0] == -108.55
    assert fig["left_shoulder_z_llimit"][0] == -108.55
    figure.set_group_percentile(JOINT_LIMITS, 95)
    assert parse_fig(render_fig(figure)).variables["neck_y_llimit"][0] == -103.0


def test_strength_page_and_data_agree_on_the_shoulder():
    """The strength page's check uses the shipped sign as it is."""
    figure = Figure.default("male")
    check_angle(figure, "right", "shoulder_z", -100)
    with pytest.raises(StrengthError, match="lower limit -108.55"):
        check_angle(figure, "right", "shoulder_z", -110)
