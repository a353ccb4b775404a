"""q quits at once with nothing to lose; with edits, only on a second q."""

from __future__ import annotations

import pytest
from _screen import settle

from sass_tui.model.names import GIRTH


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


def test_the_question_lasts_while_its_message_is_shown(drive, app_at):
    """However long the user takes, a second q quits while the question is
    on the message line; once another message has replaced it, q asks again."""

    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            app.session.set_group_percentile(GIRTH, 90)
            await pilot.press("q")
            app._quit_asked_at -= 3600  # an hour later: still the question shown
            await pilot.press("n")  # another message replaces it
            assert "press q again" not in shown_message(app)
            await pilot.press("q")
            await pilot.pause()
            assert app.is_running
            assert "press q again to quit" in shown_message(app)
            app._quit_asked_at -= 3600
            await pilot.press("q")
            await pilot.pause()
            assert not app.is_running

    drive(scenario())


def test_undone_back_to_the_saved_sheet_q_quits_at_once(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            app.session.set_group_percentile(GIRTH, 90)
            app.session.undo()  # nothing to lose any more
            await pilot.press("q")
            await pilot.pause()
            assert not app.is_running

    drive(scenario())
