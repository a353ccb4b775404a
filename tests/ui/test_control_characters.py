"""Names from files never send escape sequences to the terminal (a
person named `\\x1b[2J\\x1b]0;pwned\\x07` cleared the screen when listed)."""

from __future__ import annotations

import pytest
from _screen import settle
from test_query_screen import SAMPLE, build_sample_query, choose, open_query_screen

from sass_tui.db.engine.schema import connect
from sass_tui.db.query.query import run_query
from sass_tui.ui.query.query_screen import ListSheet

HOSTILE = "\x1b[2J\x1b]0;pwned\x07"


@pytest.mark.slow
def test_a_hostile_name_is_shown_escaped_in_the_list_and_messages(drive, app_at, db):
    with connect(db) as conn:
        first = run_query(conn, SAMPLE).ids()[0]
        conn.execute("UPDATE person SET name = ? WHERE id_num = ?", (HOSTILE, first))

    async def scenario():
        async with app_at((120, 40), db=True) as (app, pilot):
            await open_query_screen(pilot)
            await pilot.press("d")
            await pilot.click(ListSheet, offset=(20, 6), button=3)
            await build_sample_query(pilot, [])
            await choose(pilot, "Done")
            await settle(pilot)
            screen = app.export_screenshot()
            assert "^[[2J" in screen  # the name is listed, made visible
            assert "\x1b" not in screen and "\x07" not in screen
            await pilot.press("s")  # Select One: the message names the person
            await pilot.pause()
            message = str(app.screen.query_one("#message").render())
            assert "^[[2J" in message and "\x1b" not in message

    drive(scenario())
