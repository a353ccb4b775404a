"""A hand's reach drawn in the figure view (model/body/reach.py's
ReachDrawing; plain Python: the view is drawn before numpy is loaded): its outline over the side view, and seen from above in a
view of its own right of the side view, the shoulder and a point marked
(green when the hand reaches it, red when it does not)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.color import Color

if TYPE_CHECKING:
    from textual_canvas import Canvas

    from sass_tui.model.body.reach import ReachDrawing

REACH = Color.parse("#87d787")
REACHED = Color.parse("#00ff00")
MISSED = Color.parse("#ff0000")


def side_extent(reach: ReachDrawing) -> tuple[float, float]:
    """(left, right) of the side view's outline, cm forward."""
    return float(reach.side[:, 0].min()), float(reach.side[:, 0].max())


def top_extent(reach: ReachDrawing) -> tuple[float, float]:
    """(left, right) of the view from above, cm (the body's right on the left)."""
    return float(-reach.top[:, 0].max()), float(-reach.top[:, 0].min())


def draw_reach(
    canvas: Canvas,
    reach: ReachDrawing,
    side_origin: float,
    top_origin: float,
    floor: int,
    scale: float,
) -> None:
    """The side outline (z, y) and the view from above (-x, z: seen from
    above with the body facing up the screen, its right hand on the left),
    standing on the floor line."""
    base = float(reach.top[:, 1].min())
    side = [(side_origin + z * scale, floor - y * scale) for z, y in reach.side]
    top = [(top_origin - x * scale, floor - (z - base) * scale) for x, z in reach.top]
    pixels = _ring(side) + _ring(top)
    _put(canvas, pixels, REACH)
    sx, sy, sz = reach.shoulder
    marks = [
        (side_origin + sz * scale, floor - sy * scale),
        (top_origin - sx * scale, floor - (sz - base) * scale),
    ]
    _put(canvas, _cross(marks), REACH)
    if reach.point is not None:
        px, py, pz = reach.point
        at = [
            (side_origin + pz * scale, floor - py * scale),
            (top_origin - px * scale, floor - (pz - base) * scale),
        ]
        _put(canvas, _cross(at), REACHED if reach.reached else MISSED)


def _ring(points: list[tuple[float, float]]) -> list[tuple[int, int]]:
    """The pixels along the closed polygon through `points`."""
    out: list[tuple[int, int]] = []
    for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=True):
        steps = max(1, int(max(abs(x1 - x0), abs(y1 - y0))))
        out += [
            (round(x0 + k / steps * (x1 - x0)), round(y0 + k / steps * (y1 - y0)))
            for k in range(steps + 1)
        ]
    return out


def _cross(centres: list[tuple[float, float]]) -> list[tuple[int, int]]:
    out = []
    for x, y in centres:
        cx, cy = round(x), round(y)
        out += [(cx + d, cy) for d in (-1, 0, 1)] + [(cx, cy + d) for d in (-1, 1)]
    return out


def _put(canvas: Canvas, pixels: list[tuple[int, int]], colour: Color) -> None:
    inside = [
        (int(x), int(y)) for x, y in pixels if 0 <= x < canvas.width and 0 <= y < canvas.height
    ]
    canvas.set_pixels(inside, colour, refresh=False)
