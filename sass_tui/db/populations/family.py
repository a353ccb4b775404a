"""Manikin families from the database: the population's people of a gender,
their values and the database's prediction model (model/population/accommodation.py
builds the family), for `sass family` and the family screen.

Separate from db/populations/fit.py (the fit test, which `sass fit` runs without the
prediction model: its row in sass_tui/startup.py forbids db.predict), so
that db/populations/predict.py is imported at this module's top.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Sequence
from dataclasses import replace
from typing import TYPE_CHECKING

import numpy as np

from sass_tui.db.people.values import Values, load_values
from sass_tui.db.populations.fit import DEFAULT_POPULATION, FitError
from sass_tui.db.populations.predict import open_predictor
from sass_tui.db.progress import Cancel, Progress, Steps, interruptible
from sass_tui.db.query.query import ParsedQuery, joined, parsed
from sass_tui.model.population.accommodation import Family, build_family
from sass_tui.model.population.measure_fields import measure_field
from sass_tui.model.population.targets import kish_effective_n
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.engine.database import Database
    from sass_tui.db.populations.targets import TargetWeights
    from sass_tui.model.population.prediction import Predictor


def load_family(
    conn: sqlite3.Connection,
    gender: str,
    measures: Sequence[str],
    target: float,
    kind: str = "boundary",
    population: str | ParsedQuery = DEFAULT_POPULATION,
    predictor: Predictor | None = None,
    progress: Progress | None = None,
    cancel: Cancel | None = None,
    weighted_to: TargetWeights | None = None,
) -> Family:
    """The manikin family of `gender` over `measures` (see
    `sass_tui.model.population.accommodation`): the population's people of that gender,
    their values, and the database's prediction model to complete each manikin.
    `measures` are `--measures` names (`stature`, `mass`, `sittingheight`, ...).
    `progress(steps done, 3)`: the people read, the model, the family built;
    `cancel` stops it with Cancelled between them (it writes nothing).
    `weighted_to` (a target population of `gender`): the target's people, weighted."""
    if gender not in GENDERS:
        raise FitError(f"gender must be {' or '.join(GENDERS)}, not {gender!r}")
    fields = [measure_field(m) for m in measures]
    people_query = parsed(population)  # its own error, before the combined query's
    if weighted_to is not None:
        made = weighted_to.target
        if gender not in made.genders:
            raise FitError(f"the target {made.name} is of {made.gender} people, not {gender}")
        if people_query.text != made.population:
            people_query = joined(people_query, made.population)
    steps = Steps(progress, cancel, "the family")
    steps(0, 3)
    with interruptible(conn, cancel, "the family"):
        values = load_values(conn, fields, joined(people_query, f"gender = {gender}"))
    if weighted_to is not None and weighted_to.target.is_virtual:
        # a virtual population's people are its weighted ones (--within-range leaves some out)
        values = values.only(weighted_to.ids)
    steps(1, 3)
    if len(values) == 0:
        raise FitError(f"the population {people_query.text!r} has no {gender} people")
    with interruptible(conn, cancel, "the family"):
        model = predictor if predictor is not None else open_predictor(conn)
    steps(2, 3)
    weights = None if weighted_to is None else weighted_to.of(values.ids)
    family = build_family(
        gender, fields, values.ids, values.names, values.matrix, target, model, kind, weights
    )
    if weighted_to is not None and weights is not None:
        used = ~np.isnan(values.matrix).any(axis=1)
        family = replace(
            family,
            target=weighted_to.target.to_json()
            | {"effective_n": round(kish_effective_n(weights[used]), 2)},
        )
    steps(3, 3)
    return family


# --- the limits drawn on the population (the Fit Test screen's histogram) --------


def family_and_scatter(
    database: Database,
    gender: str,
    measures: Sequence[str],
    target: float,
    kind: str,
    population: str,
    progress: Progress | None = None,
    cancel: Cancel | None = None,
) -> tuple[Family, Values]:
    """The manikin family (load_family) and the people's values of its first
    two measures: the scatter the family screen draws it over, read under
    the database's lock."""
    with database.connection() as conn:
        family = load_family(
            conn, gender, measures, target, kind, population, progress=progress, cancel=cancel
        )
        people = load_values(
            conn, list(family.measures[:2]), f"({population}) AND gender = {gender}"
        )
    return family, people
