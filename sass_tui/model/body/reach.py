"""Reach: where a figure's hands can go (docs/reach.md).

The arm is the figure's HAnim linkage (model/body/hanim.py): the shoulder's
centre, the elbow (radiale), the wrist (stylion) and, beyond the wrist, a
point of the hand -- the fingertip (the hand length: wrist crease to the
middle finger's tip), the grip centre or the thumb tip.  Each hand's points
are sampled over the figure's own joint limits (the shoulder's abduction,
flexion and rotation, the elbow's flexion; the wrist straight), turned as
model/body/posture.py turns a limb (R = Rx(x) Ry(y) Rz(z) about the joint's
limit frame); with `trunk`, the trunk also bends, leans and twists at vl5
within its limits.  The reachable volume is the set of the samples seen from
the shoulder: in each direction, as far as the farthest sample (a radial
envelope, star-shaped about the shoulder).

The survey's own reach measures (ANSUR II, Gordon et al. 2014) follow from
the same linkage, in closed form:

  thumbtipreach    from a wall touching the back (the trunk's back at the
                   chest: half the chest depth behind the shoulder centre,
                   as model/body/body_surface.py places it) to the thumb
                   tip, the arm straight forward at shoulder height;
  overheadfingertipreachsitting  from the seat to the middle fingertip, the
                   arm as high as the shoulder's limits raise it; the
                   shoulder above the seat is the sitting height less the
                   vertex-to-shoulder distance standing;
  span             fingertip to fingertip, both arms straight out sideways.

Named assumptions (docs/reach.md): the shoulder girdle moves with the arm
(scapular protraction, elevation and upward rotation) -- the `TRAVEL`
forward, upward and sideways, each weighted by the square of the reach
direction's component that way (none backwards or down); the thumb tip
lies THUMB_TIP_SHARE of the hand length beyond the wrist (thumb pressed to
the index finger); the grip centre GRIP_SHARE of it, else where the
person's own forearm-hand and forearm-centre-of-grip lengths put it.  The
travels are the mean of what the linkage leaves of the measured reach over
ANSUR II (scripts/reach_validation.py computes them and checks these
numbers).  A real person with a measured reach has their own travel: the
one that gives back their measurement.

Coordinates are the humanoid's (metres, +Y up, +Z front, +X the body's
left); standing, the origin is on the floor between the feet; seated
(`seated=True`), on the seat's surface below the midpoint of the hips.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from sass_tui.model.body.body_measures import figure_measures
from sass_tui.model.body.body_surface import closed_tube
from sass_tui.model.body.hanim import build_humanoid, humanoid_stature
from sass_tui.model.body.landmarks import measured
from sass_tui.model.errors import SassError
from sass_tui.model.units import UnitError, finite_number, parse_quantity, quantity_unit

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.body.hanim import Humanoid

REACH_MEASURES: tuple[str, ...] = ("thumbtipreach", "overheadfingertipreachsitting", "span")
# The ANSUR II measurements linkage_from_measures builds an arm from (no reach among them).
LINKAGE_MEASURES: tuple[str, ...] = (
    "stature",
    "sittingheight",
    "acromialheight",
    "biacromialbreadth",
    "acromionradialelength",
    "wristheight",
    "handlength",
    "forearmhandlength",
    "forearmcenterofgriplength",
    "chestdepth",
    "iliocristaleheight",
)
HAND_POINTS: tuple[str, ...] = ("fingertip", "grip", "thumbtip")
SIDES: tuple[str, ...] = ("right", "left")

# The thumb tip beyond the wrist, a share of the hand length (sass's own
# assumption: the thumb's tip pressed to the index finger's last phalanx).
THUMB_TIP_SHARE = 0.75
# The grip centre beyond the wrist crease, a share of the hand length: the
# ANSUR II mean of (hand length - (forearm-hand length - forearm-centre-of-
# grip length)) / hand length (scripts/reach_validation.py checks it).
GRIP_SHARE = {"male": 0.321, "female": 0.325}
# Sitting height / stature, ANSUR II means (scripts/reach_validation.py).
SITTING_HEIGHT_FRACTION = {"male": 0.5231, "female": 0.5262}
# The shoulder girdle's travel (m) with the arm reaching forward, up and
# sideways: what the linkage leaves of ANSUR II's measured thumb-tip reach,
# overhead reach sitting and half the span, on average
# (scripts/reach_validation.py computes and checks these).
TRAVEL = {
    "male": (0.0175, 0.1787, 0.0084),
    "female": (0.0057, 0.1487, 0.0126),
}
# A direction no sample reaches gets this radius (m): the envelope stays a
# closed surface about the shoulder.
_INSIDE = 0.03
# The envelope's directions: polar bins from +Y and bins around it.
POLAR_BINS, AROUND_BINS = 36, 72

_X, _Y, _Z = np.eye(3)


class ReachError(ValueError, SassError):
    """The figure's reach cannot be had."""


@dataclass(frozen=True)
class ArmLimits:
    """One arm's limits (radians) about its limit frames (hanim.Limits)."""

    shoulder_frame: np.ndarray
    shoulder_lower: np.ndarray  # x, y, z
    shoulder_upper: np.ndarray
    elbow_axis: np.ndarray  # the elbow's flexion axis standing
    elbow_upper: float
    trunk_frame: np.ndarray
    trunk_lower: np.ndarray
    trunk_upper: np.ndarray


@dataclass(frozen=True)
class Linkage:
    """One arm of n people (arrays of n; metres, the standing frame)."""

    gender: str
    side: str
    shoulder: np.ndarray  # (n, 3)
    vl5: np.ndarray  # (n, 3)
    upper_arm: np.ndarray  # shoulder centre to elbow
    forearm: np.ndarray  # elbow to wrist
    hand: dict[str, np.ndarray]  # HAND_POINTS -> wrist to that point
    back: np.ndarray  # the wall's z behind the scapulae (negative)
    chest_depth: np.ndarray
    sitting_shoulder: np.ndarray  # the shoulder centre above the seat, sitting
    travel: np.ndarray  # (n, 3) forward, up, sideways
    limits: ArmLimits
    sources: dict[str, str] = field(default_factory=dict)  # measure -> "measured"/"model"

    @property
    def count(self) -> int:
        return len(self.upper_arm)

    def reach_length(self, point: str) -> np.ndarray:
        """Shoulder centre to the hand's `point`, the arm straight."""
        out: np.ndarray = self.upper_arm + self.forearm + self.hand[point]
        return out


# --- the linkage -----------------------------------------------------------------


def arm_limits(humanoid: Humanoid, side: str) -> ArmLimits:
    s = side[0]
    shoulder, elbow, trunk = (humanoid.limits[j] for j in (f"{s}_shoulder", f"{s}_elbow", "vl5"))
    return ArmLimits(
        shoulder.frame,
        np.array(shoulder.lower),
        np.array(shoulder.upper),
        elbow.frame[:, 1],
        float(elbow.upper[1]),
        trunk.frame,
        np.array(trunk.lower),
        np.array(trunk.upper),
    )


def linkage_of(figure: Figure, side: str = "right") -> Linkage:
    """The figure's arm (its humanoid and body measurements), the shoulder
    travel the model's (own_travel gives a person's measured reach back)."""
    if side not in SIDES:
        raise ReachError(f"hand {side!r}: expected one of {', '.join(SIDES)}")
    humanoid = build_humanoid(figure)
    stature = humanoid_stature(figure)
    measures = figure_measures(figure, stature)
    s = side[0]
    c = humanoid.centers
    own: Mapping[str, float] = figure.landmarks or {}
    hand_length = measures.m("handlength")
    sitting = measured(own, "sittingheight")
    if sitting is None:
        sitting = SITTING_HEIGHT_FRACTION[figure.gender] * stature / 100.0
    shoulder = np.asarray(c[f"{s}_shoulder"], dtype=float)
    return Linkage(
        gender=figure.gender,
        side=side,
        shoulder=shoulder[None, :].copy(),
        vl5=np.asarray(c["vl5"], dtype=float)[None, :].copy(),
        upper_arm=np.array([float(np.linalg.norm(c[f"{s}_elbow"] - shoulder))]),
        forearm=np.array([float(np.linalg.norm(c[f"{s}_radiocarpal"] - c[f"{s}_elbow"]))]),
        hand=_hand_points(figure.gender, np.array([hand_length]), _grip(own, hand_length)),
        back=np.array([-measures.m("chestdepth") / 2]),
        chest_depth=np.array([measures.m("chestdepth")]),
        sitting_shoulder=np.array([sitting - (stature / 100.0 - shoulder[1])]),
        travel=np.array([TRAVEL[figure.gender]], dtype=float),
        limits=arm_limits(humanoid, side),
    )


def _grip(own: Mapping[str, float], hand_length: float) -> np.ndarray | None:
    whole, to_grip = measured(own, "forearmhandlength"), measured(own, "forearmcenterofgriplength")
    if whole is None or to_grip is None:
        return None
    return np.array([hand_length - (whole - to_grip)])


def _hand_points(gender: str, hand: np.ndarray, grip: np.ndarray | None) -> dict[str, np.ndarray]:
    return {
        "fingertip": hand,
        "grip": GRIP_SHARE[gender] * hand if grip is None else grip,
        "thumbtip": THUMB_TIP_SHARE * hand,
    }


def linkage_from_measures(
    gender: str, values: Mapping[str, np.ndarray], limits: ArmLimits, side: str = "right"
) -> Linkage:
    """The arms of n people from their ANSUR II measurements (LINKAGE_MEASURES, cm arrays):
    the same placements as the humanoid's (model/body/landmarks.py), with
    no reach measure among them (scripts/reach_validation.py)."""

    def m(name: str) -> np.ndarray:
        return np.asarray(values[name], dtype=float) / 100.0

    breadth, acromion = m("biacromialbreadth"), m("acromialheight")
    below = 0.17 * breadth  # landmarks.shoulder_below_acromion
    sign = 1.0 if side == "left" else -1.0
    shoulder = np.column_stack(
        [sign * (breadth / 2 - 0.025), acromion - below, np.zeros_like(breadth)]
    )
    elbow_y = acromion - m("acromionradialelength")
    hand = m("handlength")
    grip = hand - (m("forearmhandlength") - m("forearmcenterofgriplength"))
    n = len(breadth)
    return Linkage(
        gender=gender,
        side=side,
        shoulder=shoulder,
        vl5=np.column_stack([np.zeros(n), m("iliocristaleheight"), np.zeros(n)]),
        upper_arm=shoulder[:, 1] - elbow_y,
        forearm=elbow_y - m("wristheight"),
        hand=_hand_points(gender, hand, grip),
        back=-m("chestdepth") / 2,
        chest_depth=m("chestdepth"),
        sitting_shoulder=m("sittingheight") - (m("stature") - shoulder[:, 1]),
        travel=np.tile(np.array(TRAVEL[gender], dtype=float), (n, 1)),
        limits=limits,
    )


def own_travel(linkage: Linkage, own: Mapping[str, float]) -> Linkage:
    """The linkage with the travel its people's measured reach asks
    (each measure sets its own direction's travel); the others as they were."""
    travel = linkage.travel.copy()
    bare = reach_measures(linkage, travel=np.zeros_like(travel))
    sources = {name: "model" for name in REACH_MEASURES}
    for axis, name in enumerate(REACH_MEASURES):
        value = measured(own, name)
        if value is None:
            continue
        left = value - bare[name] / 100.0
        if name == "span":
            left = left / 2
        elif name == "overheadfingertipreachsitting":
            left = left / max(overhead_rise(linkage.limits), 0.1) ** 2
        travel[:, axis] = left
        sources[name] = "measured"
    return Linkage(**{**linkage.__dict__, "travel": travel, "sources": sources})


# --- the survey's measures ------------------------------------------------------


def overhead_rise(limits: ArmLimits) -> float:
    """How high (a share of the arm's length) the shoulder's limits raise the
    straight arm: 1 when flexion or abduction reaches 180 degrees."""
    most = min(max(float(limits.shoulder_upper[0]), float(limits.shoulder_upper[1])), math.pi)
    return -math.cos(most)


def reach_measures(linkage: Linkage, travel: np.ndarray | None = None) -> dict[str, np.ndarray]:
    """The survey's reach measures (cm arrays) of the linkage's people."""
    t = linkage.travel if travel is None else travel
    fingertip = linkage.reach_length("fingertip")
    rise = overhead_rise(linkage.limits)
    return {
        "thumbtipreach": 100.0
        * (linkage.shoulder[:, 2] - linkage.back + linkage.reach_length("thumbtip") + t[:, 0]),
        "overheadfingertipreachsitting": 100.0
        * (linkage.sitting_shoulder + rise * fingertip + rise**2 * t[:, 1]),
        "span": 200.0 * (np.abs(linkage.shoulder[:, 0]) + fingertip + t[:, 2]),
    }


# --- sampling the hand ------------------------------------------------------------


def _rotations(axis: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """(k, 3, 3) rotations by `angles` about the unit `axis` (Rodrigues)."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    s, c = np.sin(angles)[:, None, None], np.cos(angles)[:, None, None]
    out: np.ndarray = np.eye(3)[None] + s * k[None] + (1 - c) * (k @ k)[None]
    return out


def _grid(lower: float, upper: float, count: int) -> np.ndarray:
    return np.linspace(lower, upper, count) if upper > lower else np.array([lower])


@dataclass(frozen=True)
class Sampling:
    """How finely the joint ranges are sampled (counts of angles)."""

    abduction: int = 31
    flexion: int = 41
    rotation: int = 7
    elbow: int = 9
    trunk: int = 3


# With the trunk free each arm sample is turned 27 ways: the arm coarser.
_TRUNK_SAMPLING = Sampling(abduction=19, flexion=25, rotation=5, elbow=6)


def hand_samples(
    linkage: Linkage,
    point: str = "fingertip",
    seated: bool = False,
    trunk: bool = False,
    sampling: Sampling | None = None,
) -> np.ndarray:
    """The hand's `point` over the joint ranges (m, (k, 3)) of the first of
    the linkage's people."""
    if point not in HAND_POINTS:
        raise ReachError(f"hand point {point!r}: expected one of {', '.join(HAND_POINTS)}")
    n = sampling or (_TRUNK_SAMPLING if trunk else Sampling())
    lim = linkage.limits
    frame = lim.shoulder_frame
    lo, hi = lim.shoulder_lower, lim.shoulder_upper
    upper = (
        _rotations(frame[:, 0], _grid(lo[0], hi[0], n.abduction))[:, None, None]
        @ _rotations(frame[:, 1], _grid(lo[1], hi[1], n.flexion))[None, :, None]
        @ _rotations(frame[:, 2], _grid(lo[2], hi[2], n.rotation))[None, None, :]
    ).reshape(-1, 3, 3)
    elbow = _rotations(lim.elbow_axis, _grid(0.0, lim.elbow_upper, n.elbow))
    down = -_Y
    arm = upper @ down  # (a, 3) the upper arm's direction
    fore = (upper[:, None] @ elbow[None] @ down).reshape(len(upper), len(elbow), 3)
    length = float(linkage.forearm[0] + linkage.hand[point][0])
    reach = (float(linkage.upper_arm[0]) * arm[:, None, :] + length * fore).reshape(-1, 3)
    reach = reach + _girdle(linkage, reach)
    shoulder = _shoulder(linkage, seated)
    if not trunk:
        out: np.ndarray = shoulder + reach
        return out
    pivot = shoulder.copy()
    pivot[1] -= float(linkage.shoulder[0, 1] - linkage.vl5[0, 1])
    tl, tu = lim.trunk_lower, lim.trunk_upper
    bend = (
        _rotations(lim.trunk_frame[:, 0], _grid(tl[0], tu[0], n.trunk))[:, None, None]
        @ _rotations(lim.trunk_frame[:, 1], _grid(tl[1], tu[1], n.trunk))[None, :, None]
        @ _rotations(lim.trunk_frame[:, 2], _grid(tl[2], tu[2], n.trunk))[None, None, :]
    ).reshape(-1, 3, 3)
    points = (shoulder - pivot) + reach  # from vl5
    moved: np.ndarray = pivot + np.einsum("tij,kj->tki", bend, points).reshape(-1, 3)
    return moved


def _girdle(linkage: Linkage, reach: np.ndarray) -> np.ndarray:
    """The shoulder girdle's travel with the hand at `reach` from the
    shoulder: forward, up and outward, each by the square of the direction's
    component that way."""
    u = reach / np.maximum(np.linalg.norm(reach, axis=1, keepdims=True), 1e-9)
    outward = 1.0 if linkage.side == "left" else -1.0
    forward, up, sideways = linkage.travel[0]
    out: np.ndarray = (
        np.clip(u[:, 2:3], 0, None) ** 2 * forward * _Z
        + np.clip(u[:, 1:2], 0, None) ** 2 * up * _Y
        + np.clip(outward * u[:, 0:1], 0, None) ** 2 * sideways * outward * _X
    )
    return out


def _shoulder(linkage: Linkage, seated: bool) -> np.ndarray:
    shoulder: np.ndarray = linkage.shoulder[0].copy()
    if seated:
        shoulder[1] = float(linkage.sitting_shoulder[0])
    return shoulder


# --- the envelope ------------------------------------------------------------------


@dataclass(frozen=True)
class Envelope:
    """The radial envelope about `centre`: the farthest sample in each
    direction bin (POLAR_BINS from +Y x AROUND_BINS), and the samples."""

    centre: np.ndarray
    radius: np.ndarray  # (POLAR_BINS, AROUND_BINS) m
    samples: np.ndarray
    side: str
    point: str
    seated: bool
    trunk: bool

    def radius_towards(self, offsets: np.ndarray) -> np.ndarray:
        """The envelope's radius in the direction of each offset from the centre."""
        polar, around = _bins(offsets)
        out: np.ndarray = self.radius[polar, around]
        return out

    def mesh(self) -> tuple[np.ndarray, np.ndarray]:
        """A closed surface: a ring per polar bin, a point at each pole."""
        polar = (np.arange(POLAR_BINS) + 0.5) * math.pi / POLAR_BINS
        around = (np.arange(AROUND_BINS) + 0.5) * 2 * math.pi / AROUND_BINS
        d = _directions(polar[:, None], around[None, :])
        rings = self.centre + self.radius[..., None] * d
        top = self.centre + float(self.radius[0].mean()) * _Y
        bottom = self.centre - float(self.radius[-1].mean()) * _Y
        return closed_tube(list(rings), top, bottom)


def _directions(polar: np.ndarray, around: np.ndarray) -> np.ndarray:
    s = np.sin(polar)
    return np.stack(np.broadcast_arrays(s * np.cos(around), np.cos(polar), s * np.sin(around)), -1)


def _bins(offsets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    r = np.maximum(np.linalg.norm(offsets, axis=-1), 1e-12)
    polar = np.arccos(np.clip(offsets[..., 1] / r, -1.0, 1.0))
    around = np.arctan2(offsets[..., 2], offsets[..., 0]) % (2 * math.pi)
    p = np.minimum((polar / math.pi * POLAR_BINS).astype(np.int64), POLAR_BINS - 1)
    a = np.minimum((around / (2 * math.pi) * AROUND_BINS).astype(np.int64), AROUND_BINS - 1)
    return p, a


def envelope(
    linkage: Linkage,
    point: str = "fingertip",
    seated: bool = False,
    trunk: bool = False,
    sampling: Sampling | None = None,
) -> Envelope:
    """The hand point's reachable volume about the (resting) shoulder."""
    samples = hand_samples(linkage, point, seated, trunk, sampling)
    centre = _shoulder(linkage, seated)
    offsets = samples - centre
    polar, around = _bins(offsets)
    radius = np.full((POLAR_BINS, AROUND_BINS), -1.0)
    np.maximum.at(radius, (polar, around), np.linalg.norm(offsets, axis=1))
    radius = _near_the_poles(_fill(radius))
    return Envelope(centre, radius, samples, linkage.side, point, seated, trunk)


def _near_the_poles(radius: np.ndarray) -> np.ndarray:
    """Each bin the farthest of the bins of its ring within about one bin's
    width of arc (5 degrees): near the poles a ring's bins are narrow, and a
    sample falls in one and not its neighbour."""
    out = radius.copy()
    for row in range(POLAR_BINS):
        polar = (row + 0.5) * math.pi / POLAR_BINS
        half = min(AROUND_BINS // 2, math.ceil(0.5 / math.sin(polar))) - 1
        if half > 0:
            ring = radius[row]
            out[row] = np.max([np.roll(ring, k) for k in range(-half, half + 1)], axis=0)
    return out


def _fill(radius: np.ndarray) -> np.ndarray:
    """A bin no sample fell in takes the lesser of its filled neighbours
    around the same ring when it lies between them (sampling gaps), else
    _INSIDE (a direction the hand cannot go)."""
    empty = radius < 0
    left, right = np.roll(radius, 1, axis=1), np.roll(radius, -1, axis=1)
    up = np.vstack([radius[:1], radius[:-1]])
    down = np.vstack([radius[1:], radius[-1:]])
    gap = empty & (((left > 0) & (right > 0)) | ((up > 0) & (down > 0)))
    between = np.where(
        (left > 0) & (right > 0), np.minimum(left, right), np.minimum(np.abs(up), np.abs(down))
    )
    out = np.where(gap, between, radius)
    return np.where(out > 0, out, _INSIDE)


# --- a point ----------------------------------------------------------------------


def parse_point(text: str) -> np.ndarray:
    """'30,120,50' (cm), '30,120,50 cm', '0.3 m, 1.2 m, 20 in' -> metres
    (3,): three lengths, each with its own unit or the last one's, else cm."""
    parts = [part.strip() for part in text.split(",")]
    if len(parts) != 3 or not all(parts):
        raise ReachError(f"{text.strip()!r}: expected X,Y,Z, e.g. 30,120,50 or 0.3,1.2,0.5 m")
    try:
        # each part a number with an optional unit, said of the first that is not
        unit = [quantity_unit(part) for part in parts][-1] or "cm"
        parse_quantity(f"1 {unit}", "cm")  # the last part's unit is a length
        return np.array([_length(part, unit) for part in parts]) / 100.0
    except UnitError as exc:
        raise ReachError(f"{text.strip()!r}: {exc}") from None


def _length(part: str, unit: str) -> float:
    try:
        value = finite_number(part)
    except UnitError:
        return parse_quantity(part, "cm")
    return parse_quantity(f"{value!r} {unit}", "cm")


@dataclass(frozen=True)
class PointVerdict:
    point: np.ndarray  # m
    reached: bool
    miss: float  # m: 0 when reached, else to the nearest reachable sample


def point_verdict(env: Envelope, point: np.ndarray) -> PointVerdict:
    """Whether the envelope holds `point` (m) and, if not, how far the hand
    falls short of it (the nearest sample)."""
    offset = point - env.centre
    reached = bool(np.linalg.norm(offset) <= env.radius_towards(offset[None, :])[0])
    miss = 0.0 if reached else float(np.linalg.norm(env.samples - point, axis=1).min())
    return PointVerdict(point, reached, miss)


def own_arms_reaching(
    figure_arms: list[tuple[Envelope, Linkage]],
    people: list[Linkage],
    weights: np.ndarray,
    point: np.ndarray,
) -> tuple[float, float, int]:
    """(the weight of the people who reach `point` (m) with any hand, the
    weight of everyone counted, how many were left out for want of a
    measurement): each person with their own shoulder and their own arm's
    length, the figure's joint ranges -- the figure's envelope about the
    person's shoulder, its radius scaled by their arm's length over the
    figure's.  `people[k]` is the side of `figure_arms[k]`."""
    w = np.asarray(weights, dtype=float)
    reached = np.zeros(len(w), dtype=bool)
    known = np.isfinite(w)
    for (env, figure), arm in zip(figure_arms, people, strict=True):
        shoulder = arm.shoulder.copy()
        if env.seated:
            shoulder[:, 1] = arm.sitting_shoulder
        ratio = arm.reach_length(env.point) / float(figure.reach_length(env.point)[0])
        offsets = point[None, :] - shoulder
        ok = np.isfinite(offsets).all(axis=1) & np.isfinite(ratio) & (ratio > 0)
        known &= ok
        inside = np.zeros(len(w), dtype=bool)
        inside[ok] = np.linalg.norm(offsets[ok], axis=1) <= (
            env.radius_towards(offsets[ok]) * ratio[ok]
        )
        reached |= inside
    if not known.any() or float(w[known].sum()) <= 0:
        raise ReachError("no person with the arm's measurements and a weight to count")
    return float(w[known & reached].sum()), float(w[known].sum()), int((~known).sum())


# --- on screen ----------------------------------------------------------------------


@dataclass(frozen=True)
class ReachDrawing:
    """One hand's envelope seen from the side (z forward, y up) and from
    above (x the body's left, z forward), cm, and a point with its verdict."""

    side: np.ndarray  # (k, 2)
    top: np.ndarray  # (k, 2)
    shoulder: np.ndarray  # (3,) cm
    point: np.ndarray | None = None  # (3,) cm
    reached: bool | None = None


def silhouette(env: Envelope, axes: tuple[int, int], bins: int = 90) -> np.ndarray:
    """The envelope's outline projected on two axes (cm, (k, 2)): in each of
    `bins` directions about the shoulder, the farthest sample."""
    centre = env.centre[list(axes)]
    d = env.samples[:, list(axes)] - centre
    angle = np.arctan2(d[:, 1], d[:, 0])
    index = ((angle + math.pi) / (2 * math.pi) * bins).astype(np.int64) % bins
    far = np.zeros(bins)
    np.maximum.at(far, index, np.hypot(d[:, 0], d[:, 1]))
    middle = -math.pi + (np.arange(bins) + 0.5) * 2 * math.pi / bins
    keep = far > 0
    points = centre + far[keep, None] * np.column_stack([np.cos(middle), np.sin(middle)])[keep]
    out: np.ndarray = points * 100.0
    return out


def reach_drawing(env: Envelope, point: np.ndarray | None = None) -> ReachDrawing:
    """What the figure view draws of an envelope (and a point, m)."""
    verdict = None if point is None else point_verdict(env, point).reached
    return ReachDrawing(
        side=silhouette(env, (2, 1)),
        top=silhouette(env, (0, 2)),
        shoulder=env.centre * 100.0,
        point=None if point is None else point * 100.0,
        reached=verdict,
    )
