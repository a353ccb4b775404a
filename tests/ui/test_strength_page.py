"""The strength page (report §12.2.3, figures 5 and 6) and Export HAnim,
driven by key presses and clicks (Textual Pilot)."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest
from _screen import message, paste

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.names import JOINT_LIMITS, STRENGTH
from sass_tui.model.strength.strength import (
    DEFAULT_NON_DOMINANT_FACTOR,
    StrengthSheet,
    percentile_factor,
    read_strength_file,
    strength_type_factor,
    training_factor,
)
from sass_tui.ui.spreadsheet.strength_page import StrengthPage
from sass_tui.ui.widgets import GlobalPanel, MenuItem

SIZE = (100, 37)
REPORT_VALUE = 17.98  # figure 5: right shoulder abduction at x 30, y 45, elbow 90


def page_text(app) -> str:
    return str(app.query_one(StrengthPage).render())


def row_line(app, label: str) -> str:
    return next(line for line in page_text(app).splitlines() if line.startswith(label))


def row_value(app, label: str) -> float:
    """The strength of a row as shown (the number after the seven angles)."""
    return float(row_line(app, label).split()[-2])


def button_label(app, name: str) -> str:
    return str(app.query_one(f"#command-{name}", MenuItem).label)


async def open_strength(pilot) -> None:
    await pilot.press("s")
    await pilot.pause()
    assert pilot.app.data_group == STRENGTH


async def edit_global(pilot, field: str, text: str) -> None:
    panel = pilot.app.query_one(GlobalPanel)
    panel.select(field)
    panel.focus()
    await pilot.pause()
    await pilot.press("enter")
    await paste(pilot, text)
    await pilot.press("enter")
    await pilot.pause()


def expected_sheet(**figure_settings) -> StrengthSheet:
    """The model's own answer, computed beside the app to check the screen."""
    figure = Figure.default()
    for name, value in figure_settings.items():
        figure.set_strength_parameter(name, value)
    return StrengthSheet(read_strength_file(), figure)


def test_strength_page_shows_figure_5(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            text = page_text(app)
            lines = text.splitlines()
            assert lines[0].startswith("Motion impetus")
            assert "Shoulder" in lines[0] and "Elbow" in lines[0] and "Wrist" in lines[0]
            # The side label under the motion impetus header; the unit over the values.
            assert lines[1].startswith("right") and "ft-lb" in lines[1]
            assert row_line(app, "Shoulder abduction").split()[2:9] == [
                "30",
                "45",
                "0",
                "90",
                "0",
                "0",
                "0",
            ]
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE
            assert "stored" in row_line(app, "Shoulder abduction")
            assert len(lines) == 2 + 14  # the report's 14-row strength page
            assert "Strength: 14 rows, 1 page." in message(app)
            assert button_label(app, "convert_units") == "ft-lb → N-m"
            assert app.query_one("#command-switch_side").display
            await pilot.press("g")
            assert not app.query_one("#command-switch_side").display
            assert button_label(app, "convert_units") == "cm → in"

    drive(scenario())


@pytest.mark.slow
def test_edit_angle_recomputes_row_stored_then_predicted(drive, app_at):
    async def scenario():
        expected = expected_sheet()
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            # Shoulder abduction, shoulder x: a stored configuration.
            await pilot.press("enter")
            assert "shoulder x angle [30 deg]" in message(app)
            await pilot.press(*"60", "enter")
            await pilot.pause()
            assert row_value(app, "Shoulder abduction") == 11.24
            assert "stored" in row_line(app, "Shoulder abduction")
            assert "11.24 ft-lb (stored)" in message(app)
            # A configuration not in the data: the equation, typed in radians.
            await pilot.press(*"0.7854 rad", "enter")
            await pilot.pause()
            expected.set_angle(0, 0, "0.7854 rad")
            predicted = expected.row(0)
            assert predicted.source == "predicted"
            assert row_value(app, "Shoulder abduction") == round(predicted.value, 2)
            assert "predicted" in row_line(app, "Shoulder abduction")
            assert app.strength_sheet.angles[0, 0] == pytest.approx(45.0, abs=0.01)
            # Only that row changed.
            assert row_value(app, "Shoulder adduction") == 8.24
            # RETURN with nothing typed leaves the angle as it was.
            await pilot.press("enter", "enter")
            assert "unchanged" in message(app)
            assert app.strength_sheet.angles[0, 0] == pytest.approx(45.0, abs=0.01)

    drive(scenario())


def test_click_an_angle_cell_then_edit(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            page = app.query_one(StrengthPage)
            start, _ = page._column_start(3)  # elbow y
            # +1: the sheet's left padding and its top border; row 6 = elbow flexion.
            await pilot.click(StrengthPage, offset=(start + 2, page.HEADER_LINES + 6 + 1))
            assert (page.cursor_row, page.cursor_column) == (6, 3)
            before = row_value(app, "Elbow flexion")
            await pilot.press(*"90", "enter")
            await pilot.pause()
            assert app.strength_sheet.angles[6, 3] == 90
            assert row_value(app, "Elbow flexion") != before
            assert "Right elbow flexion at elbow y 90 deg" in message(app)

    drive(scenario())


@pytest.mark.slow
def test_angle_beyond_the_joint_limit_is_refused(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            await pilot.press(*"200", "enter")
            await pilot.pause()
            assert "above the right shoulder upper limit 180.95 deg" in message(app)
            assert app.query_one("#message").has_class("-error")
            assert app.strength_sheet.angles[0, 0] == 30
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE
            # The joint limits' percentile moves the limit: 178 is allowed at the
            # 50th (180.95) but not at the 5th (173.2).
            await pilot.press("j")
            await edit_global(pilot, "group_percentile", "5")
            await pilot.press("s")
            app.strength_page.focus()
            await pilot.pause()
            await pilot.press(*"178", "enter")
            await pilot.pause()
            assert "upper limit 173.2 deg (joint limits, 5th percentile)" in message(app)
            assert app.strength_sheet.angles[0, 0] == 30

    drive(scenario())


def test_ft_lb_to_n_m_and_back(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            await pilot.press("c")
            assert row_value(app, "Shoulder abduction") == 24.38
            assert "N-m" in page_text(app).splitlines()[1]
            assert button_label(app, "convert_units") == "N-m → ft-lb"
            await pilot.click("#command-convert_units")
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE
            assert button_label(app, "convert_units") == "ft-lb → N-m"

    drive(scenario())


@pytest.mark.slow
def test_right_to_left_with_a_typed_factor_and_with_return(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            assert button_label(app, "switch_side") == "Right → Left"
            await pilot.press("r")
            assert f"RETURN = default {DEFAULT_NON_DOMINANT_FACTOR:.3f}" in message(app)
            assert "0.896" in message(app)
            await pilot.press(*"0.8", "enter")
            await pilot.pause()
            assert page_text(app).splitlines()[1].startswith("left")
            assert row_value(app, "Shoulder abduction") == round(REPORT_VALUE * 0.8, 2)
            assert button_label(app, "switch_side") == "Left → Right"
            # Back to the dominant right limb, RETURN = default factor: unscaled.
            await pilot.click("#command-switch_side")
            await pilot.press("enter")
            await pilot.pause()
            assert page_text(app).splitlines()[1].startswith("right")
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE
            await pilot.press("r", "enter")
            await pilot.pause()
            assert "(default)" in message(app)
            assert row_value(app, "Shoulder abduction") == round(
                REPORT_VALUE * DEFAULT_NON_DOMINANT_FACTOR, 2
            )
            # A factor that is not a number is refused, the side kept.
            await pilot.press("r", *"abc", "enter")
            assert "not a number" in message(app)
            assert app.strength_sheet.side == "left"

    drive(scenario())


@pytest.mark.slow
def test_global_strength_parameters_move_the_values(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            await edit_global(pilot, "strength_type", "isokinetic")
            await edit_global(pilot, "motion_speed", "60")
            assert "Strength values recomputed." in message(app)
            # the isokinetic decay has no published source: off, and said so, until asked for
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE
            page = app.spreadsheet.strength_page
            assert "isokinetic decay and training gain off" in str(page.border_title)
            await pilot.press("M")
            assert "Assumed modifiers on" in message(app)
            assert "assumed modifiers on" in str(page.border_title)
            factor = strength_type_factor("isokinetic", 60.0)
            assert row_value(app, "Shoulder abduction") == round(REPORT_VALUE * factor, 2)
            await edit_global(pilot, "training_level", "2")
            factor *= training_factor(2)
            assert row_value(app, "Shoulder abduction") == round(REPORT_VALUE * factor, 2)
            # The group percentile of the strength page is the strength percentile.
            await edit_global(pilot, "group_percentile", "95")
            assert "95.0" in str(app.query_one(GlobalPanel).render())
            assert row_value(app, "Shoulder abduction") == round(
                REPORT_VALUE * factor * float(percentile_factor(95)), 2
            )
            # Handedness left: the shown right limb becomes the non-dominant one.
            await edit_global(pilot, "handedness", "left")
            assert row_value(app, "Shoulder abduction") == round(
                REPORT_VALUE * factor * float(percentile_factor(95)) * DEFAULT_NON_DOMINANT_FACTOR,
                2,
            )
            # Gender: the women's data (figure 5's point is 8.99 ft-lb for them).
            await edit_global(pilot, "handedness", "right")
            await edit_global(pilot, "group_percentile", "50")
            await edit_global(pilot, "training_level", "0")
            await edit_global(pilot, "strength_type", "isometric")
            await edit_global(pilot, "gender", "female")
            assert row_value(app, "Shoulder abduction") == 8.99
            # Undo goes back through the figure's edits.
            await pilot.press("u")
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE

    drive(scenario())


def test_input_data_on_the_strength_page(drive, app_at, tmp_path):
    broken = tmp_path / "broken.dat"
    broken.write_text("P broken\nG MALE\nL RIGHT\n30 45 0 90 0 0 0 17 50\n")
    small = tmp_path / "small.dat"
    small.write_text(
        "P Small strength file\nG MALE\nL RIGHT\n"
        "30 45 0 90 0 0 0 21.50 50 /* shoulder abduction */\n"
    )

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            await pilot.press("i")
            assert "Strength data file:" in message(app)
            await paste(pilot, str(broken))
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert f"{broken}:4:" in message(app) and "strength data unchanged" in message(app)
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE
            await pilot.press("i")
            await paste(pilot, str(small))
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert app.strength_sheet.data.title == "Small strength file"
            assert row_value(app, "Shoulder abduction") == 21.5
            # The file's warnings (motions without data) are shown one at a time.
            assert "has no data for" in message(app)
            assert "no data" not in row_line(app, "Shoulder abduction")
            assert row_line(app, "Wrist flexion").split()[-3:] == ["0", "no", "data"]

    drive(scenario())


@pytest.mark.slow
def test_create_figure_with_and_without_strength(drive, app_at, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("f", "enter")
            assert "Include strength in the figure? (Y/n; 'example'" in message(app)
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert "Wrote MALE50.FIG" in message(app)
            # Enter: only published strength, no invented arm strength
            published = read_fig(tmp_path / "MALE50.FIG").variables
            assert "right_shoulder_abduction_strength" not in published
            assert "right_knee_extension_strength" in published
            assert "TEST DATA" not in (tmp_path / "MALE50.FIG").read_text()
            # the example data only by name, and said so
            await pilot.press("f")
            await paste(pilot, "example.fig")
            await pilot.press("enter", *"example", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert "Its arm strength is the example data (invented)" in message(app)
            with_strength = read_fig(tmp_path / "example.fig").variables
            value, unit = with_strength["right_shoulder_abduction_strength"]
            assert (value, unit) == (24.38, "Nm")
            assert with_strength["left_shoulder_abduction_strength"][0] == pytest.approx(
                24.38 * DEFAULT_NON_DOMINANT_FACTOR, abs=0.01
            )
            assert "source: example data (invented" in (tmp_path / "example.fig").read_text()
            await pilot.press("f")
            await paste(pilot, "plain.fig")
            await pilot.press("enter", "n", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            without = read_fig(tmp_path / "plain.fig").variables
            assert not any(name.endswith("_strength") for name in without)
            assert without["ctorsoz"] == with_strength["ctorsoz"]
            # Anything but y or n writes nothing.
            await pilot.press("f")
            await paste(pilot, "maybe.fig")
            await pilot.press("enter", *"perhaps", "enter")
            assert "expected y, n or example" in message(app)
            assert not (tmp_path / "maybe.fig").exists()

    drive(scenario())


def test_create_figure_without_strength_data_does_not_ask(drive, app_at, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at(SIZE, strength_path=tmp_path / "missing.dat") as (app, pilot):
            await pilot.press("f", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert "Wrote MALE50.FIG" in message(app)
            variables = read_fig(tmp_path / "MALE50.FIG").variables
            assert not any(name.endswith("_strength") for name in variables)

    drive(scenario())


@pytest.mark.slow
def test_export_hanim_writes_x3d_and_asks_before_overwriting(drive, app_at, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.click("#command-export_hanim")
            assert "HAnim file name [MALE50.x3d]:" in message(app)
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert "Exported the HAnim humanoid to MALE50.x3d" in message(app)
            root = ET.parse(tmp_path / "MALE50.x3d").getroot()
            assert root.tag == "X3D"
            humanoids = root.findall(".//HAnimHumanoid")
            assert len(humanoids) == 1
            first = (tmp_path / "MALE50.x3d").read_text()
            # Existing file: kept on anything but y.
            await pilot.press("enter", *"25", "enter")  # change a girth
            await pilot.press("e", "enter")
            assert "exists" in message(app)
            await pilot.press("n", "enter")
            assert (tmp_path / "MALE50.x3d").read_text() == first
            await pilot.press("e", "enter", "y", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert (tmp_path / "MALE50.x3d").read_text() != first
            ET.parse(tmp_path / "MALE50.x3d")
            # A directory that does not exist: said on the message line.
            await pilot.press("e")
            await paste(pilot, str(tmp_path / "no" / "such.x3d"))
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert f"{tmp_path / 'no' / 'such.x3d'}: cannot write" in message(app)
            assert app.query_one("#message").has_class("-error")

    drive(scenario())


def test_export_hanim_refuses_an_incomplete_figure(drive, app_at, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    figure = Figure.default()
    figure.groups[JOINT_LIMITS].values = None  # as if no joint limits for this gender

    async def scenario():
        async with app_at(SIZE, figure) as (app, pilot):
            await pilot.press("e", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert "Joint Limits not loaded" in message(app)
            assert not (tmp_path / "MALE50.x3d").exists()

    drive(scenario())


def test_strength_page_snapshot(snap_compare, new_app):
    assert snap_compare(new_app(), press=["s"], terminal_size=SIZE)


@pytest.mark.slow
def test_angles_outside_new_limits_are_marked(drive, app_at):
    """Lowering the joint-limit percentile can leave a shown angle outside its limit."""

    def outside_cells(page) -> list[str]:
        text = page.render()
        style = page.get_component_rich_style("strengthpage--outside")
        return [
            text.plain[span.start : span.end].strip() for span in text.spans if span.style == style
        ]

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            await pilot.press(*"175", "enter", "right")  # allowed at the 50th (180.95)
            await pilot.pause()
            page = app.query_one(StrengthPage)
            assert app.strength_sheet.angles[0, 0] == 175
            assert outside_cells(page) == []
            await pilot.press("j")
            await edit_global(pilot, "group_percentile", "5")
            await pilot.press("s")
            assert outside_cells(page) == ["175"]

    drive(scenario())


def test_undo_takes_the_newest_edit_angle_or_figure(drive, app_at):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await open_strength(pilot)
            await pilot.press("enter")  # shoulder abduction, shoulder x
            await paste(pilot, "60")
            await pilot.press("enter")
            assert row_line(app, "Shoulder abduction").split()[2] == "60"
            await edit_global(pilot, "training_level", "2")
            assert app.figure.training_level == 2
            await pilot.press("u")  # the newer edit: training level
            assert app.figure.training_level == 0
            assert row_line(app, "Shoulder abduction").split()[2] == "60"
            await pilot.press("u")  # then the angle
            assert row_line(app, "Shoulder abduction").split()[2] == "30"
            assert row_value(app, "Shoulder abduction") == REPORT_VALUE
            await pilot.press("u")
            assert message(app) == "Nothing to undo."

    drive(scenario())


@pytest.mark.slow
def test_lengths_the_humanoid_leaves_out_are_said_on_edit_and_on_export(
    drive, app_at, tmp_path, monkeypatch
):
    # The humanoid (and the figure view drawn from it) stands its joints at the
    # stature's landmarks: a leg length typed here reaches the .fig only, and
    # the user is told so where it would otherwise look ignored.
    monkeypatch.chdir(tmp_path)

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.click("#command-export_hanim")
            await pilot.press("enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert message(app).endswith("Exported the HAnim humanoid to MALE50.x3d.")
            before = (tmp_path / "MALE50.x3d").read_text()
            # Right Upper Leg z (row 9, the z value column)
            await pilot.press(*["down"] * 8, *["right"] * 4, "enter", *"50", "enter")
            said = message(app)
            assert said.startswith("Right Upper Leg z = 50.00 cm (")
            assert "It goes to a .fig; the figure view and Export HAnim stand" in said
            await pilot.click("#command-export_hanim")
            await pilot.press("enter", "y", "enter")
            await app.workers.wait_for_complete()
            await pilot.pause()
            assert message(app) == (
                "Exported the HAnim humanoid to MALE50.x3d. The humanoid's joints stand at "
                "its stature's landmarks (175.5 cm, percentile 50.0; docs/hanim.md). A .fig "
                "(Create Figure) has Right Upper Leg z as set here; the humanoid does not."
            )
            assert (tmp_path / "MALE50.x3d").read_text() == before
            # A length the humanoid uses (Right Upper Arm z) is not mentioned.
            await pilot.press(*["up"] * 4, "enter", *"40", "enter")
            assert message(app).startswith("Right Upper Arm z = 40.00 cm (")
            assert "It goes to a .fig" not in message(app)

    drive(scenario())
