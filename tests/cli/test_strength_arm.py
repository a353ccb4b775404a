"""`sass strength arm_force` (cli/strength_arm.py): the Arm Force Field from
a posture file, the figure in a posture, or a real person.  The posture-file
numbers are the authors' script's (tests/model/test_arm_force_field.py)."""

from __future__ import annotations

import json

import pytest

from sass_tui.cli import main
from sass_tui.model.strength.arm_force_field import POSTURE_JOINTS
from tests.model.test_arm_force_field import POSTURES


def posture_file(tmp_path, name="bent_trunk", change=None):
    points = dict(zip(POSTURE_JOINTS, POSTURES[name]))
    points.update(change or {})
    path = tmp_path / f"{name}.json"
    path.write_text(json.dumps(points))
    return str(path)


def answer(capsys, *argv):
    assert main(["strength", "arm_force", *argv, "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_a_posture_file_gives_the_authors_numbers(tmp_path, capsys):
    # bent_trunk: the script's left hand down, 90 N, 75 % capable; right hand up, 45 N
    path = posture_file(tmp_path)
    left = answer(
        capsys, "--posture", path, "--side", "left", "--direction", "down", "--gender", "female",
        "--load", "90N", "--capable", "75",
    )  # fmt: skip
    assert left["mean_N"] == pytest.approx(86.0733, abs=0.05)
    assert left["sd_N"] == pytest.approx(23.8423, abs=0.05)
    assert left["gravity_N"] == pytest.approx(12.0606, abs=0.05)
    assert left["strength_N"] == pytest.approx(82.0526, abs=0.05)
    assert left["percent_capable"] == pytest.approx(63.3507, abs=0.05)
    assert left["source"].startswith("La Delfa & Potvin 2017")
    right = answer(
        capsys, "--posture", path, "--side", "right", "--direction=0,1,0", "--gender", "female",
        "--load", "45", "--capable", "75",
    )  # fmt: skip
    assert right["strength_N"] == pytest.approx(50.8933, abs=0.05)
    assert right["percent_capable"] == pytest.approx(82.5071, abs=0.05)
    # rounded to the data's precision: no 12.732395447351628
    assert all(len(repr(right[k]).split(".")[-1]) <= 1 for k in ("mean_N", "sd_N", "gravity_N"))


def test_the_figure_in_a_posture_names_where_the_hand_is(capsys):
    assert main(
        ["strength", "arm_force", "shoulder_y=90", "elbow_y=0", "--direction", "up",
         "--load", "60 N", "--gender", "female"]
    ) == 0  # fmt: skip
    out = capsys.readouterr().out
    assert "percent capable of 60.0 N:" in out
    assert "m forward, 0.000 m up" in out
    assert "the female figure in posture shoulder_y=90 elbow_y=0" in out
    assert "source: La Delfa & Potvin 2017 (Arm Force Field), women, as published" in out


def test_lbf_on_request_and_the_curve(capsys):
    got = answer(capsys, "shoulder_y=60", "--direction", "forward", "--plot")
    curve = got["curve"]
    assert curve[0] == [0.0, 100.0] and curve[-1][1] <= 0.6
    assert all(a[1] >= b[1] for a, b in zip(curve, curve[1:]))
    assert main(["strength", "arm_force", "--direction", "up", "--unit", "lbf"]) == 0
    assert " lbf " in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv, message",
    [
        (["shoulder_q=30", "--direction", "up"], "unknown joint 'shoulder_q'"),
        (["--direction=0,0,0"], "the zero vector has no direction"),
        (["--direction=nan,1,0"], "three finite numbers"),
        (["shoulder_y=nan", "--direction", "up"], "shoulder_y=nan"),
        ([], "arm_force needs --direction"),
        (["--direction", "up", "--capable", "120"], "--capable 120"),
        (["--direction", "up", "--age", "30"], "--age"),
        (["--direction", "up", "--unit", "N-m"], "an arm force is given in N or lbf"),
    ],
)
def test_bad_input_names_the_field(capsys, argv, message):
    assert main(["strength", "arm_force", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_a_hand_inside_the_shoulder_and_a_broken_file(tmp_path, capsys):
    inside = posture_file(tmp_path, change={"r_metacarpophalangeal_3": POSTURES["bent_trunk"][7]})
    assert main(["strength", "arm_force", "--posture", inside, "--direction", "up"]) == 2
    assert "r_metacarpophalangeal_3 is within 1 cm of r_shoulder" in capsys.readouterr().err
    unknown = posture_file(tmp_path, change={"l_knuckle": [0, 1, 0]})
    assert main(["strength", "arm_force", "--posture", unknown, "--direction", "up"]) == 2
    assert "unknown joint 'l_knuckle'" in capsys.readouterr().err


def test_arm_options_are_refused_for_other_motions(capsys):
    assert main(["strength", "elbow_flexion", "--direction", "up"]) == 2
    assert "--direction is for arm_force" in capsys.readouterr().err
