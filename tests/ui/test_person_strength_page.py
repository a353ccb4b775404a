"""Disp. Indv. shows the person's own strength on the strength page,
driven by keys: the query screen selects a person, the spreadsheet shows them."""

from __future__ import annotations

import pytest
from _screen import typed_query

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.individual import fetch_individual, strength_measurements
from sass_tui.model.strength.strength import MOTION_NAMES
from sass_tui.model.units import convert
from sass_tui.ui.query.query_screen import QueryScreen


async def show_first_person_of(pilot, query: str) -> None:
    """Query screen: the query typed as text, Done, Select One, Exit; Disp. Indv."""
    app = pilot.app
    await typed_query(pilot, query)
    await pilot.press("s", "e")  # Select One, Exit Query
    assert not isinstance(app.screen, QueryScreen)
    await pilot.press("v", "s")  # Disp. Indv., the Strength group
    await pilot.pause()


@pytest.mark.slow
def test_the_strength_page_shows_the_persons_own_experiments(db, drive, app_at):
    async def scenario():
        async with app_at((100, 37), db=True) as (app, pilot):
            population_title = app.session.strength_sheet.title
            assert "TEST DATA" in population_title
            await show_first_person_of(pilot, "source = synthetic")
            person_id = app.query_lists.selected_id(0)
            with connect(db) as conn:
                person = fetch_individual(conn, person_id)
            sheet = app.session.strength_sheet
            page = app.strength_page
            assert page.sheet is sheet
            assert "own strength experiments" in page.border_title
            assert person.name in page.border_title and "TEST DATA" not in page.border_title
            # Every stored experiment of the shown side is a stored row at its angles.
            measured = [
                m
                for m in strength_measurements(person)
                if m[0] == sheet.side and m[4] == sheet.data.measured_at
            ]
            assert measured
            rows = sheet.rows()
            compared = 0
            for _side, motion, angles, value_nm, _conditions in measured:
                row = rows[MOTION_NAMES.index(motion)]
                if tuple(row.angles) == tuple(angles):
                    assert row.source == "stored"
                    assert row.value == pytest.approx(
                        convert(value_nm, "N_m", sheet.unit.replace("-", "_"))
                    )
                    compared += 1
            assert compared
            # Disp. Pop.: the population's (test) strength again.
            await pilot.press("o")
            assert app.strength_page.border_title == population_title

    drive(scenario())


@pytest.mark.slow
def test_a_person_without_experiments_is_said_so(db, drive, app_at):
    async def scenario():
        async with app_at((100, 37), db=True) as (app, pilot):
            await show_first_person_of(pilot, "source = ansur2")
            assert app.session.strength_sheet is None
            page = app.strength_page
            assert page.display
            assert "has no strength experiments in the database" in page.missing
            assert "no strength experiments" in app.message_line.history[-1][1]

    drive(scenario())
