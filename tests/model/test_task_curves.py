"""The Task panel's curves (model/task.hand_curves): percent capable against
the load on a hand, for a figure alone (the Arm Force Field's own share) and
for weighted people, each with their arm's weight by their own mass, checked
by a direct weighted sum of the normal tail here."""

from __future__ import annotations

from statistics import NormalDist

import numpy as np
import pytest

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure
from sass_tui.model.strength.arm_force_field import arm_force
from sass_tui.model.strength.task import (
    CURVE_POINTS,
    CurveGroup,
    Population,
    hand_curves,
    hand_load,
)

ANGLES = parse_angles(["shoulder_y=90", "elbow_y=0"])
# the hand exerts 50 N up: a weight held
LOAD = hand_load("right", 50.0, (0.0, 1.0, 0.0))


def people(gender: str, masses: list[float], weights: list[float]) -> Population:
    n = len(masses)
    return Population(
        words=f"some {gender}",
        gender=gender,
        ages=np.full(n, 30.0),
        masses=np.array(masses),
        statures=np.full(n, 1.7),
        weights=np.array(weights),
        note="",
    )


def test_a_figure_alone_is_the_arm_force_fields_share():
    body = pose_figure(Figure.default("female"), ANGLES)
    (curve,) = hand_curves([CurveGroup("women", body, "female")], LOAD).values()
    arm = arm_force(body.points, "right", (0, 1, 0), "female", body.body_mass)
    assert len(curve) == CURVE_POINTS and curve[0][0] == 0.0
    assert curve[-1][0] == pytest.approx(arm.strength(0.5))
    for force, share in curve[::7]:
        assert share == pytest.approx(arm.percent_capable(force))


def test_weighted_people_and_everyone_pooled():
    women = people("female", [50.0, 65.0, 90.0], [1.0, 2.0, 0.5])
    men = people("male", [70.0, 95.0, float("nan")], [1.5, 1.0, 3.0])  # no mass: left out
    groups = [
        CurveGroup(p.words, pose_figure(Figure.default(p.gender), ANGLES), p.gender, p)
        for p in (women, men)
    ]
    curves = hand_curves(groups, LOAD, together="everyone")
    assert list(curves) == ["some female", "some male", "everyone"]
    sums: dict[int, list[float]] = {}
    for group in groups:
        body = group.body
        arm = arm_force(body.points, "right", (0, 1, 0), group.gender, body.body_mass)
        for i, (force, share) in enumerate(curves[group.words]):
            each = [
                (
                    w,
                    1
                    - NormalDist().cdf(
                        (force - arm.gravity * m / body.body_mass - arm.mean) / arm.sd
                    ),
                )
                for m, w in zip(group.people.masses, group.people.weights)
                if np.isfinite(m)
            ]
            total = sum(w for w, _ in each)
            assert share == pytest.approx(100 * sum(w * c for w, c in each) / total)
            pooled = sums.setdefault(i, [0.0, 0.0])
            pooled[0] += sum(w * c for w, c in each)
            pooled[1] += total
    for i, (_, share) in enumerate(curves["everyone"]):
        assert share == pytest.approx(100 * sums[i][0] / sums[i][1])
