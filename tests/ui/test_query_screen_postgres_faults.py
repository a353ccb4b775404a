"""The query screen on a PostgreSQL database when things go wrong or are
forbidden: after the server restarts, the next query answers and the
message line says what the restart took from the lists; a session served
read-only (`sass serve --read-only`, $SASS_READ_ONLY) queries and refuses
Input DB, its connection read-only by the server's rule.  The fixtures
`cluster` and `initialised` are tests/conftest.py's (a throwaway cluster)."""

from __future__ import annotations

import pytest
from _screen import message, settle, wait_until

from sass_tui.db.engine.database import Database
from sass_tui.model.served import READ_ONLY_ENV
from sass_tui.ui.app import make_app
from sass_tui.ui.query.query_screen import COMPLETE, QueryScreen

QUERY = "gender = female AND stature > 175 cm"


def expected_count(url: str) -> int:
    db = Database.open(url)
    try:
        return db.count(QUERY)
    finally:
        db.close()


async def query_screen(app, pilot) -> QueryScreen:
    await pilot.press("d")
    await settle(pilot)
    screen = app.screen
    assert isinstance(screen, QueryScreen)
    await wait_until(pilot, lambda: screen.lists is not None, "the database open")
    return screen


async def run(pilot, screen: QueryScreen, text: str) -> None:
    screen.start_query(text)
    await settle(pilot)


@pytest.mark.slow
def test_the_first_query_after_a_server_restart_answers(drive, cluster, initialised, app_at):
    url = initialised["postgresql"]
    expected = expected_count(url)
    assert expected > 1

    async def scenario():
        async with app_at((120, 40), db=url) as (app, pilot):
            screen = await query_screen(app, pilot)
            await run(pilot, screen, QUERY)
            assert message(app) == f"{COMPLETE} {expected} people found."
            await pilot.press("a")  # Select All
            await settle(pilot)
            cluster.restart()
            await run(pilot, screen, QUERY)
            said = message(app)
            assert said.startswith(f"{COMPLETE} {expected} people found."), said
            assert "restarted" in said and f"the selected list ({expected} people)" in said
            await run(pilot, screen, QUERY)  # said once
            assert message(app) == f"{COMPLETE} {expected} people found."

    drive(scenario())


@pytest.mark.slow
def test_a_read_only_session_queries_and_refuses_input_db(drive, initialised, monkeypatch):
    url = initialised["postgresql"]
    expected = expected_count(url)
    monkeypatch.setenv(READ_ONLY_ENV, "1")
    monkeypatch.setenv("SASS_DB", url)  # as sass serve hands a session its address

    async def scenario():
        app = make_app()
        assert app.read_only
        async with app.run_test(size=(120, 40)) as pilot:
            screen = await query_screen(app, pilot)
            assert screen.lists is not None and screen.lists._conn.read_only
            await run(pilot, screen, QUERY)
            assert message(app) == f"{COMPLETE} {expected} people found."
            await pilot.press("i")
            await settle(pilot)
            assert message(app) == (
                "Input DB is off: this database is served read-only (sass serve)."
            )

    drive(scenario())
