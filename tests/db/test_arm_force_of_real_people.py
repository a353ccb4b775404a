"""`sass strength arm_force --person`: a real person's own figure in the
posture, their own gender and body mass for the arm's weight (read here from
the independent ANSUR II copy).  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json

import pytest

from sass_tui.cli import main
from tests._paths import ANSUR, shared_file


def first_woman() -> dict[str, str]:
    if not ANSUR.is_dir():
        pytest.skip(f"the independent ANSUR II copy is not at {ANSUR}")
    with open(
        shared_file(ANSUR / "ANSUR_II_FEMALE_Public.csv"), encoding="latin-1", newline=""
    ) as handle:
        row = next(csv.DictReader(handle))
    return {**row, "name": f"ANSUR II F {row.get('subjectid') or row['SubjectId']}"}


def test_a_real_person_pushes_with_her_own_arm(shared_target, capsys):
    woman = first_woman()
    argv = ["strength", "arm_force", "shoulder_y=90", "elbow_y=0", "--db", shared_target]
    posture = ["--format", "json", "--direction", "up", "--person", woman["name"]]
    assert main([*argv, *posture]) == 0
    got = json.loads(capsys.readouterr().out)
    assert got["gender"] == "female"
    assert got["body_mass_kg"] == pytest.approx(int(woman["weightkg"]) / 10, abs=0.05)
    assert got["source"].startswith("La Delfa & Potvin 2017 (Arm Force Field), women")
    assert woman["name"] in got["posture"] and got["person"] == woman["name"]
    # the arm held forward at shoulder height: the hand level with the shoulder
    assert got["hand_m"]["up"] == pytest.approx(0.0, abs=0.001)
    assert main([*argv, *posture, "--mass", "70"]) == 2
    assert "--person takes the person's own gender, mass and stature" in capsys.readouterr().err
