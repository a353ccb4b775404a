"""REBA (Hignett & McAtamney 2000, Rapid Entire Body Assessment) from a
task's posture: body part scores from the posed figure's own angles, Tables
A, B and C as published (datasets/reba.json), one arm at a time (docs/task.md
"RULA and REBA").

- trunk: its inclination (as for RULA, model/strength/rula.py): upright
  (under 1 deg) 1, to 20 deg 2, 20-60 3, over 60 4; +1 twisted or side-bent;
- neck: neck flexion (neck_y) 0-20 deg 1, over 20 or in extension (beyond
  1 deg back) 2; +1 twisted or side-bent (neck_z, neck_x beyond 1 deg);
- legs: 1 both feet bearing in balance, or seated; 2 out of balance or on
  one foot (the paper's unilateral weight bearing); +1 the knee flexed
  30-60 deg, +2 over 60 (standing);
- load: the hands' forces together under 5 kg 0, 5-10 kg 1, over 10 kg 2;
- upper arm: as RULA's (+1 abducted past 20 deg); lower arm: elbow 60-100
  deg 1, otherwise 2; wrist: flexion or extension to 15 deg 1, beyond 2; +1
  deviated (wrist_x) or twisted (wrist_z) beyond 1 deg;
- coupling: good (0), activity: none (0), assumed.

No Textual import here.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import cache

from sass_tui.model.datasets import path as dataset_path
from sass_tui.model.strength.rula import KG, lower_arm_score, upper_arm_score

FILE_NAME = "reba.json"
ASSUMED = "a good coupling, no static, repeated or rapid activity"


@dataclass(frozen=True)
class Tables:
    a: list[list[list[int]]]
    b: list[list[list[int]]]
    c: list[list[int]]


@cache
def read_tables() -> Tables:
    doc = json.loads(dataset_path(FILE_NAME).read_text(encoding="utf-8"))
    return Tables(doc["table_a"], doc["table_b"], doc["table_c"])


@dataclass(frozen=True)
class Reba:
    side: str
    trunk: int
    neck: int
    legs: int
    load: int
    upper_arm: int
    lower_arm: int
    wrist: int
    score_a: int
    score_b: int
    score: int

    @property
    def action_level(self) -> int:
        """0 negligible, 1 low, 2 medium, 3 high, 4 very high (the paper's)."""
        s = self.score
        return 0 if s == 1 else 1 if s <= 3 else 2 if s <= 7 else 3 if s <= 10 else 4


def trunk_score(inclination: float, twisted_or_bent: bool) -> int:
    score = (
        1 if inclination < 1.0 else 2 if inclination <= 20.0 else 3 if inclination <= 60.0 else 4
    )
    return score + int(twisted_or_bent)


def neck_score(flexion: float, twisted_or_bent: bool) -> int:
    return (1 if -1.0 <= flexion <= 20.0 else 2) + int(twisted_or_bent)


def legs_score(balanced: bool, knee: float, seated: bool) -> int:
    score = 1 if balanced or seated else 2
    if not seated:
        score += 2 if knee > 60.0 else 1 if knee >= 30.0 else 0
    return score


def load_score(newtons: float) -> int:
    return 0 if newtons < 5 * KG else 1 if newtons <= 10 * KG else 2


def wrist_score(flexion: float, deviation: float, twist: float) -> int:
    return (1 if abs(flexion) <= 15.0 else 2) + (abs(deviation) > 1.0 or abs(twist) > 1.0)


def scores(
    trunk: int, neck: int, legs: int, load: int, upper: int, lower: int, wrist: int
) -> tuple[int, int, int]:
    """(score A, score B, REBA score) from the tables (coupling and activity 0)."""
    t = read_tables()
    a = t.a[min(trunk, 5) - 1][min(neck, 3) - 1][min(legs, 4) - 1] + load
    b = t.b[min(upper, 6) - 1][min(lower, 2) - 1][min(wrist, 3) - 1]
    return a, b, t.c[min(a, 12) - 1][min(b, 12) - 1]


def reba(
    side: str,
    angles: dict[tuple[str, str], float],
    inclination: float,
    seated: bool,
    stable: bool,
    both_forces: float,
) -> Reba:
    def angle(axis: str) -> float:
        return angles.get((side, axis), 0.0)

    twisted = (
        abs(angles.get(("", "trunk_z"), 0.0)) > 1.0 or abs(angles.get(("", "trunk_x"), 0.0)) > 1.0
    )
    trunk = trunk_score(0.0 if seated and inclination < 1.0 else inclination, twisted)
    legs = legs_score(stable, angle("knee_y"), seated)
    load = load_score(both_forces)
    upper = upper_arm_score(angle("shoulder_y"), angle("shoulder_x"))
    lower = lower_arm_score(angle("elbow_y"))
    wrist = wrist_score(angle("wrist_y"), angle("wrist_x"), angle("wrist_z"))
    neck = neck_score(
        angles.get(("", "neck_y"), 0.0),
        abs(angles.get(("", "neck_z"), 0.0)) > 1.0 or abs(angles.get(("", "neck_x"), 0.0)) > 1.0,
    )
    a, b, score = scores(trunk, neck, legs, load, upper, lower, wrist)
    return Reba(side, trunk, neck, legs, load, upper, lower, wrist, a, b, score)
