"""The figure screen's reach (`r`) and point (`p`): the right fingertip's
envelope drawn over the side view and from above, and a point's verdict
said on the message line and marked."""

from __future__ import annotations

import pytest
from _screen import wait_until
from textual_canvas import Canvas

from sass_tui.model.body.hanim import build_humanoid
from sass_tui.ui.spreadsheet.figure_screen import FigureScreen
from sass_tui.ui.spreadsheet.figure_view import FigureView
from sass_tui.ui.spreadsheet.reach_drawing import MISSED, REACH, REACHED


def _columns(app, colour) -> list[int]:
    canvas = app.screen.query_one(Canvas)
    return [
        x
        for x in range(canvas.width)
        if any(canvas.get_pixel(x, y) == colour for y in range(canvas.height))
    ]


def _said(app) -> str:
    return app.screen.message_line.history[-1][1]


@pytest.mark.slow
def test_r_draws_the_reach_and_p_judges_a_point(drive, app_at):
    async def scenario():
        async with app_at((120, 40)) as (app, pilot):
            await pilot.press("b")
            await pilot.pause()
            assert isinstance(app.screen, FigureScreen)
            view = app.screen.query_one(FigureView)
            assert view.reach is None and not _columns(app, REACH)
            await pilot.press("r")
            await wait_until(pilot, lambda: view.reach is not None, "no reach drawn")
            columns = _columns(app, REACH)
            # the side outline and the view from above: two separate runs of columns
            assert columns and max(b - a for a, b in zip(columns, columns[1:])) > 1
            assert "from above" in str(view.query_one("#figure-caption").render())
            # straight ahead of the right shoulder, 40 cm: reached
            shoulder = build_humanoid(app.session.figure).centers["r_shoulder"] * 100
            x, y = shoulder[0], shoulder[1]
            await pilot.press("p", *f"{x:.1f},{y:.1f},40", "enter")
            await wait_until(pilot, lambda: view.reach.point is not None, "no point")
            assert "reaches it" in _said(app)
            assert _columns(app, REACHED)
            await pilot.press("p", *["backspace"] * 20, *f"{x:.1f},{y:.1f},200", "enter")
            await wait_until(pilot, lambda: "misses it by" in _said(app), "")
            assert _columns(app, MISSED)
            await pilot.press("p", *["backspace"] * 20, *"1,2", "enter")
            await wait_until(pilot, lambda: "unchanged" in _said(app), "")
            # no command-line option named on the screen (it said "--point '1,2'")
            assert _said(app) == (
                "The point is unchanged: '1,2': expected X,Y,Z, e.g. 30,120,50 or 0.3,1.2,0.5 m"
            )
            await pilot.press("r")
            await wait_until(pilot, lambda: view.reach is None, "the reach still drawn")

    drive(scenario())
