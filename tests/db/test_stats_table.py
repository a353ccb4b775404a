"""`sass stats` (db/populations/stats.py, cli/stats.py) on both engines: the real
people's percentiles are numpy's over the ANSUR II CSV; the virtual NHANES
adults aged 20-59 have NHANES's own weighted 5th/50th/95th stature and mass
(cumulative weight over the published CSV, computed here); and a target's
outside_share of mass is the weighted share of NHANES women beyond every
ANSUR II woman."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

from sass_tui.cli import main
from tests._paths import ANSUR, nhanes_lines, shared_file


def nhanes_rows(code: str, low_age: float, high_age: float) -> list[dict[str, str]]:
    lines = nhanes_lines()
    return [
        r
        for r in csv.DictReader(lines)
        if r["RIAGENDR"] == code
        and r["RIDAGEYR"] != "NA"
        and low_age <= float(r["RIDAGEYR"]) <= high_age
        and r["BMXHT"] != "NA"
        and r["BMXWT"] != "NA"
    ]


def by_cumulative_weight(values: np.ndarray, weights: np.ndarray, q: float) -> float:
    order = np.argsort(values)
    share = np.cumsum(weights[order]) / weights.sum()
    return float(values[order][np.searchsorted(share, q)])


def run_json(capsys, *argv: str) -> dict:
    capsys.readouterr()
    assert main([*argv, "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.fixture(scope="module")
def shipped(template_target, copy_database) -> str:
    """A copy of the default database whose first use made the shipped populations."""
    db = copy_database(template_target)
    assert main(["stats", "--db", db, "--virtual", "nhanes-2017-2020", "stature"]) == 0
    return db


def test_the_real_womens_table_is_numpys_over_the_csv(shared_target, capsys):
    with shared_file(ANSUR / "ANSUR_II_FEMALE_Public.csv").open(
        encoding="latin-1", newline=""
    ) as handle:
        rows = list(csv.DictReader(handle))
    stature = np.array([float(r["stature"]) / 10 for r in rows])
    sitting = np.array([float(r["sittingheight"]) / 10 for r in rows])
    table = run_json(
        capsys, "stats", "--db", shared_target, "--gender", "female", "stature", "sittingheight"
    )
    assert table["n"] == 1986 and table["effective_n"] == 1986.0
    assert table["weighted_by"] is None and table["virtual"] is False
    for name, values in (("stature", stature), ("measure.sittingheight", sitting)):
        shown = table["measures"][name]
        assert shown["unit"] == "cm" and shown["n"] == 1986
        assert shown["mean"] == pytest.approx(values.mean(), abs=0.005)
        assert shown["sd"] == pytest.approx(values.std(), abs=0.005)
        for p in (1, 5, 50, 95, 99):
            assert shown["percentiles"][str(p)] == pytest.approx(
                np.percentile(values, p), abs=0.005
            )
        assert shown["outside_share"] is None


def test_inches_when_asked(shared_target, capsys):
    table = run_json(capsys, "stats", "--db", shared_target, "--unit", "in", "stature", "mass")
    assert table["measures"]["stature"]["unit"] == "in"
    assert table["measures"]["mass"]["unit"] == "kg"  # a length unit leaves mass in kg
    cm = run_json(capsys, "stats", "--db", shared_target, "stature")
    assert table["measures"]["stature"]["mean"] == pytest.approx(
        cm["measures"]["stature"]["mean"] / 2.54, abs=0.01
    )


@pytest.mark.slow
@pytest.mark.parametrize(("gender", "code"), [("female", "2"), ("male", "1")])
def test_virtual_adults_20_to_59_have_nhanes_weighted_percentiles(shipped, capsys, gender, code):
    rows = nhanes_rows(code, 20, 59)
    weights = np.array([float(r["WTMECPRP"]) for r in rows])
    table = run_json(
        capsys,
        "stats",
        "--db",
        shipped,
        "--virtual",
        "nhanes-2017-2020",
        "--query",
        "age >= 20 AND age <= 59",
        "--gender",
        gender,
        "--percentiles",
        "5,50,95",
        "stature",
        "mass",
    )
    assert table["virtual"] is True and "VIRTUAL" in table["population"]
    assert table["n"] == len(rows)
    assert main(["stats", "--db", shipped, "--virtual", "nhanes-2017-2020", "stature"]) == 0
    heading = capsys.readouterr().out.splitlines()[0]
    assert heading.startswith("VIRTUAL people, not measured: nhanes-2017-2020 (")
    assert heading.count("VIRTUAL") == 1  # said once, not twice
    for name, column in (("stature", "BMXHT"), ("mass", "BMXWT")):
        values = np.array([float(r[column]) for r in rows])
        for p in (5, 50, 95):
            own = by_cumulative_weight(values, weights, p / 100)
            assert table["measures"][name]["percentiles"][str(p)] == pytest.approx(own, abs=0.6)
        assert table["measures"][name]["outside_share"] is None


@pytest.mark.slow
def test_outside_share_of_the_weighted_real_women(shipped, capsys):
    rows = nhanes_rows("2", 20, 200)
    mass = np.array([float(r["BMXWT"]) for r in rows])
    weights = np.array([float(r["WTMECPRP"]) for r in rows])
    with shared_file(ANSUR / "ANSUR_II_FEMALE_Public.csv").open(
        encoding="latin-1", newline=""
    ) as handle:
        soldiers = np.array([float(r["weightkg"]) / 10 for r in csv.DictReader(handle)])
    beyond = (mass > soldiers.max()) | (mass < soldiers.min())
    expected = weights[beyond].sum() / weights.sum()
    table = run_json(
        capsys,
        "stats",
        "--db",
        shipped,
        "--target",
        "nhanes-2017-2020",
        "--gender",
        "female",
        "mass",
    )
    assert table["weighted_by"] == "target nhanes-2017-2020"
    assert table["measures"]["mass"]["outside_share"] == pytest.approx(expected, abs=1e-4)
    capsys.readouterr()
    argv = ["stats", "--db", shipped, "--virtual", "nhanes-2017-2020", "--format", "csv", "mass"]
    assert main(argv) == 0
    (row,) = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert row["population"].startswith("VIRTUAL")
