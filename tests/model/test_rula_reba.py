"""RULA (McAtamney & Corlett 1993) and REBA (Hignett & McAtamney 2000) from
a task's posture (model/strength/rula.py, reba.py, datasets/rula.json,
reba.json).  Each case is scored here by
hand with the paper's rules and its tables' cells, typed from the paper."""

from __future__ import annotations

import pytest

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles
from sass_tui.model.strength.reba import neck_score as reba_neck_score
from sass_tui.model.strength.reba import read_tables as read_reba_tables
from sass_tui.model.strength.rula import (
    force_score,
    lower_arm_score,
    neck_score,
    read_tables,
    trunk_score,
    upper_arm_score,
    wrist_score,
)
from sass_tui.model.strength.task import Reference, assess_task, load_of

# (table, indices 1-based) -> the paper's cell
CELLS = [
    ("a", (1, 1, 1), 1), ("a", (3, 2, 1), 3), ("a", (5, 3, 8), 8), ("a", (6, 1, 8), 9),
    ("b", (1, 1), 1), ("b", (1, 7), 5), ("b", (4, 12), 8), ("b", (6, 8), 9),
    ("c", (4, 7), 6), ("c", (1, 1), 1), ("c", (8, 7), 7), ("c", (5, 4), 5),
]  # fmt: skip


@pytest.mark.parametrize("table, where, value", CELLS)
def test_the_tables_are_the_papers(table, where, value):
    cells = getattr(read_tables(), table)
    for i in where:
        cells = cells[i - 1]
    assert cells == value


def test_the_body_part_scores_follow_the_paper():
    assert [upper_arm_score(f, 0) for f in (0, 30, -30, 60, 120)] == [1, 2, 2, 3, 4]
    assert upper_arm_score(60, 45) == 4  # abducted: +1
    assert [lower_arm_score(e) for e in (0, 80, 120)] == [2, 1, 2]
    assert [wrist_score(w, 0) for w in (0, 10, -30)] == [1, 2, 3]
    assert wrist_score(10, 20) == 3  # bent from the midline: +1
    assert [trunk_score(t, 0, 0) for t in (0, 10, 40, 80)] == [1, 2, 3, 4]
    assert trunk_score(10, 20, 10) == 4  # twisted and side-bent
    assert [force_score(n) for n in (10, 50, 150)] == [0, 1, 3]


def test_standing_upright_and_a_stoop_with_20_kg():
    women = [Reference("women", Figure.default("female"), None)]
    upright = assess_task(women, {}, [])
    # arms hanging: upper arm 1, lower arm 2 (elbow 0), wrist 1, twist 1: A = 2;
    # neck 1, trunk 1, legs 1: B = 1; C 2, D 1 -> Table C = 2
    assert [(r.posture_a, r.posture_b, r.score) for r in upright.rula] == [(2, 1, 2)] * 2
    angles = parse_angles(["trunk_y=30", "hip_y=60", "shoulder_y=90"])
    stoop = assess_task(women, angles, [load_of("left", "10 kg"), load_of("right", "10 kg")])
    # upper arm 3 (90 deg to the trunk), lower arm 2, wrist 1, twist 1: A = 3, +1
    # (10 kg in the hand) = 4; trunk 4 (90 deg), neck 1, legs 1: B = 5, +3 (20 kg) = 8 -> 7;
    # Table C (4, 7) = 6, action level 3
    right = stoop.rula[0]
    assert (right.upper_arm, right.trunk, right.posture_a, right.posture_b) == (3, 4, 3, 5)
    assert (right.score, right.action_level) == (6, 3)


# REBA (Hignett & McAtamney 2000): the paper's cells, typed from it
REBA_CELLS = [
    ("a", (1, 1, 1), 1), ("a", (1, 3, 1), 3), ("a", (4, 1, 1), 3), ("a", (5, 3, 4), 9),
    ("b", (3, 2, 1), 4), ("b", (6, 2, 3), 9), ("b", (1, 1, 3), 2),
    ("c", (5, 4), 5), ("c", (1, 12), 7), ("c", (12, 1), 12), ("c", (6, 9), 10),
]  # fmt: skip


@pytest.mark.parametrize("table, where, value", REBA_CELLS)
def test_rebas_tables_are_the_papers(table, where, value):
    cells = getattr(read_reba_tables(), table)
    for i in where:
        cells = cells[i - 1]
    assert cells == value


def test_reba_of_upright_standing_and_a_stoop_with_20_kg():
    women = [Reference("women", Figure.default("female"), None)]
    upright = assess_task(women, {}, [])
    # trunk 1, neck 1, legs 1: A 1, no load; upper arm 1, lower arm 2, wrist 1: B 1;
    # Table C (1, 1) = 1, negligible
    assert [(r.score_a, r.score_b, r.score, r.action_level) for r in upright.reba] == [
        (1, 1, 1, 0)
    ] * 2
    angles = parse_angles(["trunk_y=30", "hip_y=60", "shoulder_y=90"])
    stoop = assess_task(women, angles, [load_of("left", "10 kg"), load_of("right", "10 kg")])
    # trunk 4 (90 deg), neck 1, legs 1: Table A 3, +2 (20 kg) = 5; upper arm 3, lower
    # arm 2, wrist 1: Table B 4; Table C (5, 4) = 5, medium (action level 2)
    right = stoop.reba[0]
    assert (right.trunk, right.score_a, right.score_b, right.score) == (4, 5, 4, 5)
    assert right.action_level == 2
    # a deep squat's knees: +2 on the legs
    squat = assess_task(women, parse_angles(["hip_y=100", "knee_y=100", "ankle_y=10"]), [])
    assert squat.reba[0].legs >= 3


def test_the_neck_scores_follow_the_papers():
    # RULA: 0-10 deg flexion 1, 10-20 2, over 20 3, in extension 4; +1 twisted,
    # +1 side-bent
    assert [neck_score(f, 0, 0) for f in (0, 10, 15, 20, 35, -10)] == [1, 1, 2, 2, 3, 4]
    assert neck_score(5, 20, 0) == 2 and neck_score(5, 20, 15) == 3
    # REBA: 0-20 deg flexion 1, over 20 or in extension 2; +1 twisted or side-bent
    assert [reba_neck_score(f, False) for f in (0, 20, 25, -10)] == [1, 1, 2, 2]
    assert reba_neck_score(10, True) == 2


def test_the_posed_neck_reaches_both_scores():
    women = [Reference("women", Figure.default("female"), None)]
    # upright, the head bent forward 30 deg and turned 20 deg to the right
    task = assess_task(women, parse_angles(["neck_y=30", "neck_z=20"]), [])
    rula, reba = task.rula[0], task.reba[0]
    # RULA neck 3 (over 20 deg) + 1 (twisted) = 4; trunk 1, legs 1: Table B
    # (neck 4, trunk 1, legs 1) = 5; A 2 (arms hanging, as upright); Table C (2, 5)
    assert (rula.neck, rula.posture_b) == (4, 5)
    assert rula.score == read_tables().c[2 - 1][5 - 1]
    # REBA neck 2 + 1 (twisted) = 3; trunk 1, legs 1: Table A (1, 3, 1) = 3;
    # B 1; Table C (3, 1) = 2, low (the upright posture alone scores 1)
    assert (reba.neck, reba.score_a, reba.score_b, reba.score) == (3, 3, 1, 2)
    upright = assess_task(women, {}, [])
    assert (upright.rula[0].neck, upright.reba[0].neck) == (1, 1)
    # the head bent back: RULA's extension, 4
    back = assess_task(women, parse_angles(["neck_y=-20"]), [])
    assert (back.rula[0].neck, back.reba[0].neck) == (4, 2)
