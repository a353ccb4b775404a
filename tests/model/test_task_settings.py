"""The Task panel's settings in the worksheet (model/files/task_settings.py):
written and read back, a bad shape refused naming the field."""

from __future__ import annotations

import json

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.task_settings import (
    TaskSettings,
    TaskSettingsError,
    read_task_settings,
    task_settings_out,
)
from sass_tui.model.files.worksheet import parse_worksheet, worksheet_text
from sass_tui.model.session import Session


def test_the_task_goes_round_the_worksheet():
    session = Session(Figure.default("female"))
    session.task = TaskSettings(
        ("trunk_y=30", "hip_y=60"), (("left", "5 kg"), ("right", "40 N forward")), "women"
    )
    back = parse_worksheet(worksheet_text(session), "w.sass.json")
    assert back.task == session.task
    session.task = None
    assert parse_worksheet(worksheet_text(session)).task is None


@pytest.mark.parametrize(
    "value, field",
    [([], "task.: expected an object"), ({"posture": "hip_y=3"}, "task.posture"),
     ({"loads": {"middle": "3 N"}}, "task.loads"), ({"loads": {"left": 3}}, "task.loads.left"),
     ({"people": ""}, "task.people")],
)  # fmt: skip
def test_a_bad_task_names_its_field(value, field):
    with pytest.raises(TaskSettingsError, match=f"w.json: {field}"):
        read_task_settings(value, "w.json")


json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.text(max_size=8),
    lambda inner: (
        st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=8), inner, max_size=3)
    ),
    max_leaves=8,
)


@settings(max_examples=60, deadline=None)
@given(st.dictionaries(st.sampled_from(["posture", "loads", "people", "x"]), json_values))
def test_any_task_value_is_settings_or_a_clear_refusal(value):
    try:
        found = read_task_settings(json.loads(json.dumps(value)), "w.json")
    except TaskSettingsError as exc:
        assert str(exc).startswith("w.json: task.")
    else:
        assert found is not None and read_task_settings(task_settings_out(found), "w") == found
