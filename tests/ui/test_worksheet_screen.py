"""Save, quit, open: the same sheet cell for cell, every group; Save As and
Open on the spreadsheet's keys; undo says what it undid, redo does it again."""

from __future__ import annotations

import json
import math
import shutil

import pytest
from _screen import message, paste, settle, wait_until
from _tmux import sass_in_tmux
from test_palette import choose_in_palette

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import AXES_OF, CENTER_OF_MASS, GIRTH, GROUPS, JOINT_LIMITS, row_index
from sass_tui.ui.app import SassApp

LARGE = (120, 40)
ARM = row_index(GIRTH, "right_upper_arm")


def cells(figure: Figure) -> dict:
    """Every group's values and percentiles, cell by cell, and the global data."""
    out: dict = {
        name: getattr(figure, name)
        for name in ("gender", "figure_type", "population", "mass", "mass_percentile",
                     "stature", "stature_percentile", "strength_type", "motion_speed",
                     "handedness", "training_level", "fatigue_level")
    }  # fmt: skip
    for group in GROUPS:
        state = figure.groups[group]
        out[group] = (state.percentile, state.unit, state.source.path)
        for row in range(len(state.rows)):
            for axis in range(AXES_OF[group]):
                value, percentile = state.cell(row, axis)
                out[group, row, axis] = tuple(
                    "nan" if math.isnan(v) else v for v in (value, percentile)
                )
    return {k: ("nan" if isinstance(v, float) and math.isnan(v) else v) for k, v in out.items()}


async def edit_every_group(app, pilot) -> None:
    """An edit in each group, one of them typed; the strength page's angle too."""
    session = app.session
    session.set_gender("female")  # first: a new gender puts every cell at its percentile
    await pilot.press("7", "enter")  # Bottom Head x, typed
    await settle(pilot)
    assert app.figure.groups[GIRTH].values[0, 0] == 7.0
    session.set_value(GIRTH, ARM, 2, 31.25)
    session.set_group_percentile(JOINT_LIMITS, 95)
    session.set_cell_percentile(CENTER_OF_MASS, 2, 0, 80)
    session.set_mass(61.5)
    session.set_strength_parameter("training_level", 2)
    session.set_angle(0, 0, 40)


async def save_as(pilot, path) -> None:
    await pilot.press("S")
    await wait_until(pilot, lambda: "Save worksheet as" in message(pilot.app), "no prompt")
    await paste(pilot, str(path))
    await pilot.press("enter")
    await settle(pilot)
    await wait_until(
        pilot, lambda: message(pilot.app).startswith("Saved"), lambda: message(pilot.app)
    )


@pytest.mark.slow
def test_save_quit_open_is_the_same_sheet_cell_for_cell(drive, app_at, tmp_path):
    path = tmp_path / "day.sass.json"

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await edit_every_group(app, pilot)
            await save_as(pilot, path)
            saved, angles = cells(app.figure), app.strength_sheet.angles.copy()
            await pilot.press("q")  # nothing since the save: quits at once
            await pilot.pause()
            assert not app.is_running
        opened = SassApp(worksheet=str(path))  # what `sass --open FILE` runs
        async with opened.run_test(size=LARGE) as pilot:
            await settle(pilot)
            assert cells(opened.figure) == saved
            assert (opened.strength_sheet.angles == angles).all()
            assert opened.worksheet_path == path
            # The spreadsheet shows the file's: the girth cell typed, in cm.
            assert "7.00" in str(opened.screen.sheet.render())
            await pilot.press("q")
            await pilot.pause()
            assert not opened.is_running

    drive(scenario())


@pytest.mark.slow
def test_open_replaces_the_sheet_and_a_bad_file_changes_nothing(drive, app_at, tmp_path):
    path = tmp_path / "day.sass.json"
    bad = tmp_path / "bad.sass.json"

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await edit_every_group(app, pilot)
            await save_as(pilot, path)
            saved = cells(app.figure)
            document = json.loads(path.read_text())
            document["groups"]["girth"]["values"][3] = [1, 2]
            bad.write_text(json.dumps(document))
            app.session.set_value(GIRTH, ARM, 2, 40.0)  # after the save
            await pilot.press("O")
            assert "edits since the last save are replaced" in message(app)
            await paste(pilot, str(bad))
            await pilot.press("enter")
            await settle(pilot)
            assert "groups.girth.values[3]: expected a list of 3" in message(app)
            assert "the sheet is unchanged" in message(app)
            assert app.figure.groups[GIRTH].values[ARM, 2] == 40.0
            await pilot.press("O")
            await paste(pilot, str(path))
            await pilot.press("enter")
            await settle(pilot)
            assert message(app).startswith(f"Opened the worksheet {path}")
            assert cells(app.figure) == saved
            assert not app.session.unsaved_edits()

    drive(scenario())


def test_undo_says_what_it_undid_and_redo_does_it_again(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("7", "enter")
            await settle(pilot)
            await pilot.press("u")
            assert message(app) == "Undone: Bottom Head x value 7 cm (U redoes it)."
            assert app.figure.groups[GIRTH].values[0, 0] != 7.0
            await pilot.press("U")
            assert message(app) == "Redone: Bottom Head x value 7 cm."
            assert app.figure.groups[GIRTH].values[0, 0] == 7.0
            await pilot.press("U")
            assert message(app) == "Nothing to redo."

    drive(scenario())


def test_ctrl_s_saves_again_to_the_same_file(drive, app_at, tmp_path):
    path = tmp_path / "day.sass.json"

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await save_as(pilot, path)
            await pilot.press("7", "enter")
            await settle(pilot)
            assert app.session.unsaved_edits()
            await pilot.press("ctrl+s")
            await settle(pilot)
            assert message(app) == f"Saved the worksheet to {path}."
            assert json.loads(path.read_text())["groups"]["girth"]["values"][0][0] == 7.0
            assert not app.session.unsaved_edits()

    drive(scenario())


@pytest.mark.slow
def test_the_palette_runs_save_as_and_open(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await choose_in_palette(pilot, "save worksheet as")
            assert message(app).startswith("Save worksheet as [worksheet.sass.json]:")
            await pilot.press("escape")
            await settle(pilot)
            await choose_in_palette(pilot, "open worksheet")
            assert message(app).startswith("Open worksheet file:")

    drive(scenario())


@pytest.mark.slow
def test_a_worksheet_whose_strength_file_moved_opens_and_says_so(drive, app_at, tmp_path):
    path = tmp_path / "day.sass.json"
    moved = tmp_path / "gone.dat"

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await edit_every_group(app, pilot)
            await save_as(pilot, path)
            saved = cells(app.figure)
            document = json.loads(path.read_text())
            document["strength"]["file"] = str(moved)
            path.write_text(json.dumps(document))
            sheet = app.strength_sheet
            await pilot.press("O")
            await paste(pilot, str(path))
            await pilot.press("enter")
            await settle(pilot)
            assert message(app).startswith(f"Opened the worksheet {path}")
            assert f"Its strength file is not read ({moved}: cannot read" in message(app)
            assert cells(app.figure) == saved
            assert app.strength_sheet is sheet  # the strength page as it was

    drive(scenario())


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("tmux") is None, reason="tmux is not installed")
def test_saved_quit_and_opened_with_sass_open_in_a_real_terminal(tmp_path):
    """The whole day in a tmux pane: a value typed, ctrl+s and a name, q
    (nothing to ask about), then `sass --open FILE` shows the value."""
    path = tmp_path / "day.sass.json"
    with sass_in_tmux(tmp_path) as pane:
        pane.wait_for(lambda text: "Bottom Head" in text and "q Quit" in text, "no first screen")
        pane.send("Down", "7")
        pane.send("Enter")
        pane.wait_for(lambda text: "Neck" in text and "7.00" in text, "no 7.00 in the Neck row")
        pane.send("C-s")
        pane.wait_for(lambda text: "Save worksheet as" in text, "ctrl+s asked nothing")
        pane.send(path.name, "Enter")
        pane.wait_for(lambda text: "Saved the worksheet to" in text, "not saved")
        pane.send("q")
        pane.wait_for_exit("q did not quit at once")
    assert json.loads(path.read_text())["groups"]["girth"]["values"][1][0] == 7.0
    with sass_in_tmux(tmp_path, "--open", path.name) as pane:
        pane.wait_for(
            lambda text: any(line.split()[:2] == ["Neck", "7.00"] for line in text.splitlines()),
            "sass --open does not show Neck x = 7.00",
        )
