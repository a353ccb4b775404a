"""Stats on the query screen (ui/query/stats_screen.py), driven by key presses:
the table is db/populations/stats.py's over the same people, computed here directly;
with the virtual NHANES population picked (`t`) it is said to be VIRTUAL."""

from __future__ import annotations

import pytest
from _screen import open_query_screen, settle, wait_until

from sass_tui.db.engine.schema import connect
from sass_tui.db.populations.stats import EVERY_MEASURE, format_stats, stats_table
from sass_tui.db.populations.targets import SHIPPED
from sass_tui.ui.query.stats_screen import StatsScreen
from sass_tui.ui.query.target_picker import TargetPicker

SIZE = (130, 40)


@pytest.mark.slow
def test_stats_of_every_real_person_then_of_the_virtual_civilians(drive, app_at, db):
    with connect(db) as conn:
        expected = format_stats(stats_table(conn, list(EVERY_MEASURE)))

    async def scenario():
        async with app_at(SIZE, db=db) as (app, pilot):
            query_screen = await open_query_screen(pilot)
            await pilot.press("S")
            await settle(pilot)
            screen = app.screen
            assert isinstance(screen, StatsScreen)
            await wait_until(pilot, lambda: screen.text, "the table was never shown")
            assert screen.text == expected
            assert "6068 people selected" in screen.text
            await pilot.press("t")
            await pilot.pause()
            assert isinstance(app.screen, TargetPicker) and app.screen.names == list(SHIPPED)
            await pilot.press("down", "down", "enter")
            await settle(pilot)
            await wait_until(
                pilot,
                lambda: "VIRTUAL" in screen.text,
                lambda: (
                    f"no virtual table: {screen.message_line.history[-3:]} {screen.title_text()}"
                ),
            )
            assert screen.text.startswith("VIRTUAL people, not measured: nhanes-2017-2020 (")
            assert screen.text.count("VIRTUAL") == 1
            title = str(screen.query_one("#stats-title").render())
            assert "VIRTUAL people of nhanes-2017-2020" in title
            await pilot.press("escape")
            await pilot.pause()
            assert app.screen is query_screen

    drive(scenario())


@pytest.mark.slow
def test_stats_screen_snapshot(db, snap_compare, new_app):
    async def run_before(pilot):
        await pilot.press("d")
        await settle(pilot)
        await pilot.press("S")
        await settle(pilot)

    assert snap_compare(new_app(db=True), run_before=run_before, terminal_size=(130, 30))
