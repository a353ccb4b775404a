"""Plausible values on the spreadsheet, by key presses: a typed value beyond
the population's 0.5th-99.5th percentile is accepted with a warning naming
that range (computed here from the shipped file by the spec's two-piece
normal model, with the standard library's normal quantile) and its percentile
shows `>99.5` or `<0.5`, never a rounded `100.0`; a cell with no spread shows
no percentile; a motion speed, which isometric strength does not use, says so."""

from __future__ import annotations

from statistics import NormalDist

import pytest
from _screen import message

from sass_tui.model import datasets
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, row_index
from sass_tui.ui.widgets import DataSheet, MessageLine

LARGE = (120, 40)
Z95, Z995 = NormalDist().inv_cdf(0.95), NormalDist().inv_cdf(0.995)


def _range(v5: float, v50: float, v95: float) -> tuple[float, float]:
    """The 0.5th and 99.5th percentile values (spec §2: v50 + z(p) s)."""
    return v50 - Z995 * (v50 - v5) / Z95, v50 + Z995 * (v95 - v50) / Z95


def _row_text(app, row: int) -> str:
    lines = str(app.query_one(DataSheet).render()).splitlines()
    label = app.figure.groups[app.query_one(DataSheet)._group].rows[row].label
    return next(line for line in lines if line.startswith(label))


def _is_warning(app) -> bool:
    return app.screen.query_one(MessageLine).query_one("#message").has_class("-warning")


async def _type_into(pilot, app, row: int, column: int, text: str) -> None:
    sheet = app.query_one(DataSheet)
    sheet.focus()
    while sheet.cursor_row < row:
        await pilot.press("down")
    while sheet.cursor_column < column:
        await pilot.press("right")
    await pilot.press("enter", *text, "enter")
    await pilot.pause()


@pytest.mark.parametrize(("typed", "shown"), [("60", ">99.5"), ("20", "<0.5")])
def test_a_value_beyond_the_range_is_accepted_with_a_warning(drive, app_at, typed, shown):
    row = row_index(GIRTH, "right_upper_arm")
    stats = read_population_file(datasets.path("girth.dat"), GIRTH).stats("male")[row, 2]
    low, high = _range(*stats)

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await _type_into(pilot, app, row, 4, typed)  # z value, in cm
            assert app.figure.value(GIRTH, "right_upper_arm", 2) == float(typed)
            said = message(app)
            assert f"Right Upper Arm z = {float(typed):.2f} cm ({shown} percentile)" in said
            assert f"0.5th-99.5th percentile range, {low:.2f}-{high:.2f} cm; accepted" in said
            assert _is_warning(app)
            row_text = _row_text(app, row)
            assert shown in row_text and "100.0" not in row_text and " 0.0 " not in row_text
            # inside the range: no warning
            await _type_into(pilot, app, row, 4, "37")
            assert "range" not in message(app) and not _is_warning(app)

    drive(scenario())


def test_mass_beyond_the_range_names_it(drive, app_at):
    mass = read_population_file(datasets.path("global.dat"), GLOBAL).stats("male")
    low, high = _range(*mass[row_index(GLOBAL, "mass"), 0])

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("tab", "down", "down", "enter")
            assert "Mass (kg" in message(app)
            await pilot.press(*"250", "enter")
            await pilot.pause()
            assert app.figure.mass == 250
            said = message(app)
            assert f"range, {low:.1f}-{high:.1f} kg; accepted" in said and _is_warning(app)
            assert "Mass = 250.0 kg" in said

    drive(scenario())


def test_a_cell_with_no_spread_shows_no_percentile(drive, app_at):
    stats = read_population_file(datasets.path("cmass.dat"), CENTER_OF_MASS).stats("male")
    row = next(r for r in range(len(stats)) if len(set(stats[r, 0])) == 1)
    wide = next(r for r in range(len(stats)) if len(set(stats[r, 2])) == 3)

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("m")
            await pilot.pause()
            label = app.figure.groups[CENTER_OF_MASS].rows[row].label
            x_value, x_percentile = _row_text(app, row).removeprefix(label).split()[:2]
            assert float(x_value) == stats[row, 0, 1] and x_percentile == "—"
            assert "50.0" in _row_text(app, wide)
            await _type_into(pilot, app, row, 1, "50")  # its percentile
            assert "no percentile: the population's 5th, 50th and 95th are all" in message(app)

    drive(scenario())


def test_a_motion_speed_for_isometric_strength_says_it_has_no_effect(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            assert app.figure.strength_type == "isometric"
            await pilot.press("tab", "right", "down", "enter")
            assert "Motion speed" in message(app)
            await pilot.press(*"30", "enter")
            await pilot.pause()
            assert app.figure.motion_speed == 30
            assert "has no effect on isometric strength" in message(app) and _is_warning(app)
            # isokinetic: the speed counts, nothing to warn of
            await pilot.press("up", "enter", *"isokinetic", "enter")
            await pilot.pause()
            assert app.figure.strength_type == "isokinetic"
            assert "no effect" not in message(app) and not _is_warning(app)

    drive(scenario())
