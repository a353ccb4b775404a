"""q quits at once with nothing to lose; with edits, only on a second q."""

from __future__ import annotations

import pytest

from sass_tui.model.names import GIRTH
from sass_tui.ui.app import SassApp


def shown_message(app) -> str:
    return str(app.screen.message_line.query_one("#message").render())


def test_q_quits_at_once_without_edits(drive):
    async def scenario():
        app = SassApp()
        async with app.run_test(size=(100, 30)) as pilot:
            await pilot.press("q")
            await pilot.pause()
            assert not app.is_running

    drive(scenario())


@pytest.mark.parametrize("opener", [[], ["b"], ["d"]], ids=["spreadsheet", "figure", "query"])
def test_q_asks_first_when_edits_would_be_lost(drive, opener, db):
    async def scenario():
        app = SassApp(db_path=db)
        async with app.run_test(size=(100, 30)) as pilot:
            app.session.set_group_percentile(GIRTH, 90)
            if opener:
                await pilot.press(*opener)
                await pilot.pause(0.3)
            await pilot.press("q")
            await pilot.pause()
            assert app.is_running
            assert "press q again to quit" in shown_message(app)
            await pilot.press("q")
            await pilot.pause()
            assert not app.is_running

    drive(scenario())


def test_a_late_second_q_asks_again(drive):
    async def scenario():
        app = SassApp()
        async with app.run_test(size=(100, 30)) as pilot:
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
