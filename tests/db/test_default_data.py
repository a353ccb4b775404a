"""The default (synthetic) data set and the report's sample query on it, on both
engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest
from _built_once import copy_database_file
from test_database_safety import NHANES_ADULTS

from sass_tui.cli import main
from sass_tui.db.engine.schema import DatabaseError, row_counts
from sass_tui.db.people.individual import fetch_individual
from sass_tui.db.query.query import run_query
from sass_tui.model.names import GIRTH, JOINT_LIMITS, row_index
from sass_tui.model.units import convert

DEFAULT_FLAT = Path(__file__).resolve().parents[2] / "datasets" / "db"

# Only the synthetic demonstration people carry strength: the query names their source.
SAMPLE = (
    "gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb "
    "AND source = synthetic"
)


def _flat(name):
    with (DEFAULT_FLAT / name).open() as handle:
        return [row for row in csv.reader(handle)]


def expected_ids(arm_cm: float, elbow_ftlb: float) -> set[int]:
    """The sample query computed straight from the flat files."""
    male = {int(r[0]) for r in _flat("person.db") if r[2] == "male"}
    arm = {int(r[0]): float(r[4]) for r in _flat("girth.db") if r[1] == "RIGHT_UPPER_ARM"}
    elbow = defaultdict(float)
    for r in _flat("elbow-strgh.db"):
        elbow[int(r[0])] = max(elbow[int(r[0])], float(r[9]))  # pstrgh, N-m
    limit = convert(elbow_ftlb, "ft_lb", "N_m")
    return {i for i in male if arm.get(i, 0) > arm_cm and elbow[i] > limit}


@pytest.mark.parametrize("arm, elbow", [(28, 20), (37, 45), (39, 30)])
def test_sample_query_matches_direct_computation(engine_db, arm, elbow):
    query = run_query(
        engine_db,
        f"gender = male AND girth.right_upper_arm.z > {arm} cm "
        f"AND strength.elbow_flexion.max > {elbow} ft-lb AND source = synthetic",
    )
    expected = expected_ids(arm, elbow)
    assert expected, "the data set must hold people the query finds"
    assert set(query.ids()) == expected
    assert query.count() == len(expected)


def test_sample_query_finds_people_and_no_women(engine_db):
    query = run_query(engine_db, SAMPLE)
    assert query.count() > 50
    assert all(p["gender"] == "male" for p in query.iter_all(page_size=7))


def test_every_person_is_labelled_with_its_source(engine_db):
    sources = dict(engine_db.execute("SELECT source, count(*) FROM person GROUP BY source"))
    synthetic = sum(1 for _ in _flat("person.db"))
    assert sources == {
        "synthetic": synthetic,
        "ansur2": 6068,
        "virtual:nhanes-2017-2020": NHANES_ADULTS,  # VIRTUAL: out of every real answer
    }
    names = {n for (n,) in engine_db.execute("SELECT name FROM person WHERE source = 'synthetic'")}
    assert names == {r[1] for r in _flat("person.db")}


def test_paging_never_loads_more_than_a_page(engine_db):
    query = run_query(engine_db, "source = synthetic")
    total = query.count()
    assert total == 200
    first, second = query.page(0, 25), query.page(25, 25)
    assert len(first) == 25 and first[-1]["id"] < second[0]["id"]
    assert query.page_after(first[-1]["id"], 25) == second
    assert len(query.page(190, 25)) == 10


def test_fetch_individual_returns_every_group(engine_db):
    person = fetch_individual(engine_db, 1)
    assert person.name == "SYNTH_M_001" and person.gender == "male"
    assert person.groups[GIRTH].shape == (25, 3)
    assert person.groups[JOINT_LIMITS].shape == (40, 3)
    girth_row = next(r for r in _flat("girth.db") if r[0] == "1" and r[1] == "RIGHT_UPPER_ARM")
    assert np.allclose(
        person.groups[GIRTH][row_index(GIRTH, "right_upper_arm")],
        [float(v) for v in girth_row[2:5]],
    )
    assert person.experiments and person.elbow and len(person.shoulder) % 3 == 0
    assert person.strength["elbow_flexion_max"] == max(e["pstrgh"] for e in person.elbow)
    with pytest.raises(DatabaseError):
        fetch_individual(engine_db, 99999)


def test_cli_query_json(shared_target, capsys):
    assert main(["query", "--db", shared_target, "--format", "json", SAMPLE]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["count"] == len(out["persons"]) == len(expected_ids(28, 20))
    assert set(out["persons"][0]) == {
        "id",
        "name",
        "gender",
        "mass",
        "stature",
        "handedness",
        "age",
        "source",
    }


def test_cli_query_csv_and_table(shared_target, capsys):
    assert main(["query", "--db", shared_target, "--format", "csv", "handedness = either"]) == 0
    rows = list(csv.DictReader(capsys.readouterr().out.splitlines()))
    assert rows and all(r["handedness"] == "either" for r in rows)
    assert main(["query", "--db", shared_target, "gender = female AND age < 20"]) == 0
    assert capsys.readouterr().out.strip().endswith(("people", "person"))


@pytest.mark.slow
def test_cli_db_init_uses_xdg_location(tmp_path, monkeypatch, capsys, few_default_people):
    monkeypatch.delenv("SASS_DB", raising=False)
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    # First use of `sass query` creates the default database.
    assert main(["query", "--format", "json", "gender = female"]) == 0
    assert json.loads(capsys.readouterr().out)["count"] == few_default_people.female  # real only
    assert (tmp_path / "sass" / "sass.db").is_file()
    target = tmp_path / "other.db"
    monkeypatch.setenv("SASS_DB", str(target))
    assert main(["db", "init"]) == 0
    assert target.is_file()
    capsys.readouterr()
    # A fresh install: the ANSUR II people, the synthetic ones and the
    # shipped virtual people (a query naming `source` reaches every source),
    # no file given.
    assert main(["query", "--format", "json", "stature > 0 cm AND source != none"]) == 0
    assert json.loads(capsys.readouterr().out)["count"] == few_default_people.everyone
    assert main(["query", "--count", "--virtual", "nhanes-2017-2020", "stature > 0 cm"]) == 0
    assert capsys.readouterr().out.splitlines()[0] == str(few_default_people.virtual)


def test_cli_query_missing_database_is_an_error(tmp_path, capsys):
    assert main(["query", "--db", str(tmp_path / "none.db"), "gender = male"]) == 2
    assert "no database" in capsys.readouterr().err
    assert not (tmp_path / "none.db").exists()


def test_bad_query_leaves_database_unchanged(engine_db, shared_target, capsys):
    before = row_counts(engine_db)
    for text in ("name = x'; DROP TABLE person; --", "gender = male'; DROP TABLE person; --"):
        assert main(["query", "--db", shared_target, text]) == 2
        err = capsys.readouterr().err
        assert "column" in err and "^" in err
    assert row_counts(engine_db) == before


@pytest.mark.slow
def test_query_output_into_a_closed_pipe_is_not_an_error(shipped_db_file, tmp_path):
    """`sass query ... | head -1`: the reader closes early; sass exits quietly."""
    import subprocess
    import sys

    db = tmp_path / "sass.db"
    copy_database_file(shipped_db_file, db)  # what `sass db init` builds
    done = subprocess.run(
        f'"{sys.executable}" -m sass_tui query --db "{db}" --format csv "mass > 0" | head -1',
        shell=True,
        capture_output=True,
        text=True,
    )
    assert done.stdout.count("\n") == 1
    assert "Broken pipe" not in done.stderr and "error" not in done.stderr
