"""Keys on a number cell: a value's keys go to its edit, a command's key runs
the command (report §12.2) when no edit is open, and a key that is neither
says so.  The keys typed fast after a number on a cell that takes no value
(no motion about that axis) were run as commands: `4abc` ran Interval,
opened the figure and switched the sheet to radians."""

from __future__ import annotations

from _screen import message, wait_until
from textual import events

from sass_tui.model.names import GIRTH, JOINT_LIMITS
from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen
from sass_tui.ui.widgets import DataSheet

SIZE = (120, 40)
NO_MOTION = (2, 4)  # R Clavicle ul, z: no motion about this axis in the default figure


def test_letters_typed_for_a_refused_cell_run_no_command(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("j")
            await pilot.pause()
            app.query_one(DataSheet).choose(NO_MOTION)
            # One read of the terminal: `4abc` typed fast.
            for key in "4abc":
                app.post_message(events.Key(key, key))
            await wait_until(pilot, lambda: message(app).endswith(": abc"), lambda: message(app))
            assert "no motion about this axis" in message(app)
            assert isinstance(app.screen, SpreadsheetScreen)  # b did not open the figure
            assert app.figure.groups[JOINT_LIMITS].unit == "deg"  # c did not convert
            assert not app.message_line.prompting
            # No edit open: the report's command keys are commands again.
            await pilot.press("c")
            await pilot.pause()
            assert app.figure.groups[JOINT_LIMITS].unit == "rad"

    drive(scenario())


def test_a_key_neither_of_a_value_nor_a_command_says_so(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            before = app.figure.groups[GIRTH].values.copy()
            await pilot.press("z")
            await pilot.pause()
            assert message(app).startswith("'z' is neither part of this cell's value nor a command")
            assert (app.figure.groups[GIRTH].values == before).all()
            assert not app.message_line.prompting

    drive(scenario())


def test_an_open_edit_takes_every_printable_key(drive, app_at):
    """Enter, then letters that are command keys: they are the answer's."""

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("enter", "a", "b", "c")
            await pilot.pause()
            assert app.message_line.answer.value == "abc"
            assert isinstance(app.screen, SpreadsheetScreen)
            assert app.figure.groups[GIRTH].unit == "cm"

    drive(scenario())
