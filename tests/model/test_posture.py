"""The figure in a posture (model/body/posture.py): the hand placed on the
figure's own HAnim humanoid (model/body/hanim.py), and the posture file."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.body.posture import PostureError, parse_angles, pose_figure, read_posture_file
from sass_tui.model.names import GIRTH, row_index
from sass_tui.model.strength.strength_conditions import StrengthError


@pytest.fixture(scope="module")
def figure():
    return Figure.default("female")


def palm(figure, side):
    """The wrist to the third knuckle: de Leva (1996) puts the hand's centre
    of mass at 74.74 % of wrist-MET3 and 34.27 % of wrist-fingertip (women)."""
    values = figure.output_values(GIRTH)[0]
    hand = (
        values[row_index(GIRTH, f"{side}_hand"), 2]
        + values[row_index(GIRTH, f"{side}_knuckles"), 2]
    )
    return hand / 100.0 * 34.27 / 74.74


def test_standing_the_hand_hangs_below_the_wrist_to_the_third_knuckle(figure):
    humanoid = build_humanoid(figure)
    body = pose_figure(figure)
    for s, side in (("l", "left"), ("r", "right")):
        wrist = humanoid.centers[f"{s}_radiocarpal"]
        assert body.points[f"{s}_radiocarpal"] == pytest.approx(wrist)
        knuckle = body.points[f"{s}_metacarpophalangeal_3"]
        assert knuckle == pytest.approx(wrist - [0, palm(figure, side), 0])


def test_arms_held_forward_reach_the_segment_lengths_at_shoulder_height(figure):
    humanoid = build_humanoid(figure)
    body = pose_figure(figure, parse_angles(["shoulder_y=90", "elbow_y=0"]))
    for s, side in (("l", "left"), ("r", "right")):
        shoulder = humanoid.centers[f"{s}_shoulder"]  # standing, the feet flat: no lean
        reach = shoulder[1] - humanoid.centers[f"{s}_radiocarpal"][1] + palm(figure, side)
        hand = body.points[f"{s}_metacarpophalangeal_3"]
        assert hand == pytest.approx(shoulder + [0, 0, reach], abs=1e-9)


def test_abduction_flexion_and_one_side(figure):
    humanoid = build_humanoid(figure)
    body = pose_figure(figure, parse_angles(["left_shoulder_x=90", "right_elbow_y=90"]))
    shoulder, elbow = humanoid.centers["l_shoulder"], humanoid.centers["l_elbow"]
    upper = shoulder[1] - elbow[1]
    # the left arm out to the body's left (+x), level with the shoulder
    assert body.points["l_elbow"] == pytest.approx(shoulder + [upper, 0, 0], abs=1e-9)
    # the right forearm forward (+z) from the hanging elbow
    wrist = body.points["r_radiocarpal"]
    assert wrist[1] == pytest.approx(humanoid.centers["r_elbow"][1], abs=1e-9)
    assert wrist[2] > 0.2


def test_segments_move_with_their_joint_and_keep_their_mass(figure):
    humanoid = build_humanoid(figure)
    body = pose_figure(figure, parse_angles(["shoulder_y=90", "elbow_y=0"]))
    for segment in ("l_upperarm", "l_forearm", "l_carpal", "l5", "r_thigh"):
        assert body.masses[segment] == pytest.approx(humanoid.segments[segment].mass)
    shoulder = humanoid.centers["l_shoulder"]
    standing = humanoid.segments["l_upperarm"].center_of_mass - shoulder
    turned = body.centers_of_mass["l_upperarm"] - shoulder
    # a quarter turn forward about the shoulder: down becomes forward
    assert turned == pytest.approx([standing[0], -standing[2], -standing[1]], abs=1e-9)
    assert body.centers_of_mass["l5"] == pytest.approx(humanoid.segments["l5"].center_of_mass)


def test_the_neck_turns_the_head_about_the_head_neck_joint(figure):
    """neck_y (flexion) turns the head (HAnim skull) about skullbase, the
    report's atlanto-occipital joint; nothing below it moves."""
    humanoid = build_humanoid(figure)
    body = pose_figure(figure, parse_angles(["neck_y=60"]))
    joint = humanoid.centers["skullbase"]
    _, dy, dz = humanoid.segments["skull"].center_of_mass - joint
    a = math.radians(60)
    # flexion tips the head forward (+z): about the body's lateral axis
    expected = joint + [
        0.0,
        dy * math.cos(a) - dz * math.sin(a),
        dy * math.sin(a) + dz * math.cos(a),
    ]
    assert body.centers_of_mass["skull"] == pytest.approx(expected, abs=1e-9)
    assert body.centers_of_mass["skull"][2] > humanoid.segments["skull"].center_of_mass[2]
    for segment in ("l5", "l_upperarm", "r_thigh"):
        assert body.centers_of_mass[segment] == pytest.approx(
            humanoid.segments[segment].center_of_mass, abs=1e-12
        )
    # bent to the right: the head goes to the body's right (-x)
    bent = pose_figure(figure, parse_angles(["neck_x=30"]))
    assert bent.centers_of_mass["skull"][0] < joint[0] - 0.005


def test_the_neck_has_no_side_and_keeps_to_the_reports_neck_limits(figure):
    with pytest.raises(PostureError, match="the neck has no side; write neck_y=ANGLE"):
        parse_angles(["left_neck_y=10"])
    with pytest.raises(StrengthError, match="neck y 80 deg is above the neck upper limit"):
        pose_figure(figure, parse_angles(["neck_y=80"]))


@pytest.mark.parametrize(
    "items, message",
    [
        (["shoulder_q=30"], "unknown joint 'shoulder_q'"),
        (["elbow=30"], "unknown joint 'elbow'"),
        (["shoulder_y"], r"expected JOINT=ANGLE, e.g. shoulder_y=90$"),
        (["cm"], r"'cm' is a unit: write it against its number, as in 12cm"),
        (
            ["trunk_y=10", "trunk_y=20"],
            r"'trunk_y=20': trunk_y is given twice \(also 'trunk_y=10'\)",
        ),
        (["left_knee_y=10", "knee_y=20"], r"knee_y is given twice \(also 'left_knee_y=10'\)"),
        (["shoulder_y=nan"], "shoulder_y=nan"),
        (["elbow_y=abc"], "elbow_y=abc"),
    ],
)
def test_bad_angles_name_the_joint(items, message):
    with pytest.raises(PostureError, match=message):
        parse_angles(items)


def test_a_sides_word_after_the_word_for_both_sides_sets_that_side():
    angles = parse_angles(["shoulder_y=90", "left_shoulder_y=45"])
    assert angles[("left", "shoulder_y")] == 45 and angles[("right", "shoulder_y")] == 90


def test_an_angle_beyond_the_joint_limit_is_refused(figure):
    with pytest.raises(StrengthError, match="left elbow y 200 deg is above the left elbow upper"):
        pose_figure(figure, parse_angles(["left_elbow_y=200"]))


@settings(max_examples=80, deadline=None)
@given(st.lists(st.text(max_size=20), max_size=3))
def test_any_angle_text_parses_or_is_refused_clearly(items):
    try:
        angles = parse_angles(items)
    except PostureError as exc:
        assert str(exc)
    else:
        assert all(math.isfinite(v) for v in angles.values())


def test_a_posture_file_reads_back_and_bad_ones_say_where(tmp_path):
    body = pose_figure(Figure.default("male"), parse_angles(["shoulder_y=45"]))
    good = tmp_path / "reach.json"
    good.write_text(json.dumps({k: v.tolist() for k, v in body.points.items()}))
    read = read_posture_file(good)
    assert all(np.array_equal(read[k], body.points[k]) for k in body.points)
    broken = tmp_path / "broken.json"
    broken.write_text('{"vc7": [0, 1,\n')
    with pytest.raises(PostureError, match=r"broken.json:2: not JSON"):
        read_posture_file(broken)
    with pytest.raises(PostureError, match="cannot read"):
        read_posture_file(tmp_path / "missing.json")
