"""The figure in a posture: its HAnim humanoid (model/body/hanim.py: the joint
centres, segment masses and centres of mass the HAnim and glTF exports
carry) with joints turned by the angles of the strength page, or joint
centres read from a posture file.

Angles (degrees, the strength page's and `sass strength`'s axes, docs/model.md
"Strength"): shoulder_x (abduction +), shoulder_y (flexion +), shoulder_z
(lateral rotation +), elbow_y (flexion +), wrist_x (radial deviation +),
wrist_y (flexion +), wrist_z (pronation +); hip_y, knee_y (flexion +) and
ankle_y (dorsiflexion +); trunk_x (lateral bend to the right +), trunk_y
(flexion +) and trunk_z (twist to the left +) at the lumbar joint (HAnim vl5,
the waist's joint limits); neck_x (lateral bend to the right +), neck_y
(flexion +) and neck_z (rotation to the right +) at the head-neck joint
(HAnim skullbase, the report's atlanto-occipital joint and its neck limits,
Appendix D), which carries the head.  `shoulder_y=90` turns both arms,
`left_shoulder_y=90` the left one; the trunk and the neck have no side.  Each joint turns about its joint-limit frame in the standing
figure (hanim._LIMIT_AXES, docs/hanim.md), x then y then z applied to the
limb: R = Rx(x) Ry(y) Rz(z), so an arm flexed forward by y is then swung
sideways by x.  A joint's turn carries every segment below it.

Standing (the default), the feet stay flat on the floor where they stood:
the whole body turns about the lateral axis until the feet are level (the
mean of the two feet's pitch) and moves so the lower sole is on the floor
and the ankles' midpoint keeps its place, so `hip_y=60` is a stoop (the
pelvis and trunk tip forward over straight legs) and hip, knee and ankle
flexion together a squat.  When one leg is posed shorter than the other (its
ankle over SAME_HEIGHT_M higher: `left_knee_y=30`, `left_hip_y=30`) the body
stands on the other foot: that foot is levelled and put on the floor, and
the raised one bears only where a corner of its sole reaches the floor
(`PosedBody.bearing`, the feet the floor's force acts on: model/strength/
statics.py).  Seated, the pelvis stays where it stands (on the seat) and the
legs swing from it.

The hand's grip point is the third knuckle (de Leva 1996's MET3, the end of
his hand segment): along the hand from the wrist centre at the fraction of
the wrist-fingertip length that de Leva's two hand definitions put it (the
centre of mass at 79.00 % of wrist-MET3 and 36.24 % of wrist-fingertip for
men, 74.74 % and 34.27 % for women: MET3 at 36.24 / 79.00 = 45.9 % of the
hand length), so the grip and the hand's centre of mass (hanim_mass.py,
36.24 % of the same length) are one hand.  A handle held in a power grip
lies across the palm under these knuckles: sass places the load there.

A posture file is JSON: HAnim joint centres in metres on HAnim's axes (+x the
body's left, +y up, +z forward), the ten of arm_force_field.POSTURE_JOINTS.

No Textual import here.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import (
    LOA1,
    Humanoid,
    build_humanoid,
    humanoid_stature,
    landmark_heights,
)
from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import PathError, read_user_text
from sass_tui.model.names import GIRTH, row_index
from sass_tui.model.strength.arm_force_field import ArmForceError, Posture, check_posture
from sass_tui.model.strength.strength_conditions import check_angle
from sass_tui.model.units import UnitError, parse_quantity, unit_name
from sass_tui.model.vocabulary import JOINT_AXES

LEG_AXES: tuple[str, ...] = ("hip_y", "knee_y", "ankle_y")
TRUNK_AXES: tuple[str, ...] = ("trunk_x", "trunk_y", "trunk_z")
NECK_AXES: tuple[str, ...] = ("neck_x", "neck_y", "neck_z")
POSTURE_AXES: tuple[str, ...] = (*JOINT_AXES, *LEG_AXES, *TRUNK_AXES, *NECK_AXES)
TRUNK = ""  # the side in Angles of the trunk and the neck: they have none
_HANIM_JOINT = {
    "shoulder": "shoulder",
    "elbow": "elbow",
    "wrist": "radiocarpal",
    "hip": "hip",
    "knee": "knee",
    "ankle": "talocrural",
    "trunk": "vl5",
    "neck": "skullbase",
}
# de Leva (1996) table 4, the hand's centre of mass from the wrist centre:
# % of wrist-MET3 (third metacarpale) and % of wrist-fingertip (DA3)
DE_LEVA_HAND_COM = {"male": (79.00, 36.24), "female": (74.74, 34.27)}


def grip_fraction(gender: str) -> float:
    """The third knuckle's place along the wrist-fingertip length (de Leva 1996)."""
    to_knuckle, to_fingertip = DE_LEVA_HAND_COM[gender]
    return to_fingertip / to_knuckle


_SIDE_WORDS = {"left": "l", "right": "r"}
# one leg posed shorter than the other by more than this stands on the other
SAME_HEIGHT_M = 0.005
# a sole's corner this near the floor (or below it) bears
ON_FLOOR_M = 0.005
_SEGMENT = {joint: segment for joint, segment, _ in LOA1}

# (side, axis) -> degrees
Angles = dict[tuple[str, str], float]


class PostureError(ArmForceError):
    """A posture the figure cannot take: an unknown joint, an angle outside
    the joint limits, a file that is not a posture."""


def _unit_hint(item: str) -> str:
    """A unit standing alone among the angles was most likely typed apart from
    its option's number (`--load 10 kg`): the shell made two words of it."""
    try:
        unit_name(item)
    except UnitError:
        return ""
    return f" ({item.strip()!r} is a unit: write it against its number, as in 12{item.strip()})"


def parse_angles(items: list[str]) -> Angles:
    """['shoulder_y=90', 'left_elbow_y=1.5 rad'] -> {('left', 'shoulder_y'): 90, ...}.

    A joint is given once: a side's word may follow the word for both sides
    (`shoulder_y=90 left_shoulder_y=45`: the left arm at 45), any other
    repeat is refused rather than the last word silently kept."""
    out: Angles = {}
    given: dict[tuple[str, str], tuple[str, bool]] = {}  # -> (the word, for both sides)
    for item in items:
        name, sep, value = item.partition("=")
        key = name.strip().lower().replace(".", "_")
        if not sep or not value.strip():
            raise PostureError(
                f"{item!r}: expected JOINT=ANGLE, e.g. shoulder_y=90{_unit_hint(item)}"
            )
        sides: tuple[str, ...] = ("left", "right")
        for word in sides:
            if key.startswith(f"{word}_"):
                sides, key = (word,), key[len(word) + 1 :]
                break
        if key in TRUNK_AXES or key in NECK_AXES:
            if len(sides) == 1:
                part = key.split("_")[0]
                raise PostureError(f"{item!r}: the {part} has no side; write {key}=ANGLE")
            sides = (TRUNK,)
        if key not in POSTURE_AXES:
            raise PostureError(
                f"{item!r}: unknown joint {name.strip()!r}; expected one of "
                f"{', '.join(POSTURE_AXES)} (left_ or right_ before it for one side)"
            )
        try:
            degrees = parse_quantity(value, "deg")
        except SassError as exc:
            raise PostureError(f"{item!r}: {exc}") from None
        if not math.isfinite(degrees):
            raise PostureError(f"{item!r}: the angle is not a finite number")
        for side in sides:
            earlier = given.get((side, key))
            if earlier is not None and not (earlier[1] and len(sides) == 1):
                raise PostureError(f"{item!r}: {name.strip()} is given twice (also {earlier[0]!r})")
            given[(side, key)] = (item, len(sides) == 2)
            out[(side, key)] = degrees
    return out


def _rotation(axis: npt.NDArray[np.float64], degrees: float) -> npt.NDArray[np.float64]:
    """Rodrigues: the matrix turning by `degrees` about the unit `axis`."""
    a = math.radians(degrees)
    x, y, z = axis / np.linalg.norm(axis)
    k = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    turn: npt.NDArray[np.float64] = np.eye(3) + math.sin(a) * k + (1 - math.cos(a)) * (k @ k)
    return turn


@dataclass(frozen=True)
class PosedBody:
    """The humanoid in a posture: joint centres, and each segment's mass and
    centre of mass, in metres on HAnim's axes (the pelvis where it stands)."""

    centers: dict[str, npt.NDArray[np.float64]]
    masses: dict[str, float]  # kg, by HAnim segment
    centers_of_mass: dict[str, npt.NDArray[np.float64]]
    points: Posture  # the Arm Force Field's ten joint centres
    angles: Angles
    body_mass: float  # kg
    stature: float  # m
    # the soles' corners on the floor (side -> 4 x 3, m), heel to toe tip
    soles: dict[str, npt.NDArray[np.float64]]
    seated: bool = False
    # each joint's turn in the world (for the trunk's axis at L5/S1)
    turns: dict[str, npt.NDArray[np.float64]] | None = None
    # the feet with a sole on the floor (standing; none seated)
    bearing: tuple[str, ...] = ("left", "right")

    def grip(self, side: str) -> npt.NDArray[np.float64]:
        """Where a load on the hand acts: the third knuckle (module docstring)."""
        return self.points[f"{side[0]}_metacarpophalangeal_3"]

    def center_of_mass(self) -> npt.NDArray[np.float64]:
        total = sum(self.masses.values())
        weighted = sum(m * self.centers_of_mass[s] for s, m in self.masses.items())
        return np.asarray(weighted, dtype=float) / total

    def below(self, joint: str) -> list[str]:
        """The segments a joint carries (its own and every one further out)."""
        joints = [joint]
        for child, _, parent in LOA1:
            if parent in joints:
                joints.append(child)
        return [_SEGMENT[j] for j in joints]


def pose_figure(
    figure: Figure,
    angles: Angles | None = None,
    seated: bool = False,
    humanoid: Humanoid | None = None,
) -> PosedBody:
    """The figure's humanoid with `angles` applied, each checked against the
    figure's joint limits (StrengthError naming the limit); standing on the
    floor or seated (module docstring)."""
    angles = dict(angles or {})
    for (side, axis), degrees in angles.items():
        check_angle(figure, side, axis, degrees)
    humanoid = humanoid or build_humanoid(figure)  # a caller posing it often builds it once
    local = _local_rotations(humanoid, angles)
    world: dict[str, npt.NDArray[np.float64]] = {}
    centers: dict[str, npt.NDArray[np.float64]] = {}
    for joint, _, parent in LOA1:
        standing = humanoid.centers[joint]
        if parent is None:
            world[joint] = local.get(joint, np.eye(3))
            centers[joint] = standing.copy()
            continue
        offset = standing - humanoid.centers[parent]
        centers[joint] = centers[parent] + world[parent] @ offset
        world[joint] = world[parent] @ local.get(joint, np.eye(3))
    coms = {}
    masses = {}
    for joint, segment, _ in LOA1:
        part = humanoid.segments[segment]
        masses[segment] = float(part.mass)
        coms[segment] = centers[joint] + world[joint] @ (
            part.center_of_mass - humanoid.centers[joint]
        )
    soles = _soles(humanoid, centers, world)
    bearing: tuple[str, ...] = ()
    if not seated:
        bearing = _stand(humanoid, centers, coms, world, soles)
    heights = landmark_heights(figure.gender, humanoid_stature(figure) / 100.0, figure.landmarks)
    points: Posture = {}
    girth = np.asarray(figure.output_values(GIRTH)[0], dtype=float) / 100.0
    for side, s in _SIDE_WORDS.items():
        wrist = f"{s}_radiocarpal"
        hand = float(
            girth[row_index(GIRTH, f"{side}_hand"), 2]
            + girth[row_index(GIRTH, f"{side}_knuckles"), 2]
        )
        # the third knuckle, down the hand from the wrist standing
        knuckle = np.array([0.0, -grip_fraction(figure.gender) * hand, 0.0])
        points[f"{s}_metacarpophalangeal_3"] = centers[wrist] + world[wrist] @ knuckle
        for joint in ("radiocarpal", "elbow", "shoulder"):
            points[f"{s}_{joint}"] = centers[f"{s}_{joint}"].copy()
    points["vl5"] = centers["vl5"].copy()
    # C7/T1 at the cervicale's height on the trunk, above L5
    points["vc7"] = centers["vl5"] + world["vl5"] @ np.array(
        [0.0, heights["cervicale"] - heights["vl5"], 0.0]
    )
    return PosedBody(
        centers=centers,
        masses=masses,
        centers_of_mass=coms,
        points=points,
        angles=angles,
        body_mass=float(figure.output_mass()),
        stature=heights["vertex"],
        soles=soles,
        seated=seated,
        turns=world,
        bearing=bearing,
    )


def _soles(
    humanoid: Humanoid,
    centers: dict[str, npt.NDArray[np.float64]],
    world: dict[str, npt.NDArray[np.float64]],
) -> dict[str, npt.NDArray[np.float64]]:
    """Each sole's corners (heel to toe tip, the foot's width), carried by
    the foot's turn from where they stand on the floor."""
    out = {}
    for side, s in _SIDE_WORDS.items():
        ankle = f"{s}_talocrural"
        (_, foot_centre, foot_size), *_ = humanoid.segments[f"{s}_talus"].shapes
        (_, toe_centre, toe_size), *_ = humanoid.segments[f"{s}_tarsal_proximal_phalanx_2"].shapes
        heel = foot_centre[2] - foot_size[2] / 2
        tip = toe_centre[2] + toe_size[2] / 2
        half = foot_size[0] / 2
        corners = np.array(
            [[foot_centre[0] + dx, 0.0, z] for z in (heel, tip) for dx in (-half, half)]
        )
        standing = humanoid.centers[ankle]
        out[side] = np.array([centers[ankle] + world[ankle] @ (c - standing) for c in corners])
    return out


def _stand(
    humanoid: Humanoid,
    centers: dict[str, npt.NDArray[np.float64]],
    coms: dict[str, npt.NDArray[np.float64]],
    world: dict[str, npt.NDArray[np.float64]],
    soles: dict[str, npt.NDArray[np.float64]],
) -> tuple[str, ...]:
    """Turn and move the whole body (in place) so the feet it stands on are
    flat on the floor (module docstring); the feet that bear."""
    standing = _standing_feet(centers)
    pitches = []
    for side in standing:
        forward = world[f"{_SIDE_WORDS[side]}_talocrural"] @ np.array([0.0, 0.0, 1.0])
        pitches.append(math.degrees(math.atan2(forward[1], forward[2])))
    level = _rotation(np.array([1.0, 0.0, 0.0]), float(np.mean(pitches)))
    ankles = [f"{s}_talocrural" for s in _SIDE_WORDS.values()]
    before = np.mean([humanoid.centers[a] for a in ankles], axis=0)
    for points in (centers, coms, soles):
        for key in points:
            points[key] = points[key] @ level.T
    for key in world:
        world[key] = level @ world[key]
    floor = min(float(soles[side][:, 1].min()) for side in standing)
    after = np.mean([centers[a] for a in ankles], axis=0)
    shift = np.array([before[0] - after[0], -floor, before[2] - after[2]])
    for points in (centers, coms, soles):
        for key in points:
            points[key] = points[key] + shift
    return tuple(side for side in _SIDE_WORDS if float(soles[side][:, 1].min()) <= ON_FLOOR_M)


def _standing_feet(centers: dict[str, npt.NDArray[np.float64]]) -> tuple[str, ...]:
    """Both feet, or the one whose ankle is lower when the legs differ by
    over SAME_HEIGHT_M (the pelvis as it stands, before the body turns)."""
    left, right = (float(centers[f"{s}_talocrural"][1]) for s in _SIDE_WORDS.values())
    if abs(left - right) <= SAME_HEIGHT_M:
        return ("left", "right")
    return ("left",) if left < right else ("right",)


def _local_rotations(humanoid: Humanoid, angles: Angles) -> dict[str, npt.NDArray[np.float64]]:
    by_joint: dict[str, dict[str, float]] = {}
    for (side, axis), degrees in angles.items():
        joint_word, letter = axis.split("_")
        joint = _HANIM_JOINT[joint_word]
        if side != TRUNK:
            joint = f"{_SIDE_WORDS[side]}_{joint}"
        by_joint.setdefault(joint, {})[letter] = degrees
    out = {}
    for joint, turns in by_joint.items():
        limits = humanoid.limits[joint]
        frame = limits.frame
        # the anatomical z (lateral rotation, pronation): the frame's z, or its
        # opposite where hanim mirrored it
        z_axis = -frame[:, 2] if limits.mirrored_z else frame[:, 2]
        turn = np.eye(3)
        for letter, about in (("x", frame[:, 0]), ("y", frame[:, 1]), ("z", z_axis)):
            if letter in turns:
                turn = turn @ _rotation(about, turns[letter])
        out[joint] = turn
    return out


def read_posture_file(path: str | Path) -> Posture:
    """A posture file's ten joint centres (JSON object, metres, HAnim axes)."""
    try:
        read, text = read_user_text(path)
    except PathError as exc:
        raise PostureError(f"{path}: cannot read: {exc.reason}") from None
    try:
        raw = json.loads(text)
    except ValueError as exc:
        line = getattr(exc, "lineno", 1)
        raise PostureError(f"{read}:{line}: not JSON: {exc}") from None
    except RecursionError:  # [[[... 100,000 deep
        raise PostureError(f"{read}: not JSON sass reads: nested too deep") from None
    return check_posture(raw, str(read))
