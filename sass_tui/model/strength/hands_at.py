"""A standing posture found from where the hands must be: the grasp at H
ahead of the ankles and V above the floor (the NIOSH manual's H and V,
model/strength/hand_position.py), reached by a stoop, as 3DSSPP predicts
a posture from the hands' place (Chaffin, Andersson & Martin 2006, ch. 6).
The angles found are the figure's own: a short woman and a tall man reach
one box with different postures.

A stoop: the legs straight, the pelvis and trunk tip forward at the hips
(hip_y on both sides), the arms swing at the shoulders (shoulder_y).  A
squat is posed by its angles (knee_y, hip_y, ankle_y): with both the knees
and the hips free, the hands' place alone does not say how far each bends,
and the ankles' range in the report's joint limits (about 14 degrees of
dorsiflexion) leaves a squat balanced only with the trunk far forward.

The body still leans at the ankles for balance as every standing task does
(model/strength/task.py pose_task); every other angle the user gives (the
trunk's, the elbows', the wrists', the neck's) is kept.  The two unknowns
are found by Newton's method on the figure's own linkage (a finite-difference
Jacobian, Broyden updates), each angle held within the figure's joint limits,
from up to three starting postures: a local search, so a place it does not
reach is refused naming the nearest place it found, which a stoop does
reach (tests/model/test_hands_at.py).

No Textual import here.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.body.posture import Angles, PosedBody, parse_angles
from sass_tui.model.errors import SassError
from sass_tui.model.strength.hand_position import grasp
from sass_tui.model.strength.strength_conditions import joint_limit_range
from sass_tui.model.strength.task import HandLoad, PostureOf, TaskError, pose_task
from sass_tui.model.units import parse_quantity

SIDES = ("left", "right")
HANDS_WORD = "hands="  # the posture word of a place the hands reach: hands=40cm,30cm
# the angles a stoop solves (on both sides): the user leaves them out
SOLVED_AXES = ("hip_y", "shoulder_y")
REACHED_M = 0.002  # the grasp within 2 mm of its place
STEP_DEG = 1.0  # the finite-difference step of the Jacobian
MAX_EVALUATIONS = 40
# hip_y, shoulder_y where Newton's method starts; the next where one fails
STARTS_DEG = ((30.0, 30.0), (0.0, 60.0), (90.0, 100.0))
MAX_STEP_DEG = 20.0


@dataclass(frozen=True)
class HandsAt:
    """Where the grasp must be (m), reached by a stoop."""

    h: float  # ahead of the ankles' midpoint, on the floor
    v: float  # above the floor

    def words(self) -> str:
        return f"H {self.h * 100:.1f} cm, V {self.v * 100:.1f} cm by a stoop"


def parse_hands_at(text: str) -> HandsAt:
    """'40cm,30cm', '16 in, 12 in', '40,30' (cm without a unit) -> HandsAt."""
    said = f"{HANDS_WORD}{text.strip()}"
    parts = text.split(",")
    if len(parts) != 2:
        raise TaskError(
            f"{said}: expected H,V (the grasp ahead of the ankles and above the floor), "
            "e.g. 40cm,30cm"
        )
    try:
        h, v = (parse_quantity(part.strip(), "cm") / 100.0 for part in parts)
    except SassError as exc:
        raise TaskError(f"{said}: {exc}") from None
    if not (0.0 <= h <= 2.0 and 0.0 <= v <= 3.0):
        raise TaskError(f"{said}: H from 0 to 200 cm and V from 0 to 300 cm expected")
    return HandsAt(h, v)


def split_posture(words: Sequence[str], seated: bool = False) -> tuple[Angles, HandsAt | None]:
    """A posture's words (the Task panel's posture cell): JOINT=ANGLE ... and
    at most one `hands=H,V`, the place a stoop reaches (`sass task`'s too)."""
    goals = [word for word in words if word.lower().startswith(HANDS_WORD)]
    if len(goals) > 1:
        raise TaskError(f"one {HANDS_WORD}H,V in a posture, not {len(goals)}")
    angles = parse_angles([word for word in words if word not in goals])
    if not goals:
        return angles, None
    goal = parse_hands_at(goals[0][len(HANDS_WORD) :])
    check_free(goal, angles, seated)
    return angles, goal


def posture_of(angles: Angles, goal: HandsAt | None, loads: list[HandLoad]) -> PostureOf:
    """A posture as a task takes it (split_posture's parts): its angles, or
    with a place for the hands each figure's own stoop."""
    if goal is None:
        return angles
    return partial(solve_hands_at, goal=goal, angles=angles, loads=loads)


def check_free(goal: HandsAt, angles: Angles, seated: bool) -> None:
    """Refuse what the goal cannot be combined with: a seated figure, or an
    angle the goal solves given too."""
    if seated:
        raise TaskError(f"{HANDS_WORD}H,V stands the figure in a stoop: not with --seated")
    given = sorted({axis for _, axis in angles if axis in SOLVED_AXES})
    if given:
        raise TaskError(
            f"{HANDS_WORD}H,V solves {' and '.join(SOLVED_AXES)} for a stoop; "
            f"leave out {', '.join(given)}"
        )


def _range(figure: Figure, axis: str) -> tuple[float, float]:
    """The angles both sides allow."""
    lows, highs = zip(*(joint_limit_range(figure, side, axis) for side in SIDES), strict=True)
    return max(lows), min(highs)


def _both(axis: str, degrees: float) -> Angles:
    return {(side, axis): float(degrees) for side in SIDES}


def _reach_of(body: PosedBody) -> npt.NDArray[np.float64]:
    """(forward distance, height) of the grasp, forward from the ankles' midpoint."""
    x, y, z = grasp(body.points)
    ankles = (body.centers["l_talocrural"] + body.centers["r_talocrural"]) / 2.0
    ahead = float(np.hypot(x - ankles[0], z - ankles[2]))
    return np.array([ahead if z >= ankles[2] else -ahead, y])


def solve_hands_at(figure: Figure, goal: HandsAt, angles: Angles, loads: list[HandLoad]) -> Angles:
    """The user's angles with those the goal solves (module docstring)."""
    check_free(goal, angles, seated=False)
    humanoid = build_humanoid(figure)
    (hip_low, hip_high), (shoulder_low, shoulder_high) = (_range(figure, a) for a in SOLVED_AXES)
    low = np.array([hip_low, shoulder_low])
    high = np.array([hip_high, shoulder_high])
    target = np.array([goal.h, goal.v])

    def posed(u: npt.NDArray[np.float64]) -> tuple[Angles, npt.NDArray[np.float64]]:
        solved = {**angles, **_both("hip_y", u[0]), **_both("shoulder_y", u[1])}
        body, *_ = pose_task(figure, solved, loads, humanoid=humanoid)
        return solved, _reach_of(body) - target

    best: tuple[float, npt.NDArray[np.float64], Angles] | None = None
    for start in STARTS_DEG:
        found = _newton(posed, np.clip(np.array(start), low, high), low, high)
        if best is None or found[0] < best[0]:
            best = found
        if best[0] <= REACHED_M:
            return best[2]
    assert best is not None
    reached = best[1] + target
    raise TaskError(
        f"the hands cannot reach {goal.words()} for the {figure.gender} figure: the "
        f"nearest is H {reached[0] * 100:.1f} cm, V {reached[1] * 100:.1f} cm ("
        f"{_hint(goal, reached)})"
    )


def _hint(goal: HandsAt, reached: npt.NDArray[np.float64]) -> str:
    """What might reach the place, from where it lies against the nearest one."""
    hints = []
    if goal.h < reached[0] - 0.01:
        hints.append("bend the elbows, elbow_y, for a place nearer the body")
    if goal.v < reached[1] - 0.01:
        hints.append("pose a squat by its angles, knee_y and hip_y, for one lower")
    return "; ".join(hints) or "beyond the arms' reach from a stoop"


Residual = tuple[Angles, npt.NDArray[np.float64]]


def _newton(
    posed: Callable[[npt.NDArray[np.float64]], Residual],
    u: npt.NDArray[np.float64],
    low: npt.NDArray[np.float64],
    high: npt.NDArray[np.float64],
) -> tuple[float, npt.NDArray[np.float64], Angles]:
    """Newton's method from `u` within [low, high]: (the grasp's distance from
    its place, the residual, the angles) at the best point found.  An angle
    held at its limit that the step would push further stays there, and the
    other alone moves (least squares on its column of the Jacobian)."""
    best_angles, r = posed(u)
    best = (float(np.linalg.norm(r)), u, r)
    evaluations = 1
    jacobian: npt.NDArray[np.float64] | None = None
    while best[0] > REACHED_M and evaluations < MAX_EVALUATIONS:
        if jacobian is None:
            jacobian = np.empty((2, 2))
            for k in range(2):
                nudge = np.zeros(2)
                nudge[k] = STEP_DEG if u[k] + STEP_DEG <= high[k] else -STEP_DEG
                jacobian[:, k] = (posed(u + nudge)[1] - r) / nudge[k]
                evaluations += 1
        step = _step(jacobian, r, u, low, high)
        u_next = np.clip(u + step, low, high)
        moved = u_next - u
        if not np.any(np.abs(moved) > 1e-9):
            break  # held at the limits: the nearest reach from here
        solved, r_next = posed(u_next)
        evaluations += 1
        # Broyden's update of the Jacobian for the step taken
        jacobian = jacobian + np.outer(r_next - r - jacobian @ moved, moved) / (moved @ moved)
        u, r = u_next, r_next
        size = float(np.linalg.norm(r))
        if size < best[0]:
            best, best_angles = (size, u, r), solved
        elif size > 2 * best[0]:
            jacobian = None  # a poor secant: a fresh finite difference from the best
            u, r = best[1], best[2]
    return best[0], best[2], best_angles


def _step(
    jacobian: npt.NDArray[np.float64],
    r: npt.NDArray[np.float64],
    u: npt.NDArray[np.float64],
    low: npt.NDArray[np.float64],
    high: npt.NDArray[np.float64],
) -> npt.NDArray[np.float64]:
    """The Newton step, the angles at a limit it pushes against held, at most
    MAX_STEP_DEG."""
    free = np.ones(2, dtype=bool)
    step = np.zeros(2)
    for _ in range(2):
        step = np.zeros(2)
        if free.any():
            solved, *_ = np.linalg.lstsq(jacobian[:, free], -r, rcond=None)
            step[free] = solved
        pushing = ((u <= low) & (step < 0)) | ((u >= high) & (step > 0))
        if not (pushing & free).any():
            break
        free &= ~pushing
    # the linkage is far from linear over more than MAX_STEP_DEG
    largest = float(np.abs(step).max())
    return step * min(1.0, MAX_STEP_DEG / largest) if largest > 0 else step


def solved_angles(angles: Angles) -> dict[str, float]:
    """The angles a stoop solved (both sides alike), axis -> degrees."""
    return {axis: angles[("left", axis)] for axis in SOLVED_AXES}


def hands_at_note(goal: HandsAt, postures: dict[str, Angles]) -> str:
    """'hands at H 40.0 cm, V 30.0 cm by a stoop: women hip_y=113.2 ...; men ...'."""
    each = "; ".join(
        f"{who} " + " ".join(f"{axis}={deg:.1f}" for axis, deg in solved_angles(angles).items())
        for who, angles in postures.items()
    )
    return f"hands at {goal.words()} (the grasp, from the ankles' midpoint): {each}"


def hands_at_json(goal: HandsAt, postures: dict[str, Angles]) -> dict[str, object]:
    """{"h", "v": {"value", "unit"}, "by": "stoop", "solved": {who: {axis: deg}}}."""
    return {
        "h": {"value": round(goal.h * 100, 1), "unit": "cm"},
        "v": {"value": round(goal.v * 100, 1), "unit": "cm"},
        "by": "stoop",
        "solved": {
            who: {axis: round(deg, 1) for axis, deg in solved_angles(angles).items()}
            for who, angles in postures.items()
        },
    }
