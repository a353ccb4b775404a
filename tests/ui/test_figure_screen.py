"""The figure screen: opened from the spreadsheet, drawn to scale, overlays."""

from __future__ import annotations

import pytest
from _screen import wait_until
from textual_canvas import Canvas

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.ui.app import SassApp
from sass_tui.ui.spreadsheet.figure_screen import FigureScreen
from sass_tui.ui.spreadsheet.figure_view import FILL, OVERLAY, FigureView


def percentile_figure(gender: str, p: float) -> Figure:
    figure = Figure.default(gender)
    for group in (GIRTH, CENTER_OF_MASS, JOINT_LIMITS):
        figure.set_group_percentile(group, p)
    figure.set_stature_percentile(p)
    figure.set_mass_percentile(p)
    return figure


def colour_rows(app, colour) -> list[int]:
    canvas = app.screen.query_one(Canvas)
    return [
        y
        for y in range(canvas.height)
        if any(canvas.get_pixel(x, y) == colour for x in range(canvas.width))
    ]


@pytest.mark.parametrize("size", [(80, 24), (120, 40)])
@pytest.mark.parametrize("gender, p", [("male", 95), ("female", 5)])
def test_figure_view_snapshot(snap_compare, new_app, gender, p, size):
    assert snap_compare(new_app(percentile_figure(gender, p)), press=["b"], terminal_size=size)


def test_figure_view_snapshot_with_overlay(snap_compare, new_app):
    app = new_app(percentile_figure("female", 5))
    assert snap_compare(app, press=["b", "o"], terminal_size=(120, 40))


def test_b_opens_the_figure_and_escape_goes_back(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("b")
            await pilot.pause()
            assert isinstance(app.screen, FigureScreen)
            assert len(app.screen.query_one(FigureView).outlines) == 1
            assert colour_rows(app, FILL)
            await pilot.press("escape")
            await pilot.pause()
            assert not isinstance(app.screen, FigureScreen)

    drive(scenario())


def test_an_edit_is_drawn_when_the_screen_is_shown_again(drive, app_at):
    """Stature 50th -> 99th on the spreadsheet: the figure stands taller."""

    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("b")
            await pilot.pause()
            before = app.screen.query_one(FigureView).outlines[0].height
            await pilot.press("escape")
            app.session.set_group_percentile(GIRTH, 99)
            app.session.set_stature_percentile(99)
            await pilot.press("b")
            await pilot.pause()
            after = app.screen.query_one(FigureView).outlines[0].height
            assert after > before + 5  # cm
            # u undoes on the figure screen too, and the figure is redrawn.
            await pilot.press("u", "u")
            await pilot.pause()
            assert app.screen.query_one(FigureView).outlines[0].height == pytest.approx(before)

    drive(scenario())


def test_o_cycles_the_population_overlay(drive, app_at):
    async def scenario():
        async with app_at((120, 40), percentile_figure("male", 95)) as (app, pilot):
            await pilot.press("b", "o")
            await pilot.pause()
            view = app.screen.query_one(FigureView)
            shown, overlay = view.outlines
            assert overlay.label == "population 50th"
            assert overlay.height < shown.height  # the 50th is shorter than the 95th
            fifty_height = overlay.height
            assert colour_rows(app, OVERLAY)
            await pilot.press("o")  # the 5th
            await pilot.pause()
            assert view.outlines[1].height < fifty_height
            await pilot.press("o", "o")  # the 95th, then none
            await pilot.pause()
            assert len(view.outlines) == 1
            # The overlay never changes the figure shown.
            assert app.session.figure.stature_percentile == 95

    drive(scenario())


# --- the live figure panel beside the spreadsheet (from 120 columns) -------------------


def panel_rows(app, colour) -> list[int]:
    canvas = app.screen.query_one("#figure-panel").query_one(Canvas)
    return [
        y
        for y in range(canvas.height)
        if any(canvas.get_pixel(x, y) == colour for x in range(canvas.width))
    ]


def test_the_spreadsheet_with_the_figure_panel_snapshot(snap_compare, new_app):
    assert snap_compare(new_app(percentile_figure("male", 95)), terminal_size=(120, 40))


def test_no_figure_panel_below_120_columns(drive, app_at):
    async def scenario():
        async with app_at((119, 40)) as (app, pilot):
            await pilot.pause()
            assert app.spreadsheet.figure_panel is None
            await pilot.resize_terminal(120, 40)
            await wait_until(
                pilot,
                lambda: (
                    app.spreadsheet.figure_panel is not None
                    and app.spreadsheet.figure_panel.display
                ),
                "no figure panel at 120 columns",
            )
            await pilot.resize_terminal(100, 40)
            await wait_until(
                pilot,
                lambda: not app.spreadsheet.figure_panel.display,
                "the figure panel still shows at 100 columns",
            )

    drive(scenario())


def test_quitting_on_the_first_screen_before_the_panel_is_drawn(drive, app_at, monkeypatch):
    """The panel adds its canvas one frame after the first screen:
    an app closing by then (q pressed at once) ends cleanly, not with a
    MountError."""
    monkeypatch.setattr(SassApp, "first_screen_drawn", lambda app: app.exit())

    async def scenario():
        async with app_at((120, 40)) as (app, pilot):
            await pilot.pause()
        assert app.return_code == 0

    drive(scenario())


def test_the_panel_is_outlined_once_at_start_and_when_it_comes_back(drive, app_at, monkeypatch):
    """At start-up the figure is outlined once when the app starts,
    not again for each resize or the first screen resume; a panel hidden by a
    narrow terminal draws the edits made meanwhile when it shows again."""
    import sass_tui.ui.spreadsheet.figure_screen as figure_screen

    outlined = []

    def counted(figure, label):
        outlined.append(label)
        return figure_outline(figure, label)

    figure_outline = figure_screen.figure_outline
    monkeypatch.setattr(figure_screen, "figure_outline", counted)

    async def scenario():
        async with app_at((120, 40)) as (app, pilot):
            # The panel draws a frame after the first screen (two refreshes later).
            await wait_until(pilot, lambda: outlined, "the figure was never outlined")
            assert outlined == ["male figure"]
            await pilot.resize_terminal(130, 40)
            await pilot.pause()
            assert len(outlined) == 1
            await pilot.resize_terminal(100, 40)
            await pilot.pause()
            app.session.set_stature_percentile(99)
            app.spreadsheet.refresh_screen()
            await pilot.resize_terminal(120, 40)
            await wait_until(pilot, lambda: len(outlined) > 1, "the edit was never drawn")
            panel = app.spreadsheet.figure_panel
            assert panel.display and len(outlined) == 2
            assert panel.outlines == figure_screen.session_outlines(app.session, None)

    drive(scenario())


@pytest.mark.slow
def test_every_edit_redraws_the_figure_panel(drive, app_at):
    """Typed on the spreadsheet: the panel draws each edit as it is made."""

    async def scenario():
        async with app_at((120, 40)) as (app, pilot):
            # The panel draws a frame after the first screen (two refreshes later),
            # and its canvas shows it one refresh after the outlines are made.
            await wait_until(
                pilot,
                lambda: app.spreadsheet.figure_panel.outlines and panel_rows(app, FILL),
                "the panel never drew",
            )
            panel = app.spreadsheet.figure_panel
            assert panel is not None and panel.display
            start = panel.outlines[0]
            top = panel_rows(app, FILL)[0]
            # The stature percentile, on the global panel: the figure stands taller.
            await pilot.press("tab", "down", "down", "down", "right", "enter")
            await pilot.press(*"99", "enter")
            await pilot.pause()
            assert app.figure.stature_percentile == 99
            assert panel.outlines[0].stature > start.stature + 10
            assert panel_rows(app, FILL)[0] < top
            # A cell: the right upper leg's width (x) on the data sheet.
            leg = panel.outlines[0]
            await pilot.press("shift+tab")
            assert app.spreadsheet.sheet.has_focus
            await pilot.press(*["down"] * 8, *"30", "enter")
            await pilot.pause()
            assert app.figure.value(GIRTH, "right_upper_leg", 0) == 30
            assert panel.outlines[0] != leg
            # Undo, and the gender: each is drawn at once.
            await pilot.press("u")
            await pilot.pause()
            assert panel.outlines[0] == leg
            await pilot.press("tab", "left", "up", "up", "enter", *"female", "enter")
            await pilot.pause()
            assert app.figure.gender == "female"
            assert panel.outlines[0].stature < leg.stature - 5

    drive(scenario())


def test_the_panel_keeps_the_overlay_chosen_on_the_figure_screen(drive, app_at):
    async def scenario():
        async with app_at((120, 40), percentile_figure("male", 95)) as (app, pilot):
            # The panel draws a frame after the first screen (two refreshes later).
            await wait_until(
                pilot, lambda: app.spreadsheet.figure_panel.outlines, "the panel never drew"
            )
            panel = app.spreadsheet.figure_panel
            assert len(panel.outlines) == 1
            await pilot.press("b", "o", "escape")
            await wait_until(pilot, lambda: len(panel.outlines) > 1, "no overlay drawn")
            assert [o.label for o in panel.outlines] == ["male figure", "population 50th"]
            assert panel_rows(app, OVERLAY)
            # Kept when the figure screen opens again, and still drawn after an edit.
            await pilot.press("b")
            await pilot.pause()
            assert len(app.screen.query_one(FigureView).outlines) == 2
            await pilot.press("escape")
            app.session.set_stature_percentile(50)
            app.spreadsheet.refresh_screen()
            await pilot.pause()
            assert len(panel.outlines) == 2

    drive(scenario())


def test_g_switches_the_gender_on_the_figure_screen_and_redraws(drive, app_at):
    async def scenario():
        async with app_at((100, 30)) as (app, pilot):
            await pilot.press("b")
            await pilot.pause()
            view = app.screen.query_one(FigureView)
            male = view.outlines[0]
            await pilot.press("g")
            await pilot.pause()
            assert app.figure.gender == "female"
            assert view.outlines[0].label == "female figure"
            assert view.outlines[0].stature < male.stature - 5
            await pilot.press("u")  # one undo entry: back to the male figure
            await pilot.pause()
            assert app.figure.gender == "male" and view.outlines[0] == male

    drive(scenario())
