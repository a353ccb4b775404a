"""Where a figure's hands are, as the manual-handling methods measure it:
H, the horizontal distance from the midpoint of the ankles to the midpoint of
the hands' grasp (the third knuckles, the "large middle knuckle" of the
NIOSH manual's section 1.3.1), and V, that midpoint's height above the floor
(model/body/posture.py's joint centres: metres on HAnim's axes, +y up, the
floor at y = 0).  A posture file has no ankles: H is then measured from the
point below L5 (the body's mid-sagittal line, standing upright)."""

from __future__ import annotations

import math

import numpy as np

from sass_tui.model.body.posture import PosedBody
from sass_tui.model.strength.arm_force_field import Posture


def grasp(points: Posture) -> tuple[float, float, float]:
    """The midpoint of the two third knuckles (m, HAnim axes)."""
    middle = (points["l_metacarpophalangeal_3"] + points["r_metacarpophalangeal_3"]) / 2.0
    return float(middle[0]), float(middle[1]), float(middle[2])


def hands_h_v(points: Posture, feet: tuple[float, float]) -> tuple[float, float]:
    """(H, V) in metres of the grasp, H from `feet` (x, z) on the floor."""
    x, y, z = grasp(points)
    return math.hypot(x - feet[0], z - feet[1]), y


def body_h_v(body: PosedBody) -> tuple[float, float]:
    """(H, V) of a posed figure, H from the midpoint of its ankles."""
    ankles = (body.centers["l_talocrural"] + body.centers["r_talocrural"]) / 2.0
    return hands_h_v(body.points, (float(ankles[0]), float(ankles[2])))


def posture_h_v(points: Posture) -> tuple[float, float]:
    """(H, V) of a posture file's joint centres, H from below L5."""
    l5 = np.asarray(points["vl5"], dtype=float)
    return hands_h_v(points, (float(l5[0]), float(l5[2])))
