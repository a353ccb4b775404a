"""A task's hand loads (model/task.parse_hand_load): a force, then the way
it pulls ('60 N down', '15 lbf up', '40 N 0,0,2')."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.errors import SassError
from sass_tui.model.strength.task import TaskError, parse_hand_load


@pytest.mark.parametrize(
    "text, force, direction",
    [("60 N down", 60.0, (0, -1, 0)), ("60N", 60.0, (0, -1, 0)), ("15 lbf up", 66.72, (0, 1, 0)),
     ("40 N 0,0,2", 40.0, (0, 0, 1))],
)  # fmt: skip
def test_a_hand_load_is_a_force_then_its_direction(text, force, direction):
    load = parse_hand_load("left", text)
    assert load.force == pytest.approx(force, abs=0.01)
    assert tuple(load.direction) == pytest.approx(direction)


@pytest.mark.parametrize("text", ["", "abc", "60 N sideways", "-3 N", "nan N"])
def test_a_bad_hand_load_is_refused(text):
    with pytest.raises(TaskError if text in ("", "-3 N") else SassError, match="."):
        parse_hand_load("left", text)


@settings(max_examples=80, deadline=None)
@given(st.text(max_size=30))
def test_any_hand_load_text_is_a_load_or_a_clear_refusal(text):
    try:
        load = parse_hand_load("right", text)
    except SassError as exc:
        assert str(exc)
    else:
        assert load.force >= 0 and math.isclose(float((load.direction**2).sum()), 1.0)
