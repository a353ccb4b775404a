"""q quits at once with nothing to lose; with edits, only on a second q."""

from __future__ import annotations

import pytest
from _screen import settle

from sass_tui.model.names import GIRTH
from sass_tui.ui.app import SassApp


def shown_message(app) -> str:
    return str(app.screen.message_line.query_one("#message").render())


def test_q_quits_at_once_without_edits(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("q")
            await pilot.pause()
            assert not app.is_running

    drive(scenario())


@pytest.mark.parametrize("opener", [[], ["b"], ["d"]], ids=["spreadsheet", "figure", "query"])
def test_q_asks_first_when_edits_would_be_lost(drive, app_at, opener, db):
    async def scenario():
        async with app_at((100, 30), db=True) as (app, pilot):
            app.session.set_group_percentile(GIRTH, 90)
            if opener:
                await pilot.press(*opener)
                await settle(pilot)  # the query screen opens its database in a worker
            await pilot.press("q")
            await pilot.pause()
            assert app.is_running
            assert "press q again to quit" in shown_message(app)
            await pilot.press("q")
            await pilot.pause()
            assert not app.is_running

    drive(scenario())


def test_a_late_second_q_asks_again(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            app.session.set_group_percentile(GIRTH, 90)
            await pilot.press("q")
            app._quit_asked_at -= SassApp.QUIT_AGAIN_S + 1  # as if 4 s had passed
            await pilot.press("q")
            await pilot.pause()
            assert app.is_running
            app.session.undo()  # nothing to lose any more
            await pilot.press("q")
            await pilot.pause()
            assert not app.is_running

    drive(scenario())
