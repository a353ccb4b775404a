"""A standing posture whose legs differ (model/body/posture.py `_stand`,
model/strength/statics.py): the body stands on the foot of the longer leg,
the floor's force acts only on the feet on the floor, and a foot off the
floor carries nothing but its own weight.  Each number is checked by hand
from the posed figure's own segment masses and positions, or by the whole
body's equilibrium."""

from __future__ import annotations

import json

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import ON_FLOOR_M, parse_angles, pose_figure
from sass_tui.model.strength.statics import GRAVITY, moment_about, weights
from sass_tui.model.strength.task import QUIET_STANCE_COP_M, Reference, assess_task, pose_task

# the left leg swung forward, its foot pointed: shorter than the right
ON_THE_RIGHT_FOOT = ["left_hip_y=30", "left_ankle_y=-30"]
RIGHT_FOOT = ["r_talus", "r_tarsal_proximal_phalanx_2"]
LEFT_FOOT = ["l_talus", "l_tarsal_proximal_phalanx_2"]


@pytest.fixture(scope="module")
def woman():
    return Figure.default("female")


def moment(answer, joint):
    return np.array(next(m for m in answer.moments if m.joint == joint).moment)


def test_the_longer_leg_stands_flat_and_the_other_foot_is_off_the_floor(woman):
    body = pose_figure(woman, parse_angles(ON_THE_RIGHT_FOOT))
    assert body.bearing == ("right",)
    assert body.soles["right"][:, 1] == pytest.approx([0.0] * 4, abs=1e-9)
    assert float(body.soles["left"][:, 1].min()) > ON_FLOOR_M
    # both legs the same: both feet flat on the floor, as before
    assert pose_figure(woman, parse_angles(["hip_y=20", "ankle_y=-20"])).bearing == (
        "left",
        "right",
    )


def test_the_foot_off_the_floor_carries_only_its_own_weight(woman):
    answer = assess_task([Reference("women", woman, None)], parse_angles(ON_THE_RIGHT_FOOT), [])
    body, stance, *_ = pose_task(woman, parse_angles(ON_THE_RIGHT_FOOT), [])
    assert stance.bearing == ("right",)
    assert np.allclose(stance.feet["left"][1], 0.0)
    weight = woman.output_mass() * GRAVITY
    assert stance.feet["right"][1][1] == pytest.approx(weight, rel=1e-9)
    # the left ankle: the moment of the left foot's own weight, by hand
    ankle = body.centers["l_talocrural"]
    by_hand = np.zeros(3)
    for segment in LEFT_FOOT:
        r = body.centers_of_mass[segment] - ankle
        f = np.array([0.0, -body.masses[segment] * GRAVITY, 0.0])
        by_hand -= np.cross(r, f)
    assert moment(answer, "left ankle") == pytest.approx(by_hand, abs=0.05)
    assert np.linalg.norm(by_hand) < 2.0  # a foot's weight, not the body's


def test_the_standing_ankle_carries_everything_above_it(woman):
    """The right ankle's moment equals that of every weight but the right
    foot's about it: the floor acts on the right foot alone (its free moment
    about the vertical aside)."""
    answer = assess_task([Reference("women", woman, None)], parse_angles(ON_THE_RIGHT_FOOT), [])
    body, *_ = pose_task(woman, parse_angles(ON_THE_RIGHT_FOOT), [])
    above = [segment for segment in body.masses if segment not in RIGHT_FOOT]
    by_hand = moment_about(body.centers["r_talocrural"], weights(body, above))
    got = moment(answer, "right ankle")
    assert got[[0, 2]] == pytest.approx(by_hand[[0, 2]], abs=0.05)


def test_on_one_foot_the_base_is_that_foot(woman):
    """The body's centre of mass stays at the midline (no angle moves it
    sideways), outside the right sole: the posture would tip sideways, and
    REBA and RULA score the legs 2 (on one foot)."""
    answer = assess_task([Reference("women", woman, None)], parse_angles(ON_THE_RIGHT_FOOT), [])
    assert not answer.stance.stable
    assert "sideways" in answer.stance.reason
    right_sole = pose_task(woman, parse_angles(ON_THE_RIGHT_FOOT), [])[0].soles["right"]
    # the centre of pressure at the midline (x 0), the right sole's inner edge at -x
    assert answer.stance.center_of_pressure[0] == pytest.approx(0.0, abs=1e-9)
    assert answer.stance.margin == pytest.approx(float(right_sole[:, 0].max()), abs=1e-6)
    assert {r.legs for r in answer.reba} == {r.legs for r in answer.rula} == {2}
    quiet = assess_task([Reference("women", woman, None)], {}, [])
    assert {r.legs for r in quiet.reba} == {r.legs for r in quiet.rula} == {1}


def test_feet_apart_front_to_back_balance_the_body(woman):
    """The left foot forward and its heel down on the floor (the body leans
    onto it): both feet bear, their forces and the weights balance, moments
    too (the free moment is about the vertical alone), and neither foot pulls."""
    angles = parse_angles(["left_hip_y=30"])
    body, stance, *_ = pose_task(woman, angles, [])
    assert stance.bearing == ("left", "right")
    forces = weights(body) + list(stance.feet.values())
    assert np.sum([f for _, f in forces], axis=0) == pytest.approx([0.0] * 3, abs=1e-6)
    turning = moment_about(np.zeros(3), forces)
    assert turning[[0, 2]] == pytest.approx([0.0, 0.0], abs=1e-6)
    assert all(force[1] >= 0.0 for _, force in stance.feet.values())
    # the left foot's share acts where its sole touches: its heel, ahead of the right foot
    assert stance.feet["left"][0][2] > stance.feet["right"][0][2]


def test_the_standing_hips_side_to_side_moment_is_said_uncovered(woman):
    """On one foot the right hip carries the body above it side to side:
    the body's weight above the hip times the hip's distance from the
    foot's force, which Anderson et al.'s models (flexion and extension)
    do not cover, said in a note with its size; both feet down, none."""
    answer = assess_task([Reference("women", woman, None)], parse_angles(ON_THE_RIGHT_FOOT), [])
    sideways = abs(moment(answer, "right hip")[2])
    assert sideways > 40.0
    said = [n for n in answer.cautions if n.startswith("right hip: the moment side to side")]
    assert len(said) == 1 and f"{sideways:.1f} N-m is not covered" in said[0]
    quiet = assess_task([Reference("women", woman, None)], {}, [])
    assert not [n for n in quiet.cautions if "is not covered" in n]


def test_on_one_foot_the_body_leans_over_that_foot(woman):
    """A marching step (the left thigh forward, its knee bent, no ankle
    given): the lean at the ankles puts the centre of pressure 5 cm ahead
    of the standing foot's ankle, not of the ankles' midpoint (which the
    raised leg carries 18 cm forward)."""
    body, stance, _, lean = pose_task(woman, parse_angles(["left_hip_y=60", "left_knee_y=60"]), [])
    assert body.bearing == ("right",)
    ahead = stance.center_of_pressure[2] - body.centers["r_talocrural"][2]
    assert ahead == pytest.approx(QUIET_STANCE_COP_M, abs=1e-3)
    assert abs(lean) < 5.0


def test_the_cli_says_which_foot_stands(capsys):
    assert main(["task", *ON_THE_RIGHT_FOOT, "--gender", "female"]) == 0
    out = capsys.readouterr().out
    assert "standing on the right foot" in out
    assert "left 0 N (off the floor)" in out
    assert main(["task", *ON_THE_RIGHT_FOOT, "--gender", "female", "--format", "json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["balance"]["feet_on_floor"] == ["right"]
    assert data["balance"]["feet_N"]["left"] == [0.0, 0.0, 0.0]


def test_a_sole_put_into_the_floor_is_said(capsys):
    """A knee bent with the thigh upright and the foot not pointed puts the
    toes into the floor: counted as standing there, and said."""
    assert main(["task", "left_knee_y=30", "--gender", "female"]) == 0
    out = capsys.readouterr().out
    assert "the posture puts the left sole" in out and "cm into the floor" in out
