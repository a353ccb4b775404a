"""The figure view draws figures to scale (the geometry the HAnim export writes)."""

from __future__ import annotations

import asyncio

import pytest
from textual.app import App, ComposeResult
from textual_canvas import Canvas

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.outline import OutlineError, figure_outline
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.ui.spreadsheet.figure_view import FILL, OVERLAY, FigureView


def percentile_figure(gender: str, p: float) -> Figure:
    figure = Figure.default(gender)
    for group in (GIRTH, CENTER_OF_MASS, JOINT_LIMITS):
        figure.set_group_percentile(group, p)
    figure.set_stature_percentile(p)
    figure.set_mass_percentile(p)
    return figure


class ViewApp(App):
    def __init__(self, outlines) -> None:
        super().__init__()
        self.outlines = outlines

    def compose(self) -> ComposeResult:
        yield FigureView()

    def on_mount(self) -> None:
        self.query_one(FigureView).outlines = self.outlines


def drawn_rows(outlines, colour, size=(120, 40)) -> tuple[list[int], int]:
    """The canvas rows holding a pixel of `colour`, and the canvas height."""

    async def scenario():
        app = ViewApp(outlines)
        async with app.run_test(size=size) as pilot:
            await pilot.pause()
            canvas = app.query_one(Canvas)
            rows = [
                y
                for y in range(canvas.height)
                if any(canvas.get_pixel(x, y) == colour for x in range(canvas.width))
            ]
            return rows, canvas.height

    return asyncio.run(scenario())


def test_a_taller_figure_is_drawn_taller_in_proportion():
    tall = figure_outline(percentile_figure("male", 95), "male 95th")
    short = figure_outline(percentile_figure("female", 5), "female 5th")
    tall_rows, height = drawn_rows((tall, short), FILL)
    short_rows, _ = drawn_rows((tall, short), OVERLAY)
    floor = height - 1
    assert max(tall_rows) == floor and max(short_rows) == floor  # both stand on the floor
    tall_px = floor - min(tall_rows) + 1
    short_px = floor - min(short_rows) + 1
    # One scale for both: the drawn heights keep the figures' ratio (to a pixel).
    assert tall_px / short_px == pytest.approx(tall.height / short.height, abs=2 / short_px)
    assert tall.height > short.height * 1.15


def test_the_view_says_why_when_a_figure_cannot_be_drawn():
    figure = Figure.default("male")
    figure.groups[GIRTH].values = None  # as if Girth had never been loaded
    with pytest.raises(OutlineError, match="not loaded"):
        figure_outline(figure)
