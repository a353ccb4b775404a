"""What a human body can measure: one check for a stature, a mass and a
joint's place, the same whichever verb, file or screen the number came from.

Outside these ranges a number is a typing error (2 for 200, metres for cm,
grams for kg) or a hostile file, not a person: it is refused, with one
wording (`not_human`).  Inside them but beyond a population's 0.5th-99.5th
percentile a value stands with a warning (`Figure.implausible_range`).

The ranges: statures 50-300 cm (a newborn to beyond the tallest recorded
man, 272 cm); masses above 0 and at most 500 kg (the database importers'
ceiling, model/files and db/people); a joint at most 3 m from the body's
root joint (no limb reaches farther; a posture file's elbow at 1e15 m gave
a negative strength).
"""

from __future__ import annotations

import math

MIN_STATURE_CM = 50.0
MAX_STATURE_CM = 300.0
MAX_MASS_KG = 500.0
# The farthest a joint can be from the body's root (the pelvis), in metres.
MAX_JOINT_DISTANCE_M = 3.0

# name -> (lowest, highest, unit, lowest allowed itself)
RANGES: dict[str, tuple[float, float, str, bool]] = {
    "stature": (MIN_STATURE_CM, MAX_STATURE_CM, "cm", True),
    "mass": (0.0, MAX_MASS_KG, "kg", False),
}


def not_human(name: str, value: float) -> str | None:
    """Why `value` (cm for a stature, kg for a mass) is no human's `name`,
    or None when it may be: "stature 1e+308 cm is not a human one; expected
    50-300 cm"."""
    low, high, unit, low_allowed = RANGES[name]
    inside = (low <= value if low_allowed else low < value) and value <= high
    if math.isfinite(value) and inside:
        return None
    return f"{name} {value:g} {unit} is not a human one; expected {low:g}-{high:g} {unit}"


def joint_too_far(name: str, distance_m: float, root: str) -> str | None:
    """Why a joint `distance_m` metres from the body's root joint `root`
    cannot be a human's, or None when it may be."""
    if math.isfinite(distance_m) and distance_m <= MAX_JOINT_DISTANCE_M:
        return None
    return (
        f"{name} is {distance_m:g} m from {root}; a human's joints are within "
        f"{MAX_JOINT_DISTANCE_M:g} m of it"
    )
