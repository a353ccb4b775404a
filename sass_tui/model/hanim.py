"""HAnim export: the figure as an ISO/IEC 19774 humanoid (LOA-1) in X3D XML.

The construction (joint centres from the segment dimensions, joint-limit axes,
solid approximations for inertia, sites) is documented in docs/hanim.md; the
comments here say why a choice was made, that page says what it gives.
No Textual import: the CLI and the TUI both call export_hanim().
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from sass_tui.model.appendix_l import HEEL_BEHIND_ANKLE
from sass_tui.model.atomic import write_text_atomic
from sass_tui.model.errors import SassError
from sass_tui.model.figfile import FigureIncompleteError
from sass_tui.model.landmarks import (
    BIACROMIAL_FRACTION,
    HUMERAL_HEAD_RADIUS,
    half_breadths,
    measured_heights,
    shoulder_below_acromion,
)
from sass_tui.model.names import (
    CENTER_OF_MASS,
    GIRTH,
    GLOBAL,
    JOINT_LIMITS,
    ROWS,
    row_index,
)
from sass_tui.model.percentile import value_at

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET

    from sass_tui.model.figure import Figure

HANIM_VERSION = "2.0"
LOA = 1  # clause 4.8.5: the 18 joints of figure 4.4

# Figure 4.10 (clause 4.9.6.1): joint, its segment, its parent joint.
LOA1: tuple[tuple[str, str, str | None], ...] = (
    ("humanoid_root", "sacrum", None),
    ("sacroiliac", "pelvis", "humanoid_root"),
    ("l_hip", "l_thigh", "sacroiliac"),
    ("l_knee", "l_calf", "l_hip"),
    ("l_talocrural", "l_talus", "l_knee"),
    ("l_metatarsophalangeal_2", "l_tarsal_proximal_phalanx_2", "l_talocrural"),
    ("r_hip", "r_thigh", "sacroiliac"),
    ("r_knee", "r_calf", "r_hip"),
    ("r_talocrural", "r_talus", "r_knee"),
    ("r_metatarsophalangeal_2", "r_tarsal_proximal_phalanx_2", "r_talocrural"),
    ("vl5", "l5", "humanoid_root"),
    ("skullbase", "skull", "vl5"),
    ("l_shoulder", "l_upperarm", "vl5"),
    ("l_elbow", "l_forearm", "l_shoulder"),
    ("l_radiocarpal", "l_carpal", "l_elbow"),
    ("r_shoulder", "r_upperarm", "vl5"),
    ("r_elbow", "r_forearm", "r_shoulder"),
    ("r_radiocarpal", "r_carpal", "r_elbow"),
)
SEGMENT_OF = {joint: segment for joint, segment, _ in LOA1}

# Where the joint centres stand (clause 4.8.2: "placed so that the joints
# rotate in the same way that they do on a real human body"): each at the
# height of a body landmark.  A real person's landmarks are their own
# measurements (model/landmarks.py); a percentile figure's are its stature
# times the mean landmark/stature ratio of the ANSUR II public data (Gordon et
# al. 2014, 4,082 men and 1,986 women; scripts/hanim_landmarks.py computes the
# ratios and measures the placements, docs/hanim.md).
#   ankle (talocrural)  lateral malleolus height
#   knee                lateral femoral epicondyle height (the flexion axis)
#   hip                 trochanterion height (level with the femoral head)
#   vl5                 iliocristale height (the iliac crest, at L4-L5)
#   shoulder            acromion height less 17 % of the biacromial breadth
#                       (model/landmarks.py: Rab et al. 2002, for every figure)
#   neck base (top of l5) cervicale height; skullbase: tragion height
#   omphalion           the navel (waist height, omphalion): where de Leva's
#                       lower trunk begins (segment masses, below)
#   skull vertex        the stature
LANDMARK_FRACTIONS: dict[str, dict[str, float]] = {
    "male": {
        "lateral_malleolus": 0.0415,
        "femoral_epicondyle": 0.2799,
        "trochanterion": 0.5128,
        "iliocristale": 0.6044,
        "acromion": 0.8203,
        "cervicale": 0.8639,
        "omphalion": 0.6014,
        "tragion": 0.9252,
    },
    "female": {
        "lateral_malleolus": 0.0385,
        "femoral_epicondyle": 0.2860,
        "trochanterion": 0.5190,
        "iliocristale": 0.6113,
        "acromion": 0.8198,
        "cervicale": 0.8570,
        "omphalion": 0.6017,
        "tragion": 0.9222,
    },
}
# The segment dimensions (GIRTH row, axis) the humanoid does not use: its
# joint heights follow the stature's landmarks (above), so the lengths of
# the neck, the trunk and the legs reach only the .fig, and LOA-1 has no
# clavicle or eye segment.  A test changes every cell: these leave the
# export as it was, every other one changes it.
NOT_IN_HUMANOID: tuple[tuple[str, int], ...] = (
    ("neck", 2),
    ("center_torso", 2),
    ("lower_torso", 2),
    *((f"{side}_{part}", 2) for side in ("right", "left") for part in ("upper_leg", "lower_leg")),
    *(
        (f"{side}_{part}", axis)
        for side in ("right", "left")
        for part in ("clavicle", "eye")
        for axis in range(3)
    ),
)

# Segment masses and centres of mass: de Leva (1996), "Adjustments to
# Zatsiorsky-Seluyanov's segment inertia parameters", J. Biomech. 29(9),
# 1223-1230, table 4 (young adults: 100 men, 15 women).  Appendix K's fractions
# give the legs ~32 % of the body and the trunk ~50 %, where these measured
# tables give ~40 % and ~43 %: with K's masses the humanoid's centre of mass
# stood at ~58 % of the stature, the top of the adult range (docs/hanim.md).
# The .fig keeps appendix K (BODY.FIG's masses); only the export uses these.
# Per segment: % of body mass, and the centre of mass as % of the distance
# between de Leva's two endpoints, from the first:
#   head    vertex - cervicale (head and neck)      thigh  hip - knee centre
#   trunk   cervicale - hip centres (the whole)     shank  knee - lateral malleolus
#   lower trunk  omphalion - hip centres            foot   heel - toe tip
#   upper arm  shoulder - elbow centre              hand   wrist - middle fingertip
#   forearm    elbow - wrist centre
DE_LEVA: dict[str, dict[str, tuple[float, float]]] = {
    "male": {
        "head": (6.94, 50.02),
        "trunk": (43.46, 51.38),
        "lower_trunk": (11.17, 61.15),
        "upper_arm": (2.71, 57.72),
        "forearm": (1.62, 45.74),
        "hand": (0.61, 36.24),
        "thigh": (14.16, 40.95),
        "shank": (4.33, 44.59),
        "foot": (1.37, 44.15),
    },
    "female": {
        "head": (6.68, 48.41),
        "trunk": (42.57, 49.64),
        "lower_trunk": (12.47, 49.20),
        "upper_arm": (2.55, 57.54),
        "forearm": (1.38, 45.59),
        "hand": (0.56, 34.27),
        "thigh": (14.78, 36.12),
        "shank": (4.81, 44.16),
        "foot": (1.29, 40.14),
    },
}
# Which de Leva segment each HAnim segment carries: the pelvis is the lower
# trunk, l5 the rest of the trunk (upper and middle), the skull the head with
# the neck; sacrum and toes (in de Leva's foot) carry nothing.
SEGMENT_MASSES: dict[str, str | None] = {
    "sacrum": None,
    "pelvis": "lower_trunk",
    "l5": "trunk",  # less the lower trunk
    "skull": "head",
}
for _side in ("l", "r"):
    SEGMENT_MASSES.update(
        {
            f"{_side}_thigh": "thigh",
            f"{_side}_calf": "shank",
            f"{_side}_talus": "foot",
            f"{_side}_tarsal_proximal_phalanx_2": None,
            f"{_side}_upperarm": "upper_arm",
            f"{_side}_forearm": "forearm",
            f"{_side}_carpal": "hand",
        }
    )


def segment_mass_fractions(gender: str) -> dict[str, float]:
    """Each HAnim segment's share of the body mass (de Leva 1996), scaled to
    add up to exactly 1 (the female table adds up to 99.99 %)."""
    table = DE_LEVA[gender]
    shares = {
        name: 0.0 if part is None else table[part][0] for name, part in SEGMENT_MASSES.items()
    }
    shares["l5"] -= table["lower_trunk"][0]
    total = sum(shares.values())
    return {name: share / total for name, share in shares.items()}


_X, _Y, _Z = np.eye(3)

# Joint-limit frames.  SASS names its axes per joint: x = the antero-posterior
# axis (abduction, lateral bending, radial deviation, supination), y = the
# medio-lateral axis (flexion), z = the long axis (rotation), each signed so
# that the upper limit is the motion appendix G names first.  Here each axis is
# given in HAnim humanoid coordinates (+X left, +Y up, +Z front) with the sign
# that makes a positive rotation that motion.  SASS's signs do not always form
# a right-handed frame (a mirror cannot be a rotation): the frame's z is then
# x cross y and the rotation limits on it are negated and swapped.
# (HAnim joint, SASS joint row stem, x axis, y axis, anatomical z axis or None)
_LIMIT_AXES: tuple[tuple[str, str, np.ndarray, np.ndarray, np.ndarray | None], ...] = (
    ("vl5", "waist", _Z, _X, _Y),  # bend right, bend forward, twist left
    ("skullbase", "neck", _Z, _X, -_Y),  # lateral right, flexion, rotation right
    ("l_shoulder", "left_shoulder", _Z, -_X, _Y),  # abduction, flexion, lateral rotation
    ("r_shoulder", "right_shoulder", -_Z, -_X, -_Y),
    ("l_elbow", "left_elbow", _Z, -_X, None),  # flexion only
    ("r_elbow", "right_elbow", -_Z, -_X, None),
    # palms face the thighs (4.8.2), so the thumb points to +Z
    ("l_radiocarpal", "left_wrist", -_X, -_Z, -_Y),  # radial, flexion, pronation
    ("r_radiocarpal", "right_wrist", -_X, _Z, _Y),
    ("l_hip", "left_hip", _Z, -_X, _Y),  # abduction, flexion, lateral rotation
    ("r_hip", "right_hip", -_Z, -_X, -_Y),
    ("l_knee", "left_knee", _Z, _X, None),  # flexion (the shank goes back)
    ("r_knee", "right_knee", -_Z, _X, None),
    ("l_talocrural", "left_ankle", -_Z, -_X, _Y),  # supination, dorsiflexion, lateral rotation
    ("r_talocrural", "right_ankle", _Z, -_X, -_Y),
    # BODY.FIG gives the ball of the foot the elbow's R(0,1,0): toes up
    ("l_metatarsophalangeal_2", "left_ball_of_foot", -_Z, -_X, None),
    ("r_metatarsophalangeal_2", "right_ball_of_foot", _Z, -_X, None),
)


class HAnimError(ValueError, SassError):
    """The figure cannot be exported as a humanoid."""


@dataclass
class Limits:
    sass_joint: str
    frame: np.ndarray  # 3x3, columns = the limit frame's axes in humanoid coordinates
    upper: list[float]  # radians about the frame's x, y, z
    lower: list[float]
    mirrored_z: bool

    @property
    def orientation(self) -> tuple[float, float, float, float]:
        return axis_angle(self.frame)


# (box|ellipsoid, centre, full size along X, Y, Z)
Shape = tuple[str, np.ndarray, np.ndarray]


@dataclass
class Segment:
    name: str
    mass: float  # kg
    center_of_mass: np.ndarray  # m, humanoid coordinates
    inertia: np.ndarray  # 3x3 kg m^2 about the centre of mass
    shapes: list[Shape] = field(default_factory=list)


@dataclass
class Site:
    name: str
    segment: str
    translation: np.ndarray
    rotation: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 0.0)


@dataclass
class Humanoid:
    """The LOA-1 humanoid SASS's figure becomes; all lengths in metres."""

    name: str
    info: list[str]
    centers: dict[str, np.ndarray]
    segments: dict[str, Segment]
    limits: dict[str, Limits]
    sites: list[Site]


# --- construction ------------------------------------------------------------


def build_humanoid(figure: Figure) -> Humanoid:
    missing = figure.missing_groups()
    if missing:
        raise FigureIncompleteError(
            f"cannot export a humanoid: {', '.join(missing)} not loaded for {figure.gender}"
        )
    if not figure.output_mass() > 0:
        raise HAnimError("cannot export a humanoid: the figure has no mass")
    girth = _rows(figure, GIRTH) / 100.0  # cm -> m
    if np.isnan(girth).any():
        bad = [ROWS[GIRTH][i].label for i in np.unique(np.nonzero(np.isnan(girth))[0])]
        raise HAnimError(f"cannot export a humanoid: no segment dimensions for {', '.join(bad)}")
    dim = {row.name: girth[i] for i, row in enumerate(ROWS[GIRTH])}
    heights = landmark_heights(figure.gender, humanoid_stature(figure) / 100.0, figure.landmarks)
    breadths = half_breadths(figure.landmarks)
    centers = _joint_centers(dim, heights, breadths)
    segments = _segments(figure, dim, centers, heights)
    limits = _limits(figure)
    sites = _sites(dim, centers, heights, breadths)
    return Humanoid(_humanoid_name(figure), _info(figure), centers, segments, limits, sites)


def humanoid_stature(figure: Figure) -> float:
    """The stature (cm) the humanoid stands to: the figure's, else (a person
    whose stature was not measured) the population's median."""
    if not math.isnan(figure.stature):
        return float(figure.stature)
    if figure.global_stats is None or not figure.global_stats.has(figure.gender):
        raise HAnimError("cannot export a humanoid: no stature, and no population stature")
    stats = figure.global_stats.stats(figure.gender)[row_index(GLOBAL, "stature"), 0]
    return float(value_at(stats, 50.0))


def landmark_heights(
    gender: str, stature: float, landmarks: Mapping[str, float] | None = None
) -> dict[str, float]:
    """Landmark and joint-centre heights (m) of a figure `stature` m tall:
    where `landmarks` (a person's own ANSUR II measurements, cm) place one,
    there (model/landmarks.py); elsewhere the stature's share of it."""
    fractions = LANDMARK_FRACTIONS[gender]
    heights = {name: fraction * stature for name, fraction in fractions.items()}
    heights.update(measured_heights(landmarks or {}, stature))
    if "shoulder" not in heights:
        # Rab's rule as for a person, on the stature's share of the biacromial breadth
        breadth = BIACROMIAL_FRACTION[gender] * stature
        heights["shoulder"] = heights["acromion"] - shoulder_below_acromion(breadth)
    heights["vertex"] = stature
    heights["ankle"] = heights["lateral_malleolus"]
    heights["knee"] = heights["femoral_epicondyle"]
    heights["hip"] = heights["trochanterion"]
    heights["vl5"] = heights["iliocristale"]
    heights["skullbase"] = heights["tragion"]
    return heights


def _population_girth(figure: Figure) -> np.ndarray:
    """The population's segment dimensions (cm) at the figure's girth percentile."""
    state = figure.groups[GIRTH]
    if state.source is None:
        raise HAnimError("cannot export a humanoid: no girth statistics loaded")
    return np.asarray(value_at(state.source.stats(figure.gender), state.percentile), dtype=float)


def _rows(figure: Figure, group: str) -> np.ndarray:
    return np.asarray(figure.output_values(group)[0], dtype=float)


def _joint_centers(
    dim: dict[str, np.ndarray], heights: dict[str, float], breadths: dict[str, float]
) -> dict[str, np.ndarray]:
    """Heights from the landmarks (a person's own, else LANDMARK_FRACTIONS);
    the shoulders' spacing from the biacromial breadth where it is measured,
    the elbow and wrist at the radiale and wrist heights where they are
    (model/landmarks.py); other side spacing and the arm and foot lengths
    from the segment dimensions."""
    c: dict[str, np.ndarray] = {}
    for side, name in (("l", "left"), ("r", "right")):
        sign = 1.0 if side == "l" else -1.0
        foot, upper = dim[f"{name}_foot"], dim[f"{name}_upper_leg"]
        # hip centre in the middle of the thigh's width, inside the lower torso
        x = sign * (dim["lower_torso"][1] - upper[1]) / 2
        c[f"{side}_talocrural"] = np.array([x, heights["ankle"], 0.0])
        c[f"{side}_knee"] = np.array([x, heights["knee"], 0.0])
        c[f"{side}_hip"] = np.array([x, heights["hip"], 0.0])
        toes = dim[f"{name}_ball_of_foot"]
        c[f"{side}_metatarsophalangeal_2"] = np.array(
            [x, toes[2] / 2, (1 - HEEL_BEHIND_ANKLE) * foot[0]]
        )
    c["humanoid_root"] = np.array([0.0, heights["hip"], 0.0])
    c["sacroiliac"] = c["humanoid_root"].copy()
    c["vl5"] = np.array([0.0, heights["vl5"], 0.0])
    c["skullbase"] = np.array([0.0, heights["skullbase"], 0.0])
    # sternum (ctorsoy - clavz, psurf half widths) + clavicle = half the torso width
    half_width = dim["center_torso"][1] / 2
    if "acromion" in breadths:
        # a person's own acromia, the head's radius outside the shoulder centre
        half_width = breadths["acromion"] - HUMERAL_HEAD_RADIUS
    for side, name in (("l", "left"), ("r", "right")):
        sign = 1.0 if side == "l" else -1.0
        shoulder = np.array([sign * half_width, heights["shoulder"], 0.0])
        # ANSUR's acromion-radiale length (SASS upper arm z) runs from the acromion
        elbow = np.array([sign * half_width, heights["acromion"], 0.0])
        elbow -= _Y * dim[f"{name}_upper_arm"][2]
        if "radiale" in heights:
            elbow[1] = heights["radiale"]
        wrist = elbow - _Y * dim[f"{name}_lower_arm"][2]
        if "wrist" in heights:
            wrist[1] = heights["wrist"]
        c[f"{side}_shoulder"], c[f"{side}_elbow"] = shoulder, elbow
        c[f"{side}_radiocarpal"] = wrist
    return {joint: c[joint] for joint, _, _ in LOA1}


# (segment, SASS girth/centre-of-mass row, joint whose centre is the SASS
#  proximal site, long axis direction, depth (SASS x) direction, solid)
def _segment_table() -> list[tuple[str, str | None, str, np.ndarray, np.ndarray, str]]:
    table = [
        ("sacrum", None, "humanoid_root", _Y, _Z, "none"),
        ("pelvis", "lower_torso", "humanoid_root", _Y, _Z, "cylinder"),
        ("l5", "center_torso", "vl5", _Y, _Z, "cylinder"),
        ("skull", "bottom_head", "skullbase", _Y, _Z, "ellipsoid"),
    ]
    for side, name in (("l", "left"), ("r", "right")):
        table += [
            (f"{side}_thigh", f"{name}_upper_leg", f"{side}_hip", -_Y, _Z, "cylinder"),
            (f"{side}_calf", f"{name}_lower_leg", f"{side}_knee", -_Y, _Z, "cylinder"),
            (f"{side}_talus", f"{name}_foot", f"{side}_talocrural", -_Y, _Z, "box"),
            (
                f"{side}_tarsal_proximal_phalanx_2",
                f"{name}_ball_of_foot",
                f"{side}_metatarsophalangeal_2",
                _Z,
                _Y,
                "box",
            ),
            (f"{side}_upperarm", f"{name}_upper_arm", f"{side}_shoulder", -_Y, _Z, "cylinder"),
            # palms face the thighs: the forearm and hand depth (SASS x) lies along X
            (f"{side}_forearm", f"{name}_lower_arm", f"{side}_elbow", -_Y, _X, "cylinder"),
            (f"{side}_carpal", f"{name}_hand", f"{side}_radiocarpal", -_Y, _X, "box"),
        ]
    return table


def _extents(
    dim: dict[str, np.ndarray], centers: dict[str, np.ndarray], heights: dict[str, float]
) -> dict[str, float]:
    """Each segment's length along its long axis (m) in the humanoid: to the
    next joint, or to the landmark that ends it.  The segment's table length
    is kept only where no landmark ends it (hand, fingers, toes)."""
    out = {
        "pelvis": heights["vl5"] - heights["hip"],
        "l5": heights["cervicale"] - heights["vl5"],
        "skull": float(dim["bottom_head"][2]),  # chin to vertex, ending at the stature
    }
    for side in ("l", "r"):
        out[f"{side}_thigh"] = heights["hip"] - heights["knee"]
        out[f"{side}_calf"] = heights["knee"] - heights["ankle"]
        out[f"{side}_talus"] = heights["ankle"]
        out[f"{side}_upperarm"] = float(
            centers[f"{side}_shoulder"][1] - centers[f"{side}_elbow"][1]
        )
        out[f"{side}_forearm"] = float(
            centers[f"{side}_elbow"][1] - centers[f"{side}_radiocarpal"][1]
        )
    return out


def _segments(
    figure: Figure,
    dim: dict[str, np.ndarray],
    centers: dict[str, np.ndarray],
    heights: dict[str, float],
) -> dict[str, Segment]:
    shares = segment_mass_fractions(figure.gender)
    com_rows = {row.name: i for i, row in enumerate(ROWS[CENTER_OF_MASS])}
    com_values, com_filled = figure.output_values(CENTER_OF_MASS)
    com_values = np.asarray(com_values, dtype=float) / 100.0
    # A centre of mass taken from the population (a person's is not measured)
    # goes with the population's segment length, not the person's.
    population_lengths = _population_girth(figure)[:, 2] / 100.0
    extents = _extents(dim, centers, heights)
    along_axis = _de_leva_centers(figure.gender, dim, centers, heights, extents)
    segments: dict[str, Segment] = {}
    for name, row, joint, long_axis, depth_axis, solid in _segment_table():
        mass = figure.output_mass() * shares[name]
        origin = centers[joint]
        if name == "skull":  # the head is measured from the chin (appendix L.1)
            origin = np.array([0.0, heights["vertex"] - extents["skull"], 0.0])
        width_axis = np.abs(np.cross(long_axis, depth_axis))
        shapes = _shapes(
            name, row, dim, origin, long_axis, depth_axis, width_axis, centers, heights, extents
        )
        # size along X, Y, Z of the principal solid (first shape)
        size = shapes[0][2] if shapes else np.zeros(3)
        # SASS's centre-of-mass row: its offsets off the segment's axis (x
        # forward, y sideways) stay; de Leva's tables place the centre on the axis.
        i = com_rows.get(row) if row is not None else None
        offset = None
        if i is not None and not np.isnan(com_values[i]).any():
            offset = com_values[i].copy()
        if name in along_axis:
            cx, cy = (offset[0], offset[1]) if offset is not None else (0.0, 0.0)
            com = origin + along_axis[name] * long_axis + cx * depth_axis + cy * width_axis
        elif name.endswith("_talus") and offset is not None and i is not None and row:
            # de Leva's foot centre lies along heel - toe tip (forward, here Z);
            # its height is SASS's (appendix L.2, down from the ankle), the
            # table's distance in proportion to the ankle height here
            length = float(population_lengths[i] if com_filled[i, 2] else dim[row][2])
            down = offset[2] * (extents[name] / length if length > 0 else 1.0)
            side = "left" if name[0] == "l" else "right"
            foot = float(dim[f"{side}_foot"][0])
            toe_tip = foot + float(dim[f"{side}_ball_of_foot"][0])
            forward = -HEEL_BEHIND_ANKLE * foot + DE_LEVA[figure.gender]["foot"][1] / 100 * toe_tip
            com = origin + down * long_axis + forward * depth_axis + offset[1] * width_axis
        elif shapes:  # the toes (their mass is in de Leva's foot)
            com = shapes[0][1].copy()
        else:
            com = origin.copy()
        segments[name] = Segment(name, mass, com, _inertia(solid, mass, size, long_axis), shapes)
    return segments


def _de_leva_centers(
    gender: str,
    dim: dict[str, np.ndarray],
    centers: dict[str, np.ndarray],
    heights: dict[str, float],
    extents: dict[str, float],
) -> dict[str, float]:
    """Each segment's centre of mass as a distance (m) along its long axis from
    its origin (_segment_table's joint; the skull's chin), from de Leva's
    percentages of the distance between his endpoints (DE_LEVA)."""

    def share(part: str) -> float:
        return DE_LEVA[gender][part][1] / 100

    def mass(part: str) -> float:
        return DE_LEVA[gender][part][0]

    hip, cervicale, vertex = heights["hip"], heights["cervicale"], heights["vertex"]
    omphalion = heights["omphalion"]
    lower_trunk = omphalion - share("lower_trunk") * (omphalion - hip)
    trunk = cervicale - share("trunk") * (cervicale - hip)
    # l5 carries the trunk above the lower trunk: the two together have the
    # whole trunk's centre of mass
    upper_trunk = (mass("trunk") * trunk - mass("lower_trunk") * lower_trunk) / (
        mass("trunk") - mass("lower_trunk")
    )
    head = vertex - share("head") * (vertex - cervicale)
    out = {
        "pelvis": lower_trunk - hip,
        "l5": upper_trunk - heights["vl5"],
        "skull": head - (vertex - extents["skull"]),
    }
    for side, name in (("l", "left"), ("r", "right")):
        hand = float(dim[f"{name}_hand"][2] + dim[f"{name}_knuckles"][2])  # wrist to fingertip
        out[f"{side}_thigh"] = share("thigh") * extents[f"{side}_thigh"]
        out[f"{side}_calf"] = share("shank") * extents[f"{side}_calf"]
        out[f"{side}_upperarm"] = share("upper_arm") * extents[f"{side}_upperarm"]
        out[f"{side}_forearm"] = share("forearm") * extents[f"{side}_forearm"]
        out[f"{side}_carpal"] = share("hand") * hand
    return out


def _shapes(
    name: str,
    row: str | None,
    dim: dict[str, np.ndarray],
    origin: np.ndarray,
    long_axis: np.ndarray,
    depth_axis: np.ndarray,
    width_axis: np.ndarray,
    centers: dict[str, np.ndarray],
    heights: dict[str, float],
    extents: dict[str, float],
) -> list[Shape]:
    """Boxes and ellipsoids in place (humanoid coordinates), one per SASS psurf,
    each as long as the segment is in the humanoid (_extents)."""
    if row is None:
        return []
    depth, width, length = dim[row]
    length = extents.get(name, length)

    def along(
        start: np.ndarray, extent_long: float, d: float, w: float
    ) -> tuple[np.ndarray, np.ndarray]:
        size = np.abs(depth_axis) * d + width_axis * w + np.abs(long_axis) * extent_long
        return start + long_axis * extent_long / 2, size

    if name.endswith("_talus"):
        # foot x is heel to ball; the box stands on the floor up to the ankle
        size = np.array([width, length, depth])
        centre = origin + np.array([0, -length / 2, (0.5 - HEEL_BEHIND_ANKLE) * depth])
        return [("box", centre, size)]
    if name.startswith(("l_tarsal", "r_tarsal")):
        size = np.array([width, length, depth])
        centre = origin + np.array([0, 0, depth / 2])
        return [("box", centre, size)]
    if name == "skull":
        centre, size = along(origin, length, depth, width)
        return [("ellipsoid", centre, size)]
    centre, size = along(origin, length, depth, width)
    shapes: list[Shape] = [("box", centre, size)]
    if name == "l5":  # the neck, from the cervicale up to the skull base
        neck = dim["neck"]
        neck_base = origin + long_axis * length
        extent = centers["skullbase"][1] - neck_base[1]
        c, s = along(neck_base, extent, neck[0], neck[1])
        shapes.append(("box", c, s))
    if name.endswith("_carpal"):  # the fingers (knuckles row) below the hand
        side = "left" if name[0] == "l" else "right"
        fingers = dim[f"{side}_knuckles"]
        c, s = along(origin + long_axis * length, fingers[2], fingers[0], fingers[1])
        shapes.append(("box", c, s))
    return shapes


def _inertia(solid: str, mass: float, size: np.ndarray, long_axis: np.ndarray) -> np.ndarray:
    """Principal moments (kg m^2) of a homogeneous solid of the segment's size."""
    sx, sy, sz = size
    if solid == "none" or mass == 0:
        return np.zeros((3, 3))
    if solid == "box":
        moments = mass / 12 * np.array([sy**2 + sz**2, sx**2 + sz**2, sx**2 + sy**2])
    elif solid == "ellipsoid":
        a, b, c = size / 2
        moments = mass / 5 * np.array([b**2 + c**2, a**2 + c**2, a**2 + b**2])
    else:  # elliptic cylinder along the long axis
        semi = size / 2
        along = int(np.argmax(np.abs(long_axis)))
        moments = np.empty(3)
        for axis in range(3):
            others = [i for i in range(3) if i != axis]
            if axis == along:
                moments[axis] = mass / 4 * sum(semi[i] ** 2 for i in others)
            else:
                (cross,) = [i for i in others if i != along]
                moments[axis] = mass * (semi[cross] ** 2 / 4 + size[along] ** 2 / 12)
    return np.diag(moments)


def _limits(figure: Figure) -> dict[str, Limits]:
    values = np.radians(_rows(figure, JOINT_LIMITS))
    out: dict[str, Limits] = {}
    for joint, stem, x_axis, y_axis, z_anatomical in _LIMIT_AXES:
        frame = np.column_stack([x_axis, y_axis, np.cross(x_axis, y_axis)])
        upper_row = values[row_index(JOINT_LIMITS, f"{stem}_ul")]
        lower_row = values[row_index(JOINT_LIMITS, f"{stem}_ll")]
        # 999 (NaN): SASS allows no motion about the axis, so both limits are 0
        upper = [0.0 if math.isnan(v) else float(v) for v in upper_row]
        lower = [0.0 if math.isnan(v) else float(v) for v in lower_row]
        mirrored = z_anatomical is not None and float(frame[:, 2] @ z_anatomical) < 0
        if mirrored:
            upper[2], lower[2] = -lower[2], -upper[2]
        out[joint] = Limits(stem, frame, upper, lower, mirrored)
    return out


def _sites(
    dim: dict[str, np.ndarray],
    centers: dict[str, np.ndarray],
    heights: dict[str, float],
    breadths: dict[str, float],
) -> list[Site]:
    # eye location: x head depth to the eyes, y half the eye spacing, z the
    # ectocanthus below the top of the head (report 10.1, eyelocz)
    eyes = dim["eye_location"]
    eye_height = heights["vertex"] - eyes[2]
    front = eyes[0] / 2
    # the eye sites look where the humanoid looks (4.6): a camera's -Z turned to +Z
    looking_front = (0.0, 1.0, 0.0, math.pi)
    sites = [
        Site("skull_vertex_pt", "skull", np.array([0.0, heights["vertex"], 0.0])),
        Site("sellion_pt", "skull", np.array([0.0, eye_height, front])),
        Site("x_l_eye_pt", "skull", np.array([eyes[1], eye_height, front]), looking_front),
        Site("x_r_eye_pt", "skull", np.array([-eyes[1], eye_height, front]), looking_front),
    ]
    for side, name in (("l", "left"), ("r", "right")):
        sign = 1.0 if side == "l" else -1.0
        acromion = centers[f"{side}_shoulder"].copy()
        acromion[1] = heights["acromion"]
        if "acromion" in breadths:  # a person's own biacromial breadth
            acromion[0] = sign * breadths["acromion"]
        else:
            acromion += _X * sign * dim[f"{name}_upper_arm"][1] / 2
        sites.append(Site(f"{side}_acromion_pt", "l5", acromion))
        tip = centers[f"{side}_radiocarpal"] - _Y * (
            dim[f"{name}_hand"][2] + dim[f"{name}_knuckles"][2]
        )
        sites.append(Site(f"{side}_dactylion_pt", f"{side}_carpal", tip))
        ankle = centers[f"{side}_talocrural"]
        heel = np.array([ankle[0], 0.0, -HEEL_BEHIND_ANKLE * dim[f"{name}_foot"][0]])
        sites.append(Site(f"{side}_calcaneus_posterior_pt", f"{side}_talus", heel))
    return sites + _person_sites(dim, centers, heights, breadths)


def _person_sites(
    dim: dict[str, np.ndarray],
    centers: dict[str, np.ndarray],
    heights: dict[str, float],
    breadths: dict[str, float],
) -> list[Site]:
    """The table 4.7 sites (segments of its LOA-1 column) that a person's own
    measurements place (model/landmarks.py), where they place them: none
    for a figure placed from its stature alone.  Heights are the measured
    ones; sideways, the measured breadths, else the segment's surface."""
    if not breadths:
        return []
    sites = []
    chest_depth = float(dim["center_torso"][0])
    for name, segment, z in (
        ("cervicale", "l5", -chest_depth / 2),  # C7, at the back
        ("suprasternale", "l5", chest_depth / 2),  # the jugular notch, in front
    ):
        if name in heights:
            sites.append(Site(f"{name}_pt", segment, np.array([0.0, heights[name], z])))
    for side, long in (("l", "left"), ("r", "right")):
        sign = 1.0 if side == "l" else -1.0
        elbow, knee = centers[f"{side}_elbow"], centers[f"{side}_knee"]
        ankle = centers[f"{side}_talocrural"]
        placed = (
            # the radial head's top, on the lateral side of the elbow
            ("radiale", f"{side}_forearm", elbow[0] + sign * dim[f"{long}_lower_arm"][0] / 2),
            ("iliocristale", "pelvis", sign * breadths.get("iliocristale", math.nan)),
            ("trochanterion", "pelvis", sign * breadths.get("trochanterion", math.nan)),
            # the medial tibial condyle's top: on the calf's inner side
            ("tibiale", f"{side}_calf", knee[0] - sign * dim[f"{long}_lower_leg"][1] / 2),
            (
                "lateral_malleolus",
                f"{side}_calf",
                ankle[0] + sign * breadths.get("malleoli", math.nan),
            ),
        )
        for name, segment, x in placed:
            if name in heights and math.isfinite(x):
                sites.append(Site(f"{side}_{name}_pt", segment, np.array([x, heights[name], 0.0])))
    return sites


def _humanoid_name(figure: Figure) -> str:
    who = figure.person or f"{figure.gender}_{figure.groups[GIRTH].percentile:g}"
    return "".join(ch if ch.isalnum() else "_" for ch in who).strip("_") or "sass_figure"


def _info(figure: Figure) -> list[str]:
    groups = figure.groups
    info = []
    if figure.person:
        info.append(f"person={figure.person}")
    info += [
        f"population={figure.population}",
        f"gender={figure.gender}",
        f"girthPercentile={groups[GIRTH].percentile:g}",
        f"jointLimitPercentile={groups[JOINT_LIMITS].percentile:g}",
        f"centerOfMassPercentile={groups[CENTER_OF_MASS].percentile:g}",
        _measure("mass", figure.mass, "kg", figure.mass_percentile, 2),
        _measure("stature", figure.stature, "cm", figure.stature_percentile, 1),
        "generator=sass (Spreadsheet Anthropometry Scaling System)",
        "construction=docs/hanim.md",
    ]
    return info


def _measure(name: str, value: float, unit: str, percentile: float, decimals: int) -> str:
    if math.isnan(value):
        return f"{name}=not measured"
    if math.isnan(percentile):
        return f"{name}={value:.{decimals}f} {unit}"
    return f"{name}={value:.{decimals}f} {unit} (percentile {percentile:.3g})"


# --- rotations ---------------------------------------------------------------


def axis_angle(matrix: np.ndarray) -> tuple[float, float, float, float]:
    """X3D SFRotation (axis, angle) of a proper rotation matrix."""
    r = np.asarray(matrix, dtype=float)
    cos = np.clip((np.trace(r) - 1) / 2, -1.0, 1.0)
    angle = math.acos(cos)
    if angle < 1e-9:
        return (0.0, 0.0, 1.0, 0.0)
    if math.pi - angle < 1e-6:
        # sin(angle) ~ 0: read the axis from the symmetric part, R = 2aa^T - I
        outer = (r + np.eye(3)) / 2
        k = int(np.argmax(np.diag(outer)))
        axis = outer[:, k] / math.sqrt(outer[k, k])
    else:
        axis = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]])
    axis = axis / np.linalg.norm(axis)
    return (float(axis[0]), float(axis[1]), float(axis[2]), angle)


def rotation_matrix(axis: npt.ArrayLike, angle: float) -> np.ndarray:
    """Rodrigues' formula (the inverse of axis_angle)."""
    a = np.asarray(axis, dtype=float)
    a = a / np.linalg.norm(a)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    rotation: np.ndarray = np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)
    return rotation


# --- X3D ---------------------------------------------------------------------


def _num(value: float) -> str:
    if not math.isfinite(value):
        raise HAnimError(f"cannot write the humanoid: a value is {value}, not a number")
    text = f"{value:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _vec(values: Iterable[float]) -> str:
    return " ".join(_num(v) for v in values)


def _mfstring(values: list[str]) -> str:
    return " ".join('"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"' for v in values)


SKIN = {"male": "0.80 0.62 0.50", "female": "0.86 0.66 0.58"}


def humanoid_element(humanoid: Humanoid, gender: str) -> ET.Element:
    """The HAnimHumanoid node.  DEF names follow the HAnim convention the x3d
    package checks: the humanoid's name, '_', the node's name ('male_50_l_hip');
    humanoids with different names can share a scene."""
    # deferred: xml.etree.ElementTree — the X3D document only: not the TUI's drawing
    import xml.etree.ElementTree as ET

    prefix = f"{humanoid.name}_"
    # skeletalConfiguration is "BASIC" (clause 4.8.2) through the field's X3D 4.0
    # default: X3D's canonical XML form leaves defaults out, and Debian's
    # view3dscene 4.2, which predates the field, warns when it is written.
    root = ET.Element(
        "HAnimHumanoid",
        {
            "DEF": humanoid.name,
            "name": humanoid.name,
            "version": HANIM_VERSION,
            "loa": str(LOA),
            "info": _mfstring(humanoid.info),
        },
    )
    appearance_def = f"{prefix}skin_appearance"
    joints: dict[str, ET.Element] = {}
    first_shape = True
    sites_by_segment: dict[str, list[Site]] = {}
    for site in humanoid.sites:
        sites_by_segment.setdefault(site.segment, []).append(site)
    for joint, segment_name, parent in LOA1:
        attrs = {"DEF": f"{prefix}{joint}", "name": joint, "center": _vec(humanoid.centers[joint])}
        if parent is None:
            attrs["containerField"] = "skeleton"
        limits = humanoid.limits.get(joint)
        if limits is not None:
            attrs["limitOrientation"] = _vec(limits.orientation)
            attrs["ulimit"] = _vec(limits.upper)
            attrs["llimit"] = _vec(limits.lower)
        element = ET.SubElement(root if parent is None else joints[parent], "HAnimJoint", attrs)
        joints[joint] = element
        segment = humanoid.segments[segment_name]
        seg = ET.SubElement(
            element,
            "HAnimSegment",
            {
                "DEF": f"{prefix}{segment_name}",
                "name": segment_name,
                "mass": _num(segment.mass),
                "centerOfMass": _vec(segment.center_of_mass),
                "momentsOfInertia": _vec(segment.inertia.ravel()),
            },
        )
        for kind, centre, size in segment.shapes:
            if kind == "ellipsoid":
                transform = ET.SubElement(
                    seg, "Transform", {"translation": _vec(centre), "scale": _vec(size / 2)}
                )
                geometry = ("Sphere", {"radius": "1"})
            else:
                transform = ET.SubElement(seg, "Transform", {"translation": _vec(centre)})
                geometry = ("Box", {"size": _vec(size)})
            shape = ET.SubElement(transform, "Shape")
            if first_shape:
                appearance = ET.SubElement(shape, "Appearance", {"DEF": appearance_def})
                ET.SubElement(
                    appearance, "Material", {"diffuseColor": SKIN.get(gender, SKIN["male"])}
                )
                first_shape = False
            else:
                ET.SubElement(shape, "Appearance", {"USE": appearance_def})
            ET.SubElement(shape, geometry[0], geometry[1])
        for site in sites_by_segment.get(segment_name, []):
            ET.SubElement(
                seg,
                "HAnimSite",
                {
                    "DEF": f"{prefix}{site.name}",
                    "name": site.name,
                    "translation": _vec(site.translation),
                    "rotation": _vec(site.rotation),
                },
            )
    for joint, _, _ in LOA1:
        ET.SubElement(root, "HAnimJoint", {"USE": f"{prefix}{joint}", "containerField": "joints"})
    for _, segment_name, _ in LOA1:
        ET.SubElement(
            root, "HAnimSegment", {"USE": f"{prefix}{segment_name}", "containerField": "segments"}
        )
    for site in humanoid.sites:
        ET.SubElement(root, "HAnimSite", {"USE": f"{prefix}{site.name}", "containerField": "sites"})
    return root


def scene_document(humanoids: list[tuple[ET.Element, float]], title: str, height: float) -> str:
    """An X3D 4.0 document holding humanoids side by side (x offsets in metres)."""
    # deferred: xml.etree.ElementTree — off the first screen's next frame, sass export gltf, sass fit (sass_tui/startup.py)
    import xml.etree.ElementTree as ET

    x3d = ET.Element(
        "X3D",
        {
            "profile": "Immersive",
            "version": "4.0",
            "xmlns:xsd": "http://www.w3.org/2001/XMLSchema-instance",
            "xsd:noNamespaceSchemaLocation": "https://www.web3d.org/specifications/x3d-4.0.xsd",
        },
    )
    head = ET.SubElement(x3d, "head")
    ET.SubElement(head, "component", {"name": "HAnim", "level": "1"})
    ET.SubElement(head, "meta", {"name": "title", "content": title})
    ET.SubElement(head, "meta", {"name": "generator", "content": "sass export hanim"})
    ET.SubElement(
        head,
        "meta",
        {
            "name": "reference",
            "content": "ISO/IEC 19774-1:2019 HAnim, clause 4; SASS report, appendix D",
        },
    )
    scene = ET.SubElement(x3d, "Scene")
    ET.SubElement(scene, "WorldInfo", {"title": title})
    ET.SubElement(scene, "Background", {"skyColor": "1 1 1"})
    ET.SubElement(scene, "NavigationInfo", {"type": '"EXAMINE" "ANY"'})
    offsets = [x for _, x in humanoids]
    span = max(offsets) - min(offsets)
    middle = (max(offsets) + min(offsets)) / 2
    # far enough back that the tallest figure and the whole row fit a 45 degree view
    distance = 1.3 * max(height, span + 0.8)
    # turned a little to the humanoid's left: a straight front view hides the arms
    turn = 0.35
    ET.SubElement(
        scene,
        "Viewpoint",
        {
            "description": "front, three quarters",
            "position": _vec(
                (middle + distance * math.sin(turn), height / 2, distance * math.cos(turn))
            ),
            "orientation": _vec((0, 1, 0, turn)),
            "centerOfRotation": _vec((middle, height / 2, 0)),
        },
    )
    for element, x in humanoids:
        if x:
            transform = ET.SubElement(scene, "Transform", {"translation": _vec((x, 0, 0))})
            transform.append(element)
        else:
            scene.append(element)
    ET.indent(x3d)
    body = ET.tostring(x3d, encoding="unicode")
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<!DOCTYPE X3D PUBLIC "ISO//Web3D//DTD X3D 4.0//EN" '
        '"https://www.web3d.org/specifications/x3d-4.0.dtd">\n' + body + "\n"
    )


def figure_title(figure: Figure) -> str:
    if figure.person:
        return f"{figure.person} ({figure.gender}) - SASS HAnim humanoid"
    return (
        f"{figure.population}, {figure.gender}, girth percentile "
        f"{figure.groups[GIRTH].percentile:g} - SASS HAnim humanoid"
    )


def edits_not_in_humanoid(figure: Figure) -> list[str]:
    """The segment dimensions of a population figure set by hand (their
    percentile is no longer the group's) that the humanoid does not use
    (NOT_IN_HUMANOID), e.g. "Right Upper Leg z": an export says so."""
    state = figure.groups[GIRTH]
    if figure.person is not None or not state.loaded:
        return []  # a person's own values: docs/hanim.md measures that case
    edited = []
    for name, axis in NOT_IN_HUMANOID:
        row = row_index(GIRTH, name)
        value, percentile = state.cell(row, axis)
        if not math.isnan(value) and percentile != state.percentile:
            edited.append(f"{ROWS[GIRTH][row].label} {'xyz'[axis]}")
    return edited


def not_in_humanoid_note(figure: Figure) -> str:
    """What of a population figure's lengths the humanoid leaves out, as a
    sentence for an export's message ("" when nothing is): those set by
    hand, and the neck, torso and leg lengths of a girth percentile other
    than the stature's (the joints follow the stature)."""
    state = figure.groups[GIRTH]
    if figure.person is not None or not state.loaded:
        return ""
    left_out = []
    if abs(state.percentile - figure.stature_percentile) > 0.05:  # NaN: no stature percentile
        left_out.append(
            f"the neck, torso and leg lengths at the girth percentile ({state.percentile:.1f})"
        )
    edited = edits_not_in_humanoid(figure)
    if edited:
        left_out.append(f"{', '.join(edited)} as set here")
    if not left_out:
        return ""
    return (
        f" The humanoid's joints stand at its stature's landmarks ({humanoid_stature(figure):.1f} cm, "
        f"percentile {figure.stature_percentile:.1f}; docs/hanim.md). A .fig (Create Figure) has "
        f"{' and '.join(left_out)}; the humanoid does not."
    )


def render_hanim(figure: Figure) -> str:
    humanoid = build_humanoid(figure)
    height = float(humanoid.sites[0].translation[1])  # skull vertex
    return scene_document(
        [(humanoid_element(humanoid, figure.gender), 0.0)], figure_title(figure), height
    )


def export_hanim(figure: Figure, path: str | Path) -> Path:
    """Write the figure as an HAnim X3D file, atomically (the TUI's Export HAnim)."""
    text = render_hanim(figure)
    write_text_atomic(path, text)
    return Path(path)
