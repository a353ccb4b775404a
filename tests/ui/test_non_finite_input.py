"""The spreadsheet refuses numbers that are not numbers ("1e400"
became "inf cm" in a cell, and Create Figure then wrote `botheadx = infcm;`)."""

from __future__ import annotations

from _screen import message

from sass_tui.model.names import GIRTH


def test_a_cell_refuses_1e400_and_keeps_its_value(drive, app_at):
    async def scenario():
        async with app_at((80, 24)) as (app, pilot):
            await pilot.press(*"1e400", "enter")
            assert "not a usable number" in message(app)
            assert app.query_one("#message").has_class("-error")
            assert app.figure.groups[GIRTH].values[0, 0] == 20.0
            await pilot.press("enter", *"inf cm", "enter")
            assert "expected a number" in message(app)
            assert app.figure.groups[GIRTH].values[0, 0] == 20.0

    drive(scenario())
