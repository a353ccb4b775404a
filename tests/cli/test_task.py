"""`sass task` (cli/task.py, model/strength/task.py): the moments of a posture with
loads on the hands, from the figure's own segment masses and centres of
mass, and who can do it.  The shoulder's moment is computed here by hand
from the HAnim export's segments (`sass export hanim`) and the .fig's palm."""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET

import pytest

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure
from sass_tui.model.strength.arm_force_field import arm_force

G = 9.81


def hanim_parts(path):
    """name -> (mass kg, centre of mass or joint centre [x, y, z] m)."""
    parts = {}
    for element in ET.parse(path).iter():
        tag = element.tag.split("}")[-1]
        if tag == "HAnimSegment" and element.get("mass"):
            com = [float(v) for v in element.get("centerOfMass").split()]
            parts[element.get("name")] = (float(element.get("mass")), com)
        elif tag == "HAnimJoint" and element.get("center"):
            parts[element.get("name")] = (0.0, [float(v) for v in element.get("center").split()])
    return parts


@pytest.fixture(scope="module")
def female(tmp_path_factory):
    where = tmp_path_factory.mktemp("female")
    assert main(["export", "hanim", "--gender", "female", "-o", str(where / "f.x3d")]) == 0
    assert main(["fig", "--gender", "female", "--no-strength", "-o", str(where / "f.fig")]) == 0
    text = (where / "f.fig").read_text()
    palm = re.search(r"lhandz = ([\d.]+)cm;", text)
    fingers = re.search(r"lfingersz = ([\d.]+)cm;", text)
    # the third knuckle (de Leva 1996): the hand's centre of mass is 74.74 % of
    # wrist-MET3 and 34.27 % of wrist-fingertip for women
    hand = (float(palm.group(1)) + float(fingers.group(1))) / 100.0
    return hanim_parts(where / "f.x3d"), hand * 34.27 / 74.74


def task(capsys, *argv):
    assert main(["task", *argv, "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


def moment_of(answer, joint):
    return next(m for m in answer["moments_N_m"] if m["joint"] == joint)


def test_arm_held_forward_with_a_load_shoulder_moment_by_hand(female, capsys):
    parts, palm = female
    shoulder_y = parts["l_shoulder"][1][1]
    wrist_y = parts["l_radiocarpal"][1][1]
    # Held forward (shoulder flexed 90 deg, elbow straight): each centre of
    # mass as far forward of the shoulder as it hung below it.
    by_hand = sum(
        parts[s][0] * G * (shoulder_y - parts[s][1][1])
        for s in ("l_upperarm", "l_forearm", "l_carpal")
    )
    reach = shoulder_y - wrist_y + palm  # to the third knuckle, the grip centre
    by_hand += 50.0 * reach
    # ankle_y given: the body stands as exported, no lean at the ankles
    answer = task(capsys, "left_shoulder_y=90", "left_elbow_y=0", "ankle_y=0", "--left-load",
                  "50N", "--left-direction", "up", "--gender", "female")  # fmt: skip
    shoulder = moment_of(answer, "left shoulder")
    assert shoulder["moment"][0] == pytest.approx(by_hand, abs=0.06)
    assert shoulder["moment"][1] == pytest.approx(0.0, abs=0.06)
    assert shoulder["moment"][2] == pytest.approx(0.0, abs=0.06)
    assert shoulder["from_loads"][0] == pytest.approx(50.0 * reach, abs=0.06)
    elbow_y = parts["l_elbow"][1][1]
    elbow_by_hand = sum(
        parts[s][0] * G * (elbow_y - parts[s][1][1]) for s in ("l_forearm", "l_carpal")
    ) + 50.0 * (elbow_y - wrist_y + palm)
    assert moment_of(answer, "left elbow")["moment"][0] == pytest.approx(elbow_by_hand, abs=0.06)
    # the unloaded right arm hangs: no moment at its shoulder
    assert moment_of(answer, "right shoulder")["size"] == pytest.approx(0.0, abs=0.06)


def test_the_loaded_hand_is_the_arm_force_field_against_the_load(capsys):
    posture = ["shoulder_y=90", "elbow_y=0", "ankle_y=0"]
    answer = task(capsys, *posture, "--right-load", "60N", "--gender", "male")
    body = pose_figure(Figure.default("male"), parse_angles(posture))
    expected = arm_force(body.points, "right", (0, 1, 0), "male", body.body_mass)
    hand = next(c for c in answer["capable"] if c["what"] == "right hand")
    assert hand["percent"]["men"] == pytest.approx(expected.percent_capable(60.0), abs=0.05)
    assert hand["source"].startswith("La Delfa & Potvin 2017")
    assert answer["limiting"]["men"] in {c["what"] for c in answer["capable"]}
    assert set(answer["not_covered"]) == {"left wrist", "right wrist"}


def test_women_and_men_by_default_and_the_limiting_joint_named(capsys):
    assert main(["task", "shoulder_y=60", "elbow_y=30", "--right-load", "100N"]) == 0
    out = capsys.readouterr().out
    assert "women" in out and "men" in out
    assert "limiting for women: right hand" in out
    assert "not covered: left wrist, right wrist: no published model" in out


def test_a_forward_lean_needs_hip_extension(capsys):
    # a load held far forward: the body above the hips tips forward
    answer = task(capsys, "shoulder_y=90", "elbow_y=0", "--left-load", "100N",
                  "--right-load", "100N", "--gender", "female")  # fmt: skip
    hip = next(c for c in answer["capable"] if c["what"] == "left hip")
    assert hip["motion"] == "hip_extension" and hip["demand"] > 0
    assert hip["source"] == "Anderson et al. 2007"


@pytest.mark.parametrize(
    "argv, message",
    [
        (["--left-direction", "up"], "--left-direction without --left-load"),
        (["--left-load", "10 kg", "--left-direction", "down"], "is a mass: the hand holds"),
        (["--left-load", "abc"], "expected a number"),
        (["--left-load", "10", "--left-direction=0,0,0"], "the zero vector has no direction"),
        (["--left-load", "-5"], "--left-load '-5': expected a force or a mass of 0 or more"),
        # said as typed (it said "--left-load -98.10000000000001 N")
        (["--left-load", "-10kg"], "--left-load '-10kg': expected a force or a mass of 0 or more"),
        (["shoulder_y=90", "shoulder_y=45"], "'shoulder_y=45': shoulder_y is given twice"),
        (["knee_q=10", "--left-load", "10"], "unknown joint 'knee_q'"),
        (["--left-load", "10", "--person", "1", "--mass", "70"], "leave out --mass"),
    ],
)
def test_bad_tasks_say_what_is_wrong(capsys, argv, message):
    assert main(["task", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_the_hands_share_is_the_same_in_task_and_arm_force(capsys):
    """One convention: the force the hand exerts, in both verbs, the same
    posture (ankle_y given: the task's body does not lean; 20 N keeps it in
    balance) and force."""
    posture = ["shoulder_y=90", "elbow_y=0", "ankle_y=0"]
    answer = task(capsys, *posture, "--right-load", "20N", "--right-direction", "forward",
                  "--gender", "female")  # fmt: skip
    hand = next(c for c in answer["capable"] if c["what"] == "right hand")
    assert main(["strength", "arm_force", *posture, "--side", "right", "--direction", "forward",
                 "--load", "20N", "--gender", "female", "--format", "json"]) == 0  # fmt: skip
    arm = json.loads(capsys.readouterr().out)
    assert hand["percent"]["women"] == arm["percent_capable"]
    # and both say the same of where the Arm Force Field was fitted: the
    # woman's straight arm puts the hand past the 0.52 m ahead it was fitted on
    assert hand["extrapolated"] == arm["outside_fitted"]
    assert arm["outside_fitted"].startswith("the hand 0.56 m forward (fitted 0.00 to 0.52)")


def test_a_hand_within_the_fitted_places_is_not_called_extrapolated(capsys):
    # The elbow bent at shoulder height: the hand 0.24 m ahead, 0.33 m up.
    posture = ["shoulder_y=90", "elbow_y=90", "ankle_y=0"]
    answer = task(capsys, *posture, "--right-load", "20N", "--right-direction", "forward",
                  "--gender", "female")  # fmt: skip
    hand = next(c for c in answer["capable"] if c["what"] == "right hand")
    assert hand["extrapolated"] is None
    assert main(["task", *posture, "--right-load", "20N", "--right-direction", "forward",
                 "--gender", "female"]) == 0  # fmt: skip
    assert "extrapolated" not in capsys.readouterr().out
    # the straight arm: the text says it under the hand's row
    assert main(["task", "shoulder_y=90", "elbow_y=0", "ankle_y=0", "--right-load", "20N",
                 "--right-direction", "forward", "--gender", "female"]) == 0  # fmt: skip
    text = capsys.readouterr().out
    assert re.search(r"\n  right hand: force exerted 20\.0 N .*\n    right hand: the hand 0\.56 m "
                     r"forward \(fitted 0\.00 to 0\.52\) lies outside", text), text  # fmt: skip
