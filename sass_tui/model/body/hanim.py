"""The figure as an ISO/IEC 19774 humanoid (LOA-1): its skeleton.

The joint centres (from the landmarks and the segment dimensions), the
joint-limit axes and the sites live here; the segments' masses, centres of
mass, inertia and solids in model/body/hanim_mass.py; the X3D document in
model/files/hanim_x3d.py.  The construction is documented in docs/hanim.md; the
comments here say why a choice was made, that page says what it gives.
No Textual import: the CLI and the TUI both call build_humanoid().
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.appendix_l import HEEL_BEHIND_ANKLE
from sass_tui.model.body.hanim_mass import Segment, build_segments
from sass_tui.model.body.landmarks import (
    BIACROMIAL_FRACTION,
    HUMERAL_HEAD_RADIUS,
    half_breadths,
    measured_heights,
    shoulder_below_acromion,
)
from sass_tui.model.errors import SassError
from sass_tui.model.files.figfile import FigureIncompleteError
from sass_tui.model.names import (
    CENTER_OF_MASS,
    GIRTH,
    GLOBAL,
    JOINT_LIMITS,
    ROWS,
    row_index,
)
from sass_tui.model.population.percentile_arrays import value_at

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure

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
# measurements (model/body/landmarks.py); a percentile figure's are its stature
# times the mean landmark/stature ratio of the ANSUR II public data (Gordon et
# al. 2014, 4,082 men and 1,986 women; scripts/hanim_landmarks.py computes the
# ratios and measures the placements, docs/hanim.md).
#   ankle (talocrural)  lateral malleolus height
#   knee                lateral femoral epicondyle height (the flexion axis)
#   hip                 trochanterion height (level with the femoral head)
#   vl5                 iliocristale height (the iliac crest, at L4-L5)
#   shoulder            acromion height less 17 % of the biacromial breadth
#                       (model/body/landmarks.py: Rab et al. 2002, for every figure)
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
    # the neck's and the fingers' depth and width and the toes' width shaped
    # only the solids the body's surface replaced (model/body/body_surface.py)
    ("neck", 0),
    ("neck", 1),
    *((f"{side}_knuckles", axis) for side in ("right", "left") for axis in (0, 1)),
    *((f"{side}_ball_of_foot", 1) for side in ("right", "left")),
)


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
    # A centre of mass taken from the population (a person's is not measured)
    # goes with the population's segment length, not the person's.
    population_lengths = _population_girth(figure)[:, 2] / 100.0
    segments = build_segments(figure, dim, centers, heights, population_lengths)
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
    there (model/body/landmarks.py); elsewhere the stature's share of it."""
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
    (model/body/landmarks.py); other side spacing and the arm and foot lengths
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
    measurements place (model/body/landmarks.py), where they place them: none
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
