"""Strength of real people: `sass strength --person` predicts an ANSUR II
person's knee-extension torque from their own gender, age, mass and stature
through Anderson et al. 2007, marked as predicted.

The person's numbers are read here from the independent copy of ANSUR II
(tests/_paths.ANSUR), the model's coefficients typed from the paper's
Table 3 (knee extension).  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json
import math
from statistics import NormalDist

import pytest

from sass_tui.cli import main
from tests._paths import ANSUR, shared_file

# Table 3, knee extension: (gender, age group) -> C1, C2, C3 (rad).
KNEE_EXTENSION = {
    ("Male", "18-25"): (0.163, 1.258, 1.133),
    ("Male", "55-65"): (0.156, 1.225, 1.173),
    ("Female", "18-25"): (0.159, 1.187, 1.274),
    ("Female", "55-65"): (0.128, 1.286, 1.141),
    ("Male", "over-65"): (0.137, 1.310, 1.067),
    ("Female", "over-65"): (0.124, 1.347, 1.140),
}


# Table 3, knee extension: the SD of C1 (the spread percent capable reads).
KNEE_EXTENSION_SD = {
    ("Male", "18-25"): 0.040,
    ("Male", "55-65"): 0.031,
    ("Female", "18-25"): 0.028,
    ("Female", "55-65"): 0.016,
    ("Male", "over-65"): 0.017,
    ("Female", "over-65"): 0.018,
}


def spread(key: tuple[str, str]) -> float:
    """The SD of C1 between people: Table 3's, floored at the pooled CV of the
    18-25 and 55-65 groups (14 people each) times the group's mean."""
    gender, _ = key
    cvs = [
        KNEE_EXTENSION_SD[(gender, g)] / KNEE_EXTENSION[(gender, g)][0] for g in ("18-25", "55-65")
    ]
    pooled = math.sqrt(sum(cv * cv for cv in cvs) / 2)
    return max(KNEE_EXTENSION_SD[key], pooled * KNEE_EXTENSION[key][0])


def group_of(age: int) -> str:
    # The paper's groups; between them the nearer (docs/strength.md: 40 splits).
    return "18-25" if age <= 40 else "55-65" if age <= 65 else "over-65"


def people() -> list[dict[str, str]]:
    """The first ANSUR II man and woman of 18-25 and of 41-65 in the survey's order."""
    if not ANSUR.is_dir():
        pytest.skip(f"the independent ANSUR II copy is not at {ANSUR}")
    chosen = []
    for gender, letter in (("MALE", "M"), ("FEMALE", "F")):
        path = ANSUR / f"ANSUR_II_{gender}_Public.csv"
        with open(path, encoding="latin-1", newline="") as handle:
            rows = list(csv.DictReader(handle))
        for low, high in ((18, 25), (41, 65)):
            row = next(r for r in rows if low <= int(r["Age"]) <= high)
            # The two files spell the id column differently (subjectid, SubjectId).
            ident = row.get("subjectid") or row["SubjectId"]
            chosen.append({**row, "name": f"ANSUR II {letter} {ident}"})
    return chosen


def test_real_people_get_predicted_strength_from_their_own_body(shared_target, capsys):
    for person in people():
        mass, stature, age = (
            int(person["weightkg"]) / 10,
            int(person["stature"]) / 1000,
            int(person["Age"]),
        )
        c1, c2, c3 = KNEE_EXTENSION[(person["Gender"], group_of(age))]
        expected = c1 * mass * 9.81 * stature * math.cos(c2 * (math.radians(60) - c3))
        argv = ["strength", "--db", shared_target, "--unit", "N-m", "--format", "json"]
        assert main([*argv, "knee_extension", "knee_y=60", "--person", person["name"]]) == 0
        answer = json.loads(capsys.readouterr().out)
        assert answer["value"] == pytest.approx(expected, rel=0.005), person["name"]
        assert answer["predicted"] is True
        assert answer["source"].startswith("Anderson et al. 2007, ")
        assert f"predicted for {person['name']}" in answer["source"]


def test_person_refuses_what_it_takes_from_the_person(shared_target, capsys):
    argv = ["strength", "--db", shared_target, "knee_extension", "--person", "17"]
    assert main([*argv, "--mass", "80"]) == 2
    assert "--mass cannot be given with it" in capsys.readouterr().err
    assert main([*argv[:-1], "nobody"]) == 2
    assert "no person with id or name 'nobody'" in capsys.readouterr().err


def test_a_fit_test_takes_a_strength_limit_on_real_people(shared_target, capsys):
    """`sass fit --strength`: each person's probability of exerting the torque
    (C1 normal, Table 3's mean and the spread between people), its mean the
    share; computed here over
    the independent ANSUR II copy."""
    if not ANSUR.is_dir():
        pytest.skip(f"the independent ANSUR II copy is not at {ANSUR}")
    expected = {}
    for gender in ("MALE", "FEMALE"):
        with open(
            shared_file(ANSUR / f"ANSUR_II_{gender}_Public.csv"), encoding="latin-1", newline=""
        ) as f:
            rows = list(csv.DictReader(f))
        n, fit = 0, 0.0
        for row in rows:
            age, stature = int(row["Age"]), int(row["stature"])
            if age < 18:  # the paper starts at 18: not predicted, left out
                continue
            key = (row["Gender"], group_of(age))
            c1, c2, c3 = KNEE_EXTENSION[key]
            shape = int(row["weightkg"]) / 10 * 9.81 * stature / 1000
            shape *= math.cos(c2 * (math.radians(60) - c3))
            capable = 1 - NormalDist().cdf((150 / shape - c1) / spread(key))
            n += 1
            fit += capable if stature <= 1900 else 0.0
        expected[gender.lower()] = (n, round(fit, 2))
    argv = ["fit", "--db", shared_target, "--format", "json", "--strength"]
    assert main([*argv, "knee_extension >= 150 N-m at knee_y=60", "stature <= 190 cm"]) == 0
    result = json.loads(capsys.readouterr().out)
    got = {g: (v["n"], v["fit"]) for g, v in result["accommodated"].items() if g != "weighted"}
    for gender, (n, fit) in expected.items():
        assert got[gender][0] == n
        assert got[gender][1] == pytest.approx(fit, abs=0.02)
    assert result["limits"][-1] == "knee_extension >= 150 N-m at knee_y=60 (predicted)"
    table = ["fit", "--db", shared_target, "--strength", "knee_extension >= 150 N-m"]
    assert main([*table, "stature <= 190 cm"]) == 0
    assert "fit and excluded are expected numbers of people" in capsys.readouterr().out
    assert main([*argv, "knee_extension >= 150 at hip_y=3", "stature <= 190 cm"]) == 2
    assert "expected 'at knee_y=ANGLE'" in capsys.readouterr().err
