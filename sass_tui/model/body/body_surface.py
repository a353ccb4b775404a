"""The body's surface, lofted through the person's own measurements.

One geometry for the glTF body (model/files/gltf.py) and the HAnim skin
(model/files/hanim_x3d.py): closed parts, each a loft through cross-sections
(superellipses |x/a|^n + |z/b|^n = 1) whose width is a measured breadth,
whose depth a measured depth and whose perimeter -- what a tape measure
reads, the section being convex -- a measured circumference, at the height
the survey measured it (model/body/body_measures.py gives the values: a person's
own, else sass predict's from stature and mass).

  trunk   one surface from the crotch through the buttock, waist (omphalion),
          iliac crest, tenth rib, chest, axilla, shoulder (acromion), neck
          base, neck, chin and head to the vertex (the stature)
  legs    thigh (hip centre to ankle) and foot, each side
  arms    arm (shoulder centre to wrist) and hand, each side

The limbs start inside the trunk at their joint centres and overlap the
part below, so nothing floats and no gap opens at the hips, shoulders,
ankles or wrists.  Heights, breadths, depths and girths ANSUR II does not
measure are named where they are set (the `_ASSUMED` shares and the
comments): sass's own choices, documented in docs/gltf.md, "The surface".

Every vertex belongs to one HAnim joint (its segment's) and is blended with
its neighbour across each joint (skin_weights), so a pose bends the surface
smoothly.  Coordinates are the humanoid's: metres, +Y up, +Z front, +X left.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from sass_tui.model.body.appendix_l import HEEL_BEHIND_ANKLE
from sass_tui.model.body.body_measures import BodyMeasures, figure_measures
from sass_tui.model.body.hanim import LOA1, SEGMENT_OF, humanoid_stature

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.body.hanim import Humanoid

# Points around each cross-section (a multiple of 4: the extremes of the
# width and the depth are points of the section, so a cut measures them).
AROUND = 32
# The greatest distance (m) between neighbouring rings of a part.
RING_SPACING = 0.02
# The most rings _dense puts between two: 3 m (model/body/human.py's farthest
# joint) at RING_SPACING.
MAX_RINGS_BETWEEN = 150
# Superellipse exponents: 2 is an ellipse; the solver keeps n in this range.
_N_MIN, _N_MAX = 1.2, 12.0

# Shares sass assumes where ANSUR II has no measurement (docs/gltf.md):
_ASSUMED = {
    # the neck's depth over its breadth (an ellipse)
    "neck_depth": 0.9,
    # the chin (menton) below the tragion, as a share of menton-sellion length
    "chin_below_tragion": 0.83,
    # the head's widest girth above the tragion, share of tragion-vertex
    "head_girth_up": 0.3,
    # the head's centre in front of the skull base joint, share of head length
    "head_forward": 0.1,
    # the trunk at the acromion: its depth as a share of the chest depth
    "shoulder_depth": 0.6,
    # the trunk at the axilla: its depth as a share of the chest depth
    "axilla_depth": 0.92,
    # lower thigh girth above the knee's axis, share of knee - crotch
    "lower_thigh_up": 0.2,
    # the calf's widest girth below the knee, share of knee - ankle
    "calf_down": 0.35,
    # the ankle's least girth above the lateral malleolus (m)
    "ankle_up": 0.04,
    # the forearm's widest girth below the elbow, share of elbow - wrist
    "forearm_down": 0.25,
    # the wrist's and hand's thickness over their breadth (front to back)
    "wrist_thickness": 0.65,
    # the thigh's top stays this far (m) inside the hip breadth (the skin
    # over the greater trochanter), and the two thighs this far apart
    "thigh_inside_hips": 0.005,
    "thighs_apart": 0.004,
}


# The skin's colour (sRGB), by gender: the X3D document's Material and the
# glTF body's base colour (model/files/hanim_x3d.py, model/files/gltf.py).
SKIN = {"male": "0.80 0.62 0.50", "female": "0.86 0.66 0.58"}


@dataclass(frozen=True)
class Section:
    """A closed superellipse: centre, width axis `u` (half-width a), depth
    axis `v` (half-depth b), exponent n."""

    name: str
    centre: np.ndarray
    u: np.ndarray
    v: np.ndarray
    a: float
    b: float
    n: float

    def points(self) -> np.ndarray:
        cx, cz = _unit_superellipse(self.n)
        out: np.ndarray = (
            self.centre[None, :]
            + (self.a * cx)[:, None] * self.u[None, :]
            + (self.b * cz)[:, None] * self.v[None, :]
        )
        return out


@dataclass(frozen=True)
class Part:
    """One closed surface: vertices, outward counter-clockwise triangles,
    each vertex's own joint (index into LOA1) and the sections it passes."""

    name: str
    vertices: np.ndarray  # (n, 3) m
    triangles: np.ndarray  # (m, 3)
    owners: np.ndarray  # (n,) joint index
    sections: tuple[Section, ...]


@dataclass(frozen=True)
class BodySurface:
    parts: tuple[Part, ...]
    measures: BodyMeasures

    def part(self, name: str) -> Part:
        return next(p for p in self.parts if p.name == name)


# --- sections ------------------------------------------------------------------


# _solve stops when the perimeter is within this share of its target, or the
# bracket within this share of its end: far below the 0.1 mm the files print.
# The step ceiling is met only if the steps stalled.
_SOLVE_TOLERANCE = 1e-12
_SOLVE_STEPS = 100

_ANGLES = np.linspace(0.0, 2 * math.pi, AROUND, endpoint=False)
_COS, _SIN = np.cos(_ANGLES), np.sin(_ANGLES)


def _unit_superellipse(n: float) -> tuple[np.ndarray, np.ndarray]:
    power = 2.0 / n
    return np.sign(_COS) * np.abs(_COS) ** power, np.sign(_SIN) * np.abs(_SIN) ** power


def perimeter(a: float, b: float, n: float) -> float:
    """The closed polygon's perimeter (m) of the section's AROUND points: what
    a tape around the mesh reads (the section is convex for n >= 1)."""
    cx, cz = _unit_superellipse(n)
    x, z = a * cx, b * cz
    return float(np.hypot(np.diff(np.append(x, x[0])), np.diff(np.append(z, z[0]))).sum())


def _solve(lower: float, upper: float, f: Callable[[float], float], target: float) -> float:
    """x with f(x) = target on [lower, upper], f increasing (the end nearer
    the target when it lies outside f's range there).  Regula falsi with the
    Illinois step (Dowell & Jarratt 1971): the root stays bracketed as in
    bisection, in 9-13 perimeters (both ends included) where 40 halvings took
    40 (docs/performance.md, "The lofted body")."""
    f_lower, f_upper = f(lower) - target, f(upper) - target
    if f_lower >= 0 or f_upper <= 0:
        return lower if f_lower >= 0 else upper
    kept = 0  # the end kept last step: -1 lower, +1 upper
    for _ in range(_SOLVE_STEPS):
        x = (lower * f_upper - upper * f_lower) / (f_upper - f_lower)
        f_x = f(x) - target
        if f_x < 0:
            lower, f_lower = x, f_x
            if kept == 1:  # the upper end kept twice running: halve its weight
                f_upper /= 2
            kept = 1
        else:
            upper, f_upper = x, f_x
            if kept == -1:
                f_lower /= 2
            kept = -1
        if abs(f_x) <= _SOLVE_TOLERANCE * abs(target) or upper - lower <= _SOLVE_TOLERANCE * upper:
            return x
    return (lower + upper) / 2


def fit_section(width: float, depth: float, circumference: float) -> tuple[float, float, float]:
    """Half-width, half-depth and exponent of the section `width` wide,
    `depth` deep with a tape perimeter of `circumference` (all m).  The
    width is kept; the exponent goes from diamond-like (1.2) to boxy (12);
    a circumference outside what that range reaches moves the depth."""
    a, b = width / 2, depth / 2
    low, high = perimeter(a, b, _N_MIN), perimeter(a, b, _N_MAX)
    if low <= circumference <= high:
        return a, b, _solve(_N_MIN, _N_MAX, lambda n: perimeter(a, b, n), circumference)
    n = _N_MIN if circumference < low else _N_MAX
    b = _solve(1e-4, 4 * circumference, lambda d: perimeter(a, d, n), circumference)
    return a, b, n


def _ellipse(circumference: float, ratio: float) -> tuple[float, float]:
    """Half-axes (a, ratio * a) of the ellipse with this tape perimeter."""
    a = circumference / perimeter(1.0, ratio, 2.0)
    return a, ratio * a


def _thickness(breadth: float, circumference: float, n: float = 2.5) -> float:
    """Half-thickness of a section `breadth` wide with this perimeter."""
    a = breadth / 2
    return _solve(1e-4, circumference, lambda b: perimeter(a, b, n), circumference)


_X, _Y, _Z = np.eye(3)


def _level(name: str, y: float, a: float, b: float, n: float, z: float = 0.0) -> Section:
    """A horizontal section of the trunk: width along X, depth along Z."""
    return Section(name, np.array([0.0, y, z]), _X, _Z, a, b, n)


def trunk_sections(m: BodyMeasures, humanoid: Humanoid, stature: float) -> list[Section]:
    """Crotch to vertex, lowest first (see the module's docstring)."""
    A = _ASSUMED
    # ANSUR II's own levels: (name, height, width, depth, circumference) in m
    measured: list[tuple[str, float, float, float, float]] = [
        (level, m.m(height), m.m(across), m.m(deep), m.m(tape))
        for level, height, across, deep, tape in (
            ("buttock", "buttockheight", "hipbreadth", "buttockdepth", "buttockcircumference"),
            ("waist", "waistheightomphalion", "waistbreadth", "waistdepth", "waistcircumference"),
            ("chest", "chestheight", "chestbreadth", "chestdepth", "chestcircumference"),
        )
    ]
    measured.sort(key=lambda row: row[1])
    levels = np.array([row[1] for row in measured])
    sections = [_level(row[0], row[1], *fit_section(*row[2:])) for row in measured]
    # the iliac crest and the tenth rib between the measured levels: their
    # width, depth and girth interpolated by height (ANSUR II's bicristal
    # breadth is bone, taken with the calipers pressed in, not the surface)
    for name, height in (("iliac_crest", "iliocristaleheight"), ("tenth_rib", "tenthribheight")):
        y = m.m(height)
        if levels[0] < y < levels[-1]:
            width, depth, girth = (
                float(np.interp(y, levels, [float(row[k]) for row in measured])) for k in (2, 3, 4)
            )
            sections.append(_level(name, y, *fit_section(width, depth, girth)))
    chest = next(s for s in sections if s.name == "chest")
    chest_depth = m.m("chestdepth")
    top_of_chest = max(levels[-1], chest.centre[1])
    axilla = max(m.m("axillaheight"), top_of_chest + 0.01)
    sections.append(_level("axilla", axilla, chest.a, A["axilla_depth"] * chest.b, chest.n))
    acromion = max(m.m("acromialheight"), axilla + 0.02)
    shoulder_a = m.m("biacromialbreadth") / 2
    shoulder_b = A["shoulder_depth"] * chest_depth / 2
    sections.append(_level("shoulder", acromion, shoulder_a, shoulder_b, 2.5))
    # the neck: its base at the cervicale, its girth halfway up to the chin
    tragion = float(humanoid.centers["skullbase"][1])
    chin = tragion - A["chin_below_tragion"] * m.m("mentonsellionlength")
    base_y = max(m.m("cervicaleheight"), acromion + 0.015)
    chin = max(chin, base_y + 0.04)
    base_a, base_b = _ellipse(m.m("neckcircumferencebase"), A["neck_depth"])
    sections.append(_level("neck_base", base_y, base_a, base_b, 2.0))
    # the trapezius slopes from the shoulders up to the neck's base
    for k, share in ((0.35, 0.75), (0.7, 0.4)):
        sections.append(
            _level(
                f"trapezius_{k:g}",
                acromion + k * (base_y - acromion),
                share * shoulder_a + (1 - share) * base_a,
                share * shoulder_b + (1 - share) * base_b,
                2.3,
            )
        )
    neck_a, neck_b = _ellipse(m.m("neckcircumference"), A["neck_depth"])
    sections.append(_level("neck", (base_y + chin) / 2, neck_a, neck_b, 2.0))
    # the head: chin, cheeks, tragion, its widest girth, then a dome to the vertex
    head_length, head_breadth = m.m("headlength"), m.m("headbreadth")
    forward = A["head_forward"] * head_length
    face = m.m("bizygomaticbreadth")
    # the chin and cheeks at least as far round as the neck below them, so
    # the neck's narrowest girth is the measured one (a thick neck under a
    # small face would otherwise narrow under the jaw)
    neck_girth = m.m("neckcircumference")
    for name, y, a, b in (
        ("chin", chin, 0.75 * face / 2, 0.7 * head_length / 2),
        ("cheek", (chin + tragion) / 2, 0.95 * face / 2, 0.9 * head_length / 2),
    ):
        grow = max(1.0, 1.01 * neck_girth / perimeter(a, b, 2.2))
        sections.append(_level(name, y, grow * a, grow * b, 2.2, forward))
    girth_y = tragion + A["head_girth_up"] * (stature - tragion)
    sections.append(
        _level(
            "tragion",
            tragion,
            max(face, 0.95 * head_breadth) / 2,
            0.95 * head_length / 2,
            2.2,
            forward,
        )
    )
    a, b, n = fit_section(head_breadth, head_length, m.m("headcircumference"))
    sections.append(_level("head", girth_y, a, b, n, forward))
    for k in (0.35, 0.65, 0.88):
        scale = math.sqrt(1 - k * k)
        y = girth_y + k * (stature - girth_y)
        sections.append(_level(f"dome_{k:g}", y, scale * a, scale * b, n, forward))
    bottom = min(m.m("crotchheight"), levels[0] - 0.02)
    buttock = next(s for s in sections if s.name == "buttock")
    sections.append(_level("crotch", bottom, 0.7 * buttock.a, 0.6 * buttock.b, 2.5))
    return _ordered(sections)


def _ordered(sections: list[Section]) -> list[Section]:
    """Lowest first; a section within 5 mm of the one below it is left out
    (the measured levels are kept: they come first in the list)."""
    keep: list[Section] = []
    for section in sorted(sections, key=lambda s: s.centre[1]):
        if keep and section.centre[1] - keep[-1].centre[1] < 0.005:
            if section.name in ("buttock", "waist", "chest"):
                keep[-1] = section
            continue
        keep.append(section)
    return keep


def _round_section(name: str, centre: np.ndarray, circumference: float) -> Section:
    r = circumference / perimeter(1.0, 1.0, 2.0)
    return Section(name, centre, _X, _Z, r, r, 2.0)


def _upper_thigh(name: str, centre: np.ndarray, girth: float, inside: float) -> Section:
    """The thigh's top, round unless that stands out past `inside` (m from
    the mid-sagittal plane: within the hip breadth) or across the midline:
    then narrower and deeper, the same girth, its centre moved in between."""
    r = girth / perimeter(1.0, 1.0, 2.0)
    side = 1.0 if centre[0] >= 0 else -1.0
    x = abs(float(centre[0]))
    gap = _ASSUMED["thighs_apart"] / 2
    if x + r <= inside and x - r >= gap:
        return _round_section(name, centre, girth)
    a = min(r, (inside - gap) / 2)
    x = min(max(x, gap + a), inside - a)
    b = _solve(a, girth, lambda d: perimeter(a, d, 2.0), girth)
    return Section(name, np.array([side * x, centre[1], centre[2]]), _X, _Z, a, b, 2.0)


def leg_sections(m: BodyMeasures, humanoid: Humanoid, side: str) -> list[Section]:
    """Hip centre down to the ankle (highest first): girths at the heights
    ANSUR II measured them or at the stated proxies."""
    A = _ASSUMED
    hip, knee = humanoid.centers[f"{side}_hip"], humanoid.centers[f"{side}_knee"]
    ankle = humanoid.centers[f"{side}_talocrural"]
    x = float(hip[0])

    def at(y: float) -> np.ndarray:
        return np.array([x, y, 0.0])

    crotch = min(m.m("crotchheight"), hip[1] - 0.03)
    knee_y, ankle_y = float(knee[1]), float(ankle[1])
    thigh, lower = m.m("thighcircumference"), m.m("lowerthighcircumference")
    calf, least = m.m("calfcircumference"), m.m("anklecircumference")
    inside = m.m("hipbreadth") / 2 - A["thigh_inside_hips"]
    return [
        _upper_thigh("hip", at(hip[1]), thigh, inside),
        _upper_thigh("thigh", at(crotch), thigh, inside),
        _round_section("lower_thigh", at(knee_y + A["lower_thigh_up"] * (crotch - knee_y)), lower),
        # no girth is measured at the knee: the lesser of its neighbours'
        _round_section("knee", at(knee_y), min(lower, calf)),
        _round_section("calf", at(knee_y - A["calf_down"] * (knee_y - ankle_y)), calf),
        _round_section("ankle", at(ankle_y + A["ankle_up"]), least),
        _round_section("malleoli", at(ankle_y), 1.05 * least),
    ]


def foot_sections(m: BodyMeasures, humanoid: Humanoid, side: str) -> list[Section]:
    """Heel to toes along +Z, each section standing on the floor: the heel
    HEEL_BEHIND_ANKLE foot lengths behind the ankle (appendix L.1), the ball
    of the foot at its measured distance from the heel with the measured
    breadth and girth, the toe tip a foot length from the heel."""
    ankle = humanoid.centers[f"{side}_talocrural"]
    x, ankle_y = float(ankle[0]), float(ankle[1])
    length = m.m("footlength")
    heel = -HEEL_BEHIND_ANKLE * length
    breadth, heel_breadth = m.m("footbreadthhorizontal"), m.m("heelbreadth")
    ball_z = heel + m.m("balloffootlength")
    ball_b = _thickness(breadth, m.m("balloffootcircumference"))

    def standing(name: str, z: float, width: float, height: float, n: float) -> Section:
        return Section(name, np.array([x, height / 2, z]), _X, _Y, width / 2, height / 2, n)

    return [
        standing("heel", heel + 0.012, 0.8 * heel_breadth, 0.7 * ankle_y, 2.5),
        standing("heel_back", heel + 0.3 * (0 - heel), heel_breadth, 1.4 * ankle_y, 2.5),
        standing("instep", 0.35 * ball_z, 0.85 * breadth, 1.4 * ankle_y, 2.5),
        standing("ball", ball_z, breadth, 2 * ball_b, 2.5),
        standing("toes", heel + 0.92 * length - 0.01, 0.8 * breadth, ball_b, 2.5),
    ]


def arm_sections(m: BodyMeasures, humanoid: Humanoid, side: str) -> list[Section]:
    """Shoulder centre down to the wrist (highest first)."""
    A = _ASSUMED
    shoulder = humanoid.centers[f"{side}_shoulder"]
    elbow, wrist = humanoid.centers[f"{side}_elbow"], humanoid.centers[f"{side}_radiocarpal"]
    x = float(shoulder[0])

    def at(y: float) -> np.ndarray:
        return np.array([x, y, 0.0])

    top, elbow_y, wrist_y = float(shoulder[1]), float(elbow[1]), float(wrist[1])
    # ANSUR II measures the upper arm's and forearm's girths flexed only:
    # those are the girths here
    biceps, forearm = m.m("bicepscircumferenceflexed"), m.m("forearmcircumferenceflexed")
    wrist_a, wrist_b = _ellipse(m.m("wristcircumference"), A["wrist_thickness"])
    return [
        _round_section("shoulder", at(top), 1.1 * biceps),  # the deltoid, over the joint
        _round_section("biceps", at((top + elbow_y) / 2), biceps),
        _round_section("elbow", at(elbow_y), 0.95 * min(biceps, forearm)),
        _round_section("forearm", at(elbow_y - A["forearm_down"] * (elbow_y - wrist_y)), forearm),
        # palms to the thighs: the wrist's breadth runs front to back (Z)
        Section("wrist", at(wrist_y), _X, _Z, wrist_b, wrist_a, 2.0),
    ]


def hand_sections(m: BodyMeasures, humanoid: Humanoid, side: str) -> list[Section]:
    """Wrist down to the fingertips: the hand's measured breadth and girth
    at the metacarpals, its length from the wrist."""
    A = _ASSUMED
    wrist = humanoid.centers[f"{side}_radiocarpal"]
    x, y = float(wrist[0]), float(wrist[1])
    breadth, palm = m.m("handbreadth"), m.m("palmlength")
    thick = _thickness(breadth, m.m("handcircumference"))
    wrist_a, wrist_b = _ellipse(m.m("wristcircumference"), A["wrist_thickness"])
    fingers = m.m("handlength") - palm

    def across(name: str, height: float, half_breadth: float, half_thick: float) -> Section:
        return Section(name, np.array([x, height, 0.0]), _X, _Z, half_thick, half_breadth, 2.5)

    return [
        across("wrist", y + 0.01, wrist_a, wrist_b),
        across("metacarpals", y - 0.5 * palm, breadth / 2, thick),
        across("knuckles", y - palm, 0.45 * breadth, 0.75 * thick),
        across("fingers", y - palm - 0.5 * fingers, 0.4 * breadth, 0.55 * thick),
    ]


# --- lofting -------------------------------------------------------------------


def loft(
    sections: list[Section], first_cap: np.ndarray, last_cap: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The closed surface through the sections in order, closed by a point
    before the first and one after the last: vertices and outward
    counter-clockwise triangles."""
    return closed_tube(_dense([s.points() for s in sections]), first_cap, last_cap)


def closed_tube(
    rings: list[np.ndarray], first_cap: np.ndarray, last_cap: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """The closed surface through rings of equal size in order, closed by a
    point before the first and one after the last: vertices and outward
    counter-clockwise triangles (the body's parts, the reach envelope)."""
    around = len(rings[0])
    vertices = np.vstack([first_cap[None, :], *rings, last_cap[None, :]])
    count = len(rings)
    first, last = 0, 1 + count * around
    k = np.arange(around)
    k1 = (k + 1) % around
    top = 1 + (count - 1) * around
    caps = [
        np.column_stack([np.full(around, first), 1 + k1, 1 + k]),
        np.column_stack([np.full(around, last), top + k, top + k1]),
    ]
    # ring r's point k is 1 + r * around + k; each quad between rings a, b:
    # (a+k, a+k1, b+k1) and (a+k, b+k1, b+k)
    a = 1 + np.arange(count - 1)[:, None] * around
    b = a + around
    quads = [
        np.stack([a + k, a + k1, b + k1], axis=-1).reshape(-1, 3),
        np.stack([a + k, b + k1, b + k], axis=-1).reshape(-1, 3),
    ]
    triangles = np.vstack([*caps, *quads]).astype(np.int64)
    if signed_volume(vertices, triangles) < 0:
        triangles = triangles[:, ::-1].copy()
    return vertices, triangles


def _dense(rings: list[np.ndarray]) -> list[np.ndarray]:
    """The rings with rings between them, linearly, so that no two are more
    than RING_SPACING apart: a joint bends over several rings, not at one."""
    out = [rings[0]]
    for lower, upper in zip(rings, rings[1:], strict=False):
        gap = float(np.linalg.norm(upper.mean(axis=0) - lower.mean(axis=0)))
        # At most MAX_RINGS_BETWEEN however far apart: a stature of 1e6 cm
        # asked for millions of rings (8.7 GB); no human gap needs more.
        steps = (
            min(max(1, math.ceil(gap / RING_SPACING)), MAX_RINGS_BETWEEN) if gap < math.inf else 1
        )
        out += [lower + (upper - lower) * (k / steps) for k in range(1, steps + 1)]
    return out


def signed_volume(vertices: np.ndarray, triangles: np.ndarray) -> float:
    """The enclosed volume (m^3), positive when the triangles face outward."""
    a, b, c = (vertices[triangles[:, i]] for i in range(3))
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6)


# --- the body ------------------------------------------------------------------

_JOINTS = [joint for joint, _, _ in LOA1]
_INDEX = {joint: i for i, joint in enumerate(_JOINTS)}


# Which joint owns a vertex: along an axis (1 = height, 2 = forward), the
# first band whose lower bound the vertex reaches, else the last band's joint.
Bands = tuple[int, list[tuple[float, str]]]


def _owners(vertices: np.ndarray, bands: Bands) -> np.ndarray:
    axis, table = bands
    owners = np.full(len(vertices), _INDEX[table[-1][1]], dtype=np.int64)
    for bound, joint in reversed(table):
        owners[vertices[:, axis] >= bound] = _INDEX[joint]
    return owners


def _part(
    name: str,
    sections: list[Section],
    first_cap: np.ndarray,
    last_cap: np.ndarray,
    bands: Bands,
) -> Part:
    vertices, triangles = loft(sections, first_cap, last_cap)
    return Part(name, vertices, triangles, _owners(vertices, bands), tuple(sections))


def body_surface(humanoid: Humanoid, measures: BodyMeasures, stature: float) -> BodySurface:
    """The body's closed parts around the humanoid's joints."""
    c = humanoid.centers

    def y(joint: str) -> float:
        return float(c[joint][1])

    trunk = trunk_sections(measures, humanoid, stature)
    parts = [
        _part(
            "trunk",
            trunk,
            trunk[0].centre - 0.015 * _Y,
            np.array([0.0, stature, trunk[-1].centre[2]]),
            (1, [(y("skullbase"), "skullbase"), (y("vl5"), "vl5"), (-1.0, "sacroiliac")]),
        )
    ]
    for s in ("l", "r"):
        leg = leg_sections(measures, humanoid, s)
        knee, ankle = y(f"{s}_knee"), y(f"{s}_talocrural")
        parts.append(
            _part(
                f"{s}_leg",
                leg,
                leg[0].centre + 0.5 * leg[0].a * _Y,
                leg[-1].centre - 0.02 * _Y,
                (1, [(knee, f"{s}_hip"), (ankle, f"{s}_knee"), (-1.0, f"{s}_talocrural")]),
            )
        )
        foot = foot_sections(measures, humanoid, s)
        heel = foot[0].centre - 0.012 * _Z
        toes = float(c[f"{s}_metatarsophalangeal_2"][2])
        parts.append(
            _part(
                f"{s}_foot",
                foot,
                heel,
                np.array([heel[0], 0.5 * foot[-1].b, heel[2] + measures.m("footlength")]),
                (2, [(toes, f"{s}_metatarsophalangeal_2"), (-1.0, f"{s}_talocrural")]),
            )
        )
        arm = arm_sections(measures, humanoid, s)
        elbow, wrist = y(f"{s}_elbow"), y(f"{s}_radiocarpal")
        parts.append(
            _part(
                f"{s}_arm",
                arm,
                # the deltoid's top covers the trunk's shoulder up to the acromion
                np.array(
                    [
                        arm[0].centre[0],
                        max(measures.m("acromialheight"), y(f"{s}_shoulder") + arm[0].a) + 0.01,
                        0.0,
                    ]
                ),
                arm[-1].centre - 0.02 * _Y,
                (1, [(elbow, f"{s}_shoulder"), (wrist, f"{s}_elbow"), (-1.0, f"{s}_radiocarpal")]),
            )
        )
        hand = hand_sections(measures, humanoid, s)
        tip = np.array([hand[-1].centre[0], wrist - measures.m("handlength"), 0.0])
        parts.append(
            _part(
                f"{s}_hand",
                hand,
                hand[0].centre + 0.01 * _Y,
                tip,
                (1, [(-1.0, f"{s}_radiocarpal")]),
            )
        )
    return BodySurface(tuple(parts), measures)


# --- skinning --------------------------------------------------------------------

# Half the width of the zone over which a vertex passes from one joint to the
# next (linear blend skinning), as a share of the thinner half-width of the
# segment below the joint.
_BLEND = 0.6

# (parent joint, child joint, centre, direction from the parent's segment
#  into the child's, blend half-width (m), blend the parent's side too)
Boundary = tuple[str, str, np.ndarray, np.ndarray, float, bool]


def _boundaries(humanoid: Humanoid) -> list[Boundary]:
    """Where a vertex passes from one joint's influence to the next: along
    the limbs and the spine both neighbours blend; at the hips and shoulders,
    which sit off the trunk's axis, only the limb's top does."""
    up, down, forward = _Y, -_Y, _Z
    chain: list[tuple[str, str, np.ndarray, bool]] = [
        ("sacroiliac", "vl5", up, True),
        ("vl5", "skullbase", up, True),
    ]
    for s in ("l", "r"):
        chain += [
            ("sacroiliac", f"{s}_hip", down, False),
            (f"{s}_hip", f"{s}_knee", down, True),
            (f"{s}_knee", f"{s}_talocrural", down, True),
            (f"{s}_talocrural", f"{s}_metatarsophalangeal_2", forward, True),
            ("vl5", f"{s}_shoulder", down, False),
            (f"{s}_shoulder", f"{s}_elbow", down, True),
            (f"{s}_elbow", f"{s}_radiocarpal", down, True),
        ]
    out: list[Boundary] = []
    for parent, child, direction, both in chain:
        shapes = humanoid.segments[SEGMENT_OF[child]].shapes
        size = np.asarray(shapes[0][2], dtype=float)
        across = [size[i] for i in range(3) if direction[i] == 0]
        width = max(_BLEND * min(across) / 2, 0.01)
        centre = np.asarray(humanoid.centers[child], dtype=float)
        out.append((parent, child, centre, direction, width, both))
    return out


def _weights(points: np.ndarray, joint: str, boundaries: list[Boundary]) -> np.ndarray:
    """Each point's weight on every joint (n, joints): 1 on its own segment's
    joint, shared linearly with the neighbour over a boundary's blend zone
    (half each at the joint centre)."""
    w = np.zeros((len(points), len(_INDEX)))
    own = np.ones(len(points))
    for parent, child, centre, direction, width, both in boundaries:
        if joint == child:
            # the proximal end: the part above the joint goes with the parent
            s = (points - centre) @ direction
            share = np.clip(0.5 - s / (2 * width), 0.0, 1.0)
            w[:, _INDEX[parent]] += share
            own -= share
        elif joint == parent and both:
            s = (points - centre) @ direction
            share = np.clip(0.5 + s / (2 * width), 0.0, 1.0)
            w[:, _INDEX[child]] += share
            own -= share
    # a short segment with both ends in their blend zones: scale the shares
    over = own < 0
    if over.any():
        given = 1 - own[over]
        w[over] /= given[:, None]
        own[over] = 0.0
    w[:, _INDEX[joint]] += own
    return w


def skin_weights(humanoid: Humanoid, vertices: np.ndarray, owners: np.ndarray) -> np.ndarray:
    """The weight of every joint (n, joints) on each vertex: its own joint's,
    blended with the neighbour across each joint it is near."""
    boundaries = _boundaries(humanoid)
    weights = np.zeros((len(vertices), len(_INDEX)))
    # set(), not np.unique: that imports numpy.ma, off sass export gltf's path
    for joint_index in sorted(set(owners.tolist())):
        chosen = owners == joint_index
        weights[chosen] = _weights(vertices[chosen], _JOINTS[joint_index], boundaries)
    return weights


@dataclass(frozen=True)
class BodyMesh:
    positions: np.ndarray  # (n, 3) float32, m
    normals: np.ndarray  # (n, 3) float32, unit
    joints: np.ndarray  # (n, 4) uint8, indices into LOA1's joints
    weights: np.ndarray  # (n, 4) float32, each row adds up to 1
    triangles: np.ndarray  # (m, 3) counter-clockwise seen from outside


def body_mesh(humanoid: Humanoid, surface: BodySurface) -> BodyMesh:
    """The body's surface (model/body/body_surface.py: closed parts lofted through
    the figure's measurements) with each vertex's four heaviest joints."""
    positions, normals, triangles, owners = [], [], [], []
    count = 0
    for part in surface.parts:
        positions.append(part.vertices)
        normals.append(vertex_normals(part.vertices, part.triangles))
        triangles.append(part.triangles + count)
        owners.append(part.owners)
        count += len(part.vertices)
    points = np.vstack(positions)
    w = skin_weights(humanoid, points, np.concatenate(owners))
    order = np.argsort(-w, axis=1)[:, :4]
    top = np.take_along_axis(w, order, axis=1)
    top /= top.sum(axis=1, keepdims=True)
    # slots with no weight name joint 0, as the spec's examples do
    order = np.where(top > 0, order, 0)
    weight = top.astype(np.float32)
    # float32 rows must add up to 1 to the validator's tolerance: the heaviest
    # slot takes up what rounding left
    weight[:, 0] = np.float32(1.0) - weight[:, 1:].sum(axis=1, dtype=np.float32)
    return BodyMesh(
        points.astype(np.float32),
        np.vstack(normals).astype(np.float32),
        order.astype(np.uint8),
        weight,
        np.vstack(triangles).astype(np.uint32),
    )


def figure_surface(figure: Figure, humanoid: Humanoid) -> BodySurface:
    """The figure's body surface around its humanoid: through its own
    measurements, else those sass predict gives its stature and mass."""
    stature = humanoid_stature(figure)
    return body_surface(humanoid, figure_measures(figure, stature), stature / 100.0)


def vertex_normals(points: np.ndarray, faces: np.ndarray) -> np.ndarray:
    a, b, c = (points[faces[:, i]] for i in range(3))
    face = np.cross(b - a, c - a)
    normals = np.zeros_like(points)
    for i in range(3):
        np.add.at(normals, faces[:, i], face)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    result: np.ndarray = normals / np.where(length > 0, length, 1.0)
    return result
