"""The Session: one undo journal for the figure and the strength angles;
an entry only for an accepted edit."""

from __future__ import annotations

import pytest

from sass_tui.model.body.figure import Figure
from sass_tui.model.errors import SassError
from sass_tui.model.names import GIRTH, JOINT_LIMITS, row_index
from sass_tui.model.session import Session
from sass_tui.model.strength.strength import StrengthSheet

ARM = row_index(GIRTH, "right_upper_arm")


@pytest.fixture(scope="module")
def default_figure() -> Figure:
    return Figure.default()


def fresh_session(default_figure: Figure, strength: bool = False) -> Session:
    figure = Figure.default()
    return Session(figure, StrengthSheet.default(figure) if strength else None)


def test_a_refused_edit_leaves_nothing_to_undo(default_figure):
    session = fresh_session(default_figure)
    with pytest.raises(SassError, match="figure type"):
        session.set_figure_type("banana")
    assert session.figure.figure_type == "skinny"
    assert not session.undo()


def test_a_refused_edit_never_blocks_undoing_a_newer_angle_edit(default_figure):
    session = fresh_session(default_figure, strength=True)
    sheet = session.strength_sheet
    before = sheet.angles.copy()
    with pytest.raises(SassError):
        session.set_figure_type("banana")
    session.set_angle(0, 0, "60")
    with pytest.raises(SassError):
        session.set_strength_parameter("handedness", "both")
    assert session.undo()
    assert (sheet.angles == before).all()
    assert not session.undo()


def test_undo_goes_back_one_edit_at_a_time(default_figure):
    session = fresh_session(default_figure)
    figure = session.figure
    session.set_value(GIRTH, ARM, 2, 30.0)
    session.set_group_percentile(JOINT_LIMITS, 5)
    assert session.undo()
    assert figure.groups[JOINT_LIMITS].percentile == 50
    assert figure.groups[GIRTH].values[ARM, 2] == 30.0
    assert session.undo()
    assert figure.groups[GIRTH].values[ARM, 2] == 36.6
    assert not session.undo()


def test_angle_and_figure_edits_undo_newest_first(default_figure):
    session = fresh_session(default_figure, strength=True)
    sheet, figure = session.strength_sheet, session.figure
    before = sheet.angles.copy()
    session.set_angle(0, 0, "60")
    session.set_mass_percentile(95)
    session.set_angle(0, 1, "0.5 rad")
    assert session.undo()
    assert sheet.angles[0, 1] == before[0, 1] and sheet.angles[0, 0] == 60
    assert session.undo() and figure.mass_percentile == 50
    assert session.undo() and (sheet.angles == before).all()
    assert not session.undo()


def test_display_units_are_not_undone(default_figure):
    session = fresh_session(default_figure)
    session.set_value(GIRTH, ARM, 2, 30.0)
    session.set_unit(GIRTH, "in")
    assert session.undo()
    assert session.figure.groups[GIRTH].unit == "in"


def test_a_person_edits_apart_from_the_population(default_figure):
    session = fresh_session(default_figure, strength=True)
    population = session.figure
    session.set_mass_percentile(95)
    person = population.for_person(
        "DOE", "male", {g: s.values.copy() for g, s in population.groups.items()}
    )
    session.show_person(person, 0)
    assert session.figure is person and session.strength_sheet.figure is person
    session.set_value(GIRTH, ARM, 2, 31.0)
    assert session.undo() and person.groups[GIRTH].values[ARM, 2] != 31.0
    # The population's edit waits for the population to be shown again.
    assert not session.undo()
    session.set_value(GIRTH, ARM, 2, 32.0)
    session.show_population()
    assert session.strength_sheet.figure is population
    assert session.undo() and population.mass_percentile == 50
    assert not session.undo()


def test_undo_says_what_it_undid_and_redo_does_it_again(default_figure):
    session = fresh_session(default_figure, strength=True)
    session.set_value(GIRTH, ARM, 2, 31.0)
    session.set_mass(70)
    session.set_angle(0, 0, 40)
    assert session.undo() == "Shoulder abduction: shoulder x 40 deg"
    assert session.strength_sheet.angles[0, 0] != 40
    assert session.redo() == "Shoulder abduction: shoulder x 40 deg"
    assert session.strength_sheet.angles[0, 0] == 40
    assert session.undo() == "Shoulder abduction: shoulder x 40 deg"
    assert session.undo() == "mass 70 kg"
    assert session.undo() == "Right Upper Arm z value 31 cm"
    assert session.figure.groups[GIRTH].values[ARM, 2] != 31.0
    assert session.redo() == "Right Upper Arm z value 31 cm"
    assert session.figure.groups[GIRTH].values[ARM, 2] == 31.0
    # Undone and redone again, the snapshot is still the one taken.
    assert session.undo() and session.redo()
    assert session.figure.groups[GIRTH].values[ARM, 2] == 31.0
    session.set_mass(80)  # a new edit: nothing left to redo
    assert session.redo() is None
    assert session.figure.mass == 80
