"""A standing posture found from where the hands must be: the grasp at H
ahead of the ankles and V above the floor (the NIOSH manual's H and V,
model/strength/hand_position.py), reached by a stoop, as 3DSSPP predicts
a posture from the hands' place (Chaffin, Andersson & Martin 2006, ch. 6).
The angles found are the figure's own: a short woman and a tall man reach
one box with different postures.

A stoop: the legs straight, the pelvis and trunk tip forward at the hips
(hip_y on both sides), the arms swing at the shoulders (shoulder_y).  A
squat (`hands=H,V,squat`) bends the knees too (knee_y on both sides): the
hands' place alone does not say how far the knees and the hips each bend,
so the squat keeps the trunk as upright as balance lets it, the knees bent
as far as the body still balances as in quiet standing (the lean at the
ankles that puts the floor's centre of pressure 5 cm ahead of them within
the ankles' range, model/strength/task.py pose_task).  The report's ankle
range (about 14 degrees of dorsiflexion) is what stops the knees: past it
the body would have to sit back off its feet.  The knee angle is searched
on a grid of SQUAT_GRID_DEG from straight and then halved SQUAT_HALVINGS
times between the deepest that balances and the next.

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

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import Humanoid, build_humanoid
from sass_tui.model.body.posture import Angles, PosedBody, parse_angles, pose_figure
from sass_tui.model.errors import SassError
from sass_tui.model.strength.hand_position import grasp
from sass_tui.model.strength.statics import balance
from sass_tui.model.strength.strength_conditions import joint_limit_range
from sass_tui.model.strength.task import (
    QUIET_STANCE_COP_M,
    HandLoad,
    PostureOf,
    TaskError,
    cop_ahead,
    hand_forces,
    pose_task,
)
from sass_tui.model.units import parse_quantity

SIDES = ("left", "right")
HANDS_WORD = "hands="  # the posture word of a place the hands reach: hands=40cm,30cm
# the angles a stoop solves (on both sides): the user leaves them out
SOLVED_AXES = ("hip_y", "shoulder_y")
REACHED_M = 0.002  # the grasp within 2 mm of its place
STOOP, SQUAT = "stoop", "squat"
# the angles a squat solves (on both sides), and where Newton's method starts
SQUAT_AXES = ("hip_y", "shoulder_y", "knee_y")
SQUAT_STARTS_DEG = ((60.0, 60.0, 60.0), (90.0, 90.0, 90.0), (30.0, 30.0, 30.0))
# a squat's ankles: this far short of their dorsiflexion limit (heels down)
SQUAT_ANKLE_DEG = 1.0
STEP_DEG = 1.0  # the finite-difference step of the Jacobian
MAX_EVALUATIONS = 40
# hip_y, shoulder_y where Newton's method starts; the next where one fails
STARTS_DEG = ((30.0, 30.0), (0.0, 60.0), (90.0, 100.0))
MAX_STEP_DEG = 20.0
HELD_DEG = 0.01  # an angle this near its limit is held there
# A squat whose knees end this near straight is a stoop in all but name.
STRAIGHT_KNEES_DEG = 10.0
STOOPING_WORDS = (
    f"knees within {STRAIGHT_KNEES_DEG:g} deg of straight: in effect a stoop; a deeper squat "
    "needs the hips past their flexion limit or the heels up, which sass does not model"
)


@dataclass(frozen=True)
class HandsAt:
    """Where the grasp must be (m), reached by a stoop or a squat."""

    h: float  # ahead of the ankles' midpoint, on the floor
    v: float  # above the floor
    by: str = STOOP

    def words(self) -> str:
        return f"H {self.h * 100:.1f} cm, V {self.v * 100:.1f} cm by a {self.by}"

    @property
    def solved_axes(self) -> tuple[str, ...]:
        """The angles the stoop or the squat finds (on both sides)."""
        return SOLVED_AXES + (("knee_y", "ankle_y") if self.by == SQUAT else ())


def parse_hands_at(text: str) -> HandsAt:
    """'40cm,30cm', '16 in, 12 in', '40,30' (cm without a unit), '40cm,30cm,squat'
    -> HandsAt."""
    said = f"{HANDS_WORD}{text.strip()}"
    parts = text.split(",")
    by = STOOP
    if len(parts) == 3 and parts[2].strip().lower() in (STOOP, SQUAT):
        by = parts.pop().strip().lower()
    if len(parts) != 2:
        raise TaskError(
            f"{said}: expected H,V (the grasp ahead of the ankles and above the floor), "
            f"e.g. 40cm,30cm, and {SQUAT} after them for a squat (40cm,30cm,{SQUAT})"
        )
    try:
        h, v = (parse_quantity(part.strip(), "cm") / 100.0 for part in parts)
    except SassError as exc:
        raise TaskError(f"{said}: {exc}") from None
    if not (0.0 <= h <= 2.0 and 0.0 <= v <= 3.0):
        raise TaskError(f"{said}: H from 0 to 200 cm and V from 0 to 300 cm expected")
    return HandsAt(h, v, by)


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


@dataclass(frozen=True)
class Reaching:
    """The posture of each figure whose hands reach `goal`, the other angles
    as given (task.py's PostureSolver)."""

    goal: HandsAt
    angles: Angles
    loads: tuple[HandLoad, ...]

    @property
    def solved_axes(self) -> tuple[str, ...]:
        return self.goal.solved_axes

    def __call__(self, figure: Figure) -> Angles:
        return solve_hands_at(figure, self.goal, self.angles, list(self.loads))


def posture_of(angles: Angles, goal: HandsAt | None, loads: list[HandLoad]) -> PostureOf:
    """A posture as a task takes it (split_posture's parts): its angles, or
    with a place for the hands each figure's own stoop or squat."""
    if goal is None:
        return angles
    return Reaching(goal, angles, tuple(loads))


def check_free(goal: HandsAt, angles: Angles, seated: bool) -> None:
    """Refuse what the goal cannot be combined with: a seated figure, or an
    angle the goal solves given too."""
    if seated:
        raise TaskError(f"{HANDS_WORD}H,V stands the figure in a {goal.by}: not with --seated")
    solved = goal.solved_axes
    given = sorted({axis for _, axis in angles if axis in solved})
    if given:
        raise TaskError(
            f"{HANDS_WORD}H,V solves {', '.join(solved)} for a {goal.by}; "
            f"leave out {', '.join(given)}"
        )


def _range(figure: Figure, axis: str) -> tuple[float, float]:
    """The angles both sides allow."""
    lows, highs = zip(*(joint_limit_range(figure, side, axis) for side in SIDES), strict=True)
    return max(lows), min(highs)


def _both(axis: str, degrees: float) -> Angles:
    return _each((axis,), (degrees,))


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
    if goal.by == SQUAT:
        return _squat(figure, goal, angles, loads, humanoid)
    best = _stoop(figure, goal, angles, loads, humanoid, STARTS_DEG)
    if best[0] <= REACHED_M:
        return best[2]
    raise _unreached(figure, goal, best[1])


Found = tuple[float, npt.NDArray[np.float64], Angles]  # distance, residual, angles


def _squat(
    figure: Figure, goal: HandsAt, angles: Angles, loads: list[HandLoad], humanoid: Humanoid
) -> Angles:
    """The hips, shoulders and knees that bring the grasp to its place with
    the ankles SQUAT_ANKLE_DEG short of their dorsiflexion limit and the
    floor's centre of pressure where quiet standing holds it: the knees bent
    as far as that balance allows (module docstring).  Where even straight
    knees lean less than that, the stoop.  A place above where the hands
    hang standing is refused: the squat would hold the arms up."""
    # a squat lowers the hands: not to a place above where they hang standing
    hanging = _reach_of(pose_task(figure, angles, loads, humanoid=humanoid)[0])[1]
    if goal.v > hanging:
        raise TaskError(
            f"a squat lowers the hands, and {goal.words()} is above where the "
            f"{figure.gender} figure's hands hang standing (V {hanging * 100:.1f} cm): "
            f"a stoop, {HANDS_WORD}H,V, reaches it"
        )
    ankle_low, ankle_high = _range(figure, "ankle_y")
    ankle = ankle_high - SQUAT_ANKLE_DEG
    at_ankles = {**angles, **_both("ankle_y", ankle)}
    target = np.array([goal.h, goal.v, QUIET_STANCE_COP_M])

    def posed(u: npt.NDArray[np.float64]) -> tuple[Angles, npt.NDArray[np.float64]]:
        solved = {**at_ankles, **_each(SQUAT_AXES, u)}
        body = pose_figure(figure, solved, humanoid=humanoid)
        stance = balance(body, hand_forces(body, loads))
        return solved, np.append(_reach_of(body), cop_ahead(stance, body)) - target

    hip_limit = _range(figure, "hip_y")[1]

    def hips_at_limit(found: Found) -> bool:
        # a start that ends with the hips held at their flexion limit wants
        # them further: every start did so (e.g. the 50th-percentile woman
        # at H 40 cm, V 30 cm), so the fallbacks below are tried at once
        return found[2][("left", "hip_y")] >= hip_limit - HELD_DEG

    best = _from_starts(figure, SQUAT_AXES, posed, SQUAT_STARTS_DEG, give_up=hips_at_limit)
    if best[0] <= REACHED_M:
        return best[2]
    # No such squat within the joints' limits: the hips at their flexion
    # limit, the knees bent as far as the hands' place then asks, or else
    # the knees straight (a place high enough for a stoop); the body leaning
    # at the ankles as it stands, within the ankles' range
    reached = {axis: best[2][("left", axis)] for axis in SQUAT_AXES}
    held_ways = (
        ({**angles, **_both("hip_y", hip_limit)}, ("shoulder_y", "knee_y")),
        ({**angles, **_both("knee_y", 0.0)}, SOLVED_AXES),
    )
    # the hands' place alone, of the three unknowns' nearest
    nearest: Found = (float(np.linalg.norm(best[1][:2])), best[1][:2], best[2])
    for held, free in held_ways:
        starts = [[reached[axis] for axis in free], STARTS_DEG[0]]
        found = _stoop(figure, goal, held, loads, humanoid, starts, free)
        if found[0] > REACHED_M:
            nearest = min(nearest, found, key=lambda f: f[0])
            continue
        lean = pose_task(figure, found[2], loads, humanoid=humanoid)[3]
        if lean is not None and ankle_low < lean < ankle_high:
            return {**found[2], **_both("ankle_y", lean)}
        nearest = found
    if nearest[0] > REACHED_M:
        raise _unreached(figure, goal, nearest[1])
    # reached with the ankles at the end of their range: in balance, if not
    # as in quiet standing, it stands; otherwise it would tip
    _, stance, _, lean = pose_task(figure, nearest[2], loads, humanoid=humanoid)
    if stance is not None and stance.stable:
        # the ankles' angle among those found, whichever way it was set
        return {**nearest[2], **({} if lean is None else _both("ankle_y", lean))}
    raise TaskError(
        f"the hands reach {goal.words()} for the {figure.gender} figure only with the "
        "body leaning past the ankles' range: out of balance"
    )


def _unreached(figure: Figure, goal: HandsAt, residual: npt.NDArray[np.float64]) -> TaskError:
    reached = residual + np.array([goal.h, goal.v])
    return TaskError(
        f"the hands cannot reach {goal.words()} for the {figure.gender} figure: the "
        f"nearest is H {reached[0] * 100:.1f} cm, V {reached[1] * 100:.1f} cm ("
        f"{_hint(goal, reached)})"
    )


def _stoop(
    figure: Figure,
    goal: HandsAt,
    angles: Angles,
    loads: list[HandLoad],
    humanoid: Humanoid,
    starts: Sequence[Sequence[float]],
    axes: Sequence[str] = SOLVED_AXES,
) -> Found:
    """The angles of `axes` (hip_y and shoulder_y) that bring the grasp
    nearest its place, the other angles as given and the body leaning at the
    ankles for balance: Newton's method from each start in turn until one
    reaches."""
    target = np.array([goal.h, goal.v])

    def posed(u: npt.NDArray[np.float64]) -> tuple[Angles, npt.NDArray[np.float64]]:
        solved = {**angles, **_each(axes, u)}
        body, *_ = pose_task(figure, solved, loads, humanoid=humanoid)
        return solved, _reach_of(body) - target

    return _from_starts(figure, axes, posed, starts)


def _from_starts(
    figure: Figure,
    axes: Sequence[str],
    posed: Callable[[npt.NDArray[np.float64]], Residual],
    starts: Sequence[Sequence[float]],
    give_up: Callable[[Found], bool] | None = None,
) -> Found:
    """Newton's method on `axes`, within the figure's joint limits, from each
    start in turn until one reaches, or one that does not meets `give_up`:
    the nearest found."""
    ranges = [_range(figure, axis) for axis in axes]
    low = np.array([r[0] for r in ranges])
    high = np.array([r[1] for r in ranges])
    best: Found | None = None
    for start in starts:
        found = _newton(posed, np.clip(np.array(start), low, high), low, high)
        if best is None or found[0] < best[0]:
            best = found
        if best[0] <= REACHED_M or (give_up is not None and give_up(found)):
            break
    assert best is not None
    return best


def _each(axes: Sequence[str], degrees: Iterable[float]) -> Angles:
    """Both sides of each axis at its angle."""
    return {(side, axis): float(d) for axis, d in zip(axes, degrees) for side in SIDES}


def _hint(goal: HandsAt, reached: npt.NDArray[np.float64]) -> str:
    """What might reach the place, from where it lies against the nearest one."""
    hints = []
    if goal.h < reached[0] - 0.01:
        hints.append("bend the elbows, elbow_y, for a place nearer the body")
    if goal.v < reached[1] - 0.01 and goal.by == STOOP:
        hints.append(f"a squat, {HANDS_WORD}H,V,{SQUAT}, for one lower")
    return "; ".join(hints) or f"beyond the arms' reach from a {goal.by}"


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
            jacobian = np.empty((len(r), len(u)))
            for k in range(len(u)):
                nudge = np.zeros(len(u))
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
    free = np.ones(len(u), dtype=bool)
    step = np.zeros(len(u))
    for _ in range(len(u)):
        step = np.zeros(len(u))
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


def solved_angles(axes: Sequence[str], angles: Angles) -> dict[str, float]:
    """The angles a stoop or a squat solved (both sides alike), axis -> degrees."""
    return {axis: angles[("left", axis)] for axis in axes}


def stooping(solved_axes: Sequence[str], postures: dict[str, Angles]) -> list[str]:
    """Who was asked to squat (the knees among the solved axes) but stoops:
    the knees within STRAIGHT_KNEES_DEG of straight, where no squat with the
    heels down reaches the place within the joints' limits and the fallback
    folds the hips to their limit."""
    if "knee_y" not in solved_axes:
        return []
    return [who for who, a in postures.items() if a[("left", "knee_y")] < STRAIGHT_KNEES_DEG]


def postures_words(
    solved_axes: Sequence[str], postures: dict[str, Angles], between: str = "="
) -> str:
    """'women hip_y=113.2 shoulder_y=60.1; men ...': each figure's solved
    angles (`between` axis and degrees), and the words of one that stoops."""
    stooped = stooping(solved_axes, postures)
    return "; ".join(
        f"{who} "
        + " ".join(
            f"{axis}{between}{deg:.1f}" for axis, deg in solved_angles(solved_axes, angles).items()
        )
        + (f" ({STOOPING_WORDS})" if who in stooped else "")
        for who, angles in postures.items()
    )


def hands_at_note(goal: HandsAt, postures: dict[str, Angles]) -> str:
    """'hands at H 40.0 cm, V 30.0 cm by a stoop: women hip_y=113.2 ...; men ...'."""
    each = postures_words(goal.solved_axes, postures)
    return f"hands at {goal.words()} (the grasp, from the ankles' midpoint): {each}"


def hands_at_json(goal: HandsAt, postures: dict[str, Angles]) -> dict[str, object]:
    """{"h", "v": {"value", "unit"}, "by": "stoop"|"squat", "stooping": [who],
    "solved": {who: {axis: deg}}}."""
    return {
        "h": {"value": round(goal.h * 100, 1), "unit": "cm"},
        "v": {"value": round(goal.v * 100, 1), "unit": "cm"},
        "by": goal.by,
        "stooping": stooping(goal.solved_axes, postures),
        "solved": {
            who: {
                axis: round(deg, 1) for axis, deg in solved_angles(goal.solved_axes, angles).items()
            }
            for who, angles in postures.items()
        },
    }
