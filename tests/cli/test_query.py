"""`sass query`: the counts and listings of the shipped database against the
ANSUR II CSV files read directly."""

from __future__ import annotations

import csv
import io

from sass_tui.cli import main


def test_the_counts_are_the_soldiers_of_the_csv_files(people_db, ansur_stature_cm, capsys):
    for gender, stature in ansur_stature_cm.items():
        assert main(["--db", str(people_db), "query", "--count", f"gender = {gender}"]) == 0
        assert int(capsys.readouterr().out) == len(stature)
    # A unit in the query: 190 cm against the CSV's 1900 mm.
    query = "gender = male AND stature > 190 cm"
    assert main(["--db", str(people_db), "query", "--count", query]) == 0
    assert int(capsys.readouterr().out) == int((ansur_stature_cm["male"] > 190).sum())


def test_the_csv_listing_gives_every_person_the_query_selects(people_db, ansur_stature_cm, capsys):
    query = "gender = female AND stature >= 180 cm"
    assert main(["--db", str(people_db), "query", "--format", "csv", query]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    tall = sorted(s for s in ansur_stature_cm["female"] if s >= 180)
    assert sorted(float(row["stature"]) for row in rows) == tall
    assert {row["gender"] for row in rows} == {"female"}


def test_a_bad_query_is_one_line_that_says_where(people_db, capsys):
    assert main(["--db", str(people_db), "query", "stature >> 70"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("sass query: error:") and "stature >> 70" in err
