"""A task's statics (model/strength/task.py, statics.py, low_back.py): the
floor's force under each foot, the low back by one equivalent muscle, the
balance over the feet, passive joints, the one convention for a hand's
force.  Each number is computed here by hand from the figure's own segment
masses and positions (the posed humanoid's), or from de Leva (1996)."""

from __future__ import annotations

import numpy as np
import pytest

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim_mass import DE_LEVA
from sass_tui.model.body.posture import parse_angles, pose_figure
from sass_tui.model.strength.task import (
    Reference,
    arm_demand,
    assess_task,
    hand_load,
    load_of,
    pose_task,
)

G = 9.81
ABOVE_L5 = (
    "l5",
    "skull",
    "l_upperarm",
    "l_forearm",
    "l_carpal",
    "r_upperarm",
    "r_forearm",
    "r_carpal",
)


@pytest.fixture(scope="module")
def women():
    return [Reference("women", Figure.default("female"), None)]


@pytest.fixture(scope="module")
def men():
    return [Reference("men", Figure.default("male"), None)]


def moment(answer, joint):
    return next(m for m in answer.moments if m.joint == joint).moment


def test_quiet_standing_has_no_side_to_side_moment_at_the_legs(men):
    answer = assess_task(men, {}, [])
    for side in ("left", "right"):
        for joint in ("hip", "knee", "ankle"):
            x, y, z = moment(answer, f"{side} {joint}")
            assert abs(z) < 1.0 and abs(y) < 1.0
    feet = answer.stance.feet
    weight = Figure.default("male").output_mass() * G
    assert feet["left"][1][1] + feet["right"][1][1] == pytest.approx(weight, rel=1e-6)
    assert feet["left"][1][1] == pytest.approx(feet["right"][1][1], rel=1e-6)


def test_the_elbow_moment_of_100_n_with_the_forearm_level_is_de_levas(men):
    """The 50th-percentile man: forearm level (elbow 90, upper arm down),
    100 N held: the load at the third knuckle, de Leva's forearm and hand."""
    figure = Figure.default("male")
    angles = parse_angles(["right_elbow_y=90", "ankle_y=0"])
    answer = assess_task(men, angles, [load_of("right", "100 N")])
    body = pose_figure(figure, angles)
    forearm = float(np.linalg.norm(body.centers["r_radiocarpal"] - body.centers["r_elbow"]))
    mass = figure.output_mass()
    table = DE_LEVA["male"]
    # de Leva's hand: 0.61 % of the body, 79.00 % of wrist-MET3 from the wrist;
    # MET3 (the grip) 86.2 mm from the wrist for his men: the figure's hand
    # length is the fingertip's, wrist-MET3 = 36.24 / 79.00 of it
    hand = float(
        np.linalg.norm(body.points["r_metacarpophalangeal_3"] - body.centers["r_radiocarpal"])
    )
    by_hand = (
        100.0 * (forearm + hand)
        + table["forearm"][0] / 100 * mass * G * table["forearm"][1] / 100 * forearm
        + table["hand"][0] / 100 * mass * G * (forearm + 0.79 * hand)
    )
    elbow = moment(answer, "right elbow")
    assert abs(elbow[0]) == pytest.approx(by_hand, rel=0.05)
    # and against de Leva's own 86.2 mm to the knuckle
    assert hand == pytest.approx(0.0862, rel=0.05)


def _low_back_by_hand(body, hands):
    """L5/S1 about the trunk's axes from the segments above, one muscle 5 cm behind."""
    joint = body.centers["vl5"]
    turn = body.turns["vl5"]
    lateral, along, forward = turn[:, 0], turn[:, 1], turn[:, 2]
    forces = [
        (body.centers_of_mass[s], body.masses[s] * G * np.array([0, -1.0, 0])) for s in ABOVE_L5
    ]
    forces += hands
    m = sum(np.cross(where - joint, f) for where, f in forces)
    total = sum(f for _, f in forces)
    flexion = float(m @ lateral)
    compression = max(flexion, 0.0) / 0.05 - float(total @ along)
    return flexion, compression, float(total @ forward)


@pytest.mark.parametrize(
    "posture",
    [
        ["trunk_y=30", "hip_y=60", "shoulder_y=90", "ankle_y=0"],  # a stoop, arms hanging
        ["hip_y=100", "knee_y=100", "ankle_y=10", "trunk_y=20", "shoulder_y=50"],  # a squat
    ],
)
def test_stoop_and_squat_low_back_by_hand(women, posture):
    angles = parse_angles(posture)
    figure = Figure.default("female")
    compressions = []
    for kg in (10.0, 20.0):
        loads = [load_of("left", f"{kg / 2} kg"), load_of("right", f"{kg / 2} kg")]
        answer = assess_task(women, angles, loads)
        body, _, _, _ = pose_task(figure, angles, loads)
        hands = [(body.grip(x.side), x.on_body) for x in loads]
        flexion, compression, shear = _low_back_by_hand(body, hands)
        back = answer.low_back
        assert back.moment[0] == pytest.approx(flexion, rel=0.01)
        assert back.compression == pytest.approx(compression, rel=0.01)
        assert back.shear == pytest.approx(shear, rel=0.01)
        assert back.compression >= back.moment[0] / 0.05
        compressions.append(back.compression)
    assert compressions[1] > compressions[0]


def test_a_light_push_at_shoulder_height_is_no_burden_on_the_legs(women):
    angles = parse_angles(["shoulder_y=90", "elbow_y=0"])
    answer = assess_task(women, angles, [load_of("right", "40 N", "forward")])
    assert answer.stance.stable
    for c in answer.capabilities:
        assert c.percent["women"] >= 90.0, c
    assert (
        answer.limiting("women") is None
        or answer.limiting("women").what == "right hand"
        or (answer.limiting("women").percent["women"] >= 90.0)
    )


def test_a_heavy_push_tips_the_body_and_is_not_scored(women):
    angles = parse_angles(["shoulder_y=90", "elbow_y=0"])
    answer = assess_task(women, angles, [load_of("right", "400 N", "forward")])
    assert not answer.stance.stable and "tip" in answer.stance.reason
    assert answer.limiting("women") is None and "women" in answer.unstable


def test_leaning_past_the_feet_is_out_of_balance(women):
    # ankles at their limit, trunk and hips forward, arms reaching forward
    angles = parse_angles(["ankle_y=14", "hip_y=90", "trunk_y=40", "shoulder_y=90"])
    answer = assess_task(women, angles, [load_of("right", "5 kg")])
    assert not answer.stance.stable
    assert answer.stance.center_of_pressure[2] > answer.stance.center_of_mass[2] - 1.0


def test_a_straight_knee_under_the_body_is_passive_not_limiting(women):
    answer = assess_task(women, {}, [])
    knees = [c for c in answer.capabilities if c.what.endswith("knee")]
    assert knees and all(c.passive for c in knees)
    limiting = answer.limiting("women")
    assert limiting is None or not limiting.passive


def test_the_hand_exerts_the_force_in_task_and_arm_force(women):
    angles = parse_angles(["shoulder_y=90", "elbow_y=0"])
    push = load_of("right", "40 N", "forward")
    answer = assess_task(women, angles, [push])
    body, _, _, _ = pose_task(Figure.default("female"), angles, [push])
    hand = next(c for c in answer.capabilities if c.what == "right hand")
    assert hand.percent["women"] == pytest.approx(
        arm_demand(body, push, "female").percent_capable(40.0)
    )
    assert tuple(hand_load("right", 40.0, (0, 0, 1)).vector) == (0.0, 0.0, 40.0)


def test_a_load_held_behind_the_low_back_is_said(women):
    """trunk_y=30 carries the hanging arms back with the trunk: the hand is
    15 cm behind L5/S1 and its load lowers the low back's moment, said in a
    note with the distance measured on the posed figure; arms brought
    forward, or quiet standing with the arms hanging, say nothing."""
    box = [load_of("right", "10 kg")]
    angles = parse_angles(["trunk_y=30"])
    answer = assess_task(women, angles, box)
    body = pose_task(women[0].figure, angles, box)[0]
    behind = body.centers["vl5"][2] - body.grip("right")[2]
    assert behind > 0.10
    said = [note for note in answer.cautions if "behind the low back" in note]
    assert said == [
        next(n for n in said if f"right hand holds its load {behind * 100:.1f} cm behind" in n)
    ]
    bare = assess_task(women, angles, [])
    assert answer.low_back.moment[0] < bare.low_back.moment[0]  # the load lowers it
    for words in (["trunk_y=30", "shoulder_y=30"], []):
        quiet = assess_task(women, parse_angles(words), box)
        assert not [note for note in quiet.cautions if "behind the low back" in note]
