"""`sass fit`: the share a design limit accommodates, against the ANSUR II CSV
files counted directly."""

from __future__ import annotations

import json

import numpy as np
import pytest

from sass_tui.cli import main


def test_a_stature_limit_accommodates_the_soldiers_the_csv_counts(
    people_db, ansur_stature_cm, capsys
):
    argv = ["--db", str(people_db), "fit", "--format", "json", "stature <= 190 cm"]
    assert main(argv) == 0
    answer = json.loads(capsys.readouterr().out)
    for gender, stature in ansur_stature_cm.items():
        accommodated = answer["accommodated"][gender]
        assert accommodated["n"] == len(stature)
        assert accommodated["fit"] == int((stature <= 190).sum())
        assert accommodated["percent"] == round(100 * accommodated["fit"] / len(stature), 4)
    # The default mix is half and half (docs/accommodation.md).
    shares = [answer["accommodated"][g]["percent"] for g in ("male", "female")]
    assert answer["accommodated"]["weighted"]["percent"] == round(sum(shares) / 2, 4)


def test_the_table_names_the_limits_and_the_population(people_db, capsys):
    assert main(["--db", str(people_db), "fit", "stature <= 190 cm"]) == 0
    out = capsys.readouterr().out
    assert "Design limits: stature <= 190 cm" in out
    assert "Population: source = ansur2 (6068 people)" in out


def test_who_a_range_excludes_at_each_end_is_the_csvs(people_db, ansur_stature_cm, capsys):
    """The per-limit summary counts, splits by gender (equal mix) and takes the
    median stature of the soldiers below and above, as the CSV gives them."""
    argv = ["--db", str(people_db), "fit", "--format", "json"]
    assert main([*argv, "stature BETWEEN 155 cm AND 190 cm"]) == 0
    (limit,) = json.loads(capsys.readouterr().out)["by_limit"]
    men, women = ansur_stature_cm["male"], ansur_stature_cm["female"]
    for side, outside in (("below", lambda s: s < 155), ("above", lambda s: s > 190)):
        m, f = outside(men), outside(women)
        got = limit[side]
        assert got["n"] == int(m.sum() + f.sum())
        male_weight, female_weight = m.sum() * 0.5 / len(men), f.sum() * 0.5 / len(women)
        assert got["percent"] == pytest.approx(100 * (male_weight + female_weight), abs=1e-3)
        if m.any():
            assert got["genders"]["male"] == pytest.approx(
                100 * male_weight / (male_weight + female_weight), abs=1e-3
            )
    tall = men[men > 190]  # only men: equal weights, the plain median
    assert limit["above"]["median_stature"] == pytest.approx(np.median(tall), abs=1e-3)


def test_failing_gives_each_value_and_its_end(people_db, ansur_stature_cm, capsys):
    argv = ["--db", str(people_db), "fit", "--format", "json", "--failing"]
    assert main([*argv, "stature BETWEEN 155 cm AND 190 cm"]) == 0
    failing = json.loads(capsys.readouterr().out)["failing"]
    every = np.concatenate(list(ansur_stature_cm.values()))
    outside = every[(every < 155) | (every > 190)]
    assert sorted(f["failed"][0]["value"] for f in failing) == pytest.approx(sorted(outside))
    for person in failing:
        (failed,) = person["failed"]
        assert failed["measure"] == "stature" and failed["unit"] == "cm"
        assert failed["side"] == ("below" if failed["value"] < 155 else "above")
    assert main(["--db", str(people_db), "fit", "--failing", "stature <= 190 cm"]) == 0
    shortest = float(every[every > 190].min())
    assert f"stature {shortest:g} cm above (stature <= 190 cm)" in capsys.readouterr().out
