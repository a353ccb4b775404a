"""The Fit Test histogram draws the men's and the women's bars where both
are counted: side by side in each bin, each gender's colour in the legend
(stacked, a bin's column took one colour and the women's hid the men's)."""

from __future__ import annotations

import pytest
from rich.color import Color
from textual.app import App
from textual_plotext import PlotextPlot

from sass_tui.ui.query.fit_screen import GENDER_COLORS, draw_gender_bars

EDGES = [150.0 + 5 * k for k in range(9)]
# The same people in every bin for both: a stacked column would show one colour.
COUNTS = [3, 10, 25, 40, 40, 25, 10, 3]


class OnePlot(App[None]):
    def compose(self):
        yield PlotextPlot()


def cells_by_colour(text) -> dict[int | None, int]:
    """Bar cells (█) per colour number, below the legend's two lines."""
    found: dict[int | None, int] = {}
    lines = text.split("\n")
    for line in lines[2:]:
        for span in line.spans:
            colour = span.style.color if span.style and not isinstance(span.style, str) else None
            cells = line.plain[span.start : span.end].count("█")
            if colour is not None and cells:
                found[colour.number] = found.get(colour.number, 0) + cells
    return found


@pytest.mark.slow
def test_both_genders_bars_are_drawn(drive):
    async def scenario():
        app = OnePlot()
        async with app.run_test(size=(80, 24)) as pilot:
            widget = app.query_one(PlotextPlot)
            draw_gender_bars(widget.plt, EDGES, {"male": COUNTS, "female": COUNTS})
            widget.refresh()
            await pilot.pause()
            shown = widget.render()
            assert "male" in shown.plain and "female" in shown.plain  # the legend
            found = cells_by_colour(shown)
            male, female = (
                found.get(Color.parse(GENDER_COLORS[g]).number, 0) for g in ("male", "female")
            )
            # Equal counts: equal bars, each a good share of the bars drawn.
            assert male > 20 and female > 20, found
            assert 0.5 < male / female < 2, found

    drive(scenario())
