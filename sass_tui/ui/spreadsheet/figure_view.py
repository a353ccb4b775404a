"""The figure view: the current figure drawn to scale, front and side.

Its screen hands it `Outline`s (sass_tui/model/body/outline.py, the HAnim
geometry flattened): the first is drawn filled, a second one (the
population's 50th against the person shown, or another percentile) as an
outline over it.  Pixels are half character cells (textual-canvas), about
square on a terminal, so one scale serves both axes.  A ruler stands on the
left with a tick every 10 cm and a long one every 50 cm.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from textual.app import ComposeResult
from textual.color import Color
from textual.containers import Vertical
from textual.reactive import reactive
from textual.widgets import Static

from sass_tui.ui.spreadsheet.reach_drawing import draw_reach, side_extent, top_extent

if TYPE_CHECKING:
    # The canvas: imported with the first one, ~17 ms (it reads its version).
    # The outlines: what the figure screen's module builds (model/body/outline.py,
    # the HAnim humanoid, numpy), handed to the view after the first screen.
    from textual_canvas import Canvas

    from sass_tui.model.body.outline import Outline, Shape, View
    from sass_tui.model.body.reach import ReachDrawing

FILL = Color.parse("#5f87af")
OVERLAY = Color.parse("#ffaf00")
JOINT = Color.parse("#ff5f5f")
RULER = Color.parse("#a8a8a8")
GAP = 4  # pixels between the ruler, the front view and the side view


class FigureView(Vertical):
    """Front and side views of one or two figures, with a stature ruler."""

    DEFAULT_CSS = """
    FigureView { height: 1fr; }
    FigureView Canvas { height: 1fr; width: 1fr; }
    FigureView #figure-caption { height: auto; }
    """

    outlines: reactive[tuple[Outline, ...]] = reactive((), always_update=True)
    # a hand's reach over the side view and seen from above (None: not shown)
    reach: reactive[ReachDrawing | None] = reactive(None, always_update=True)

    def __init__(
        self, *, canvas_focus: bool = True, canvas_later: bool = False, id: str | None = None
    ) -> None:
        super().__init__(id=id)
        # False beside the spreadsheet: a picture there, Tab stays with the data.
        self.canvas_focus = canvas_focus
        # True beside the spreadsheet: the view takes its place at once and
        # draws one frame after it is first shown, so that the spreadsheet's
        # first screen does not wait for the canvas.
        self.canvas_later = canvas_later

    def compose(self) -> ComposeResult:
        if not self.canvas_later:
            yield self._new_canvas()
        yield Static("", id="figure-caption")

    def on_mount(self) -> None:
        if self.canvas_later:
            self.call_after_refresh(self._add_canvas)

    def _new_canvas(self) -> Canvas:
        # deferred: textual_canvas — off the first screen (sass_tui/startup.py)
        from textual_canvas import Canvas

        canvas = Canvas(1, 2, id="figure-canvas")
        canvas.can_focus = self.canvas_focus
        return canvas

    async def _add_canvas(self) -> None:
        if not self.is_attached or self.canvas is not None:
            return  # the app is closing (q pressed at once), or the canvas is there
        await self.mount(self._new_canvas(), before="#figure-caption")
        self.call_after_refresh(self.redraw)  # once the canvas has its size

    def watch_outlines(self) -> None:
        self.redraw()

    def watch_reach(self) -> None:
        self.redraw()

    def on_resize(self) -> None:
        self.redraw()

    @property
    def canvas(self) -> Canvas | None:
        """The canvas drawn on; None until a view composed without it has added it."""
        canvases = self.query("#figure-canvas")
        return canvases.first() if canvases else None  # type: ignore[return-value]

    def redraw(self) -> None:
        canvas = self.canvas if self.is_mounted else None
        if canvas is None:
            return
        width, height = canvas.size.width, canvas.size.height * 2
        if width < 8 or height < 8:
            return
        canvas.clear(width=width, height=height)
        self.query_one("#figure-caption", Static).update(self.caption())
        if not self.outlines:
            return
        tallest = max(o.height for o in self.outlines) or 1.0
        ruler_x = 1
        front_cm = max(_view_width(o.front) for o in self.outlines)
        side_left = min(o.side.extent()[0] for o in self.outlines)
        side_right = max(o.side.extent()[1] for o in self.outlines)
        reach, top_cm, gaps = self.reach, 0.0, 2
        if reach is not None:
            side_left = min(side_left, side_extent(reach)[0])
            side_right = max(side_right, side_extent(reach)[1])
            top_cm, gaps = top_extent(reach)[1] - top_extent(reach)[0], 3
        side_cm = side_right - side_left
        if not all(math.isfinite(v) for v in (tallest, front_cm, side_cm)):
            return  # no picture of what no figure measures (the caption says the stature)
        # Pixels per cm: the full height, unless front and side would then be
        # wider than the view (a narrow panel beside the spreadsheet).
        scale = (height - 2) / tallest
        if front_cm + side_cm + top_cm > 0:
            scale = min(scale, (width - 2 - ruler_x - gaps * GAP) / (front_cm + side_cm + top_cm))
        floor = height - 1
        front_width = front_cm * scale
        front_centre = ruler_x + GAP + front_width / 2
        side_origin = front_centre + front_width / 2 + GAP - side_left * scale
        with canvas.batch_refresh():
            _draw_ruler(canvas, ruler_x, floor, scale, tallest)
            for index, outline in enumerate(self.outlines[:2]):
                filled = index == 0
                colour = FILL if filled else OVERLAY
                for view, origin in ((outline.front, front_centre), (outline.side, side_origin)):
                    for shape in view.shapes:
                        _draw_shape(canvas, shape, origin, floor, scale, colour, filled)
                    if filled:
                        pixels = [_to_pixel(x, y, origin, floor, scale) for x, y in view.joints]
                        _set(canvas, pixels, JOINT)
            if reach is not None:
                top_origin = side_origin + side_right * scale + GAP - top_extent(reach)[0] * scale
                draw_reach(canvas, reach, side_origin, top_origin, floor, scale)

    def caption(self) -> str:
        if not self.outlines:
            return "No figure to draw."
        parts = []
        for index, outline in enumerate(self.outlines[:2]):
            stature = "" if math.isnan(outline.stature) else f", stature {outline.stature:.1f} cm"
            colour = "#5f87af" if index == 0 else "#ffaf00"
            mark = "■" if index == 0 else "□"
            parts.append(f"[{colour}]{mark}[/] {outline.label}{stature}")
        views = "Front | side | reach from above.  " if self.reach else "Front | side.  "
        return views + "   ".join(parts) + "   (ruler: 10 cm ticks)"


def _view_width(view: View) -> float:
    left, right, _, _ = view.extent()
    return right - left


def _to_pixel(x: float, y: float, origin: float, floor: int, scale: float) -> tuple[int, int]:
    return round(origin + x * scale), round(floor - y * scale)


def _set(canvas: Canvas, pixels: list[tuple[int, int]], colour: Color) -> None:
    inside = [(x, y) for x, y in pixels if 0 <= x < canvas.width and 0 <= y < canvas.height]
    canvas.set_pixels(inside, colour, refresh=False)


def _draw_shape(
    canvas: Canvas,
    shape: Shape,
    origin: float,
    floor: int,
    scale: float,
    colour: Color,
    filled: bool,
) -> None:
    left = origin + (shape.x - shape.width / 2) * scale
    right = origin + (shape.x + shape.width / 2) * scale
    top = floor - (shape.y + shape.height / 2) * scale
    bottom = floor - (shape.y - shape.height / 2) * scale
    x0, x1 = math.floor(left + 0.5), max(math.floor(left + 0.5), math.ceil(right - 0.5))
    y0, y1 = math.floor(top + 0.5), max(math.floor(top + 0.5), math.ceil(bottom - 0.5))
    cx, cy = (left + right) / 2, (top + bottom) / 2
    rx, ry = max((right - left) / 2, 0.5), max((bottom - top) / 2, 0.5)
    pixels = []
    # Only the pixels on the canvas are visited, however large the shape.
    for y in range(max(y0, 0), min(y1, canvas.height - 1) + 1):
        for x in range(max(x0, 0), min(x1, canvas.width - 1) + 1):
            if shape.kind == "ellipse":
                inside = ((x - cx) / rx) ** 2 + ((y - cy) / ry) ** 2 <= 1.0
                edge = inside and (
                    ((abs(x - cx) + 1) / rx) ** 2 + ((y - cy) / ry) ** 2 > 1.0
                    or ((x - cx) / rx) ** 2 + ((abs(y - cy) + 1) / ry) ** 2 > 1.0
                )
            else:
                inside = True
                edge = x in (x0, x1) or y in (y0, y1)
            if inside and (filled or edge):
                pixels.append((x, y))
    _set(canvas, pixels, colour)


def _draw_ruler(canvas: Canvas, x: int, floor: int, scale: float, tallest: float) -> None:
    # The ticks on the canvas only: a figure 1e308 cm tall drew 1e307 ticks.
    if not (math.isfinite(tallest) and scale > 0):
        return
    tallest = min(tallest, floor / scale)
    top = floor - round(tallest * scale)
    pixels = [(x, y) for y in range(max(top, 0), floor + 1)]
    for cm in range(0, int(tallest) + 1, 10):
        y = floor - round(cm * scale)
        pixels += [(x - 1, y), (x + 1, y)]
        if cm % 50 == 0:
            pixels += [(x + 2, y)]
    _set(canvas, pixels, RULER)
