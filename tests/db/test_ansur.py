"""ANSUR II import and queries, checked against direct computations over the CSV.

Both engines: the test copy of ANSUR II is imported through the Database
service into a new database of each engine (`ansur_target`; on PostgreSQL
staged in SQLite and copied, db/engine/postgres.py), and the same counts, ids and
values are asked of both."""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Iterator
from contextlib import closing
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from _built_once import built_once, copy_database_file

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.engine.dialect import mark_of
from sass_tui.db.engine.schema import row_counts
from sass_tui.db.people.ansur import AnsurImportError, ellipse_axes, import_ansur_into
from sass_tui.db.people.individual import fetch_individual
from sass_tui.model.names import GIRTH, row_index
from tests._paths import SHARED

FILES = ("ANSUR_II_MALE_Public.csv", "ANSUR_II_FEMALE_Public.csv")


@pytest.fixture(scope="session")
def ansur_files() -> list[Path]:
    paths = [SHARED / "data" / "ansur2" / f for f in FILES]
    if not all(p.is_file() for p in paths):
        pytest.skip("../shared/data/ansur2 is absent")
    return paths


@pytest.fixture(scope="session")
def ansur_target(engine, ansur_files, tmp_path_factory, request) -> tuple[str, dict[str, int]]:
    """A new database of `engine` holding ANSUR II alone, imported through the
    Database service (SQLite's once a run, tests/_built_once.py; PostgreSQL's
    once per test process, into its cluster): its address and the import's counts."""

    def imported(target: str) -> dict[str, int]:
        with closing(Database.open(target, create=True)) as db:
            return import_ansur_into(db, ansur_files, label="ansur2")

    if engine == "sqlite":

        def build(folder: Path) -> None:
            counts = imported(str(folder / "ansur.db"))
            (folder / "counts.json").write_text(json.dumps(counts), encoding="utf-8")

        folder = built_once(tmp_path_factory, "ansur-sqlite", build)
        counts = json.loads((folder / "counts.json").read_text(encoding="utf-8"))
        return str(folder / "ansur.db"), counts
    target = request.getfixturevalue("cluster").create_database("sass_ansur")
    return target, imported(target)


@pytest.fixture()
def ansur_db(ansur_target) -> Iterator[tuple[Database, Any, dict[str, int]]]:
    """The ANSUR II database (read only): the Database, its connection, the import's counts."""
    target, counts = ansur_target
    with closing(Database.open(target)) as db, db.connection() as conn:
        yield db, conn, counts


@pytest.fixture(scope="session")
def csv_rows(ansur_files) -> list[dict]:
    rows = []
    for path in ansur_files:
        with path.open(encoding="cp1252", newline="") as handle:
            for row in csv.DictReader(handle):
                rows.append({k.lower(): v for k, v in row.items()})
    return rows


def test_counts(ansur_db):
    _db, conn, counts = ansur_db
    assert counts == {"male": 4082, "female": 1986}
    assert dict(conn.execute("SELECT gender, count(*) FROM person GROUP BY gender")) == counts


def _hand(row):
    return {"Right hand": "right", "Left hand": "left"}.get(row["writingpreference"], "either")


CASES = [
    ("gender = female", lambda r: r["gender"] == "Female"),
    ("stature > 180 cm", lambda r: float(r["stature"]) > 1800),
    (
        "stature >= 70 in AND mass < 80 kg",
        lambda r: float(r["stature"]) >= 1778 and float(r["weightkg"]) < 800,
    ),
    (
        "handedness = either OR handedness = left AND gender = female",
        lambda r: _hand(r) == "either" or (_hand(r) == "left" and r["gender"] == "Female"),
    ),
    (
        "(handedness = either OR handedness = left) AND gender = female",
        lambda r: _hand(r) in ("either", "left") and r["gender"] == "Female",
    ),
    (
        "girth.right_upper_arm.z > 13.5 in",
        lambda r: float(r["acromionradialelength"]) / 10 > 13.5 * 2.54,
    ),
    (
        "girth.right_upper_leg.z <= 42.05 cm OR girth.right_lower_leg.z > 40.05 cm",
        lambda r: (
            (float(r["trochanterionheight"]) - float(r["tibialheight"])) / 10 <= 42.05
            or (float(r["tibialheight"]) - float(r["lateralmalleolusheight"])) / 10 > 40.05
        ),
    ),
    (
        "gender = male AND (girth.right_upper_leg.x > 20 cm OR girth.neck.y < 12 cm) AND age >= 30",
        lambda r: (
            r["gender"] == "Male"
            and (
                float(r["thighclearance"]) / 10 > 20  # thigh depth: 10.1's thigh clearance
                or float(r["neckcircumference"]) / 10 / math.pi < 12
            )
            and float(r["age"]) >= 30
        ),
    ),
    ("mass > 220 lb", lambda r: float(r["weightkg"]) / 10 > 220 * 0.45359237),
]


@pytest.mark.parametrize("text, predicate", [c for c in CASES if c[1]])
def test_query_counts_match_csv(ansur_target, csv_rows, text, predicate):
    expected = sum(1 for r in csv_rows if predicate(r))
    assert 0 < expected < len(csv_rows)
    with closing(Database.open(ansur_target[0])) as db:
        assert db.count(text) == expected


def test_derivations(ansur_db, csv_rows):
    _db, conn, _ = ansur_db
    first = csv_rows[0]
    pid = conn.execute(
        f"SELECT id_num FROM person WHERE source_key = {mark_of(conn)}",
        (f"ANSUR II:male:{first['subjectid']}",),
    ).fetchone()[0]
    person = fetch_individual(conn, pid)
    girth = person.groups[GIRTH]
    arm = girth[row_index(GIRTH, "right_upper_arm")]
    assert arm[2] == pytest.approx(float(first["acromionradialelength"]) / 10)
    assert arm[1] / arm[0] == pytest.approx(17 / 20)
    fore = girth[row_index(GIRTH, "right_lower_arm")]
    assert fore[1] / fore[0] == pytest.approx(3 / 2)
    # the ellipse's circumference approximation gives back the measured circumference
    big, small = fore[1] / 2, fore[0] / 2
    c = 2 * math.pi * math.sqrt((big**2 + small**2) / 2)
    assert c == pytest.approx(float(first["forearmcircumferenceflexed"]) / 10)
    assert person.mass == pytest.approx(float(first["weightkg"]) / 10)
    assert person.handedness == _hand(first)
    assert np.isnan(person.groups["joint_limits"]).all()


def test_ellipse_axes_ratio():
    a2, b2 = ellipse_axes(np.array([30.0]), 1.5)
    assert a2[0] / b2[0] == pytest.approx(1.5)


@pytest.mark.slow
def test_reimport_does_not_duplicate(engine_target, engine_db_copy, ansur_files):
    """The women imported under a new label, then again: the second import
    replaces them under the same ids."""
    conn = engine_db_copy
    before = row_counts(conn)
    ids = "SELECT id_num FROM person WHERE source = 'again' ORDER BY id_num"
    with closing(Database.open(engine_target)) as db:
        assert import_ansur_into(db, ansur_files[1:], label="again") == {"male": 0, "female": 1986}
        first = row_counts(conn), conn.execute(ids).fetchall()
        assert first[0]["person"] == before["person"] + 1986 == before["person"] + len(first[1])
        import_ansur_into(db, ansur_files[1:], label="again")
    assert (row_counts(conn), conn.execute(ids).fetchall()) == first


@pytest.mark.slow
def test_missing_column_rejected(engine_target, engine_db_copy, ansur_files, tmp_path):
    conn = engine_db_copy
    text = ansur_files[1].read_text(encoding="cp1252").splitlines()
    header = text[0].split(",")
    k = [h.lower() for h in header].index("acromionradialelength")
    broken = [",".join(f for j, f in enumerate(line.split(",")) if j != k) for line in text]
    bad = tmp_path / "broken.csv"
    bad.write_text("\n".join(broken) + "\n", encoding="cp1252")
    before = row_counts(conn)
    with (
        closing(Database.open(engine_target)) as db,
        pytest.raises(
            AnsurImportError, match=r"broken.csv:1: missing column acromionradialelength"
        ),
    ):
        import_ansur_into(db, [ansur_files[0], bad], label="broken")
    assert row_counts(conn) == before


def test_cli_import_ansur(engine_target, engine_db_copy, ansur_files, capsys):
    argv = ["db", "import-ansur", "--db", engine_target, "--source", "cli", str(ansur_files[1])]
    assert main(argv) == 0
    assert "imported 0 men and 1986 women" in capsys.readouterr().out
    stored = "SELECT gender, count(*) FROM person WHERE source = 'cli' GROUP BY gender"
    assert engine_db_copy.execute(stored).fetchall() == [("female", 1986)]


def test_a_file_named_twice_or_of_semicolons_stores_nothing(
    shipped_db_file, ansur_files, tmp_path, capsys
):
    """One file named twice stored its people once and said them twice
    ("imported 0 men and 6 women" for 3); a survey file a spreadsheet saved
    with ';' between cells said "missing columns subjectid, gender, …"."""
    db = tmp_path / "sass.db"
    copy_database_file(shipped_db_file, db)
    lines = ansur_files[1].read_text(encoding="cp1252").splitlines()[:4]
    three = tmp_path / "three.csv"
    three.write_text("\n".join(lines) + "\n", encoding="cp1252")
    semicolons = tmp_path / "semicolons.csv"
    semicolons.write_text("\n".join(line.replace(",", ";") for line in lines) + "\n")
    before = db.read_bytes()
    argv = ["db", "import-ansur", "--db", str(db), "--source", "mine"]
    assert main([*argv, str(three), f"{tmp_path}/./three.csv"]) == 2
    assert (
        f"{tmp_path}/./three.csv is named twice (also as {three}); name each"
        in capsys.readouterr().err
    )
    assert main([*argv, str(semicolons)]) == 2
    err = capsys.readouterr().err
    assert f"{semicolons}:1: the cells are separated by ';', not commas" in err
    assert db.read_bytes() == before
    assert main([*argv, str(three)]) == 0
    assert "imported 0 men and 3 women" in capsys.readouterr().out
