"""The anthropometric spreadsheet driven by key presses and clicks (Textual Pilot)."""

from __future__ import annotations

import numpy as np
import pytest
from _screen import message, paste
from textual import events

from sass_tui.model import datasets
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.files.popfile import parse_population_text, read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS, STRENGTH, row_index
from sass_tui.ui.spreadsheet.spreadsheet import FIRST_MESSAGE
from sass_tui.ui.widgets import DataSheet, GlobalPanel

SMALL = (80, 24)
LARGE = (120, 40)


def sheet_text(app) -> str:
    return str(app.query_one(DataSheet).render())


def global_panel_text(app) -> str:
    return str(app.query_one(GlobalPanel).render())


async def click_cell(pilot, row: int, column: int) -> None:
    """Click the data cell of absolute row `row` (on the current page) and column 0-5."""
    sheet = pilot.app.query_one(DataSheet)
    start, _ = sheet._column_start(column)
    line = sheet.HEADER_LINES + row % sheet.page_size
    # +1: the sheet's left padding and its top border.
    await pilot.click(DataSheet, offset=(start + 2, line + 1))


def test_start_screen_shows_default_data(drive, app_at):
    async def scenario():
        async with app_at(SMALL) as (app, pilot):
            await pilot.pause()
            assert message(app) == FIRST_MESSAGE
            assert app.query_one("#group-girth").has_class("-selected")
            assert "NASA Crewmember Trainees" in global_panel_text(app)
            assert "male" in global_panel_text(app) and "82.2 kg" in global_panel_text(app)
            text = sheet_text(app)
            assert "Bottom Head" in text and "20.00" in text and "page 1/3" in text
            # The 80x24 page holds fewer than the report's 25 rows.
            assert app.query_one(DataSheet).page_size < 25

    drive(scenario())


def test_click_cell_type_value_with_unit(drive, app_at):
    async def scenario():
        row = row_index(GIRTH, "right_upper_arm")
        async with app_at(LARGE) as (app, pilot):
            await click_cell(pilot, row, 4)  # z value
            assert app.query_one(DataSheet).cursor_row == row
            await pilot.press(*"14in", "enter")
            await pilot.pause()
            assert app.figure.value(GIRTH, "right_upper_arm", 2) == pytest.approx(35.56)
            percentile = app.figure.groups[GIRTH].percentiles[row, 2]
            assert 0.5 < percentile < 50  # 14 in is below the 50th's 36.6 cm
            assert "35.56" in sheet_text(app)
            assert f"{percentile:.1f}" in sheet_text(app)
            assert "Right Upper Arm z = 35.56 cm" in message(app)
            # Only that cell changed.
            assert app.figure.value(GIRTH, "left_upper_arm", 2) == pytest.approx(36.6)
            await pilot.press("u")
            assert app.figure.value(GIRTH, "right_upper_arm", 2) == pytest.approx(36.6)

    drive(scenario())


@pytest.mark.slow
def test_percentile_drives_value_and_blank_return_and_escape(drive, app_at):
    async def scenario():
        stats = read_population_file(datasets.path("girth.dat"), GIRTH).stats("male")
        async with app_at(LARGE) as (app, pilot):
            await click_cell(pilot, 2, 1)  # Center Torso x percentile
            await pilot.press("enter")
            assert "percentile" in message(app)
            await pilot.press(*"95%", "enter")
            assert app.figure.groups[GIRTH].values[2, 0] == stats[2, 0, 2]
            # RETURN with nothing typed leaves the cell as it was.
            await pilot.press("enter", "enter")
            assert app.figure.groups[GIRTH].values[2, 0] == stats[2, 0, 2]
            assert "unchanged" in message(app)
            # Escape cancels a half-typed value.
            await pilot.press("right", *"12", "escape")
            assert app.figure.groups[GIRTH].values[2, 1] == stats[2, 1, 1]
            assert "Cancelled" in message(app)

    drive(scenario())


def test_wrong_unit_is_refused_and_the_cell_kept(drive, app_at):
    async def scenario():
        async with app_at(SMALL) as (app, pilot):
            await pilot.press(*"12 deg", "enter")
            assert "deg is not a unit of length" in message(app)
            assert app.query_one("#message").has_class("-error")
            assert app.figure.groups[GIRTH].values[0, 0] == 20.0
            # A blank joint-limit axis (999) cannot be edited.
            await pilot.press("j", "down", "down", *["right"] * 4, "enter")
            assert "R Clavicle ul z: no motion about this axis" in message(app)
            assert not app.message_line.prompting

    drive(scenario())


def test_paging_reaches_every_row_at_80x24(drive, app_at):
    async def scenario():
        async with app_at(SMALL) as (app, pilot):
            await pilot.press("j")
            sheet = app.query_one(DataSheet)
            pages = sheet.pages
            assert pages == -(-40 // sheet.page_size) and pages > 2
            seen = set()
            for page in range(pages):
                for row in range(page * sheet.page_size, min(40, (page + 1) * sheet.page_size)):
                    assert app.figure.groups[JOINT_LIMITS].rows[row].label in sheet_text(app)
                    seen.add(row)
                await pilot.press("n")
            assert seen == set(range(40))
            assert "last page" in message(app)
            assert "L Knuckles ll" in sheet_text(app)
            await pilot.press("pageup")
            assert sheet.page == pages - 2
            await pilot.press("p")
            assert sheet.page == pages - 3
            await pilot.press("pagedown")
            assert sheet.page == pages - 2
            # The command menu's button does the same as the key.
            await pilot.click("#command-previous_page")
            assert sheet.page == pages - 3

    drive(scenario())


def test_large_terminal_holds_the_reports_25_rows(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("j")
            sheet = app.query_one(DataSheet)
            assert sheet.page_size == 25 and sheet.pages == 2
            await pilot.press("n")
            assert "R Hip ul" not in sheet_text(app) and "L Knuckles ll" in sheet_text(app)

    drive(scenario())


def test_switch_group_by_key_and_click_and_strength(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("j")
            assert app.data_group == JOINT_LIMITS
            assert app.query_one("#group-joint_limits").has_class("-selected")
            assert not app.query_one("#group-girth").has_class("-selected")
            assert "Neck ul" in sheet_text(app) and "deg" in sheet_text(app)
            await pilot.click("#group-center_of_mass")
            assert app.data_group == CENTER_OF_MASS
            assert "Center of Mass" in sheet_text(app)
            await pilot.click("#group-strength")
            assert app.data_group == STRENGTH
            assert app.query_one("#group-strength").has_class("-selected")
            await pilot.press("g")
            assert app.data_group == GIRTH and "Bottom Head" in sheet_text(app)

    drive(scenario())


def test_strength_group_refused_when_its_data_failed_to_load(drive, app_at, tmp_path):
    async def scenario():
        async with app_at(LARGE, strength_path=tmp_path / "missing.dat") as (app, pilot):
            await pilot.press("m")
            await pilot.click("#group-strength")
            assert "Strength data is not loaded" in message(app)
            assert "missing.dat: cannot read" in message(app)
            assert app.data_group == CENTER_OF_MASS
            await pilot.press("s")
            assert "Strength data is not loaded" in message(app)

    drive(scenario())


@pytest.mark.slow
def test_switch_gender_reloads_every_group(drive, app_at):
    async def scenario():
        girth = read_population_file(datasets.path("girth.dat"), GIRTH).stats("female")
        async with app_at(SMALL) as (app, pilot):
            await pilot.click(GlobalPanel, offset=(15, 2))  # the gender value
            await pilot.press("enter")
            assert "Gender" in message(app)
            await pilot.press(*"female", "enter")
            assert app.figure.gender == "female"
            np.testing.assert_array_equal(app.figure.groups[GIRTH].values, girth[:, :, 1])
            assert f"{girth[0, 0, 1]:.2f}" in sheet_text(app)
            assert "female" in global_panel_text(app)
            assert app.figure.mass < 82.2
            await pilot.press("enter", *"robot", "enter")
            assert "gender must be male or female" in message(app)
            assert app.figure.gender == "female"

    drive(scenario())


@pytest.mark.slow
def test_group_percentile_rescales_that_group_only(drive, new_app):
    async def scenario():
        app = new_app()
        stats = read_population_file(datasets.path("girth.dat"), GIRTH).stats("male")
        joint_limits = app.figure.groups[JOINT_LIMITS].values.copy()
        async with app.run_test(size=SMALL) as pilot:
            await pilot.press("tab")
            assert app.query_one(GlobalPanel).has_focus
            for _ in range(4):
                await pilot.press("down")
            await pilot.press(*"95", "enter")
            assert app.figure.groups[GIRTH].percentile == 95
            np.testing.assert_array_equal(app.figure.groups[GIRTH].values, stats[:, :, 2])
            np.testing.assert_array_equal(app.figure.groups[JOINT_LIMITS].values, joint_limits)
            assert "95.0" in sheet_text(app)
            # Mass by value with a unit, then by percentile.
            await pilot.press("up", "up", "enter", *"180 lb", "enter")
            assert app.figure.mass == pytest.approx(81.6466, abs=1e-3)
            await pilot.press("right", *"5", "enter")
            assert app.figure.mass_percentile == 5 and app.figure.mass < 75
            # The population cannot be edited.
            await pilot.press("up", "up", "up", "enter")
            assert "cannot be edited" in message(app)

    drive(scenario())


@pytest.mark.slow
def test_convert_units_and_back(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("m")
            before = sheet_text(app)
            values = app.figure.groups[CENTER_OF_MASS].values.copy()
            button = app.query_one("#command-convert_units")
            assert str(button.label) == "cm → in"
            await pilot.click("#command-convert_units")
            assert str(button.label) == "in → cm"
            inches = sheet_text(app)
            assert " in " in inches.splitlines()[1]
            first = values[~np.isnan(values)][0]
            assert f"{first / 2.54:.2f}" in inches
            # Another group keeps its unit.
            await pilot.press("g")
            assert str(button.label) == "cm → in"
            await pilot.press("m", "c")
            assert sheet_text(app) == before
            np.testing.assert_array_equal(app.figure.groups[CENTER_OF_MASS].values, values)
            # A value typed in the other unit lands in the current one.
            await pilot.press("c", *"10cm", "enter")
            assert f"{10 / 2.54:.2f}" in sheet_text(app)

    drive(scenario())


BAD_GIRTH = """C A population that breaks the format
T MALE
 1 2 3 4 5 6 7 8 /* Bottom Head */
"""


def test_bad_file_is_refused_and_data_kept(drive, new_app, tmp_path):
    bad = tmp_path / "bad_girth.dat"
    bad.write_text(BAD_GIRTH)

    async def scenario():
        app = new_app()
        values = app.figure.groups[GIRTH].values.copy()
        async with app.run_test(size=SMALL) as pilot:
            await pilot.click("#command-input_data")
            assert "population file" in message(app)
            await paste(pilot, str(bad))
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert f"{bad}:3: 8 numbers; expected 9" in message(app)
            assert app.query_one("#message").has_class("-error")
            np.testing.assert_array_equal(app.figure.groups[GIRTH].values, values)
            assert app.figure.population == "NASA Crewmember Trainees"
            await pilot.press("i")
            await paste(pilot, str(tmp_path / "missing.dat"))
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert "missing.dat: no such file" in message(app)
            assert app.figure.population == "NASA Crewmember Trainees"

    drive(scenario())


def test_input_data_loads_and_shows_warnings(drive, app_at, tmp_path):
    text = (
        datasets.path("jntlmt.dat").read_text().replace("NASA Crewmember Trainees", "Test crew", 1)
    )
    population = tmp_path / "limits.dat"
    population.write_text(text)
    warnings = parse_population_text(text, JOINT_LIMITS, str(population)).warnings
    assert warnings  # the seed table's inconsistencies

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("j", "i")
            await paste(pilot, str(population))
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert app.figure.groups[JOINT_LIMITS].source.title == "Test crew"
            assert warnings[0] in message(app)
            assert f"warning 1 of {len(warnings)}" in message(app)
            await pilot.press("w")
            assert warnings[1] in message(app)

    drive(scenario())


@pytest.mark.slow
def test_create_figure_writes_and_asks_before_overwriting(drive, app_at, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at(SMALL) as (app, pilot):
            await pilot.press("f")
            assert "[MALE50.FIG]" in message(app)
            await pilot.press("enter")
            assert "Include strength" in message(app)
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert "Wrote MALE50.FIG" in message(app)
            written = read_fig(tmp_path / "MALE50.FIG")
            assert written.archive == "skinny.a"
            assert written.variables["ctorsoz"] == (47.6, "cm")
            assert written.variables["ruparmx"] == (5.35, "cm")
            first = (tmp_path / "MALE50.FIG").read_text()
            # Change the figure; the existing file is only replaced on "y".
            await pilot.press("enter", *"20", "enter", "f", "enter", "enter")
            assert "exists" in message(app)
            await pilot.press("n", "enter")
            assert (tmp_path / "MALE50.FIG").read_text() == first
            await pilot.press("f", "enter", "enter", "y", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert read_fig(tmp_path / "MALE50.FIG").variables["botheadx"] == (10.0, "cm")
            await pilot.press("f")
            await paste(pilot, str(tmp_path / "no" / "dir.fig"))
            await pilot.press("enter", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            # The missing directory is named, not a temporary file.
            assert (
                f"{tmp_path / 'no' / 'dir.fig'}: cannot write: no such directory: {tmp_path / 'no'}"
                in message(app)
            )
            assert app.query_one("#message").has_class("-error")

    drive(scenario())


def test_create_figure_refused_without_a_group(drive, app_at):
    figure = Figure.default()
    female_only = datasets.path("cmass.dat").read_text().split("T MALE")[0]
    if "T FEMALE" not in female_only:
        female_only = (
            "C only women\nT FEMALE\n" + datasets.path("cmass.dat").read_text().split("T FEMALE")[1]
        )
    figure.load_group(CENTER_OF_MASS, parse_population_text(female_only, CENTER_OF_MASS))
    assert not figure.groups[CENTER_OF_MASS].loaded

    async def scenario():
        async with app_at(SMALL, figure) as (app, pilot):
            await pilot.press("f")
            assert "Cannot create a figure: Center of Mass not loaded" in message(app)
            assert not app.message_line.prompting
            await pilot.press("m")
            assert "No male data loaded" in sheet_text(app)

    drive(scenario())


def test_keys_typed_in_one_burst_run_in_order(drive, app_at):
    """A command letter then digits, arriving together (a paste, a fast typist,
    `tmux send-keys "m12"`): the group switch happens before the edit starts."""

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            for key in ("m", "1", "2"):
                app.post_message(events.Key(key, key))
            await pilot.pause()
            assert app.data_group == CENTER_OF_MASS
            assert message(app).startswith("Bottom Head x value")
            assert app.query_one("#answer").value == "12"
            await pilot.press("enter")
            await pilot.pause()
            assert app.figure.groups[CENTER_OF_MASS].values[0, 0] == 12.0, (
                message(app),
                app.focused,
                app.query_one("#answer").value,
                app.data_group,
            )
            assert app.figure.groups[GIRTH].values[0, 0] == 20.0
            # While the answer is typed, letters are text, not commands.
            await pilot.press("1", "i", "n")
            assert app.query_one("#answer").value == "1in"
            await pilot.press("escape")

    drive(scenario())
