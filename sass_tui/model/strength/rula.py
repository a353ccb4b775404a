"""RULA (McAtamney & Corlett 1993, Rapid Upper Limb Assessment) from a
task's posture: the body part scores from the posed figure's own angles,
Tables A, B and C as published (datasets/rula.json), one arm at a time
(docs/task.md "RULA").

What sass knows from the posture and what it assumes (said in the answer):
- upper arm: shoulder flexion (shoulder_y) 20 deg either side of hanging 1,
  extension beyond 20 or flexion 20-45 2, 45-90 3, over 90 4; +1 abducted
  (shoulder_x over 20 deg); a raised shoulder and an arm supported are not
  posed (0);
- lower arm: elbow flexion 60-100 deg 1, otherwise 2; working across the
  midline or out to the side is not posed (0);
- wrist: wrist_y within 1 deg of neutral 1, up to 15 deg 2, beyond 3; +1
  bent from the midline (wrist_x beyond 1 deg); wrist twist (wrist_z) 1 in
  the mid-range, 2 within 10 deg of the end of its range;
- neck: neck flexion (neck_y, the head on the trunk) 0-10 deg 1, 10-20 2,
  over 20 3, in extension (beyond 1 deg back) 4; +1 twisted (neck_z beyond
  1 deg), +1 side-bent (neck_x beyond 1 deg);
- trunk: the trunk's inclination from the vertical in the posed figure
  (trunk and hip flexion together, standing): upright (under 1 deg) 1, up to
  20 2, 20-60 3, over 60 4; seated and upright 1; +1 twisted (trunk_z beyond
  1 deg), +1 side-bent (trunk_x beyond 1 deg);
- legs: 1 standing in balance on both feet, or seated; 2 out of balance or
  on one foot (the paper's "feet not evenly balanced");
- muscle use: not known (0, assumed intermittent);
- force: the hand's force under 2 kg (19.6 N) 0, up to 10 kg (98.1 N) 1
  (intermittent, assumed), over 10 kg 3; the trunk's group takes the sum of
  both hands'.

No Textual import here.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from functools import cache

import numpy as np

from sass_tui.model.datasets import path as dataset_path

FILE_NAME = "rula.json"
KG = 9.81  # N of a kilogram's weight
ASSUMED = "muscle use intermittent, shoulder not raised, arm not supported, not across the midline"


@dataclass(frozen=True)
class Tables:
    a: list[list[list[int]]]
    b: list[list[int]]
    c: list[list[int]]
    source: str


@cache
def read_tables() -> Tables:
    doc = json.loads(dataset_path(FILE_NAME).read_text(encoding="utf-8"))
    return Tables(doc["table_a"], doc["table_b"], doc["table_c"], doc["source"])


@dataclass(frozen=True)
class Rula:
    side: str
    upper_arm: int
    lower_arm: int
    wrist: int
    wrist_twist: int
    neck: int
    trunk: int
    legs: int
    force_a: int
    force_b: int
    posture_a: int
    posture_b: int
    score: int

    @property
    def action_level(self) -> int:
        """1: acceptable; 2: investigate further; 3: soon; 4: now (the paper's)."""
        return (self.score + 1) // 2


def upper_arm_score(flexion: float, abduction: float) -> int:
    if -20.0 <= flexion <= 20.0:
        score = 1
    elif flexion < -20.0 or flexion <= 45.0:
        score = 2
    elif flexion <= 90.0:
        score = 3
    else:
        score = 4
    return score + (1 if abduction > 20.0 else 0)


def lower_arm_score(elbow_flexion: float) -> int:
    return 1 if 60.0 <= elbow_flexion <= 100.0 else 2


def wrist_score(flexion: float, deviation: float) -> int:
    size = abs(flexion)
    score = 1 if size <= 1.0 else 2 if size <= 15.0 else 3
    return score + (1 if abs(deviation) > 1.0 else 0)


def neck_score(flexion: float, twist: float, side_bend: float) -> int:
    if flexion < -1.0:
        score = 4  # in extension
    else:
        score = 1 if flexion <= 10.0 else 2 if flexion <= 20.0 else 3
    return score + (abs(twist) > 1.0) + (abs(side_bend) > 1.0)


def trunk_score(inclination: float, twist: float, side_bend: float) -> int:
    score = (
        1 if inclination < 1.0 else 2 if inclination <= 20.0 else 3 if inclination <= 60.0 else 4
    )
    return score + (abs(twist) > 1.0) + (abs(side_bend) > 1.0)


def force_score(newtons: float) -> int:
    return 0 if newtons < 2 * KG else 1 if newtons <= 10 * KG else 3


def grand_score(
    upper_arm: int,
    lower_arm: int,
    wrist: int,
    twist: int,
    neck: int,
    trunk: int,
    legs: int,
    extra_a: int,
    extra_b: int,
) -> tuple[int, int, int]:
    """(posture score A, posture score B, grand score) from the tables."""
    t = read_tables()
    a = t.a[min(upper_arm, 6) - 1][min(lower_arm, 3) - 1][(min(wrist, 4) - 1) * 2 + twist - 1]
    b = t.b[min(neck, 6) - 1][(min(trunk, 6) - 1) * 2 + legs - 1]
    c = min(a + extra_a, 8)
    d = min(b + extra_b, 7)
    return a, b, t.c[c - 1][d - 1]


def rula(
    side: str,
    angles: dict[tuple[str, str], float],
    trunk_up: np.ndarray,
    twist_range: tuple[float, float],
    seated: bool,
    stable: bool,
    hand_force: float,
    both_forces: float,
) -> Rula:
    """One arm's RULA: `trunk_up` the trunk's axis in the posed figure (unit),
    `twist_range` the wrist's pronation limits (deg)."""

    def angle(axis: str) -> float:
        return angles.get((side, axis), 0.0)

    upper = upper_arm_score(angle("shoulder_y"), angle("shoulder_x"))
    lower = lower_arm_score(angle("elbow_y"))
    wrist = wrist_score(angle("wrist_y"), angle("wrist_x"))
    low, high = twist_range
    z = angle("wrist_z")
    twist = 2 if (z >= high - 10.0 or z <= low + 10.0) and z != 0.0 else 1
    inclination = math.degrees(math.acos(float(np.clip(trunk_up[1], -1.0, 1.0))))
    trunk = trunk_score(
        0.0 if seated and inclination < 1.0 else inclination,
        angles.get(("", "trunk_z"), 0.0),
        angles.get(("", "trunk_x"), 0.0),
    )
    legs = 1 if seated or stable else 2
    neck = neck_score(
        angles.get(("", "neck_y"), 0.0),
        angles.get(("", "neck_z"), 0.0),
        angles.get(("", "neck_x"), 0.0),
    )
    force_a, force_b = force_score(hand_force), force_score(both_forces)
    a, b, score = grand_score(upper, lower, wrist, twist, neck, trunk, legs, force_a, force_b)
    return Rula(side, upper, lower, wrist, twist, neck, trunk, legs, force_a, force_b, a, b, score)
