"""The people of a target or virtual population for a task (model/strength/task.py's
assess_populations): one Population a gender, each person with their own
age, mass and stature and their weight.  `sass task --target/--virtual` and
the strength page's Task panel read them here."""

from __future__ import annotations

import sqlite3

import numpy as np

from sass_tui.db.people.values import Values, load_values
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


def weighted_values(
    conn: sqlite3.Connection, name: str, fields: list[str]
) -> tuple[Target, list[tuple[str, Values, np.ndarray]]]:
    """The target (or virtual population `virtual:NAME`) `name`, made first if
    it is the shipped one, and for each of its genders its people's `fields`
    (query-language names) and weights."""
    weights = load_weights(conn, name)
    target = weights.target
    out = []
    for gender in target.genders:
        values = load_values(conn, fields, base_query(target.population, gender))
        out.append((gender, values, weights.of(values.ids)))
    return target, out


def weighted_people(conn: sqlite3.Connection, name: str) -> tuple[Target, list[Population]]:
    """The target (or virtual population `virtual:NAME`) `name`, made first if
    it is the shipped one, and its people of each of its genders, weighted."""
    target, groups = weighted_values(conn, name, ["age", "mass", "stature"])
    people = []
    for gender, values, weights in groups:
        age, mass, stature = values.matrix.T
        people.append(
            Population(
                words=group_words(target, gender),
                gender=gender,
                ages=age,
                masses=mass,
                statures=stature / 100.0,
                weights=weights,
                note=target.words(),
            )
        )
    return target, people
