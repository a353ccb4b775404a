"""Disp. Indv. shows the person's own strength: their experiments in the
database, at their angles (the model side of the strength page)."""

from __future__ import annotations

import math
import sqlite3

import pytest

from sass_tui.db.people.individual import fetch_individual, find_person, strength_measurements
from sass_tui.model.body.figure import Figure
from sass_tui.model.names import GROUPS
from sass_tui.model.strength.strength import (
    ISOKINETIC_DECAY_PER_DEG_S,
    MOTION_NAMES,
    StrengthError,
    StrengthSheet,
    person_strength_data,
)

N_M_PER_FT_LB = 1.3558179483314004


def _person(conn, text):
    person = fetch_individual(conn, find_person(conn, text))
    figure = Figure.default(person.gender).for_person(
        person.name,
        person.gender,
        {g: person.groups[g] for g in GROUPS},
        mass=person.mass,
        stature=person.stature,
        **{
            k: person.strength.get(k)
            for k in ("strength_type", "motion_speed", "training_level", "fatigue_level")
        },
    )
    return person, figure


def _conditions(figure):
    return (figure.strength_type, figure.motion_speed, figure.training_level, figure.fatigue_level)


def test_the_page_shows_the_persons_own_experiments(person_db):
    db, _ = person_db
    with sqlite3.connect(db) as conn:
        person, figure = _person(conn, "1")
        elbow = conn.execute(
            "SELECT e.elbow_ang, e.pstrgh, e.nstrgh FROM elbow_strgh e JOIN strength_par p "
            "USING (id_num, exp_num) WHERE id_num = 1 AND p.strgh_type = 'isometric' "
            "AND p.side_of_limb = 'right'"
        ).fetchone()
    data = person_strength_data(
        person.name, person.gender, strength_measurements(person), _conditions(figure)
    )
    sheet = StrengthSheet(data, figure)
    assert person.name in sheet.title and "own strength experiments" in sheet.title
    assert "TEST DATA" not in sheet.title
    row = sheet.row(MOTION_NAMES.index("elbow_flexion"))
    assert row.source == "stored" and row.angles[3] == elbow[0]
    assert row.value == pytest.approx(elbow[1] / N_M_PER_FT_LB, abs=1e-9)
    extension = sheet.row(MOTION_NAMES.index("elbow_extension"))
    assert extension.value == pytest.approx(elbow[2] / N_M_PER_FT_LB, abs=1e-9)
    # the population's test data give another number for the same motion
    population = StrengthSheet.default(Figure.default(person.gender))
    assert population.row(MOTION_NAMES.index("elbow_flexion")).value != pytest.approx(row.value)


def test_isokinetic_experiments_are_not_mixed_with_isometric_ones(person_db):
    db, _ = person_db
    with sqlite3.connect(db) as conn:
        person, figure = _person(conn, "1")
        speed, fast = conn.execute(
            "SELECT p.speed, e.pstrgh FROM elbow_strgh e JOIN strength_par p "
            "USING (id_num, exp_num) WHERE id_num = 1 AND p.strgh_type = 'isokinetic'"
        ).fetchone()
    measurements = strength_measurements(person)
    data = person_strength_data(
        person.name, person.gender, measurements, ("isokinetic", speed, 0.0, 0.0)
    )
    assert "isokinetic at 60 deg/s" in data.title
    figure.set_strength_parameter("strength_type", "isokinetic")
    figure.set_strength_parameter("motion_speed", speed)
    sheet = StrengthSheet(data, figure)
    elbow = MOTION_NAMES.index("elbow_flexion")
    assert sheet.row(elbow).value == pytest.approx(fast / N_M_PER_FT_LB, abs=1e-9)
    # asked for isometric strength, the measured isokinetic value is scaled back
    # up, by the assumed isokinetic decay, only when it is asked for
    figure.set_strength_parameter("strength_type", "isometric")
    figure.set_strength_parameter("motion_speed", 0)
    assert sheet.row(elbow).value == pytest.approx(fast / N_M_PER_FT_LB, abs=1e-9)
    sheet.assumed_modifiers = True
    expected = fast / N_M_PER_FT_LB * math.exp(ISOKINETIC_DECAY_PER_DEG_S * speed)
    assert sheet.row(elbow).value == pytest.approx(expected, rel=1e-9)


def test_a_person_without_experiments_is_said_so(person_db):
    db, rows = person_db
    with sqlite3.connect(db) as conn:
        person, _ = _person(conn, f"ANSUR II F {rows[0]['SubjectId']}")
    assert strength_measurements(person) == []
    with pytest.raises(StrengthError, match=r"ANSUR II F \d+ has no strength experiments"):
        person_strength_data(person.name, person.gender, [])
