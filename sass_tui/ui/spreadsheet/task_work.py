"""The Task panel's work (ui/spreadsheet/task_panel.py): what its worker
gets (TaskInput, an immutable copy of the figure and the task) and what it
computes off the UI thread: the answer for the people asked for (a target's
or virtual population's read from the database), the curves of percent
capable against a hand's load, and the angles of the figure shown (its own
stoop or squat for `hands=H,V`, model/strength/hands_at.py).  No widget here.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from sass_tui.db.engine.database import Database
from sass_tui.db.populations.task_people import group_words, weighted_people
from sass_tui.db.query.scope import VIRTUAL_PREFIX
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import Angles
from sass_tui.model.strength.hands_at import posture_of, split_posture
from sass_tui.model.strength.published_strength import GENDER_WORDS
from sass_tui.model.strength.task import (
    CurveGroup,
    HandLoad,
    Reference,
    TaskAnswer,
    assess_populations,
    assess_task,
    hand_curves,
    pose_task,
)
from sass_tui.ui.spreadsheet.task_words import WEIGHTED


@dataclass(frozen=True)
class TaskInput:
    """What the worker gets: a copy of the figure shown and the task."""

    figure: Figure
    posture: tuple[str, ...]
    loads: tuple[HandLoad, ...]
    people: str
    db_path: str | Path | None  # the database a target or virtual population is read from
    curve_side: str = ""  # the hand whose percent capable against its load is drawn


Curves = dict[str, list[tuple[float, float]]]


def references(task: TaskInput) -> list[Reference]:
    """The figures standing for the people asked for."""
    figure = task.figure
    if task.people == "figure":
        return [Reference(figure.person or "figure shown", figure, None)]
    genders = {
        "gender": (figure.gender,),
        "women": ("female",),
        "men": ("male",),
        "women and men": ("female", "male"),
    }[task.people]
    return [Reference(GENDER_WORDS[g], Figure.default(g), None) for g in genders]


def assess(task: TaskInput) -> tuple[TaskAnswer, Curves, Angles]:
    """The task for the people asked for (a target's or virtual population's
    read from the database, the shipped one made the first time), when
    asked the curves of percent capable against the load on a hand, and the
    angles of the figure shown (its own stoop or squat for `hands=H,V`)."""
    loads = list(task.loads)
    angles, goal = split_posture(task.posture)
    posture = posture_of(angles, goal, loads)
    shown = posture(task.figure) if callable(posture) else posture
    kind, _, name = task.people.partition(" ")
    together = ""
    if kind not in WEIGHTED:
        chosen = references(task)
        answer = assess_task(chosen, posture, loads)
        groups = [
            CurveGroup(
                r.words,
                pose_task(r.figure, answer.postures.get(r.words, shown), loads)[0],
                r.figure.gender,
            )
            for r in chosen
        ]
    else:
        db = Database.open(task.db_path)
        try:
            with db.connection() as conn:
                target, people = weighted_people(
                    conn, f"{VIRTUAL_PREFIX}{name}" if kind == "virtual" else name
                )
        finally:
            db.close()
        figures = [(Figure.default(group.gender), group) for group in people]
        together = group_words(target, None)
        answer = assess_populations(figures, posture, loads, together)
        groups = [
            CurveGroup(
                group.words,
                pose_task(figure, answer.postures.get(group.words, shown), loads)[0],
                group.gender,
                group,
            )
            for figure, group in figures
        ]
    load = next((x for x in loads if x.side == task.curve_side and x.force > 0), None)
    return answer, {} if load is None else hand_curves(groups, load, together), shown
