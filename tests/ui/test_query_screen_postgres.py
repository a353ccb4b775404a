"""The TUI on a lab's PostgreSQL database (`sass --db postgresql://...`): the
query screen opens it, runs a query, selects the people, shows a person and
runs a fit test, with the counts SQLite gives after the same `sass db init`.
The fixture `initialised` is tests/conftest.py's (a throwaway cluster)."""

from __future__ import annotations

import pytest
from _screen import message, settle, wait_until

from sass_tui.db.database import Database
from sass_tui.ui.app import SassApp
from sass_tui.ui.query_screen import COMPLETE, QueryScreen, SummaryPanel

QUERY = "gender = female AND stature > 175 cm"


@pytest.mark.slow
def test_the_query_screen_on_postgresql(drive, initialised):
    db = Database.open(initialised["sqlite"])
    try:
        expected = db.count(QUERY)
    finally:
        db.close()
    assert expected > 0

    async def scenario():
        app = SassApp(db_path=initialised["postgresql"])
        async with app.run_test(size=(120, 40)) as pilot:
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


def test_the_tui_takes_an_address(initialised):
    app = SassApp(db_path=initialised["postgresql"])
    assert app.db_path == initialised["postgresql"]  # text: a Path would fold its //
