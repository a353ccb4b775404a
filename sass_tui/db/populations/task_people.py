"""The people of a target or virtual population for a task (model/strength/task.py's
assess_populations): one Population a gender, each person with their own
age, mass and stature and their weight.  `sass task --target/--virtual` and
the strength page's Task panel read them here."""

from __future__ import annotations

import sqlite3

from sass_tui.db.people.values import load_values
from sass_tui.db.populations.shipped import load_weights
from sass_tui.db.populations.targets import Target, base_query
from sass_tui.model.strength.published_strength import GENDER_WORDS
from sass_tui.model.strength.task import Population


def group_words(target: Target, gender: str | None) -> str:
    """How an answer's column names its people; virtual people are called
    virtual, the weighting is in the notes."""
    who = "everyone" if gender is None else GENDER_WORDS[gender]
    if target.is_virtual:
        return f"VIRTUAL {who}"
    return f"{target.name} {who}"


def weighted_people(conn: sqlite3.Connection, name: str) -> tuple[Target, list[Population]]:
    """The target (or virtual population `virtual:NAME`) `name`, made first if
    it is the shipped one, and its people of each of its genders, weighted."""
    weights = load_weights(conn, name)
    target = weights.target
    groups = []
    for gender in target.genders:
        values = load_values(
            conn, ["age", "mass", "stature"], base_query(target.population, gender)
        )
        age, mass, stature = values.matrix.T
        groups.append(
            Population(
                words=group_words(target, gender),
                gender=gender,
                ages=age,
                masses=mass,
                statures=stature / 100.0,
                weights=weights.of(values.ids),
                note=target.words(),
            )
        )
    return target, groups
