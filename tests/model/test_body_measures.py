"""The body's measurements (model/body/body_measures.py): the shipped table is
`sass predict`'s regression on stature and mass, and a person's own values
win over it."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.db.people.default import open_database
from sass_tui.db.populations.predict import open_predictor
from sass_tui.model.body.body_measures import (
    MEASURED,
    PREDICTED,
    SURFACE_MEASURES,
    body_measures,
    predicted_measures,
)


@pytest.fixture(scope="module")
def predictor(shipped_db_file):
    conn = open_database(shipped_db_file)
    try:
        return open_predictor(conn, cache=False)
    finally:
        conn.close()


@pytest.mark.slow
@settings(max_examples=20, deadline=None)
@given(
    gender=st.sampled_from(["male", "female"]),
    stature=st.floats(150.0, 195.0),
    mass=st.floats(50.0, 110.0),
)
def test_the_table_is_what_sass_predict_gives(predictor, gender, stature, mass):
    """At any stature and mass the table's value is the predictor's, within
    0.01 cm (the table keeps six decimals)."""
    table = predicted_measures(gender, stature, mass)
    prediction = predictor.predict(gender, {"stature": stature, "mass": mass})
    for name in SURFACE_MEASURES:
        assert table[name] == pytest.approx(prediction.value(f"measure.{name}"), abs=0.01), name


def test_a_person_s_own_values_win_and_say_so():
    own = {"chestcircumference": 101.0, "waistcircumference": math.nan, "hipbreadth": 0.0}
    measures = body_measures("male", 175.0, 80.0, own)
    assert measures.values["chestcircumference"] == 101.0
    assert measures.sources["chestcircumference"] == MEASURED
    assert measures.sources["waistcircumference"] == PREDICTED
    assert measures.sources["hipbreadth"] == PREDICTED
    assert measures.counts() == {MEASURED: 1, PREDICTED: len(SURFACE_MEASURES) - 1}
    assert measures.m("chestcircumference") == pytest.approx(1.01)


def test_a_heavier_person_is_wider_at_the_waist_and_not_taller():
    light = predicted_measures("female", 165.0, 55.0)
    heavy = predicted_measures("female", 165.0, 95.0)
    assert heavy["waistcircumference"] > light["waistcircumference"] + 20
    assert abs(heavy["chestheight"] - light["chestheight"]) < 3
