"""`sass db init`: the database built from the shipped files holds every
ANSUR II soldier of the CSV files, and the demonstration people labelled."""

from __future__ import annotations

import sqlite3

import pytest

from sass_tui.cli import main


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
    # Everyone else is a demonstration person, stored as such (never a real one).
    assert sources and all(source.startswith("synthetic") for source in sources)


def test_init_refuses_to_replace_people_without_force(people_db, capsys):
    before = people_db.read_bytes()
    assert main(["--db", str(people_db), "db", "init"]) == 2
    assert "--force" in capsys.readouterr().err
    assert people_db.read_bytes() == before
