"""`sass task` for a real person (--person) and for a target population
(--target: each person scaled to their own size, weighted).  The target's
share is checked against the generated sample it is weighted to, computed
here with numpy.  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json
import math
from statistics import NormalDist

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.people.values import load_values
from sass_tui.db.populations.targets import load_target
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure
from sass_tui.model.strength.arm_force_field import arm_force
from tests._paths import ANSUR, shared_file
from tests._virtual_task import VIRTUAL, right_hand_sums
from tests.db.test_targets import civilian_women, write_sample

POSTURE = ["shoulder_y=90", "elbow_y=0", "ankle_y=0"]  # ankle_y given: no lean


@pytest.fixture(scope="module")
def sample() -> np.ndarray:
    return civilian_women(3000)


@pytest.fixture(scope="module")
def with_target(template_target, copy_database, sample, tmp_path_factory) -> str:
    folder = tmp_path_factory.mktemp("task-target")
    db = copy_database(template_target)
    csv_path = write_sample(folder / "civilian.csv", sample)
    assert main(["target", "civ", "--db", db, "--gender", "female", "--sample", str(csv_path)]) == 0
    return db


def test_a_target_population_is_weighted_to_its_sample(with_target, sample, capsys):
    argv = ["task", *POSTURE, "--db", with_target, "--right-load", "70N", "--target", "civ"]
    assert main([*argv, "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    (population,) = answer["limiting"]
    hand = next(c for c in answer["capable"] if c["what"] == "right hand")
    # the sample's own women: the figure's arm force, the arm's weight by each one's mass
    figure = Figure.default("female")
    body = pose_figure(figure, parse_angles(POSTURE))
    arm = arm_force(body.points, "right", (0, 1, 0), "female", body.body_mass)
    gravity = arm.gravity * sample[:, 1] / body.body_mass
    z = (70.0 - gravity - arm.mean) / arm.sd
    own = 100 * np.mean([0.5 * (1 - math.erf(v / math.sqrt(2))) for v in z])
    assert hand["percent"][population] == pytest.approx(own, abs=1.0)
    assert "target civ" in " ".join(answer["notes"])


def test_a_real_person_does_the_task_with_her_own_body(shared_target, capsys):
    if not ANSUR.is_dir():
        pytest.skip(f"the independent ANSUR II copy is not at {ANSUR}")
    with open(
        shared_file(ANSUR / "ANSUR_II_FEMALE_Public.csv"), encoding="latin-1", newline=""
    ) as handle:
        row = next(csv.DictReader(handle))
    name = f"ANSUR II F {row.get('subjectid') or row['SubjectId']}"
    argv = ["task", *POSTURE, "--db", shared_target, "--right-load", "40N", "--person", name]
    assert main([*argv, "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    assert list(answer["limiting"]) == [name]
    assert f"{int(row['weightkg']) / 10:.1f} kg" in answer["figure"]
    assert name in answer["figure"]


def test_a_fit_tests_strength_limit_is_weighted_by_the_target(with_target, capsys):
    """`sass fit --target --strength`: the target's share is the weighted mean
    of each person's probability (Table 3: knee extension C1 and its SD, the
    spread between people floored at the large groups' pooled CV)."""
    opened = Database.open(with_target)
    try:
        with opened.connection() as conn:
            weights = load_target(conn, "civ")
            values = load_values(conn, ["age", "mass", "stature"], weights.target.base_query)
    finally:
        opened.close()
    table3 = {"18-25": (0.159, 1.187, 1.274, 0.028), "55-65": (0.128, 1.286, 1.141, 0.016),
              "over-65": (0.124, 1.347, 1.140, 0.018)}  # fmt: skip
    # the spread between people: no group's CV below the pooled CV of the two
    # groups of 14 (18-25 and 55-65; docs/strength.md)
    pooled = math.sqrt(((0.028 / 0.159) ** 2 + (0.016 / 0.128) ** 2) / 2)
    table3 = {g: (c1, c2, c3, max(sd, pooled * c1)) for g, (c1, c2, c3, sd) in table3.items()}
    total = capable = 0.0
    for (age, mass, stature), w in zip(values.matrix, weights.of(values.ids)):
        if not 18 <= age <= 100 or w == 0:
            continue
        c1, c2, c3, sd = table3["18-25" if age <= 40 else "55-65" if age <= 65 else "over-65"]
        shape = mass * 9.81 * stature / 100 * math.cos(c2 * (math.radians(60) - c3))
        total += w
        capable += w * (1 - NormalDist().cdf((120 / shape - c1) / sd))
    argv = ["fit", "--db", with_target, "--target", "civ", "--format", "json", "--strength"]
    assert main([*argv, "knee_extension >= 120 N-m at knee_y=60", "stature <= 250 cm"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert result["target"]["percent"] == pytest.approx(100 * capable / total, abs=0.01)


@pytest.fixture(scope="module")
def virtual_task(template_target, copy_database) -> tuple[str, list[str]]:
    """A copy of the default database (the shipped virtual population not
    made yet: the task's first use makes it) and the task's arguments."""
    db = copy_database(template_target)
    argv = ["task", *POSTURE, "--db", db, "--right-load", "60N", "--virtual", VIRTUAL]
    return db, argv


@pytest.mark.slow
def test_a_virtual_population_is_weighted_by_its_survey_weights(virtual_task, capsys):
    """`sass task --virtual`: each gender's share of the right hand is the
    survey-weighted mean over the stored virtual people of each one's
    probability (the figure's Arm Force Field, the arm's weight by their own
    mass), computed here with numpy; together is both genders' people pooled."""
    db, argv = virtual_task
    assert main([*argv, "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    hand = next(c for c in answer["capable"] if c["what"] == "right hand")
    pooled_capable = pooled_weight = 0.0
    for gender, words in (("female", "VIRTUAL women"), ("male", "VIRTUAL men")):
        capable, weight = right_hand_sums(db, gender, POSTURE, 60.0)
        assert hand["percent"][words] == pytest.approx(100 * capable / weight, abs=0.05)
        pooled_capable += capable
        pooled_weight += weight
    together = hand["percent"]["VIRTUAL everyone"]
    assert together == pytest.approx(100 * pooled_capable / pooled_weight, abs=0.05)
    assert set(answer["limiting"]) == {
        "VIRTUAL women", "VIRTUAL men", "VIRTUAL everyone"
    }  # fmt: skip
    assert answer["notes"][0].startswith("VIRTUAL people, not measured: nhanes-2017-2020")
    knees = [c for c in answer["capable"] if c["what"].endswith("knee")]
    assert knees and all(len(c["percent"]) == 3 for c in knees)


def test_target_and_virtual_together_are_refused(virtual_task, capsys):
    db, argv = virtual_task
    with pytest.raises(SystemExit):
        main([*argv, "--target", "civ"])
    assert "not allowed with argument" in capsys.readouterr().err


def test_a_real_persons_elbow_moment_is_de_levas_from_their_own_forearm(shared_target, capsys):
    """100 N held, the forearm level: the elbow's moment within 5 % of a
    hand computation from the man's own forearm (radiale-stylion) and hand
    lengths with de Leva (1996)'s proportions: forearm 1.62 % of the body,
    its centre 45.74 % from the elbow; hand 0.61 %, its centre 36.24 % of
    the hand length; the grip (MET3) at 36.24 / 79.00 of the hand length."""
    if not ANSUR.is_dir():
        pytest.skip(f"the independent ANSUR II copy is not at {ANSUR}")
    with open(ANSUR / "ANSUR_II_MALE_Public.csv", encoding="latin-1", newline="") as handle:
        row = next(csv.DictReader(handle))
    name = f"ANSUR II M {row.get('subjectid') or row['SubjectId']}"
    forearm = float(row["radialestylionlength"]) / 1000
    hand = float(row["handlength"]) / 1000
    mass = float(row["weightkg"]) / 10
    by_hand = (
        100.0 * (forearm + hand * 36.24 / 79.00)
        + 0.0162 * mass * 9.81 * 0.4574 * forearm
        + 0.0061 * mass * 9.81 * (forearm + 0.3624 * hand)
    )
    argv = ["task", "right_elbow_y=90", "ankle_y=0", "--db", shared_target, "--right-load",
            "100N", "--person", name, "--format", "json"]  # fmt: skip
    assert main(argv) == 0
    answer = json.loads(capsys.readouterr().out)
    elbow = next(m for m in answer["moments_N_m"] if m["joint"] == "right elbow")
    assert abs(elbow["moment"][0]) == pytest.approx(by_hand, rel=0.05)
