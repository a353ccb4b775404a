"""Keys apply in the order typed, also when they arrive in one read (a paste,
SSH, `sass serve`): the terminal's driver posts every key of the read before
the app has handled the first, so an arrow's move must be done before the
Enter or the digit after it asks for its edit."""

from __future__ import annotations

import shutil

import pytest
from _screen import message, settle, wait_until
from _tmux import sass_in_tmux
from textual import events

from sass_tui.model.names import GIRTH
from sass_tui.model.strength.strength import JOINT_AXIS_LABELS, MOTIONS
from sass_tui.ui.spreadsheet.more_menu import MORE_CHOICES, MoreMenu
from sass_tui.ui.widgets import DataSheet, GlobalPanel

LARGE = (120, 40)


def one_read(app, *keys: tuple[str, str | None]) -> None:
    """Post every key at once, as the driver does with the keys of one read."""
    for key, character in keys:
        app.post_message(events.Key(key, character))


DOWN = ("down", None)
ENTER = ("enter", "\r")
SEVEN = ("7", "7")


@pytest.mark.parametrize("then", [ENTER, SEVEN], ids=["enter", "digit"])
def test_down_then_an_edit_in_one_read_edits_the_cell_below(drive, app_at, then):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            sheet = app.query_one(DataSheet)
            assert sheet.chosen() == (0, 0)
            below = app.figure.groups[GIRTH].rows[1].label
            one_read(app, DOWN, then)
            await wait_until(pilot, lambda: app.message_line.prompting, "no prompt")
            assert message(app).startswith(f"{below} x value"), message(app)
            assert sheet.chosen() == (1, 0)
            if then == SEVEN:
                assert app.query_one("#answer").value == "7"
            else:
                await pilot.press("7")
            await pilot.press("enter")
            await settle(pilot)
            assert app.figure.groups[GIRTH].values[1, 0] == 7.0
            assert app.figure.groups[GIRTH].values[0, 0] != 7.0

    drive(scenario())


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux is not installed")
def test_down_then_an_edit_in_one_tmux_write_edits_the_cell_below(tmp_path):
    """`sass` in a real terminal (tmux's pane): `send-keys Down Enter` and
    `send-keys Down 7` each write their keys to the terminal at once."""
    with sass_in_tmux(tmp_path) as pane:
        pane.wait_for(lambda text: "Bottom Head" in text and "q Quit" in text, "no first screen")
        pane.send("Down", "Enter")
        pane.wait_for(lambda text: "Neck x value" in text, "Down Enter did not edit Neck")
        pane.send("Escape")
        pane.wait_for(lambda text: "Neck x value" not in text, "Escape did not cancel")
        pane.send("Down", "7")
        pane.wait_for(
            lambda text: "Center Torso x value" in text, "Down 7 did not edit the row below"
        )
        pane.send("Enter")
        pane.wait_for(
            lambda text: any(
                line.split()[:3] == ["Center", "Torso", "7.00"] for line in text.splitlines()
            ),
            "the Center Torso row does not show 7.00",
        )


@pytest.mark.parametrize("then", [ENTER, SEVEN], ids=["enter", "digit"])
def test_down_then_an_edit_in_one_read_on_the_global_panel(drive, app_at, then):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            panel = app.query_one(GlobalPanel)
            panel.select("mass")
            panel.focus()
            await pilot.pause()
            one_read(app, DOWN, then)
            await wait_until(pilot, lambda: app.message_line.prompting, "no prompt")
            assert message(app).startswith("Stature"), message(app)
            assert app.query_one("#answer").value == ("7" if then == SEVEN else "")

    drive(scenario())


@pytest.mark.parametrize("then", [ENTER, SEVEN], ids=["enter", "digit"])
def test_down_then_an_edit_in_one_read_on_the_strength_page(drive, app_at, then):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("s")
            await wait_until(pilot, lambda: app.strength_page.display, "no strength page")
            page = app.strength_page
            row, column = page.cursor_row, page.cursor_column
            one_read(app, DOWN, then)
            await wait_until(pilot, lambda: app.message_line.prompting, "no prompt")
            below = MOTIONS[row + 1].label.lower()
            assert f"{below}, {JOINT_AXIS_LABELS[column].lower()} angle" in message(app)
            assert (page.cursor_row, page.cursor_column) == (row + 1, column)
            assert app.query_one("#answer").value == ("7" if then == SEVEN else "")

    drive(scenario())


def test_down_then_enter_in_one_read_in_a_pop_up_menu(drive, app_at):
    """The More Menu (Disp. More's choices): Down Enter chooses the second item."""

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            chosen = []
            app.push_screen(MoreMenu(), chosen.append)
            await pilot.pause()
            one_read(app, DOWN, ENTER)
            await wait_until(pilot, lambda: chosen, "nothing chosen")
            assert chosen == [MORE_CHOICES[1]]

    drive(scenario())
