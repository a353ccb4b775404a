"""The strength group's Input Data names HFDS 2003's grip table: its forces
and source are said on the message line; the strength page (joint torques of
the example data) is left as it was."""

from __future__ import annotations

import pytest

SOURCE = "FAA HFDS 2003 exhibit 14.5.2.1 (MIL-STD-1472D), men, 5th percentile, momentary hold"


@pytest.mark.slow  # the app's start-up: about 2 s on 2 shared cores
def test_input_data_hfds2003_says_the_grip_table_and_its_source(app_at, drive):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("s")
            await pilot.pause()
            title = app.session.strength_sheet.title
            await pilot.press("i")
            await pilot.pause()
            await pilot.press("ctrl+a", "ctrl+k", *"hfds2003", "enter")
            await pilot.pause()
            said = app.screen.message_line.history[-1][1]
            # The page as printed (HFDS 2003, chapter 14, page 14-45), typed here.
            assert said.startswith(f"{SOURCE}: hand grip left 200 N, right 208 N; ")
            assert "thumb-finger grip (palmar) 48 N; thumb-finger grip (tips) 48 N" in said
            assert app.session.strength_sheet.title == title
            assert "example data (invented" in title

    drive(scenario())
