"""A task: a posture, the loads on the hands, and who is to do it.  The
static moments at the joints from the figure's own segment masses and
centres of mass (model/body/posture.py on the HAnim humanoid) plus the loads, and
the percent capable where a published model covers the joint
(docs/strength.md, "A task"):

- each loaded hand: the Arm Force Field (La Delfa & Potvin 2017) for a force
  opposite to the load, gravity included;
- hip, knee and ankle: Anderson et al. 2007 for the motion that resists the
  moment (extension against a moment tipping the body forward), at the
  posture's angle.  Both feet on the ground share the body above the hips
  and the loads equally (an assumption: the task gives no foot forces);
  each leg also carries its own segments above the joint.

The elbow's and shoulder's moments are reported; their capability is the
Arm Force Field's (the arm as a whole, at the hand).  No published model in
sass covers the trunk (L5/S1) or the wrist: their moments are given and said
to be uncovered.

No Textual import here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import LOA1
from sass_tui.model.body.posture import Angles, PosedBody, pose_figure
from sass_tui.model.strength.arm_force_field import (
    DIRECTIONS,
    ArmForce,
    ArmForceError,
    arm_force,
    check_direction,
    parse_direction,
)
from sass_tui.model.strength.percent_capable import lower_limb_capable, normal_survival
from sass_tui.model.strength.published_strength import (
    AGE_GROUPS,
    Subject,
    lower_limb_percent_capable,
)
from sass_tui.model.strength.published_strength import (
    CITATION as ANDERSON,
)
from sass_tui.model.units import parse_quantity

GRAVITY = 9.81
DOWN = np.array([0.0, -1.0, 0.0])
# The legs' segments: what a foot on the ground carries below the hips.
_LEG_SEGMENTS = ("thigh", "calf", "talus", "tarsal_proximal_phalanx_2")
# joint word -> (HAnim joint, Anderson et al. 2007's motions resisting a
# moment that tips the body above forward (+x) and one that tips it back),
# its axis.  Tipping the trunk forward over the thighs flexes the hips; the
# thighs forward over the shanks extend the knees (the hips go forward, not
# back as in a squat); the shanks forward over the feet dorsiflex the ankles.
LEG_JOINTS = {
    "hip": ("hip", ("hip_extension", "hip_flexion"), "hip_y"),
    "knee": ("knee", ("knee_flexion", "knee_extension"), "knee_y"),
    "ankle": ("talocrural", ("ankle_plantarflexion", "ankle_dorsiflexion"), "ankle_y"),
}
ARM_WORDS = "La Delfa & Potvin 2017 (Arm Force Field): women as published, men x 1.66"
UNCOVERED = "no published model in sass covers it"


class TaskError(ArmForceError):
    """A task sass cannot assess (a load without a direction, no load at all)."""


@dataclass(frozen=True)
class HandLoad:
    """The load on one hand: `force` N along the unit `direction` (HAnim
    axes): a 10 kg box held is 98 N down; the hand exerts the opposite."""

    side: str
    force: float
    direction: npt.NDArray[np.float64]

    @property
    def vector(self) -> npt.NDArray[np.float64]:
        return self.force * self.direction


def hand_load(side: str, force: float, direction: npt.ArrayLike) -> HandLoad:
    if not (math.isfinite(force) and force >= 0):
        raise TaskError(f"--{side}-load {force!r} N: expected a force of 0 or more")
    return HandLoad(side, float(force), check_direction(direction, f"--{side}-direction"))


def parse_hand_load(side: str, text: str) -> HandLoad:
    """'60 N down', '60N', '15 lbf up', '40 N 0,-1,0.2': the force (N without
    a unit), then the direction it acts in (default down: a weight held)."""
    words = text.split()
    if not words:
        raise TaskError(f"the {side} hand: expected a force and a direction, e.g. 60 N down")
    direction = "down"
    if len(words) > 1 and (words[-1].lower() in DIRECTIONS or "," in words[-1]):
        direction = words.pop()
    return hand_load(side, parse_quantity(" ".join(words), "N"), parse_direction(direction))


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


def _moment_about(
    point: npt.NDArray[np.float64],
    forces: list[tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]],
) -> npt.NDArray[np.float64]:
    total = np.zeros(3)
    for where, force in forces:
        total += np.cross(where - point, force)
    return total


def _weights(
    body: PosedBody, segments: list[str]
) -> list[tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]]:
    return [(body.centers_of_mass[s], body.masses[s] * GRAVITY * DOWN) for s in segments]


def _segments_below(joint: str) -> list[str]:
    joints = [joint]
    for child, _, parent in LOA1:
        if parent in joints:
            joints.append(child)
    return [segment for j, segment, _ in LOA1 if j in joints]


def task_moments(body: PosedBody, loads: list[HandLoad]) -> list[JointMoment]:
    """The static moments of the posture and loads (the loads at the hands'
    grip centres: the third knuckle, where the Arm Force Field places the hand)."""
    grip = {load.side: body.points[f"{load.side[0]}_metacarpophalangeal_3"] for load in loads}
    applied = {load.side: (grip[load.side], load.vector) for load in loads}
    out = []

    def add(
        name: str,
        point: npt.NDArray[np.float64],
        segments: list[str],
        sides: tuple[str, ...],
        share: float,
        covered: str,
    ) -> None:
        loads_here = [applied[s] for s in sides if s in applied]
        from_loads = share * _moment_about(point, loads_here)
        total = share * _moment_about(point, _weights(body, segments)) + from_loads
        out.append(JointMoment(name, _triple(total), _triple(from_loads), covered))

    for side in ("left", "right"):
        s = side[0]
        aff = "the Arm Force Field, at the hand"
        add(
            f"{side} wrist",
            body.centers[f"{s}_radiocarpal"],
            [f"{s}_carpal"],
            (side,),
            1.0,
            UNCOVERED,
        )
        add(
            f"{side} elbow",
            body.centers[f"{s}_elbow"],
            [f"{s}_forearm", f"{s}_carpal"],
            (side,),
            1.0,
            aff,
        )
        add(
            f"{side} shoulder",
            body.centers[f"{s}_shoulder"],
            _segments_below(f"{s}_shoulder"),
            (side,),
            1.0,
            aff,
        )
    upper = [seg for _, seg, _ in LOA1 if not any(seg.endswith(leg) for leg in _LEG_SEGMENTS)]
    trunk = [seg for seg in upper if seg not in ("sacrum", "pelvis")]
    add("trunk (L5/S1)", body.centers["vl5"], trunk, ("left", "right"), 1.0, UNCOVERED)
    for side in ("left", "right"):
        s = side[0]
        own: list[str] = []
        for word, (joint, _, _) in LEG_JOINTS.items():
            point = body.centers[f"{s}_{joint}"]
            # half the body above the hips and of the loads; the leg's own segments above
            half = 0.5 * (
                _moment_about(point, _weights(body, upper))
                + _moment_about(point, list(applied.values()))
            )
            from_loads = 0.5 * _moment_about(point, list(applied.values()))
            total = half + _moment_about(point, _weights(body, own))
            out.append(JointMoment(f"{side} {word}", _triple(total), _triple(from_loads), ANDERSON))
            own.append(f"{s}_{'thigh' if word == 'hip' else 'calf'}")
    return out


def _triple(v: npt.NDArray[np.float64]) -> tuple[float, float, float]:
    return (float(v[0]), float(v[1]), float(v[2]))


@dataclass(frozen=True)
class Capability:
    """One covered hand or leg joint: what it must exert and who can."""

    what: str  # "left hand", "right knee"
    motion: str  # "force against the load" or an Anderson et al. 2007 motion
    demand: float  # N for a hand, N-m for a leg joint (on the first population's figure)
    unit: str
    percent: dict[str, float]  # population words -> percent capable
    source: str


@dataclass
class TaskAnswer:
    loads: list[HandLoad]
    moments: list[JointMoment]  # on the first population's figure
    figure_words: str
    capabilities: list[Capability] = field(default_factory=list)
    populations: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def limiting(self, population: str) -> Capability | None:
        """The covered joint or hand the fewest of `population` can do."""
        covered = [c for c in self.capabilities if population in c.percent]
        return min(covered, key=lambda c: c.percent[population], default=None)

    def record(self, found: Capability, population: str, percent: float) -> None:
        for i, c in enumerate(self.capabilities):
            if c.what == found.what:
                self.capabilities[i] = replace(c, percent={**c.percent, population: percent})
                return
        self.capabilities.append(replace(found, percent={population: percent}))


@dataclass(frozen=True)
class Reference:
    """A figure standing for its population: women, men, or one person."""

    words: str  # "women", "men", a person's name
    figure: Figure
    age: float | None  # years; None: Anderson et al. 2007's youngest group


def arm_demand(body: PosedBody, load: HandLoad, gender: str) -> ArmForce:
    """The Arm Force Field for the hand exerting against `load`."""
    return arm_force(body.points, load.side, -load.direction, gender, body.body_mass)


def leg_demand(moment: JointMoment, word: str) -> tuple[str, float]:
    """(Anderson et al. 2007's motion, torque N-m) resisting the moment about
    the lateral axis (+x: a positive moment tips the body above forward)."""
    _, (forward, back), _ = LEG_JOINTS[word]
    sagittal = moment.moment[0]
    return (forward, sagittal) if sagittal >= 0 else (back, -sagittal)


def _legs(moments: list[JointMoment]) -> list[tuple[JointMoment, str, str]]:
    """(moment, side, joint word) of each hip, knee and ankle."""
    out = []
    for moment in moments:
        side, _, word = moment.joint.partition(" ")
        if word in LEG_JOINTS:
            out.append((moment, side, word))
    return out


def assess_task(references: list[Reference], angles: Angles, loads: list[HandLoad]) -> TaskAnswer:
    """The moments (on the first reference's figure) and, for each reference,
    the percent capable of each loaded hand and each hip, knee and ankle."""
    _check_loads(loads)
    answer: TaskAnswer | None = None
    for ref in references:
        body = pose_figure(ref.figure, angles)
        moments = task_moments(body, loads)
        if answer is None:
            answer = TaskAnswer(loads, moments, _figure_words(ref.figure))
        answer.populations.append(ref.words)
        for load in loads:
            if load.force > 0:
                arm = arm_demand(body, load, ref.figure.gender)
                found = Capability(
                    f"{load.side} hand", "force against the load", load.force, "N", {}, ARM_WORDS
                )
                answer.record(found, ref.words, arm.percent_capable(load.force))
        age = ref.age if ref.age is not None else AGE_GROUPS[0][1]
        subject = Subject(ref.figure.gender, age, ref.figure.output_mass(), body.stature)
        for moment, side, word in _legs(moments):
            motion, torque = leg_demand(moment, word)
            angle = angles.get((side, LEG_JOINTS[word][2]), 0.0)
            share = lower_limb_percent_capable(motion, subject, torque, angle)
            found = Capability(moment.joint, motion, torque, "N-m", {}, ANDERSON)
            answer.record(found, ref.words, share)
        if ref.age is None:
            answer.notes.append(f"{ref.words}: age not given, {ANDERSON}'s 18-25 group")
    assert answer is not None  # at least one reference
    return answer


def _check_loads(loads: list[HandLoad]) -> None:
    if not any(load.force > 0 for load in loads):
        raise TaskError("a task needs a load on a hand: --left-load or --right-load")


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
    angles: Angles,
    loads: list[HandLoad],
    together: str = "",
) -> TaskAnswer:
    """Percent capable over many people, one population per gender, each
    scaled from its own gender's figure; the moments are on the first
    group's figure.  With `together`, a column of the groups' people
    together: every person's probability by their weight, over all groups."""
    _check_loads(loads)
    answer: TaskAnswer | None = None
    sums: dict[str, tuple[Capability, float, float]] = {}
    for figure, people in groups:
        body = pose_figure(figure, angles)
        if answer is None:
            answer = TaskAnswer(loads, task_moments(body, loads), _figure_words(figure))
        answer.populations.append(people.words)
        if people.note not in answer.notes:
            answer.notes.append(people.note)
        for found, capable, weight in _population_shares(body, people, angles, loads):
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
    body: PosedBody, people: Population, angles: Angles, loads: list[HandLoad]
) -> list[tuple[Capability, float, float]]:
    """(capability, sum of weight x probability, sum of weight) over the
    people the model covers: each person's moments are the figure's scaled
    to their own size (segment weights by mass x stature, the loads' lever
    arms by stature), their arm's weight by their mass."""
    out = []
    moments = task_moments(body, loads)
    bare = task_moments(body, [])
    m, h, w = people.masses, people.statures, people.weights
    for load in loads:
        if load.force <= 0 or not _known(people).any():
            continue
        arm = arm_demand(body, load, people.gender)
        capable, weight = _hand_sums(arm, body, people, np.array([load.force]))
        found = Capability(
            f"{load.side} hand", "force against the load", load.force, "N", {}, ARM_WORDS
        )
        out.append((found, float(capable[0]), weight))
    scale_body = m * h / (body.body_mass * body.stature)
    for (moment, side, word), unloaded in zip(_legs(moments), _legs(bare)):
        motion, torque = leg_demand(moment, word)
        sign = 1.0 if motion == LEG_JOINTS[word][1][0] else -1.0
        own = sign * unloaded[0].moment[0]
        scaled = own * scale_body + (torque - own) * h / body.stature
        angle = angles.get((side, LEG_JOINTS[word][2]), 0.0)
        capable = lower_limb_capable(
            motion, np.full(len(m), people.gender, dtype=object), people.ages, m, h, scaled, angle
        )
        ok = ~np.isnan(capable) & (w > 0)
        if ok.any():
            found = Capability(moment.joint, motion, torque, "N-m", {}, ANDERSON)
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


# --- what the answer says -------------------------------------------------------

MOMENT_DECIMALS = 1  # N-m: segment masses and lengths carry three figures
PERCENT_DECIMALS = 1


def task_json(answer: TaskAnswer, posture: list[str]) -> dict[str, object]:
    def triple(v: tuple[float, float, float]) -> list[float]:
        return [round(x, MOMENT_DECIMALS) + 0.0 for x in v]

    return {
        "posture": posture,
        "loads": [
            {
                "side": load.side,
                "force_N": round(load.force, 1),
                "direction": [round(float(x), 4) + 0.0 for x in load.direction],
            }
            for load in answer.loads
        ],  # fmt: skip
        "figure": answer.figure_words,
        "moments_N_m": [
            {
                "joint": m.joint,
                "moment": triple(m.moment),
                "size": round(m.size, MOMENT_DECIMALS),
                "from_loads": triple(m.from_loads),
                "covered_by": m.covered_by,
            }
            for m in answer.moments
        ],
        "capable": [
            {
                "what": c.what,
                "motion": c.motion,
                "demand": round(c.demand, MOMENT_DECIMALS),
                "unit": c.unit,
                "percent": {k: round(v, PERCENT_DECIMALS) for k, v in c.percent.items()},
                "source": c.source,
            }
            for c in answer.capabilities
        ],
        "limiting": {
            p: None if (c := answer.limiting(p)) is None else c.what for p in answer.populations
        },
        "not_covered": [m.joint for m in answer.moments if m.covered_by == UNCOVERED],
        "notes": answer.notes,
    }


def task_text(answer: TaskAnswer, posture: list[str]) -> list[str]:
    loads = "; ".join(
        f"{load.side} hand {load.force:.1f} N along "
        f"({', '.join(f'{x:.2f}' for x in load.direction)})"
        for load in answer.loads
    )
    lines = [
        f"Task: posture {' '.join(posture) or 'standing'}; loads on the hands: {loads}",
        f"Moments (N-m, HAnim axes: x left, y up, z forward) on {answer.figure_words}:",
        f"  {'joint':<16} {'x':>8} {'y':>8} {'z':>8} {'size':>8} {'loads':>8}  covered by",
    ]
    for m in answer.moments:
        x, y, z = m.moment
        lines.append(
            f"  {m.joint:<16} {x:>8.1f} {y:>8.1f} {z:>8.1f} {m.size:>8.1f} "
            f"{float(np.linalg.norm(m.from_loads)):>8.1f}  {m.covered_by}"
        )
    # a column as wide as its population's name (a target's are long), 20 at least
    width = max([20, *(len(p) + 2 for p in answer.populations)])
    heads = "".join(f"{p:>{width}}" for p in answer.populations)
    lines += ["", f"Percent capable{'':<33}{heads}"]
    for c in answer.capabilities:
        what = f"{c.what}: {c.motion.replace('_', ' ')} {c.demand:.1f} {c.unit}"
        cells = "".join(
            f"{c.percent[p]:>{width - 2}.1f} %" if p in c.percent else f"{'-':>{width}}"
            for p in answer.populations
        )
        lines.append(f"  {what:<46}{cells}")
    for p in answer.populations:
        worst = answer.limiting(p)
        if worst is not None:
            lines.append(f"limiting for {p}: {worst.what} ({worst.percent[p]:.1f} % capable)")
    uncovered = [m.joint for m in answer.moments if m.covered_by == UNCOVERED]
    lines.append(f"not covered: {', '.join(uncovered)}: {UNCOVERED}")
    sources = sorted({c.source.split(";")[0] for c in answer.capabilities})
    lines.append(f"sources: {'; '.join(sources)}")
    lines += [f"note: {n}" for n in answer.notes]
    return lines
