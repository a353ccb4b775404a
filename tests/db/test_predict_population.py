"""`sass predict --population QUERY` learns from the people the query
selects; without it, from every person of the gender (the query path, so
the query language's default scope applies)."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest
from _built_once import copy_database_file

from sass_tui.cli import main

pytestmark = pytest.mark.sqlite_only(
    "a database of women imported into a SQLite file; predict on both engines: test_engines_verbs.py"
)

WOMEN = "ANSUR_II_FEMALE_Public.csv"


@pytest.fixture(scope="module")
def women_db(ansur_dir, tmp_path_factory, shipped_db_file) -> tuple[Path, list[dict[str, str]]]:
    """The default database with the ANSUR II women imported, and their CSV rows."""
    folder = tmp_path_factory.mktemp("women")
    db = folder / "women.db"
    copy_database_file(shipped_db_file, db)  # what `sass db init` builds
    assert main(["--db", str(db), "db", "import-ansur", str(ansur_dir / WOMEN)]) == 0
    with (ansur_dir / WOMEN).open(encoding="latin-1", newline="") as handle:
        rows = list(csv.DictReader(handle))
    return db, rows


def _predict(capsys, db: Path, *argv: str) -> dict:
    capsys.readouterr()
    assert main(["predict", "--db", str(db), "--gender", "female", "--format", "json", *argv]) == 0
    return json.loads(capsys.readouterr().out)


def test_population_picks_the_people_learnt_from(women_db, capsys, tmp_path):
    db, rows = women_db
    copy = tmp_path / "w.db"
    shutil.copyfile(db, copy)
    query = "branch = 'Combat Arms'"
    expected = sum(r["Branch"] == "Combat Arms" for r in rows)
    chosen = _predict(capsys, copy, "--population", query, "--known", "stature=165cm")
    assert chosen["model"]["n"] == expected
    assert chosen["model"]["population"] == query
    everyone = _predict(capsys, copy, "--known", "stature=165cm")
    assert everyone["model"]["n"] == len(rows)
    assert everyone["model"]["population"] is None
    # another population, another fit: the predictions differ
    name = "measure.bideltoidbreadth"
    assert chosen["predicted"][name]["value"] != everyone["predicted"][name]["value"]
    # and the cache does not hand one population's fit to the other
    again = _predict(capsys, copy, "--population", query, "--known", "stature=165cm")
    assert again["model"]["n"] == expected
    assert again["predicted"] == chosen["predicted"]


def test_a_population_too_small_is_refused_with_the_query(women_db, capsys, tmp_path):
    db, rows = women_db
    query = "age > 55"
    assert 0 < sum(float(r["Age"]) > 55 for r in rows) < 30
    code = main(
        ["predict", "--db", str(db), "--gender", "female", "--population", query]
        + ["--known", "stature=165cm"]
    )
    err = capsys.readouterr().err
    assert code != 0
    assert "--population 'age > 55': fewer than 30 female people" in err
    assert "Traceback" not in err


def test_a_bad_population_query_says_where(women_db, capsys):
    db, _ = women_db
    code = main(
        ["predict", "--db", str(db), "--gender", "female", "--population", "age >> 60"]
        + ["--known", "stature=165cm"]
    )
    err = capsys.readouterr().err
    assert code != 0 and "column 6" in err and "Traceback" not in err
