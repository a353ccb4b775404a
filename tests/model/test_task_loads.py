"""A task's hand loads (model/task.parse_hand_load): the force the hand
exerts, then the way it exerts it ('60 N forward', '15 lbf up', '40 N 0,0,2'),
or a mass held ('10 kg': its weight, exerted up)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.errors import SassError
from sass_tui.model.strength.task import TaskError, parse_hand_load


@pytest.mark.parametrize(
    "text, force, direction",
    [("60 N down", 60.0, (0, -1, 0)), ("60N", 60.0, (0, 1, 0)), ("15 lbf up", 66.72, (0, 1, 0)),
     ("40 N 0,0,2", 40.0, (0, 0, 1)), ("10 kg", 98.1, (0, 1, 0)), ("22.0462 lb up", 98.1, (0, 1, 0))],
)  # fmt: skip
def test_a_hand_load_is_a_force_then_its_direction(text, force, direction):
    load = parse_hand_load("left", text)
    assert load.force == pytest.approx(force, abs=0.01)
    assert tuple(load.direction) == pytest.approx(direction)


@pytest.mark.parametrize("text", ["", "abc", "60 N sideways", "-3 N", "nan N", "3 m"])
def test_a_bad_hand_load_is_refused(text):
    with pytest.raises(TaskError if text in ("", "-3 N") else SassError, match="."):
        parse_hand_load("left", text)


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("-10 kg", "the left hand's load '-10 kg': expected a force or a mass of 0 or more"),
        ("10 kg forward", "the left hand's load '10 kg' is a mass"),
        ("60 N 0,0,0", "the left hand's direction '0,0,0': the zero vector has no direction"),
    ],
)
def test_the_task_panels_cell_is_named_not_a_command_line_option(text, said):
    """The Task panel's load cells: the messages named `--left-load` and
    `--direction`, options of `sass task` and `sass strength`."""
    with pytest.raises(SassError) as refused:
        parse_hand_load("left", text)
    assert str(refused.value).startswith(said) and "--" not in str(refused.value)


def test_a_mass_is_held_up_and_another_way_is_refused():
    with pytest.raises(TaskError, match="is a mass: the hand holds its weight up"):
        parse_hand_load("left", "10 kg forward")


@settings(max_examples=80, deadline=None)
@given(st.text(max_size=30))
def test_any_hand_load_text_is_a_load_or_a_clear_refusal(text):
    try:
        load = parse_hand_load("right", text)
    except SassError as exc:
        assert str(exc)
    else:
        assert load.force >= 0 and math.isclose(float((load.direction**2).sum()), 1.0)
