"""Keys that belong to a prompt stay with it, however fast they come, and the
TUI's crash and hang defects the robustness review found."""

from __future__ import annotations

import os

import pytest
from _screen import message, wait_until
from textual import events

from sass_tui.cli import main
from sass_tui.model.names import GIRTH, STRENGTH, row_index
from sass_tui.ui.app import run_app
from sass_tui.ui.query.query_screen import QueryScreen
from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen
from sass_tui.ui.widgets import DataSheet, GlobalPanel

LARGE = (120, 40)
ARM = row_index(GIRTH, "right_upper_arm")


def answer(app) -> str:
    return app.screen.query_one("#answer").value


def burst(app, text: str) -> None:
    """Every key posted at once, before the app has handled the first: a
    terminal delivers a paste or a fast typist's keys so."""
    for character in text:
        key = "space" if character == " " else character
        app.post_message(events.Key(key, character))


async def choose_cell(pilot, row: int, column: int) -> None:
    sheet = pilot.app.query_one(DataSheet)
    start, _ = sheet._column_start(column)
    line = sheet.HEADER_LINES + row % sheet.page_size
    await pilot.click(DataSheet, offset=(start + 2, line + 1))
    await pilot.pause()


@pytest.mark.slow
@pytest.mark.parametrize("how", ["burst", "press", "paste"])
def test_a_value_typed_fast_is_the_prompts_not_input_datas(drive, app_at, how):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await choose_cell(pilot, ARM, 4)
            if how == "burst":
                burst(app, "14in")
            elif how == "press":
                await pilot.press(*"14in")
            else:
                app.post_message(events.Paste("14in"))
            await pilot.pause()
            assert "population file" not in message(app)
            assert message(app).startswith("Right Upper Arm z value")
            assert answer(app) == "14in"
            await pilot.press("enter")
            await pilot.pause()
            assert app.figure.value(GIRTH, "right_upper_arm", 2) == pytest.approx(35.56)

    drive(scenario())


def test_enter_typed_ahead_with_the_value_submits_it(drive, app_at):
    """`14in` and Enter in one burst: the Enter that reached the sheet before
    the prompt had the focus submits the answer (it was dropped: the submit
    coroutine was never awaited)."""

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await choose_cell(pilot, ARM, 4)
            burst(app, "14in")
            app.post_message(events.Key("enter", "\r"))
            await pilot.pause()
            await pilot.pause()
            assert not app.screen.query_one("#answer").display  # answered
            assert app.figure.value(GIRTH, "right_upper_arm", 2) == pytest.approx(35.56)

    drive(scenario())


@pytest.mark.parametrize("how", ["burst", "paste"])
def test_an_angle_in_radians_does_not_open_the_query_screen(drive, app_at, how):
    async def scenario():
        async with app_at((100, 37)) as (app, pilot):
            await pilot.press("s")
            await pilot.pause()
            assert app.data_group == STRENGTH
            if how == "burst":
                burst(app, "0.5 rad")
            else:
                app.post_message(events.Paste("0.5 rad"))
            await pilot.pause()
            assert not isinstance(app.screen, QueryScreen)
            assert answer(app) == "0.5 rad"
            await pilot.press("enter")
            await pilot.pause()
            assert app.strength_sheet.angles[0, 0] == pytest.approx(28.65, abs=0.01)

    drive(scenario())


@pytest.mark.slow
def test_female_typed_into_the_gender_cell_does_not_create_a_figure(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            panel = app.query_one(GlobalPanel)
            panel.select("gender")
            panel.focus()
            await pilot.pause()
            # Enter opens the prompt; the letters follow at once.
            app.post_message(events.Key("enter", "\r"))
            burst(app, "female")
            await pilot.pause()
            assert "Figure file name" not in message(app)
            assert answer(app) == "female"
            await pilot.press("enter")
            await pilot.pause()
            assert app.figure.gender == "female"

    drive(scenario())


@pytest.mark.slow
def test_a_group_letter_then_digits_switch_group_first(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            burst(app, "m12")
            await pilot.pause()
            assert app.data_group == "center_of_mass"
            assert message(app).startswith("Bottom Head x value") and answer(app) == "12"
            await pilot.press("escape")

    drive(scenario())


def test_a_click_elsewhere_while_asking_leaves_the_keys_with_the_prompt(drive, app_at):
    """`9`, a click on a data cell, Down spun at 100 % CPU and
    Enter/Escape no longer reached the prompt."""

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("9")
            assert app.message_line.prompting
            await choose_cell(pilot, 3, 0)
            await pilot.press("down", "down")
            await pilot.pause()
            assert app.screen.query_one("#answer").has_focus
            await pilot.press("enter")
            await pilot.pause()
            assert not app.message_line.prompting
            assert app.figure.groups[GIRTH].values[0, 0] == 9.0
            assert "Bottom Head x = 9.00 cm" in message(app)

    drive(scenario())


@pytest.mark.parametrize("width", [40, 30, 12])
def test_a_narrow_terminal_at_start_and_on_resize(drive, app_at, width):
    """40 columns or fewer crashed with a negative field width."""

    async def scenario():
        async with app_at((width, 24)) as (app, pilot):
            await pilot.pause()
            assert "Population" in str(app.query_one(GlobalPanel).render())[:20] or width < 20
            await pilot.resize_terminal(width + 60, 24)
            await pilot.pause()
            await pilot.resize_terminal(width, 20)
            await pilot.pause()
            await pilot.press("s")
            await pilot.pause()
        assert app.return_code in (None, 0)

    drive(scenario())


def test_an_unknown_user_at_a_file_prompt_is_a_message(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            for command in ("i", "f", "e"):
                await pilot.press(command)
                app.post_message(events.Paste("~nosuchuser/x"))
                await pilot.pause()
                await pilot.press("enter")
                await pilot.pause()
                assert "cannot expand ~nosuchuser" in message(app), command
                assert app.screen.query_one("#message").has_class("-error")
        assert app.return_code in (None, 0)

    drive(scenario())


def test_an_unknown_user_in_db_is_refused_before_the_tui_starts(capsys):
    assert main(["--db", "~nosuchuser/x.db"]) == 2
    assert "cannot expand ~nosuchuser" in capsys.readouterr().err


def test_a_fifo_given_to_input_data_is_refused_and_quit_exits(drive, app_at, tmp_path):
    fifo = tmp_path / "girth.fifo"
    os.mkfifo(fifo)

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("i")
            app.post_message(events.Paste(str(fifo)))
            await pilot.pause()
            await pilot.press("enter")
            await pilot.pause()
            assert "not a regular file" in message(app)
            assert not app.workers._workers
            await pilot.press("q")
            await pilot.pause()
        assert app.return_code == 0

    drive(scenario())


def test_run_app_exits_non_zero_after_a_crash(monkeypatch):
    def crash(self):
        raise RuntimeError("a bug")

    monkeypatch.setattr(SpreadsheetScreen, "on_mount", crash)
    assert run_app(headless=True) != 0


def test_the_write_worker_writes_the_figure_as_it_was_when_asked(
    drive, app_at, tmp_path, monkeypatch
):
    """The worker wrote whatever the figure held when the thread got
    to it; an edit made meanwhile went into the file.  Every file step taken
    off the UI thread here waits until the test has edited the figure."""
    import threading

    from sass_tui.model.files import atomic, figfile
    from sass_tui.model.files.fig_reader import read_fig
    from sass_tui.ui.spreadsheet import spreadsheet_files

    edited, working = threading.Event(), threading.Event()

    def after_the_edit(function):
        def wrapper(*args, **kwargs):
            if threading.current_thread() is not threading.main_thread():
                working.set()
                assert edited.wait(30)
            return function(*args, **kwargs)

        return wrapper

    monkeypatch.setattr(figfile, "render_fig", after_the_edit(figfile.render_fig))
    monkeypatch.setattr(figfile, "write_text_atomic", after_the_edit(figfile.write_text_atomic))
    monkeypatch.setattr(atomic, "write_text_atomic", after_the_edit(atomic.write_text_atomic))
    # The spreadsheet's write worker (ui/spreadsheet/spreadsheet_files.py) holds its own name for it.
    monkeypatch.setattr(
        spreadsheet_files, "write_text_atomic", after_the_edit(atomic.write_text_atomic)
    )
    out = tmp_path / "asked.fig"

    async def scenario():
        async with app_at(LARGE, strength_path=tmp_path / "no-strength.dat") as (app, pilot):
            await pilot.press("f")
            app.post_message(events.Paste(str(out)))
            await pilot.pause()
            await pilot.press("enter")
            await wait_until(pilot, working.is_set, "the worker never started writing")
            app.session.set_value(GIRTH, 0, 0, 10.0)  # the user edits while it writes
            edited.set()
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert f"Wrote {out}" in message(app)
        # Bottom head x: half the girth cell, 20 cm as asked (10 cm after the edit).
        assert read_fig(out).variables["botheadx"] == (10.0, "cm")
        assert app.figure.groups[GIRTH].values[0, 0] == 10.0

    drive(scenario())
