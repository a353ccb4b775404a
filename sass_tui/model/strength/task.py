"""A task: a posture, the forces the hands exert and who is to do it.  The
static moments at the joints from the figure's own segment masses and
centres of mass (model/body/posture.py on the HAnim humanoid), the floor's
force under each foot, the low back and the balance (model/strength/statics.py,
model/strength/low_back.py), and the percent capable where a published model
covers the joint (docs/task.md):

- each hand that exerts a force: the Arm Force Field (La Delfa & Potvin
  2017) for that force, gravity included;
- hip, knee and ankle: Anderson et al. 2007 for the motion that resists the
  moment (extension against a moment tipping the body forward), at the
  posture's angle; a joint at the end of its range carrying a moment that
  turns it further (a straight knee under the body's weight) carries it
  passively (ligaments, bone on bone): reported passive, never limiting.

One convention: a force is what the hand exerts on the object (a box lifted:
the hand exerts its weight up); the object pushes back on the hand with the
opposite.  A load given as a mass is its weight, held up.

Standing, the body leans at the ankles, when the posture gives no ankle
angle, until the floor's centre of pressure lies where quiet standing holds
it, 5 cm ahead of the ankles (the ankle strategy; Winter 1995), as far as
the ankles' range allows; a posture that would still tip is said to and not
scored.  Seated, the seat carries the legs: no leg joint and no balance.

No Textual import here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Protocol

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import LOA1, Humanoid, build_humanoid
from sass_tui.model.body.posture import Angles, PosedBody, pose_figure
from sass_tui.model.errors import SassError
from sass_tui.model.strength.arm_force_field import (
    DIRECTIONS,
    ArmForce,
    ArmForceError,
    arm_force,
    check_direction,
    parse_direction,
)
from sass_tui.model.strength.low_back import LowBack, low_back
from sass_tui.model.strength.percent_capable import lower_limb_capable, normal_survival
from sass_tui.model.strength.published_strength import (
    AGE_GROUPS,
    MAX_AGE,
    MIN_AGE,
    Subject,
    age_group,
    beyond_curve,
    lower_limb_percent_capable,
)
from sass_tui.model.strength.published_strength import (
    CITATION as ANDERSON,
)
from sass_tui.model.strength.reba import Reba, reba
from sass_tui.model.strength.rula import Rula, rula
from sass_tui.model.strength.statics import (
    GRAVITY,
    Balance,
    Force,
    balance,
    moment_about,
    weights,
)
from sass_tui.model.strength.strength_conditions import joint_limit_range
from sass_tui.model.units import parse_quantity

# joint word -> (HAnim joint, Anderson et al. 2007's motions resisting a
# moment that tips the body above forward (+x) and one that tips it back),
# its axis, and which way a forward-tipping moment turns it (+1: the angle
# grows).  Tipping the trunk forward over the thighs flexes the hips; the
# thighs forward over the shanks extend the knees; the shanks forward over
# the feet dorsiflex the ankles.
LEG_JOINTS = {
    "hip": ("hip", ("hip_extension", "hip_flexion"), "hip_y", 1.0),
    "knee": ("knee", ("knee_flexion", "knee_extension"), "knee_y", -1.0),
    "ankle": ("talocrural", ("ankle_plantarflexion", "ankle_dorsiflexion"), "ankle_y", 1.0),
}
# A joint within this of the end of its range, turned further by its moment,
# carries the moment passively.
PASSIVE_MARGIN_DEG = 5.0
PASSIVE = "passive, at the end of its range"
# Quiet standing's centre of pressure ahead of the ankles (Winter 1995)
QUIET_STANCE_COP_M = 0.05
# a sole the posture puts deeper than this into the floor is said to be
INTO_FLOOR_M = 0.01
# a leg joint's moment outside the sagittal plane above this is said uncovered
OFF_PLANE_N_M = 5.0
# a loaded hand further behind L5/S1 than this is said to be (hanging arms
# stand about 2 cm behind it)
BEHIND_L5_M = 0.05
ARM_WORDS = "La Delfa & Potvin 2017 (Arm Force Field): women as published, men x 1.66"
UNCOVERED = "no published model in sass covers it"
LOW_BACK_WORDS = "single equivalent muscle (Chaffin, Andersson & Martin 2006)"
MASS_UNITS_WORDS = "a mass (kg, lb) is its weight, held up"


class TaskError(ArmForceError):
    """A task sass cannot assess (a load without a direction, a bad mass)."""


@dataclass(frozen=True)
class HandLoad:
    """The force one hand exerts on the object: `force` N along the unit
    `direction` (HAnim axes).  A 10 kg box held: 98.1 N up (`mass` 10)."""

    side: str
    force: float
    direction: npt.NDArray[np.float64]
    mass: float | None = None  # kg, when the load was given as a mass

    @property
    def vector(self) -> npt.NDArray[np.float64]:
        """The force the hand exerts on the object."""
        return self.force * self.direction

    @property
    def on_body(self) -> npt.NDArray[np.float64]:
        """What the object pushes back on the hand."""
        return -self.vector


def hand_load(
    side: str,
    force: float,
    direction: npt.ArrayLike,
    mass: float | None = None,
    name: str | None = None,
) -> HandLoad:
    """`name`: what the message calls the load (the command line's option)."""
    if not (math.isfinite(force) and force >= 0):
        said = name or f"the {side} hand's load"
        raise TaskError(f"{said} {force:g} N: expected a force of 0 or more")
    return HandLoad(
        side, float(force), check_direction(direction, f"the {side} hand's direction"), mass
    )


def load_of(
    side: str,
    text: str,
    direction: str | None = None,
    *,
    load_name: str | None = None,
    direction_name: str | None = None,
) -> HandLoad:
    """A hand's load from a quantity ('60 N', '15 lbf', '10 kg', '22 lb') and
    the direction the hand exerts it (default up: a weight held).  A mass is
    its weight held up: another direction is refused.  The names are what a
    message calls the two (the Task panel's cell by default; `sass task` names
    its options)."""
    load_name = load_name or f"the {side} hand's load"
    try:
        force = parse_quantity(text, "N")
        mass = None
    except SassError as as_force:
        try:
            mass = parse_quantity(text, "kg")
        except SassError:
            raise TaskError(f"{load_name} {text.strip()!r}: {as_force}") from None
        force = mass * GRAVITY
    if force < 0:  # said as typed, not as the force a mass converts to
        raise TaskError(f"{load_name} {text.strip()!r}: expected a force or a mass of 0 or more")
    if mass is not None and direction is not None and direction.strip().lower() != "up":
        raise TaskError(
            f"{load_name} {text.strip()!r} is a mass: the hand holds its weight up; "
            f"give a force (N, lbf) to exert it {direction.strip()}"
        )
    toward = parse_direction(direction or "up", direction_name or f"the {side} hand's direction")
    return hand_load(side, force, toward, mass, load_name)


def parse_hand_load(side: str, text: str) -> HandLoad:
    """'60 N forward', '60N', '15 lbf down', '10 kg', '40 N 0,-1,0.2': the
    force the hand exerts (N without a unit) or a mass held, then the
    direction the hand exerts it (default up: a weight held)."""
    words = text.split()
    if not words:
        raise TaskError(f"the {side} hand: expected a force and a direction, e.g. 60 N forward")
    direction = None
    if len(words) > 1 and (words[-1].lower() in DIRECTIONS or "," in words[-1]):
        direction = words.pop()
    return load_of(side, " ".join(words), direction)


@dataclass(frozen=True)
class JointMoment:
    """The external moment at one joint (N-m, HAnim axes, on the part of the
    body above or outward of it), the part the loads make, and what covers it."""

    joint: str  # "left elbow", "trunk (L5/S1)", ...
    moment: tuple[float, float, float]
    from_loads: tuple[float, float, float]
    covered_by: str

    @property
    def size(self) -> float:
        return float(np.linalg.norm(self.moment))


def _segments_below(joint: str) -> list[str]:
    joints = [joint]
    for child, _, parent in LOA1:
        if parent in joints:
            joints.append(child)
    return [segment for j, segment, _ in LOA1 if j in joints]


def hand_forces(body: PosedBody, loads: list[HandLoad]) -> list[Force]:
    """What the objects push back on the hands, at the grips (the third knuckle)."""
    return [(body.grip(load.side), load.on_body) for load in loads]


def task_moments(
    body: PosedBody, loads: list[HandLoad], stance: Balance | None = None
) -> list[JointMoment]:
    """The static moments of the posture and loads: the arms' from their
    segments outward and the hands' forces; the low back's from everything
    above it; each leg's from below, its segments and the floor's force
    under its foot (`stance`, standing)."""
    applied = {load.side: (body.grip(load.side), load.on_body) for load in loads}
    out = []

    def arm(name: str, point: npt.NDArray[np.float64], segments: list[str], side: str) -> None:
        loads_here = [applied[side]] if side in applied else []
        from_loads = moment_about(point, loads_here)
        total = moment_about(point, weights(body, segments)) + from_loads
        covered = UNCOVERED if name.endswith("wrist") else "the Arm Force Field, at the hand"
        out.append(JointMoment(name, _triple(total), _triple(from_loads), covered))

    for side in ("left", "right"):
        s = side[0]
        arm(f"{side} wrist", body.centers[f"{s}_radiocarpal"], [f"{s}_carpal"], side)
        arm(f"{side} elbow", body.centers[f"{s}_elbow"], [f"{s}_forearm", f"{s}_carpal"], side)
        arm(
            f"{side} shoulder",
            body.centers[f"{s}_shoulder"],
            _segments_below(f"{s}_shoulder"),
            side,
        )
    back_total = low_back(body, list(applied.values()))
    back_bare = low_back(body, [])
    out.append(
        JointMoment(
            "trunk (L5/S1)",
            back_total.moment,
            _triple(np.subtract(back_total.moment, back_bare.moment)),
            LOW_BACK_WORDS,
        )
    )
    if stance is None or not stance.feet:
        return out
    bare = balance(body, [])
    for side in ("left", "right"):
        s = side[0]
        for word, (joint, _, _, _) in LEG_JOINTS.items():
            point = body.centers[f"{s}_{joint}"]
            below = _segments_below(f"{s}_{joint}")
            total = _leg_moment(body, point, below, stance, side)
            unloaded = _leg_moment(body, point, below, bare, side) if bare.feet else total
            out.append(
                JointMoment(f"{side} {word}", _triple(total), _triple(total - unloaded), ANDERSON)
            )
    return out


def _leg_moment(
    body: PosedBody, point: npt.NDArray[np.float64], below: list[str], stance: Balance, side: str
) -> npt.NDArray[np.float64]:
    """The moment on the body above a leg joint: the opposite of the moment
    of what acts below it (its segments' weights, the floor under its foot)."""
    forces = weights(body, below)
    if side in stance.feet:
        forces.append(stance.feet[side])
    # the free moment about the vertical: shared by the feet on the floor
    share = 1.0 / len(body.bearing) if side in body.bearing else 0.0
    free = np.array([0.0, share * stance.free_moment, 0.0])
    above: npt.NDArray[np.float64] = -(moment_about(point, forces) + free)
    return above


def _triple(v: npt.ArrayLike) -> tuple[float, float, float]:
    a = np.asarray(v, dtype=float)
    return (float(a[0]), float(a[1]), float(a[2]))


@dataclass(frozen=True)
class Capability:
    """One covered hand or leg joint: what it must exert and who can."""

    what: str  # "left hand", "right knee"
    motion: str  # "force exerted" or an Anderson et al. 2007 motion
    demand: float  # N for a hand, N-m for a leg joint (on the first population's figure)
    unit: str
    percent: dict[str, float]  # population words -> percent capable
    source: str
    passive: bool = False  # carried at the end of the joint's range, not by muscle
    # "" or why the model answers outside what it was fitted on, for any of
    # the populations (the Arm Force Field's region, arm_force_field.py
    # outside_fitted; Anderson et al.'s fitted curve, published_strength.py
    # beyond_curve)
    extrapolated: str = ""


@dataclass
class TaskAnswer:
    loads: list[HandLoad]
    moments: list[JointMoment]  # on the first population's figure
    figure_words: str
    capabilities: list[Capability] = field(default_factory=list)
    populations: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    low_back: LowBack | None = None  # on the first population's figure
    stance: Balance | None = None  # on the first population's figure; None seated
    lean: float | None = None  # deg at the ankles sass chose, standing
    unstable: dict[str, str] = field(default_factory=dict)  # population -> why it tips
    rula: list[Rula] = field(default_factory=list)  # each arm, on the first figure
    reba: list[Reba] = field(default_factory=list)
    # population -> the angles its figure took, where each figure finds its own
    postures: dict[str, Angles] = field(default_factory=dict)
    solved_axes: tuple[str, ...] = ()  # the axes each figure found (both sides alike)
    # what the user should know of the posture on the first figure: a foot off
    # the floor or into it, a load behind the low back, a leg moment uncovered
    cautions: list[str] = field(default_factory=list)

    def limiting(self, population: str) -> Capability | None:
        """The covered joint or hand the fewest of `population` can do (a
        joint carried passively never is; a posture that tips has none)."""
        if population in self.unstable:
            return None
        covered = [c for c in self.capabilities if population in c.percent and not c.passive]
        return min(covered, key=lambda c: c.percent[population], default=None)

    def record(self, found: Capability, population: str, percent: float) -> None:
        for i, c in enumerate(self.capabilities):
            if c.what == found.what:
                self.capabilities[i] = replace(
                    c,
                    percent={**c.percent, population: percent},
                    extrapolated=c.extrapolated or found.extrapolated,  # any population's
                )
                return
        self.capabilities.append(replace(found, percent={population: percent}))


class PostureSolver(Protocol):
    """A posture each figure finds for itself (model/strength/hands_at.py:
    from where its hands must be), naming the axes it finds."""

    @property
    def solved_axes(self) -> tuple[str, ...]: ...

    def __call__(self, figure: Figure) -> Angles: ...


# A task's posture: the same angles for every figure, or each figure's own
PostureOf = Angles | PostureSolver


def _angles_for(posture: PostureOf, figure: Figure) -> Angles:
    return posture(figure) if callable(posture) else posture


@dataclass(frozen=True)
class Reference:
    """A figure standing for its population: women, men, or one person."""

    words: str  # "women", "men", a person's name
    figure: Figure
    age: float | None  # years; None: Anderson et al. 2007's youngest group


def hand_capability(load: HandLoad, arm: ArmForce) -> Capability:
    """The loaded hand's row, its percent capable still to record."""
    return Capability(
        f"{load.side} hand",
        "force exerted",
        load.force,
        "N",
        {},
        ARM_WORDS,
        extrapolated=arm.outside_fitted,
    )


def arm_demand(body: PosedBody, load: HandLoad, gender: str) -> ArmForce:
    """The Arm Force Field for the hand exerting `load`."""
    return arm_force(body.points, load.side, load.direction, gender, body.body_mass)


def leg_demand(moment: JointMoment, word: str) -> tuple[str, float]:
    """(Anderson et al. 2007's motion, torque N-m) resisting the moment about
    the lateral axis (+x: a positive moment tips the body above forward)."""
    _, (forward, back), _, _ = LEG_JOINTS[word]
    sagittal = moment.moment[0]
    return (forward, sagittal) if sagittal >= 0 else (back, -sagittal)


def is_passive(figure: Figure, side: str, word: str, angle: float, moment: JointMoment) -> bool:
    """A leg joint within PASSIVE_MARGIN_DEG of the end of its range that
    its moment turns further toward that end (a straight knee, the thighs
    tipped forward over the shanks)."""
    _, _, axis, turns = LEG_JOINTS[word]
    lower, upper = joint_limit_range(figure, side, axis)
    way = turns * moment.moment[0]
    if math.isnan(lower) or math.isnan(upper) or way == 0:
        return False
    return (way > 0 and angle >= upper - PASSIVE_MARGIN_DEG) or (
        way < 0 and angle <= lower + PASSIVE_MARGIN_DEG
    )


def _legs(moments: list[JointMoment]) -> list[tuple[JointMoment, str, str]]:
    """(moment, side, joint word) of each hip, knee and ankle."""
    out = []
    for moment in moments:
        side, _, word = moment.joint.partition(" ")
        if word in LEG_JOINTS:
            out.append((moment, side, word))
    return out


def cop_ahead(stance: Balance, body: PosedBody) -> float:
    """How far (m) the floor's centre of pressure lies ahead of the ankles of
    the feet on the floor (on one foot, its own)."""
    ankles = np.mean([body.centers[f"{side[0]}_talocrural"][2] for side in body.bearing])
    return float(stance.center_of_pressure[2] - ankles)


LEAN_STEPS = 12  # regula falsi steps at most
LEAN_TOLERANCE_M = 1e-4  # the centre of pressure within 0.1 mm of its place


def pose_task(
    figure: Figure,
    angles: Angles,
    loads: list[HandLoad],
    seated: bool = False,
    humanoid: Humanoid | None = None,
) -> tuple[PosedBody, Balance | None, Angles, float | None]:
    """The figure in the task's posture: seated (no balance), standing as
    given (an ankle angle given), or leaning at the ankles until the floor's
    centre of pressure lies QUIET_STANCE_COP_M ahead of them, within the
    ankles' range (the module docstring).  (body, balance, angles, lean).
    `humanoid`: the figure's, for a caller posing it many times."""
    humanoid = humanoid or build_humanoid(figure)
    if seated:
        return pose_figure(figure, angles, seated=True, humanoid=humanoid), None, angles, None
    if any(axis == "ankle_y" for _, axis in angles):
        body = pose_figure(figure, angles, humanoid=humanoid)
        return body, balance(body, hand_forces(body, loads)), angles, None

    def stand(lean: float) -> tuple[PosedBody, Balance, Angles]:
        leaned = {**angles, ("left", "ankle_y"): lean, ("right", "ankle_y"): lean}
        body = pose_figure(figure, leaned, humanoid=humanoid)
        return body, balance(body, hand_forces(body, loads)), leaned

    def ahead(stance: Balance, body: PosedBody) -> float:
        return cop_ahead(stance, body) - QUIET_STANCE_COP_M

    low = max(joint_limit_range(figure, s, "ankle_y")[0] for s in ("left", "right"))
    high = min(joint_limit_range(figure, s, "ankle_y")[1] for s in ("left", "right"))
    body, stance, leaned = stand(0.0)
    here = ahead(stance, body)
    if abs(here) <= LEAN_TOLERANCE_M:
        return body, stance, leaned, 0.0
    # the centre of pressure moves forward as the body leans forward: bracket
    # the lean between upright and the ankle's limit that way, then regula falsi
    # (the Illinois variant), nearly linear so a few steps
    end = low if here > 0 else high
    far_body, far_stance, far_leaned = stand(end)
    there = ahead(far_stance, far_body)
    if (there > 0) == (here > 0):  # even the limit does not reach it
        return far_body, far_stance, far_leaned, end
    a, fa, b, fb = 0.0, here, end, there
    lean, side = 0.0, 0
    for _ in range(LEAN_STEPS):
        lean = (a * fb - b * fa) / (fb - fa)
        body, stance, leaned = stand(lean)
        now = ahead(stance, body)
        if abs(now) <= LEAN_TOLERANCE_M:
            break
        if (now > 0) == (fb > 0):
            b, fb = lean, now
            if side == -1:
                fa /= 2
            side = -1
        else:
            a, fa = lean, now
            if side == 1:
                fb /= 2
            side = 1
    return body, stance, leaned, lean


def assess_task(
    references: list[Reference], posture: PostureOf, loads: list[HandLoad], seated: bool = False
) -> TaskAnswer:
    """The moments (on the first reference's figure) and, for each reference,
    the percent capable of each loaded hand and each hip, knee and ankle."""
    answer: TaskAnswer | None = None
    for ref in references:
        angles = _angles_for(posture, ref.figure)
        body, stance, used, lean = pose_task(ref.figure, angles, loads, seated)
        moments = task_moments(body, loads, stance)
        if answer is None:
            answer = _answer_on(ref.figure, body, stance, used, lean, loads, moments, seated)
        answer.populations.append(ref.words)
        if callable(posture):
            answer.postures[ref.words] = angles
            answer.solved_axes = posture.solved_axes
        if stance is not None and not stance.stable:
            answer.unstable[ref.words] = stance.reason
            continue
        for load in loads:
            if load.force > 0:
                arm = arm_demand(body, load, ref.figure.gender)
                answer.record(
                    hand_capability(load, arm), ref.words, arm.percent_capable(load.force)
                )
        age = ref.age if ref.age is not None else AGE_GROUPS[0][1]
        subject = Subject(ref.figure.gender, age, ref.figure.output_mass(), body.stature)
        for moment, side, word in _legs(moments):
            motion, torque = leg_demand(moment, word)
            angle = used.get((side, LEG_JOINTS[word][2]), 0.0)
            if is_passive(ref.figure, side, word, angle, moment):
                found = Capability(moment.joint, PASSIVE, torque, "N-m", {}, ANDERSON, True)
                answer.record(found, ref.words, 100.0)
                continue
            share = lower_limb_percent_capable(motion, subject, torque, angle)
            outside = beyond_curve(motion, subject.gender, [age_group(age)], angle)
            found = Capability(moment.joint, motion, torque, "N-m", {}, ANDERSON, False, outside)
            answer.record(found, ref.words, share)
        if ref.age is None:
            answer.notes.append(f"{ref.words}: age not given, {ANDERSON}'s 18-25 group")
    assert answer is not None  # at least one reference
    return answer


def _scores(
    figure: Figure,
    body: PosedBody,
    angles: Angles,
    loads: list[HandLoad],
    stance: Balance | None,
    seated: bool,
    lean: float | None,
) -> tuple[list[Rula], list[Reba]]:
    """Each arm's RULA and REBA scores of the posture (model/strength/rula.py,
    reba.py): the trunk's inclination without the lean sass chose at the
    ankles (the posture as the user gave it)."""
    forces = {load.side: load.force for load in loads}
    up = (np.eye(3) if body.turns is None else body.turns["vl5"])[:, 1]
    a = math.radians(lean or 0.0)
    up = np.array(
        [
            up[0],
            up[1] * math.cos(a) + up[2] * math.sin(a),
            -up[1] * math.sin(a) + up[2] * math.cos(a),
        ]
    )
    stable = stance is None or stance.stable
    inclination = math.degrees(math.acos(float(np.clip(up[1], -1.0, 1.0))))
    both = sum(forces.values())
    # both scores' legs: 1 only balanced on both feet (or seated)
    stable = stable and len(body.bearing) == 2
    rebas = [reba(side, angles, inclination, seated, stable, both) for side in ("right", "left")]
    return [
        rula(
            side,
            angles,
            up,
            joint_limit_range(figure, side, "wrist_z"),
            seated,
            stable,
            forces.get(side, 0.0),
            both,
        )
        for side in ("right", "left")
    ], rebas


def _answer_on(
    figure: Figure,
    body: PosedBody,
    stance: Balance | None,
    used: Angles,
    lean: float | None,
    loads: list[HandLoad],
    moments: list[JointMoment],
    seated: bool,
) -> TaskAnswer:
    """The answer's parts told on the first figure: its moments, low back,
    balance, notes, cautions and RULA and REBA scores."""
    answer = TaskAnswer(loads, moments, _figure_words(figure))
    answer.low_back = low_back(body, hand_forces(body, loads))
    answer.stance, answer.lean = stance, lean
    answer.notes += _posture_notes(seated, lean, stance)
    answer.cautions += _feet_notes(body) + _behind_notes(body, loads) + _off_plane_notes(moments)
    answer.rula, answer.reba = _scores(figure, body, used, loads, stance, seated, lean)
    return answer


def _posture_notes(seated: bool, lean: float | None, stance: Balance | None) -> list[str]:
    """What the posture's model chose: the seat, the lean at the ankles."""
    if seated:
        return ["seated: the seat carries the legs; no leg joint and no balance"]
    if lean is None or stance is None:
        return []
    return [
        f"standing: the body leans {lean:.1f} deg at the ankles, toward the floor's centre of "
        f"pressure {QUIET_STANCE_COP_M * 100:g} cm ahead of them where quiet standing holds it "
        "(Winter 1995), as far as the ankles' range allows; give ankle_y to fix the lean"
    ]


def _off_plane_notes(moments: list[JointMoment]) -> list[str]:
    """Anderson et al. (2007) model flexion and extension alone: a leg
    joint's moment side to side (about the forward axis, HAnim z) or its
    twist (about the vertical, y) beyond OFF_PLANE_N_M is said uncovered
    (standing on one foot, the hip's side-to-side moment is the body's
    weight times the hip's distance from the foot)."""
    notes = []
    for moment, side, word in _legs(moments):
        _, twist, sideways = moment.moment
        parts = [
            f"{what} {abs(size):.1f} N-m"
            for what, size in (("side to side", sideways), ("twisting", twist))
            if abs(size) > OFF_PLANE_N_M
        ]
        if parts:
            notes.append(
                f"{side} {word}: the moment {' and '.join(parts)} is not covered "
                f"({ANDERSON}'s models are of flexion and extension alone)"
            )
    return notes


def _feet_notes(body: PosedBody) -> list[str]:
    """Standing on one foot, and a sole the posture puts into the floor."""
    if body.seated:
        return []
    notes = []
    if len(body.bearing) == 1:
        (side,) = body.bearing
        other = "right" if side == "left" else "left"
        notes.append(
            f"standing on the {side} foot: the {other} leg is posed shorter, its foot off the "
            "floor carries no force"
        )
    for side in ("left", "right"):
        below = -float(body.soles[side][:, 1].min())
        if below > INTO_FLOOR_M:
            notes.append(
                f"the posture puts the {side} sole {below * 100:.1f} cm into the floor: it is "
                f"counted as standing there; bend the {side} ankle (ankle_y) or hip (hip_y) to lift it"
            )
    return notes


def _behind_notes(body: PosedBody, loads: list[HandLoad]) -> list[str]:
    """A loaded hand well behind the low back: joint angles are relative, so
    trunk_y carries hanging arms back with the trunk, and such a load lowers
    the low back's moment, which surprises whoever meant the arms to hang."""
    back = float(body.centers["vl5"][2])
    notes = []
    for load in loads:
        behind = back - float(body.grip(load.side)[2])
        if load.force > 0.0 and behind > BEHIND_L5_M:
            notes.append(
                f"the {load.side} hand holds its load {behind * 100:.1f} cm behind the low back "
                "(L5/S1), which lowers the low back's moment: joint angles are relative, so the "
                "trunk's flexion carries hanging arms back with it; give shoulder_y, or "
                "hands=H,V, for hands in front of the body"
            )
    return notes


def _figure_words(figure: Figure) -> str:
    who = figure.person or f"the {figure.gender} figure"
    return f"{who}, {figure.output_mass():.1f} kg, {figure.stature:.1f} cm"


@dataclass(frozen=True)
class Population:
    """People of one gender, each with their own age, mass and stature, weighted."""

    words: str
    gender: str
    ages: npt.NDArray[np.float64]
    masses: npt.NDArray[np.float64]  # kg
    statures: npt.NDArray[np.float64]  # m
    weights: npt.NDArray[np.float64]
    note: str


def assess_populations(
    groups: list[tuple[Figure, Population]],
    posture: PostureOf,
    loads: list[HandLoad],
    together: str = "",
    seated: bool = False,
) -> TaskAnswer:
    """Percent capable over many people, one population per gender, each
    scaled from its own gender's figure (in that figure's posture and
    balance); the moments are on the first group's figure.  With `together`,
    a column of the groups' people together: every person's probability by
    their weight, over all groups."""
    answer: TaskAnswer | None = None
    sums: dict[str, tuple[Capability, float, float]] = {}
    for figure, people in groups:
        angles = _angles_for(posture, figure)
        body, stance, used, lean = pose_task(figure, angles, loads, seated)
        moments = task_moments(body, loads, stance)
        if answer is None:
            answer = _answer_on(figure, body, stance, used, lean, loads, moments, seated)
        answer.populations.append(people.words)
        if callable(posture):
            answer.postures[people.words] = angles
            answer.solved_axes = posture.solved_axes
        if people.note not in answer.notes:
            answer.notes.append(people.note)
        if stance is not None and not stance.stable:
            answer.unstable[people.words] = stance.reason
            if together:
                answer.unstable[together] = stance.reason
            continue
        for found, capable, weight in _population_shares(
            figure, body, people, used, loads, moments
        ):
            answer.record(found, people.words, 100.0 * capable / weight)
            _, c, w = sums.get(found.what, (found, 0.0, 0.0))
            sums[found.what] = (found, c + capable, w + weight)
    assert answer is not None  # at least one group
    if together and len(groups) > 1:
        answer.populations.append(together)
        for found, capable, weight in sums.values():
            answer.record(found, together, 100.0 * capable / weight)
    return answer


def _population_shares(
    figure: Figure,
    body: PosedBody,
    people: Population,
    angles: Angles,
    loads: list[HandLoad],
    moments: list[JointMoment],
) -> list[tuple[Capability, float, float]]:
    """(capability, sum of weight x probability, sum of weight) over the
    people the model covers: each person's moments are the figure's scaled
    to their own size (segment weights by mass x stature, the loads' lever
    arms by stature), their arm's weight by their mass."""
    out = []
    m, h, w = people.masses, people.statures, people.weights
    for load in loads:
        if load.force <= 0 or not _known(people).any():
            continue
        arm = arm_demand(body, load, people.gender)
        capable, weight = _hand_sums(arm, body, people, np.array([load.force]))
        out.append((hand_capability(load, arm), float(capable[0]), weight))
    scale_body = m * h / (body.body_mass * body.stature)
    # the age groups of the people Anderson et al.'s model answers for, once
    # for every leg joint (over the distinct ages: thousands of people, few ages)
    answered = _known(people) & (people.ages >= MIN_AGE) & (people.ages <= MAX_AGE)
    groups = sorted({age_group(float(a)) for a in np.unique(people.ages[answered])})
    for moment, side, word in _legs(moments):
        motion, torque = leg_demand(moment, word)
        sign = 1.0 if motion == LEG_JOINTS[word][1][0] else -1.0
        own = sign * (moment.moment[0] - moment.from_loads[0])
        scaled = own * scale_body + (torque - own) * h / body.stature
        angle = angles.get((side, LEG_JOINTS[word][2]), 0.0)
        if is_passive(figure, side, word, angle, moment):
            found = Capability(moment.joint, PASSIVE, torque, "N-m", {}, ANDERSON, True)
            out.append((found, float(w.sum()), float(w.sum())))
            continue
        capable = lower_limb_capable(
            motion, np.full(len(m), people.gender, dtype=object), people.ages, m, h, scaled, angle
        )
        ok = ~np.isnan(capable) & (w > 0)
        if ok.any():
            outside = beyond_curve(motion, people.gender, groups, angle)
            found = Capability(moment.joint, motion, torque, "N-m", {}, ANDERSON, False, outside)
            out.append((found, *_weighted(capable[ok], w[ok])))
    return out


def _weighted(
    capable: npt.NDArray[np.float64], weights: npt.NDArray[np.float64]
) -> tuple[float, float]:
    return float((capable * weights).sum()), float(weights.sum())


def _known(people: Population) -> npt.NDArray[np.bool_]:
    m, h, w = people.masses, people.statures, people.weights
    known: npt.NDArray[np.bool_] = np.isfinite(m) & np.isfinite(h) & (m > 0) & (h > 0) & (w > 0)
    return known


def _hand_sums(
    arm: ArmForce, body: PosedBody, people: Population, forces: npt.NDArray[np.float64]
) -> tuple[npt.NDArray[np.float64], float]:
    """For each force: the sum of weight x probability of exerting it over
    `people` (the arm's weight by each one's mass), and the sum of weight."""
    known = _known(people)
    gravity = arm.gravity * people.masses[known] / body.body_mass
    capable = normal_survival((forces[:, None] - gravity[None, :] - arm.mean) / arm.sd)
    weights = people.weights[known]
    return capable @ weights, float(weights.sum())


CURVE_POINTS = 41


@dataclass(frozen=True)
class CurveGroup:
    """Whose curve: a figure alone (`people` None) or people scaled from it."""

    words: str
    body: PosedBody
    gender: str
    people: Population | None = None


def hand_curves(
    groups: list[CurveGroup], load: HandLoad, together: str = ""
) -> dict[str, list[tuple[float, float]]]:
    """Percent capable against the force on `load`'s hand (its direction
    kept), from 0 to what 0.5 % of the strongest group can exert: for each
    group and, with `together`, the weighted people of all groups pooled."""
    arms = [(group, arm_demand(group.body, load, group.gender)) for group in groups]
    top = max(max(arm.strength(0.5) for _, arm in arms), 1.0)
    forces = np.linspace(0.0, top, CURVE_POINTS)
    curves: dict[str, list[tuple[float, float]]] = {}
    pooled, pooled_weight = np.zeros(CURVE_POINTS), 0.0
    for group, arm in arms:
        if group.people is None:
            shares = [arm.percent_capable(float(f)) for f in forces]
        elif _known(group.people).any():
            capable, weight = _hand_sums(arm, group.body, group.people, forces)
            pooled, pooled_weight = pooled + capable, pooled_weight + weight
            shares = list(100.0 * capable / weight)
        else:
            continue
        curves[group.words] = [(float(f), float(p)) for f, p in zip(forces, shares)]
    if together and pooled_weight > 0 and len(curves) > 1:
        curves[together] = [
            (float(f), float(p)) for f, p in zip(forces, 100.0 * pooled / pooled_weight)
        ]
    return curves
