"""Session.show_person with the person's own strength: shown in place
of the population's, or why there is none; Disp. Pop. brings the population's back."""

from __future__ import annotations

import numpy as np

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import GROUPS, ROWS
from sass_tui.model.session import Session
from sass_tui.model.strength.strength import StrengthSheet, person_strength_data, read_strength_file

MEASURED = [("right", "elbow_flexion", (0, 0, 0, 90, 0, 0, 0), 60.0, ("isometric", 0, 0, 0))]


def _session() -> Session:
    figure = Figure.default("male")
    return Session(figure, StrengthSheet(read_strength_file(None), figure))


def _person(session: Session) -> Figure:
    unmeasured = {g: np.full((len(ROWS[g]), 3), np.nan) for g in GROUPS}
    return session.population.for_person("P", "male", unmeasured, mass=80, stature=180)


def test_own_strength_replaces_the_population_s_and_comes_back():
    session = _session()
    population_sheet = session.strength_sheet
    person = _person(session)
    session.show_person(person, 0, person_strength_data("P", "male", MEASURED))
    own = session.strength_sheet
    assert own is not population_sheet and own.figure is person
    assert "P's own strength experiments" in own.title
    session.set_angle(0, 0, "10")
    session.show_population()
    assert session.strength_sheet is population_sheet and session.strength_sheets.missing is None
    assert not session.can_undo()  # the person's sheet and its edits are gone


def test_a_person_without_strength_says_why_and_a_prediction_keeps_the_population_s():
    session = _session()
    population_sheet = session.strength_sheet
    person = _person(session)
    session.show_person(person, 0, "P has no strength experiments")
    assert session.strength_sheet is None
    assert session.strength_sheets.missing == "P has no strength experiments"
    session.show_person(person, -1)  # a predicted figure: the population's strength
    assert session.strength_sheet is population_sheet and session.strength_sheets.missing is None
    assert population_sheet.figure is person
