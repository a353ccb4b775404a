"""Input Data offers the shipped data sets by name and completes file names
with Tab (also Save As and Open); the completion stays inside a served
session's directory."""

from __future__ import annotations

import pytest
from _screen import message, settle, wait_until

from sass_tui.model import datasets
from sass_tui.model.files.paths import complete_path
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import GIRTH, JOINT_LIMITS
from sass_tui.model.strength.published_grip import GRIP_DATA_SET
from sass_tui.model.strength.published_strength import DATA_SET, EXAMPLE_DATA_SET
from sass_tui.ui.spreadsheet.spreadsheet_files import STRENGTH_DATA_SETS

LARGE = (120, 40)


def answer(app) -> str:
    return app.screen.query_one("#answer").value


def test_the_strength_data_set_names_are_the_published_modules():
    assert STRENGTH_DATA_SETS == (EXAMPLE_DATA_SET, DATA_SET, GRIP_DATA_SET)


def test_complete_path(tmp_path):
    (tmp_path / "sub").mkdir()
    for name in ("alpha.dat", "alpine.dat", "beta.dat", ".hidden"):
        (tmp_path / name).write_text("")
    assert complete_path(f"{tmp_path}/al") == [f"{tmp_path}/alpha.dat", f"{tmp_path}/alpine.dat"]
    assert complete_path(f"{tmp_path}/s") == [f"{tmp_path}/sub/"]
    assert complete_path(f"{tmp_path}/.") == [f"{tmp_path}/.hidden"]
    assert complete_path(f"{tmp_path}/nothing/x") == []
    # A served session's directory: relative names inside it only.
    assert complete_path("al", tmp_path) == ["alpha.dat", "alpine.dat"]
    assert complete_path("sub/", tmp_path) == []
    assert complete_path("/etc/pass", tmp_path) == []
    assert complete_path("../", tmp_path) == []
    assert complete_path("~/", tmp_path) == []


@pytest.mark.slow
def test_input_data_reads_the_shipped_data_set_by_name(drive, app_at):
    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            app.session.set_group_percentile(JOINT_LIMITS, 95)
            before = app.figure.groups[JOINT_LIMITS].source
            await pilot.press("j", "i")
            assert "or the shipped data set: nasa" in message(app)
            await pilot.press("n", "a", "tab")
            assert answer(app) == "nasa"
            await pilot.press("enter")
            await settle(pilot)
            state = app.figure.groups[JOINT_LIMITS]
            await wait_until(pilot, lambda: state.source is not before, lambda: message(app))
            assert any(
                "shipped data set nasa (jntlmt.dat)" in text for _, text in app.message_line.history
            )
            shipped = read_population_file(datasets.path("jntlmt.dat"), JOINT_LIMITS)
            assert app.figure.groups[JOINT_LIMITS].source.sections == shipped.sections
            assert app.figure.groups[JOINT_LIMITS].percentile == 95  # kept, as Input Data does

    drive(scenario())


@pytest.mark.slow
def test_tab_completes_a_file_name_and_names_the_choices(drive, app_at, tmp_path):
    for name in ("tall-girth.dat", "tall-cmass.dat"):
        (tmp_path / name).write_text(datasets.path("girth.dat").read_text())

    async def scenario():
        async with app_at(LARGE) as (app, pilot):
            await pilot.press("i")
            app.screen.query_one("#answer").insert_text_at_cursor(f"{tmp_path}/ta")
            await pilot.press("tab")
            assert answer(app) == f"{tmp_path}/tall-"
            assert message(app).rstrip().endswith("[tall-cmass.dat, tall-girth.dat]")
            await pilot.press("g", "tab")
            assert answer(app) == f"{tmp_path}/tall-girth.dat"
            await pilot.press("enter")
            await settle(pilot)
            girth = app.figure.groups[GIRTH]
            wanted = str(tmp_path / "tall-girth.dat")
            await wait_until(pilot, lambda: girth.source.path == wanted, lambda: message(app))

    drive(scenario())
