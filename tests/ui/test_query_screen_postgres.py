"""The TUI on a lab's PostgreSQL database (`sass --db postgresql://...`): the
query screen opens it, runs a query, selects the people and shows a person,
with the counts SQLite gives after the same `sass db init`; the family
screen builds the family SQLite's database gives.  The fixture
`initialised` is tests/conftest.py's (a throwaway cluster)."""

from __future__ import annotations

import pytest
from _screen import message, settle, wait_until
from textual.widgets import DataTable

from sass_tui.db.engine.database import Database
from sass_tui.db.populations.family import load_family
from sass_tui.ui.query.family_screen import FamilyScreen
from sass_tui.ui.query.query_screen import COMPLETE, QueryScreen, SummaryPanel

QUERY = "gender = female AND stature > 175 cm"


@pytest.mark.slow
def test_the_query_screen_on_postgresql(drive, initialised, app_at):
    db = Database.open(initialised["sqlite"])
    try:
        expected = db.count(QUERY)
    finally:
        db.close()
    assert expected > 0

    async def scenario():
        async with app_at((120, 40), db=initialised["postgresql"]) as (app, pilot):
            await pilot.press("d")
            await settle(pilot)
            screen = app.screen
            assert isinstance(screen, QueryScreen)
            await wait_until(pilot, lambda: screen.lists is not None, "the database open")
            assert "postgresql://" in message(app) and "open" in message(app)
            screen.start_query(QUERY)
            await settle(pilot)
            assert message(app) == f"{COMPLETE} {expected} people found."
            await pilot.press("a")  # Select All
            summary = str(screen.query_one(SummaryPanel).render())
            assert f"Total Data in Selected List: {expected}" in summary
            person = app.selected_individual(0)
            assert person.gender == "female" and person.stature > 175

    drive(scenario())


def test_the_tui_takes_an_address(initialised, new_app):
    app = new_app(db=initialised["postgresql"])
    assert app.db_path == initialised["postgresql"]  # text: a Path would fold its //


@pytest.mark.slow
def test_the_family_screen_on_postgresql(drive, initialised, app_at):
    db = Database.open(initialised["sqlite"])
    try:
        with db.connection() as conn:
            expected = load_family(conn, "male", ["stature", "mass"], 0.9)
    finally:
        db.close()

    async def scenario():
        async with app_at((100, 37), db=initialised["postgresql"]) as (app, pilot):
            await pilot.press("y")
            assert isinstance(app.screen, FamilyScreen)
            await pilot.press("enter")  # gender: male
            await pilot.press(*"stature,mass", "enter")
            await pilot.press(*"90", "enter")
            await settle(pilot)
            table = app.screen.query_one(DataTable)
            assert table.row_count == len(expected.manikins) > 0
            for index, manikin in enumerate(expected.manikins):
                row = table.get_row_at(index)
                assert row[0] == manikin.name
                assert row[1:3] == [f"{manikin.values[f]:.1f}" for f in expected.measures]

    drive(scenario())


@pytest.mark.slow
def test_the_spreadsheets_predictor_on_postgresql(initialised):
    from sass_tui.ui.query.people_work import open_predictor_at

    predicted = {}
    for engine, target in initialised.items():
        predictor = open_predictor_at(target)
        known = predictor.parse_known("female", [("stature", "165 cm")])
        predicted[engine] = predictor.predict("female", known).values
    assert predicted["postgresql"].keys() == predicted["sqlite"].keys()
    for field, estimate in predicted["sqlite"].items():
        assert predicted["postgresql"][field].value == pytest.approx(estimate.value, rel=1e-9)
