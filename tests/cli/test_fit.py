"""`sass fit`: the share a design limit accommodates, against the ANSUR II CSV
files counted directly."""

from __future__ import annotations

import json

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
