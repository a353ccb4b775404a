"""`sass target --weight`: NHANES's own weights in the calibration, the
share of the target beyond every soldier (`outside_share`), and bad input
refused with nothing stored.  Every expected number is computed here from
the published CSVs (../shared/data/nhanes, ../shared/data/ansur2), not
through sass.  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.populations.targets import load_target
from tests._paths import ANSUR, nhanes_lines, shared_file


def nhanes_adults(gender_code: str) -> list[dict[str, str]]:
    lines = nhanes_lines()
    return [
        r
        for r in csv.DictReader(lines)
        if r["RIAGENDR"] == gender_code and r["RIDAGEYR"] != "NA" and float(r["RIDAGEYR"]) >= 20
    ]


def ansur_masses(name: str) -> np.ndarray:
    with shared_file(ANSUR / name).open(encoding="latin-1", newline="") as handle:
        return np.array([float(r["weightkg"]) / 10 for r in csv.DictReader(handle)])


def stored(db: str, name: str):
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            return load_target(conn, name)
    finally:
        opened.close()


def target_names(db: str) -> list[str]:
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            return [r[0] for r in conn.execute("SELECT name FROM target ORDER BY name")]
    finally:
        opened.close()


@pytest.mark.slow
def test_the_weighted_women_and_what_lies_beyond_them(engine_target, capsys):
    argv = ["target", "civ", "--db", engine_target, "--sample", "nhanes-2017-2020"]
    assert main([*argv, "--weight", "WTMECPRP", "--within-range"]) == 0
    out = capsys.readouterr()
    assert "each row weighted by its WTMECPRP" in out.out
    target = stored(engine_target, "civ").target
    assert target.gender == "both" and target.weighted_by == "WTMECPRP"
    # NHANES women 20+ with a stature and a mass (the rows a target uses):
    # the weighted share heavier or lighter than every ANSUR II woman.
    women = [r for r in nhanes_adults("2") if r["BMXHT"] != "NA" and r["BMXWT"] != "NA"]
    mass = np.array([float(r["BMXWT"]) for r in women])
    weight = np.array([float(r["WTMECPRP"]) for r in women])
    soldiers = ansur_masses("ANSUR_II_FEMALE_Public.csv")
    beyond = (mass > soldiers.max()) | (mass < soldiers.min())
    expected = weight[beyond].sum() / weight.sum()
    assert 0.04 < expected < 0.07
    assert target.outside_share("female", "mass") == pytest.approx(expected, abs=1e-12)
    assert f"{100 * expected:7.1f}%" in out.out
    assert "mass: 5.3 % of the target's weight lies beyond every person's value" in out.err


@pytest.mark.parametrize(
    ("cell", "said"),
    [
        ("-2.5", "'-2.5': a survey weight must be a number greater than 0"),
        ("0", "'0': a survey weight must be a number greater than 0"),
        ("many", "'many': a survey weight must be a number greater than 0"),
    ],
)
def test_a_bad_weight_stores_nothing(engine_target, tmp_path, capsys, cell, said):
    rows = ["gender,stature,mass,wt"] + [
        f"female,{150 + i % 25},{55 + i % 30},{cell if i == 7 else 1 + i % 3}" for i in range(60)
    ]
    sample = tmp_path / "s.csv"
    sample.write_text("\n".join(rows) + "\n", encoding="utf-8")
    before = target_names(engine_target)
    argv = ["target", "w", "--db", engine_target, "--sample", str(sample), "--weight", "wt"]
    assert main(argv) != 0
    assert f"{sample}:9: column 4 'wt': {said}" in capsys.readouterr().err
    assert target_names(engine_target) == before


def test_a_sample_without_gender_for_both_stores_nothing(engine_target, tmp_path, capsys):
    sample = tmp_path / "s.csv"
    sample.write_text("stature,mass\n" + "160,60\n" * 40, encoding="utf-8")
    before = target_names(engine_target)
    assert main(["target", "w", "--db", engine_target, "--sample", str(sample)]) != 0
    assert f"{sample}:1: no gender column; a target of both genders" in capsys.readouterr().err
    assert target_names(engine_target) == before


def test_an_unused_survey_weight_is_warned_of(engine_target, tmp_path, capsys):
    rng = np.random.default_rng(3)
    rows = ["stature,mass,WTMEC2YR"] + [
        f"{rng.normal(163, 6):.1f},{rng.normal(68, 10):.1f},{rng.uniform(1e3, 9e4):.1f}"
        for _ in range(200)
    ]
    sample = tmp_path / "s.csv"
    sample.write_text("\n".join(rows) + "\n", encoding="utf-8")
    argv = ["target", "u", "--db", engine_target, "--gender", "female", "--sample", str(sample)]
    assert main(argv) == 0
    assert (
        f"warning: {sample}: column 'WTMEC2YR' looks like a survey weight and is not used"
        in capsys.readouterr().err
    )
