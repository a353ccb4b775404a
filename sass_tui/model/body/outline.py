"""A figure drawn flat: its segments seen from the front and from the side.

The geometry is the HAnim humanoid's (`hanim.build_humanoid`): the same
joint centres and segment solids the X3D export writes, so the picture and
the exported file never disagree.  Lengths here are cm, y up from the floor;
front view x = the figure's left (the viewer's right), side view x = forward.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Literal

from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.errors import SassError

ShapeKind = Literal["box", "ellipse"]


@dataclass(frozen=True)
class Shape:
    kind: ShapeKind
    x: float  # centre, cm
    y: float
    width: float
    height: float


@dataclass(frozen=True)
class View:
    shapes: tuple[Shape, ...]
    joints: tuple[tuple[float, float], ...]

    def extent(self) -> tuple[float, float, float, float]:
        """(left, right, bottom, top) of every shape, cm."""
        if not self.shapes:
            return (0.0, 0.0, 0.0, 0.0)
        return (
            min(s.x - s.width / 2 for s in self.shapes),
            max(s.x + s.width / 2 for s in self.shapes),
            min(s.y - s.height / 2 for s in self.shapes),
            max(s.y + s.height / 2 for s in self.shapes),
        )


@dataclass(frozen=True)
class Outline:
    """What the figure view draws of one figure."""

    label: str
    stature: float  # cm, the figure's global stature (NaN if unknown)
    front: View
    side: View

    @property
    def height(self) -> float:
        """The top of the drawing: the stature, or the head if it stands higher."""
        top = max(self.front.extent()[3], self.side.extent()[3])
        return top if math.isnan(self.stature) else max(top, self.stature)


class OutlineError(ValueError, SassError):
    """The figure cannot be drawn (a group not loaded, no mass, no segment sizes)."""


def figure_outline(figure: Any, label: str = "") -> Outline:
    """The front and side views of `figure` (a model Figure with every group loaded)."""
    try:
        humanoid = build_humanoid(figure)
    except SassError as exc:
        raise OutlineError(str(exc)) from None
    front: list[Shape] = []
    side: list[Shape] = []
    for segment in humanoid.segments.values():
        for solid, centre, size in segment.shapes:
            kind: ShapeKind = "box" if solid == "box" else "ellipse"
            cx, cy, cz = (float(v) * 100 for v in centre)
            sx, sy, sz = (float(v) * 100 for v in size)
            front.append(Shape(kind, cx, cy, sx, sy))
            side.append(Shape(kind, cz, cy, sz, sy))
    joints = [tuple(float(v) * 100 for v in c) for c in humanoid.centers.values()]
    return Outline(
        label=label or humanoid.name,
        stature=float(figure.stature),
        front=View(tuple(front), tuple((x, y) for x, y, _ in joints)),
        side=View(tuple(side), tuple((z, y) for _, y, z in joints)),
    )
