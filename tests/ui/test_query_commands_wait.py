"""Query DB, Input DB and Target start work on the database: while a query
or an import runs, or before the database is open, each says why it waits
(QueryScreenBase.ready_lists) and starts nothing."""

from __future__ import annotations

from _screen import message, open_query_screen

from sass_tui.ui.query.query_base import WAIT

SIZE = (120, 40)


def test_commands_on_the_database_wait_for_it(drive, app_at, db):
    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = await open_query_screen(pilot)
            lists = screen.lists
            assert lists is not None
            for why, running, open_lists in (
                (WAIT, True, lists),
                ("The database is not open yet.", False, None),
            ):
                screen.running, screen.lists = running, open_lists
                for key in ("d", "i", "t"):  # Query DB, Input DB, Target
                    screen.say("")
                    await pilot.press(key)
                    await pilot.pause()
                    assert message(app) == why, key
                    assert app.screen is screen and screen.builder is None
                    assert not screen.query_one("#answer").display
            screen.running, screen.lists = False, lists
            await pilot.press("d")
            await pilot.pause()
            assert screen.builder is not None  # ready again: the builder starts

    drive(scenario())
