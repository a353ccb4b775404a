"""The Task panel's settings as a worksheet keeps them (model/files/worksheet.py,
the key "task"): the task's own posture (JOINT=ANGLE words; none: the
strength page's row), the force each hand exerts as typed ('60 N up',
'10 kg'; none: no force) and the people.  Read back, their shape is checked
here, naming the field; their words when the panel takes them (a bad one
is said on the message line and the panel keeps its own).  No numpy here:
a worksheet opens without the task's models."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from sass_tui.model.errors import SassError

SIDES = ("left", "right")


@dataclass(frozen=True)
class TaskSettings:
    posture: tuple[str, ...]
    loads: tuple[tuple[str, str], ...]  # (side, the force as typed)
    people: str


class TaskSettingsError(ValueError, SassError):
    """A worksheet's "task" that is not the Task panel's settings."""


def task_settings_out(settings: TaskSettings | None) -> dict[str, Any] | None:
    if settings is None:
        return None
    return {
        "posture": list(settings.posture),
        "loads": {side: text for side, text in settings.loads},
        "people": settings.people,
    }


def read_task_settings(value: object, name: str) -> TaskSettings | None:
    """The "task" of worksheet `name` (None: the worksheet has none)."""
    if value is None:
        return None

    def fail(field: str, expected: str, got: object) -> TaskSettingsError:
        return TaskSettingsError(f"{name}: task.{field}: expected {expected}, got {got!r}")

    if not isinstance(value, dict):
        raise fail("", "an object", value)
    posture = value.get("posture", [])
    if not isinstance(posture, list) or not all(isinstance(w, str) for w in posture):
        raise fail("posture", "a list of JOINT=ANGLE words", posture)
    loads = value.get("loads", {})
    if not isinstance(loads, dict) or not set(loads) <= set(SIDES):
        raise fail("loads", "an object with left and right", loads)
    for side, text in loads.items():
        if not isinstance(text, str) or not text.strip():
            raise fail(f"loads.{side}", "a force such as '60 N up'", text)
    people = value.get("people", "gender")
    if not isinstance(people, str) or not people.strip():
        raise fail("people", "the people's words", people)
    ordered = tuple((side, loads[side]) for side in SIDES if side in loads)
    return TaskSettings(tuple(posture), ordered, people)
