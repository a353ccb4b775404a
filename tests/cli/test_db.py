"""`sass db init`: the database built from the shipped files holds every
ANSUR II soldier of the CSV files, and the demonstration people labelled."""

from __future__ import annotations

import csv
import sqlite3

import pytest

from sass_tui.cli import main
from tests._paths import nhanes_lines


def nhanes_adults() -> int:
    """NHANES 2017-March 2020 adults (20+) with a height and a weight, counted
    from the published CSV: one virtual person each."""
    lines = nhanes_lines()
    return sum(
        1
        for r in csv.DictReader(lines)
        if r["RIDAGEYR"] != "NA"
        and float(r["RIDAGEYR"]) >= 20
        and r["BMXHT"] != "NA"
        and r["BMXWT"] != "NA"
    )


@pytest.mark.slow
def test_init_stores_every_soldier_of_the_csv_files(tmp_path, ansur_stature_cm, capsys):
    path = tmp_path / "new.db"
    assert main(["--db", str(path), "db", "init"]) == 0
    soldiers = sum(len(s) for s in ansur_stature_cm.values())
    assert f"{soldiers} ANSUR II people" in capsys.readouterr().out
    conn = sqlite3.connect(path)
    try:
        sources = dict(conn.execute("SELECT source, count(*) FROM person GROUP BY source"))
    finally:
        conn.close()
    assert sources.pop("ansur2") == soldiers
    # The shipped virtual population: one predicted person per NHANES adult.
    assert sources.pop("virtual:nhanes-2017-2020") == nhanes_adults()
    # Everyone else is a demonstration person, stored as such (never a real one).
    assert sources and all(source.startswith("synthetic") for source in sources)


def test_init_refuses_to_replace_people_without_force(people_db, capsys):
    before = people_db.read_bytes()
    assert main(["--db", str(people_db), "db", "init"]) == 2
    assert "--force" in capsys.readouterr().err
    assert people_db.read_bytes() == before
