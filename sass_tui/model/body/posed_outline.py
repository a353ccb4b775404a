"""The figure drawn flat in a task's posture (model/body/outline.py draws it
standing): each segment's solids carried by its joint's turn in the posed
humanoid (model/body/posture.py), each drawn as the box or ellipse that
bounds the turned solid, front and side.  No Textual import here."""

from __future__ import annotations

import numpy as np

from sass_tui.model.body.hanim import LOA1, Humanoid
from sass_tui.model.body.outline import Outline, Shape, ShapeKind, View
from sass_tui.model.body.posture import PosedBody


def posed_outline(humanoid: Humanoid, body: PosedBody, label: str, stature: float) -> Outline:
    """`humanoid` standing, `body` the same humanoid posed (its turns)."""
    turns = body.turns or {}
    front: list[Shape] = []
    side: list[Shape] = []
    for joint, segment, _ in LOA1:
        turn = turns.get(joint, np.eye(3))
        standing = humanoid.centers[joint]
        for solid, centre, size in humanoid.segments[segment].shapes:
            kind: ShapeKind = "box" if solid == "box" else "ellipse"
            at = (body.centers[joint] + turn @ (centre - standing)) * 100
            bounds = np.abs(turn) @ np.asarray(size, dtype=float) * 100
            front.append(
                Shape(kind, float(at[0]), float(at[1]), float(bounds[0]), float(bounds[1]))
            )
            side.append(Shape(kind, float(at[2]), float(at[1]), float(bounds[2]), float(bounds[1])))
    joints = [tuple(float(v) * 100 for v in body.centers[j]) for j, _, _ in LOA1]
    return Outline(
        label=label,
        stature=stature,
        front=View(tuple(front), tuple((x, y) for x, y, _ in joints)),
        side=View(tuple(side), tuple((z, y) for _, y, z in joints)),
    )
