"""'Small things users hit' and 'Real people are shown as they
were measured', on the screen."""

from __future__ import annotations

from _screen import message
from textual import events

from sass_tui.model.names import GIRTH, row_index
from sass_tui.ui.message_log import MessageLog
from sass_tui.ui.query.query_screen import ListSheet, QueryScreen
from sass_tui.ui.widgets import DataSheet

LARGE = (120, 40)
CLAVICLE = row_index(GIRTH, "right_clavicle")  # x: 5th, 50th and 95th all 1.0 cm


def sheet_line(app, label: str) -> str:
    text = str(app.query_one(DataSheet).render())
    return next(line for line in text.splitlines() if line.startswith(label))


def test_a_value_on_a_row_without_spread_has_no_percentile_and_says_why(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            sheet = app.query_one(DataSheet)
            sheet.cursor_row, sheet.cursor_column = CLAVICLE, 0
            sheet.focus()
            await pilot.pause()
            await pilot.press("2", "enter")
            await pilot.pause()
            assert app.figure.groups[GIRTH].values[CLAVICLE, 0] == 2.0
            assert "( percentile)" not in message(app)
            assert "no percentile: the population's 5th, 50th and 95th are all 1.00 cm" in (
                message(app)
            )
            assert sheet_line(app, "Right Clavicle").split()[2:4] == ["2.00", "—"]

    drive(scenario())


def test_x_o_r_where_they_do_not_apply_say_why(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("x")
            assert "Disp. Indv. (v) first" in message(app)
            await pilot.press("o")
            assert "The population is already shown" in message(app)
            await pilot.press("r")
            assert "applies to the Strength group" in message(app)
            assert app.screen is app.spreadsheet and not app.message_line.prompting

    drive(scenario())


def test_long_messages_are_read_whole_in_the_message_log(drive, app_at, tmp_path):
    long_name = tmp_path / ("a-very-long-directory-name-" * 6) / "girth.dat"

    async def scenario():
        async with app_at((80, 24)) as (app, pilot):
            await pilot.press("i")
            app.post_message(events.Paste(str(long_name)))
            await pilot.pause()
            await pilot.press("enter")
            await pilot.pause()
            said = f"{long_name}: no such file"
            assert said not in str(app.screen.query_one("#message").render())[:80]
            await pilot.press("l")
            await pilot.pause()
            assert isinstance(app.screen, MessageLog)
            assert said in str(app.screen.query_one("#log-text").render()).replace("\n", "")
            await pilot.press("escape")
            await pilot.pause()
            assert app.screen is app.spreadsheet

    drive(scenario())


def test_the_query_list_shows_whole_names(drive, app_at, db):
    async def scenario():
        async with app_at(LARGE, db=True) as (app, pilot):
            await pilot.press("d")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert isinstance(app.screen, QueryScreen)
            sheet = app.screen.query_one(ListSheet)
            sheet.show_rows(
                [
                    {
                        "id": 1,
                        "name": "ANSUR II F 11533",
                        "source": "ansur2",
                        "gender": "female",
                        "mass": 60.1,
                    }
                ],
                0,
                1,
            )
            await pilot.pause()
            rows = str(sheet.render()).splitlines()
            # the whole name, then the Source column, then the gender
            assert rows[2].split()[:6] == ["ANSUR", "II", "F", "11533", "ANSUR", "II"]
            assert rows[2].startswith("ANSUR II F 11533 ANSUR II")
            assert rows[2].split()[6] == "female"

    drive(scenario())
