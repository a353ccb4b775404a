"""The query screen over real people: at 80 columns the list shows what a
real person has (age, survey branch), a strength query that finds no real
person says which demonstration people it would find, and a demonstration
person shown is titled as one."""

from __future__ import annotations

import pytest
from _screen import message, settle, typed_query

from sass_tui.db.engine.schema import connect
from sass_tui.db.query.query import run_query
from sass_tui.ui.query.query_screen import ListSheet, QueryScreen
from sass_tui.ui.widgets import GlobalPanel, MessageLine


@pytest.mark.slow
def test_at_80_columns_the_list_shows_age_and_branch(app_at, drive, db):
    with connect(db) as conn:
        first = run_query(conn, "branch = 'Combat Arms' AND age > 40").page(0, 1)[0]
        (branch,) = conn.execute(
            "SELECT branch FROM person WHERE id_num = ?", (first["id"],)
        ).fetchone()

    async def scenario():
        async with app_at((80, 30), db=db) as (app, pilot):
            await typed_query(pilot, "branch = 'Combat Arms' AND age > 40")
            sheet = app.screen.query_one(ListSheet)
            assert sheet.rows[0]["name"] == first["name"]
            screen = app.export_screenshot()
            assert "Age" in screen and "Branch" in screen
            shown = str(sheet.render()).splitlines()
            row = next(line for line in shown if first["name"] in line)
            assert f" {first['age']:g} " in row and branch in row and "ANSUR II" in row

    drive(scenario())


@pytest.mark.slow
def test_a_strength_query_finding_no_real_person_shows_the_query_that_would(app_at, drive, db):
    text = "strength.elbow_flexion.max > 20 ft-lb"
    reach = f"({text}) AND source = synthetic"
    with connect(db) as conn:
        assert run_query(conn, text).count() == 0
        found = run_query(conn, reach).count()
    assert found > 0

    async def scenario():
        async with app_at((120, 40), db=db) as (app, pilot):
            await typed_query(pilot, text)
            said = message(app)
            assert "No data satisfied the query." in said
            assert f"{found} synthetic demonstration people match" in said and reach in said
            await typed_query(pilot, reach)  # the query it showed reaches them
            assert f"{found:,} people found" in message(app)
            await pilot.press("s", "e")  # Select One, Exit Query
            await pilot.press("v")  # Disp. Indv.
            await pilot.pause()
            assert "(synthetic)" in str(app.query_one(GlobalPanel).render())

    drive(scenario())


@pytest.mark.slow
def test_make_population_of_real_women_then_create_figure(app_at, drive, db, tmp_path):
    """The selected real women make a population whose every cell has a value:
    Create Figure writes it (it refused a population with 999 cells)."""
    target = tmp_path / "young.dat"
    figure = tmp_path / "young.fig"

    async def scenario():
        async with app_at((120, 40), db=db) as (app, pilot):
            await typed_query(pilot, "gender = female AND age < 25")
            await pilot.press("a", "m", *str(target), "enter")  # Select All, Make Population
            await settle(pilot)
            assert "women" in message(app), message(app)
            await pilot.press("e")  # Exit Query
            await pilot.pause()
            assert not isinstance(app.screen, QueryScreen)
            assert app.session.population.gender == "female"
            await pilot.press("f")  # Create Figure
            await pilot.pause()
            assert "Figure file name" in message(app), message(app)
            app.screen.query_one(MessageLine).answer.value = ""
            await pilot.press(*str(figure), "enter")
            await pilot.pause()
            if "Include strength" in message(app):
                await pilot.press("enter")
            await settle(pilot)
            assert message(app) == f"Wrote {figure}.", message(app)

    drive(scenario())
    text = figure.read_text()
    assert "nan" not in text.lower() and " 999" not in text
    assert target.with_name("young-cmass.dat").is_file()


@pytest.mark.slow
def test_no_hint_when_the_real_people_found_are_all_selected(app_at, drive, db):
    """Re-run a query whose real people are all in the selected list: the query
    list is empty, but the query does reach real people, so no hint."""

    async def scenario():
        async with app_at((120, 40), db=db) as (app, pilot):
            await typed_query(pilot, "gender = female AND stature > 165 cm")
            assert "people found" in message(app) or "person" in message(app)
            await pilot.press("a")  # Select All
            await typed_query(pilot, "gender = female AND stature > 165 cm")
            assert message(app) == "No data satisfied the query."

    drive(scenario())
