"""Row names of the anthropometric groups, fixed by the model as SASS hard-coded them.

Each group's rows are listed in display order (report appendices B, C, H, I, L.2).
A row has a snake_case name (used by the query language and the database), a
display label, and the labels a population file may give it in its row comment.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from functools import cache
from types import MappingProxyType
from typing import NamedTuple

from sass_tui.model.vocabulary import CENTER_OF_MASS as CENTER_OF_MASS
from sass_tui.model.vocabulary import GIRTH as GIRTH
from sass_tui.model.vocabulary import GLOBAL as GLOBAL
from sass_tui.model.vocabulary import JOINT_LIMITS as JOINT_LIMITS
from sass_tui.model.vocabulary import MOTION_NAMES
from sass_tui.model.vocabulary import STRENGTH as STRENGTH

AXES = ("x", "y", "z")

GROUPS = (GIRTH, JOINT_LIMITS, CENTER_OF_MASS)
GROUP_TITLES = {
    GIRTH: "Girth",
    JOINT_LIMITS: "Joint Limits",
    CENTER_OF_MASS: "Center of Mass",
    STRENGTH: "Strength",
    GLOBAL: "Global statistics",
}


# A NamedTuple, not a dataclass: dataclasses imports inspect, which `sass query`
# would pay for at every start (docs/performance.md).
class Row(NamedTuple):
    name: str
    label: str
    aliases: tuple[str, ...] = ()


_SPACES = re.compile(r"\s+")


def normalise_label(text: str) -> str:
    """'/* r Upper Arm */' -> 'r upper arm' (for matching row comments)."""
    text = text.strip()
    if text.startswith("/*"):
        text = text[2:]
    if text.endswith("*/"):
        text = text[:-2]
    return _SPACES.sub(" ", text.strip().lower())


def _side_rows(stem: str, label: str, extra: tuple[str, ...] = ()) -> list[Row]:
    rows = []
    for side, short in (("right", "r"), ("left", "l")):
        aliases: tuple[str, ...] = (f"{short} {label.lower()}", f"{side} {label.lower()}")
        aliases += tuple(e.format(side=side, short=short) for e in extra)
        rows.append(Row(f"{side}_{stem}", f"{side.capitalize()} {label}", aliases))
    return rows


# Segment dimensions: appendix B/C order.  x = depth, y = width, z = length.
GIRTH_ROWS: tuple[Row, ...] = tuple(
    [
        Row("bottom_head", "Bottom Head", ("bottom head",)),
        Row("neck", "Neck", ("neck",)),
        Row("center_torso", "Center Torso", ("center torso",)),
        Row("lower_torso", "Lower Torso", ("lower torso",)),
    ]
    + _side_rows("upper_arm", "Upper Arm")
    + _side_rows("lower_arm", "Lower Arm")
    + _side_rows("upper_leg", "Upper Leg")
    + _side_rows("lower_leg", "Lower Leg")
    + _side_rows("foot", "Foot")
    + _side_rows("hand", "Hand")
    + _side_rows("clavicle", "Clavicle")
    + _side_rows("eye", "Eye")
    + [Row("eye_location", "Eye Location", ("eye location",))]
    + _side_rows("ball_of_foot", "Ball of Foot", ("ball of {side} foot",))
    + _side_rows("knuckles", "Knuckles", ("knuckles of {side} hand",))
)

# Center of mass: appendix L.2 holds the first 21 girth rows (balls of the feet
# and knuckles are commented out there).
CENTER_OF_MASS_ROWS: tuple[Row, ...] = GIRTH_ROWS[:21]

JOINTS: tuple[tuple[str, str], ...] = (
    ("neck", "Neck"),
    ("right_clavicle", "R Clavicle"),
    ("left_clavicle", "L Clavicle"),
    ("right_shoulder", "R Shoulder"),
    ("left_shoulder", "L Shoulder"),
    ("right_elbow", "R Elbow"),
    ("left_elbow", "L Elbow"),
    ("right_wrist", "R Wrist"),
    ("left_wrist", "L Wrist"),
    ("waist", "Waist"),
    ("right_hip", "R Hip"),
    ("left_hip", "L Hip"),
    ("right_knee", "R Knee"),
    ("left_knee", "L Knee"),
    ("right_ankle", "R Ankle"),
    ("left_ankle", "L Ankle"),
    ("right_ball_of_foot", "R Ball of Foot"),
    ("left_ball_of_foot", "L Ball of Foot"),
    ("right_knuckles", "R Knuckles"),
    ("left_knuckles", "L Knuckles"),
)


def _joint_rows() -> list[Row]:
    rows = []
    for joint, label in JOINTS:
        for limit in ("ul", "ll"):
            rows.append(Row(f"{joint}_{limit}", f"{label} {limit}", (f"{label.lower()} {limit}",)))
    return rows


JOINT_LIMIT_ROWS: tuple[Row, ...] = tuple(_joint_rows())

# Whole-body statistics the report does not tabulate (datasets/global.dat):
# one value per row, not three axes.
GLOBAL_ROWS: tuple[Row, ...] = (
    Row("stature", "Stature", ("stature", "stature cm")),
    Row("mass", "Mass", ("mass", "mass kg", "weight")),
)

ROWS: dict[str, tuple[Row, ...]] = {
    GIRTH: GIRTH_ROWS,
    JOINT_LIMITS: JOINT_LIMIT_ROWS,
    CENTER_OF_MASS: CENTER_OF_MASS_ROWS,
    GLOBAL: GLOBAL_ROWS,
}
AXES_OF = {GIRTH: 3, JOINT_LIMITS: 3, CENTER_OF_MASS: 3, GLOBAL: 1}

# Display order of the strength page (one page of 14 rows; model/strength/strength_data.py).
MOTIONS: tuple[Row, ...] = tuple(
    Row(name, name.replace("_", " ").capitalize(), (name.replace("_", " "),))
    for name in MOTION_NAMES
)

# The joint-angle columns of figure 8 (the strength page).
JOINT_AXIS_LABELS = (
    "Shoulder x",
    "Shoulder y",
    "Shoulder z",
    "Elbow y",
    "Wrist x",
    "Wrist y",
    "Wrist z",
)


def row_index(group: str, name: str) -> int:
    for i, row in enumerate(ROWS[group]):
        if row.name == name:
            return i
    raise KeyError(f"no row {name!r} in {GROUP_TITLES[group]}")


@cache
def label_lookup(group: str) -> Mapping[str, int]:
    """Every way a file may label a row of `group` -> the row's index (read-only:
    built once, it is shared)."""
    table: dict[str, int] = {}
    for i, row in enumerate(ROWS[group]):
        table[normalise_label(row.label)] = i
        table[row.name.replace("_", " ")] = i
        for alias in row.aliases:
            table[normalise_label(alias)] = i
    return MappingProxyType(table)


# --- .fig variable names -------------------------------------------------
# Segment prefixes of BODY.FIG (appendix D).  Appendix F misspells three of them
# (boheadx, rlolegmass, rloarmmass); BODY.FIG is what reads the file, so its
# spelling wins (docs/model.md lists the differences).
FIG_PREFIX = {
    "bottom_head": "bothead",
    "neck": "neck",
    "center_torso": "ctorso",
    "lower_torso": "ltorso",
    "right_upper_arm": "ruparm",
    "left_upper_arm": "luparm",
    "right_lower_arm": "rlowarm",
    "left_lower_arm": "llowarm",
    "right_upper_leg": "rupleg",
    "left_upper_leg": "lupleg",
    "right_lower_leg": "rlowleg",
    "left_lower_leg": "llowleg",
    "right_foot": "rfoot",
    "left_foot": "lfoot",
    "right_hand": "rhand",
    "left_hand": "lhand",
    "right_clavicle": "rclav",
    "left_clavicle": "lclav",
    "right_eye": "reye",
    "left_eye": "leye",
    "eye_location": "eyeloc",
    "right_ball_of_foot": "rtoes",
    "left_ball_of_foot": "ltoes",
    "right_knuckles": "rfingers",
    "left_knuckles": "lfingers",
}

# psurf scale factors against the table value (spec §2, appendix F against B):
# x and y half, z full, except the listed segments.
FIG_SCALE = {
    "right_eye": (1.0, 1.0, 1.0),
    "left_eye": (1.0, 1.0, 1.0),
    "eye_location": (0.5, 1.0, 1.0),
    "right_ball_of_foot": (1.0, 0.5, 1.0),
    "left_ball_of_foot": (1.0, 0.5, 1.0),
    "right_knuckles": (1.0, 0.5, 1.0),
    "left_knuckles": (1.0, 0.5, 1.0),
    "right_foot": (0.75, 0.5, 1.0),
    "left_foot": (0.75, 0.5, 1.0),
}
DEFAULT_SCALE = (0.5, 0.5, 1.0)

# Segment mass fractions of the total body mass (appendix K, male; used for both
# sexes as report §6 says), in the order of appendix F's mass variables.
MASS_FRACTIONS: tuple[tuple[str, float], ...] = (
    ("rfootmass", 0.014),
    ("lfootmass", 0.014),
    ("rlowlegmass", 0.046),
    ("llowlegmass", 0.046),
    ("ruplegmass", 0.1),
    ("luplegmass", 0.1),
    ("rhipmass", 0.042),
    ("lhipmass", 0.042),
    ("ltorsomass", 0.042),
    ("ctorsomass", 0.138),
    ("uptorsomass", 0.171),
    ("botheadmass", 0.02),
    ("topheadmass", 0.059),
    ("neckmass", 0.002),
    ("rclavmass", 0.03),
    ("lclavmass", 0.03),
    ("rsternummass", 0.002),
    ("lsternummass", 0.002),
    ("ruparmmass", 0.028),
    ("luparmmass", 0.028),
    ("rlowarmmass", 0.016),
    ("llowarmmass", 0.016),
    ("rhandmass", 0.006),
    ("lhandmass", 0.006),
    ("reyemass", 0.0),
    ("leyemass", 0.0),
    ("bodyrootmass", 0.0),
    ("rtoesmass", 0.0),
    ("ltoesmass", 0.0),
    ("rfingersmass", 0.0),
    ("lfingersmass", 0.0),
)


def joint_limit_variable(row_name: str, axis: str) -> str:
    """'right_shoulder_ul', 'x' -> 'right_shoulder_x_ulimit' (appendix F)."""
    joint, limit = row_name.rsplit("_", 1)
    return f"{joint}_{axis}_{limit}imit"


def center_of_mass_variable(row_name: str, axis: str) -> str:
    """'right_upper_arm', 'z' -> 'ruparmcmz' (our naming; docs/model.md)."""
    return f"{FIG_PREFIX[row_name]}cm{axis}"
