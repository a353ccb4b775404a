"""The expected share of a task's loaded hand over the stored virtual people
of the shipped virtual population, computed here without sass's task code:
each person's probability of exerting the load (the figure's Arm Force
Field, the arm's weight by their own mass: the normal tail written out with
math.erf), weighted by the survey's weights.  For tests/db and tests/ui."""

from __future__ import annotations

import math

import numpy as np

from sass_tui.db.engine.database import Database
from sass_tui.db.people.values import load_values
from sass_tui.db.populations.targets import load_target
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles
from sass_tui.model.strength.arm_force_field import arm_force
from sass_tui.model.strength.task import hand_load, pose_task

VIRTUAL = "nhanes-2017-2020"


def virtual_people(db: str, gender: str) -> tuple[np.ndarray, np.ndarray]:
    """The stored virtual people of one gender (mass) and their survey weights."""
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            query = f'source = "virtual:{VIRTUAL}" AND gender = {gender}'
            values = load_values(conn, ["mass"], query)
            weights = load_target(conn, f"virtual:{VIRTUAL}").of(values.ids)
    finally:
        opened.close()
    return values.matrix[:, 0], weights


def right_hand_sums(db: str, gender: str, posture: list[str], load: float) -> tuple[float, float]:
    """(sum of weight x probability, sum of weight) of one gender's virtual
    people holding `load` N down in the right hand in `posture`."""
    mass, weights = virtual_people(db, gender)
    assert len(mass) > 1000  # NHANES 2017-2020's adults of one gender
    # standing as the task stands: leaning at the ankles unless ankle_y is given
    held = [hand_load("right", load, (0.0, 1.0, 0.0))]
    body, _, _, _ = pose_task(Figure.default(gender), parse_angles(posture), held)
    arm = arm_force(body.points, "right", (0, 1, 0), gender, body.body_mass)
    z = (load - arm.gravity * mass / body.body_mass - arm.mean) / arm.sd
    each = np.array([0.5 * (1 - math.erf(v / math.sqrt(2))) for v in z])
    return float((each * weights).sum()), float(weights.sum())
