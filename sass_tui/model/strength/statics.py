"""The statics of a standing task: the forces on the body (each segment's
weight, what the objects push back on the hands), the floor's force under
each foot, and whether the body is in balance over its feet
(docs/task.md "Balance").

The floor's resultant force balances every other force; its point on the
floor (the centre of pressure) is where its moment balances theirs, with a
free moment about the vertical for the rest (Chaffin, Andersson & Martin
2006, ch. 6).  Between two feet the force is split by the lever rule
across the body (the share of each foot from how far the centre of pressure
lies from each foot's midline), each foot's share acting at the centre of
pressure's place front to back: statically determinate, so quiet standing
carries nothing sideways at the legs.  Only a foot on the floor bears
(PosedBody.bearing, model/body/posture.py): standing on one foot, that foot
carries the whole force and the raised one none.  The body is in balance
when the centre of pressure lies inside the base of support (the convex
hull of the soles' corners on the floor) and the floor pushes up; otherwise
it would tip, and the task is said to, not scored.

No Textual import here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.posture import ON_FLOOR_M, PosedBody

GRAVITY = 9.81
DOWN = np.array([0.0, -1.0, 0.0])
UP = -DOWN

Vector = npt.NDArray[np.float64]
# (where it acts, the force), HAnim axes, m and N
Force = tuple[Vector, Vector]


def weights(body: PosedBody, segments: list[str] | None = None) -> list[Force]:
    """Each segment's weight at its centre of mass."""
    names = list(body.masses) if segments is None else segments
    return [(body.centers_of_mass[s], body.masses[s] * GRAVITY * DOWN) for s in names]


def moment_about(point: Vector, forces: list[Force]) -> Vector:
    if not forces:
        return np.zeros(3)
    r = np.array([where for where, _ in forces]) - point
    f = np.array([force for _, force in forces])
    # r x f, row by row, summed
    total: Vector = np.array(
        [
            float((r[:, 1] * f[:, 2] - r[:, 2] * f[:, 1]).sum()),
            float((r[:, 2] * f[:, 0] - r[:, 0] * f[:, 2]).sum()),
            float((r[:, 0] * f[:, 1] - r[:, 1] * f[:, 0]).sum()),
        ]
    )
    return total


@dataclass(frozen=True)
class Balance:
    """The floor's forces and whether the body stands over its feet."""

    stable: bool
    reason: str  # why not, or "" when stable
    center_of_mass: Vector  # m
    center_of_pressure: Vector  # m, on the floor
    feet: dict[str, Force]  # side -> (centre of pressure, the floor's force on it)
    free_moment: float  # N-m about the vertical, both feet together
    margin: float  # m from the centre of pressure to the base's edge (< 0: outside)
    bearing: tuple[str, ...] = ("left", "right")  # the feet on the floor


def _hull(points: Vector) -> Vector:
    """The convex hull (x, z) of points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted({(round(float(x), 9), round(float(z), 9)) for x, z in points})

    def cross(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[tuple[float, float]] = []
    upper: list[tuple[float, float]] = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def inside_margin(hull: Vector, point: Vector) -> float:
    """The distance (m) from `point` (x, z) to the hull's nearest edge,
    positive inside, negative outside."""
    n = len(hull)
    inside = True
    nearest = np.inf
    for i in range(n):
        a, b = hull[i], hull[(i + 1) % n]
        edge = b - a
        t = float(np.clip(np.dot(point - a, edge) / np.dot(edge, edge), 0.0, 1.0))
        nearest = min(nearest, float(np.linalg.norm(point - (a + t * edge))))
        if edge[0] * (point[1] - a[1]) - edge[1] * (point[0] - a[0]) < 0:
            inside = False
    return nearest if inside else -nearest


def balance(body: PosedBody, hands: list[Force]) -> Balance:
    """The floor's force under each foot for the body's weight and the
    forces on its hands (what the objects push back), and whether it stands."""
    forces = weights(body) + hands
    total = np.sum([f for _, f in forces], axis=0)
    moment = moment_about(np.zeros(3), forces)
    ground = -total
    com = body.center_of_mass()
    # the sole the body stands on is level on the floor; a raised foot's
    # corner reaching down to it (or past it) bears too
    floor = max(float(body.soles[side][:, 1].min()) for side in body.bearing)
    touching = {
        side: body.soles[side][body.soles[side][:, 1] <= floor + ON_FLOOR_M][:, [0, 2]]
        for side in body.bearing
    }
    hull = _hull(np.vstack(list(touching.values())))
    if ground[1] <= 0:
        return Balance(
            False,
            "the hands lift the body off the floor",
            com,
            np.array([com[0], floor, com[2]]),
            {},
            0.0,
            -np.inf,
            body.bearing,
        )
    # the floor's resultant at (px, floor, pz): its moment about the origin
    # balances the rest (the vertical part is a free moment)
    # r x G with r = (px, floor, pz): x = floor*Gz - pz*Gy, z = px*Gy - floor*Gx
    pz = (moment[0] + floor * ground[2]) / ground[1]
    px = (-moment[2] + floor * ground[0]) / ground[1]
    cop = np.array([px, floor, pz])
    free = float(-moment[1] - (pz * ground[0] - px * ground[2]))
    margin = inside_margin(hull, np.array([px, pz]))
    feet = _split(touching, cop, ground)
    reason = ""
    if margin < 0:
        way = (
            "forward" if pz > hull[:, 1].max() else "back" if pz < hull[:, 1].min() else "sideways"
        )
        reason = (
            f"the centre of pressure falls {-margin * 100:.1f} cm outside the feet "
            f"({way}): the body would tip"
        )
    return Balance(margin >= 0, reason, com, cop, feet, free, margin, body.bearing)


def _split(touching: dict[str, Vector], cop: Vector, ground: Vector) -> dict[str, Force]:
    """The lever rule between the feet: each foot's share of the floor's
    force from where the centre of pressure lies along the line joining the
    feet's contacts (the middle of each sole's corners on the floor), each
    share acting at its contact moved across that line to the centre of
    pressure.  Feet side by side: each foot's midline at the centre of
    pressure's front-back place."""
    contact = {side: corners.mean(axis=0) for side, corners in touching.items()}
    if len(contact) == 1:
        (side,) = contact
        return _on_one_foot(side, cop, ground)
    point = cop[[0, 2]]
    joining = contact["left"] - contact["right"]
    share = float((point - contact["right"]) @ joining / (joining @ joining))
    if 0.0 < share < 1.0:
        across = point - (contact["right"] + share * joining)
        return {
            side: (np.array([at[0] + across[0], cop[1], at[1] + across[1]]), part * ground)
            for side, at, part in (
                ("left", contact["left"], share),
                ("right", contact["right"], 1.0 - share),
            )
        }
    return _on_one_foot("left" if share >= 1.0 else "right", cop, ground)


def _on_one_foot(side: str, cop: Vector, ground: Vector) -> dict[str, Force]:
    """All the floor's force on one foot, at the centre of pressure."""
    other = "right" if side == "left" else "left"
    return {side: (cop.copy(), ground.copy()), other: (cop.copy(), np.zeros(3))}
