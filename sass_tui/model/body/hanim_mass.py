"""The HAnim humanoid's segments (model/body/hanim.py builds the skeleton): each
segment's mass and centre of mass (de Leva 1996), its moments of inertia
(homogeneous solids of its size) and the solids it is drawn with.
docs/hanim.md describes what these give; the comments say why.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from sass_tui.model.body.appendix_l import HEEL_BEHIND_ANKLE
from sass_tui.model.names import CENTER_OF_MASS, ROWS

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure

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


# (box|ellipsoid, centre, full size along X, Y, Z)
Shape = tuple[str, np.ndarray, np.ndarray]


@dataclass
class Segment:
    name: str
    mass: float  # kg
    center_of_mass: np.ndarray  # m, humanoid coordinates
    inertia: np.ndarray  # 3x3 kg m^2 about the centre of mass
    shapes: list[Shape] = field(default_factory=list)


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


def build_segments(
    figure: Figure,
    dim: dict[str, np.ndarray],
    centers: dict[str, np.ndarray],
    heights: dict[str, float],
    population_lengths: np.ndarray,
) -> dict[str, Segment]:
    """The humanoid's segments around its joint `centers`; `population_lengths`
    (m) are the population's segment lengths at the figure's girth percentile,
    which a centre of mass taken from the population goes with."""
    shares = segment_mass_fractions(figure.gender)
    com_rows = {row.name: i for i, row in enumerate(ROWS[CENTER_OF_MASS])}
    com_values, com_filled = figure.output_values(CENTER_OF_MASS)
    com_values = np.asarray(com_values, dtype=float) / 100.0
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
