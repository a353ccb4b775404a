"""Legacy flat-file import: one transaction, file:line errors, nothing half-stored.

Both engines: the import goes through the Database service (`Database.import_flat`)
or the CLI with the engine's address, into a private copy of the default database
(`engine_target`, or for the refused imports `refusal_target`, one copy the
module's refusals share; on PostgreSQL staged in SQLite and copied,
db/engine/postgres.py)."""

from __future__ import annotations

import shutil
from contextlib import closing
from pathlib import Path

import pytest

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.engine.schema import row_counts
from sass_tui.db.people.flatfile import FlatFileError, FlatFiles, import_flat_into, legacy_name
from sass_tui.db.people.individual import fetch_individual
from sass_tui.model.names import GIRTH, row_index

DEFAULT_FLAT = Path(__file__).resolve().parents[2] / "datasets" / "db"
PERSON = "7,JANE_DOE,female,165.0,60.5,left,31,hand-made test person\n"
GIRTH_ROWS = (
    "7,BOTTOM_HEAD, 19.80, 15.75, 22.41, 1.40\n"
    "7,R_UPPER_ARM, 10.16, 8.54, 31.94, 1.96\n"
    "7,UPPER_TORSO,999.0,999.0,999.0, 11.97\n"
    "7,R_TOES, 7.60, 9.95, 5.46, 0.10\n"
)


def _files(tmp_path, person=PERSON, girth=GIRTH_ROWS, strength=None) -> FlatFiles:
    (tmp_path / "person.db").write_text(person)
    (tmp_path / "girth.db").write_text(girth)
    (tmp_path / "jntlmt.db").write_text("7,R_SHOULDER_UL, 150.0, 170.0, 999.0\n")
    (tmp_path / "cmass.db").write_text("7,NECK, 0.0, 0.0, 5.2\n")
    if strength:
        for name, text in strength.items():
            (tmp_path / name).write_text(text)
    return FlatFiles.in_directory(tmp_path)


def test_legacy_names():
    assert legacy_name("R_UPPER_ARM") == "right_upper_arm"
    assert legacy_name("L_FINGERS") == "left_knuckles"
    assert legacy_name("BOTTOM_HEAD") == "bottom_head"


def test_import_and_fetch(engine_target, engine_db_copy, tmp_path):
    strength = {
        "strgh-par.db": "7,1,right,isometric,0,0,0,deg,ft-lb,deg/s\n",
        "elbow-strgh.db": "7,1,90,0,0,0,0,0,0,30.0,999.0\n",
    }
    with closing(Database.open(engine_target)) as db:
        assert import_flat_into(db, _files(tmp_path, strength=strength)) == 1
    person = fetch_individual(engine_db_copy, 7)
    assert person.name == "JANE_DOE" and person.handedness == "left"
    assert person.groups[GIRTH][row_index(GIRTH, "right_upper_arm")].tolist() == [
        10.16,
        8.54,
        31.94,
    ]
    assert person.segment_masses["upper_torso"] == 11.97
    assert person.groups[GIRTH][row_index(GIRTH, "right_ball_of_foot")][2] == 5.46
    # ft-lb converted to the stored N-m
    assert person.strength["elbow_flexion_max"] == pytest.approx(30.0 * 1.3558179, rel=1e-6)
    assert person.elbow[0]["nstrgh"] is None


BAD = [
    ("person", "7,JANE_DOE,female,165.0,60.5,left,31\n", "person.db:1: expected 8"),
    ("person", PERSON + PERSON.replace("JANE", "JOHN"), "person.db:2: duplicate id_num 7"),
    (
        "person",
        PERSON.replace("165.0", "tall"),
        "person.db:1: stature: expected a number, found 'tall'",
    ),
    ("girth", GIRTH_ROWS + "7,NECK, 5.46, 5.46\n", "girth.db:5: expected 6"),
    (
        "girth",
        GIRTH_ROWS + "7,NECK, 5.46, x5, 9.18, 0.14\n",
        "girth.db:5: value 2: expected a number",
    ),
    ("girth", GIRTH_ROWS + "7,R_UPPER_ARM, 1, 1, 1, 1\n", "girth.db:5: duplicate row"),
    (
        "girth",
        GIRTH_ROWS + "8,NECK, 1, 1, 1, 1\n",
        "girth.db:5: id_num 8 is not in the person file",
    ),
    ("girth", GIRTH_ROWS + "7,TAIL, 1, 1, 1, 1\n", "girth.db:5: unknown row 'TAIL'"),
]


@pytest.mark.parametrize("which, text, message", BAD)
def test_bad_flat_file_rejects_whole_import(
    refusal_target, refusal_db, tmp_path, which, text, message
):
    before = row_counts(refusal_db)
    files = _files(tmp_path, **{which: text})
    with (
        closing(Database.open(refusal_target)) as db,
        pytest.raises(FlatFileError, match=message.replace("(", r"\(")),
    ):
        import_flat_into(db, files)
    assert row_counts(refusal_db) == before


def test_database_error_mid_transaction_rolls_back(refusal_target, refusal_db, tmp_path):
    """A strength row naming an experiment the parameter file lacks: nothing stored."""
    before = row_counts(refusal_db)
    files = _files(
        tmp_path,
        strength={
            "strgh-par.db": "7,1,right,isometric,0,0,0,deg,N-m,deg/s\n",
            "elbow-strgh.db": "7,2,90,0,0,0,0,0,0,30.0,20.0\n",
        },
    )
    with (
        closing(Database.open(refusal_target)) as db,
        pytest.raises(FlatFileError, match="elbow-strgh.db:1: experiment 2"),
    ):
        import_flat_into(db, files)
    assert row_counts(refusal_db) == before


def test_cli_import_flat(engine_target, engine_db_copy, tmp_path, capsys):
    _files(tmp_path)
    args = [
        "db",
        "import-flat",
        "--db",
        engine_target,
        "--person",
        str(tmp_path / "person.db"),
        "--girth",
        str(tmp_path / "girth.db"),
        "--jntlmt",
        str(tmp_path / "jntlmt.db"),
        "--cmass",
        str(tmp_path / "cmass.db"),
    ]
    assert main(args) == 0
    assert "imported 1 people" in capsys.readouterr().out
    assert fetch_individual(engine_db_copy, 7).name == "JANE_DOE"
    (tmp_path / "girth.db").write_text(GIRTH_ROWS + "7,NECK,1,1\n")
    before = row_counts(engine_db_copy)
    assert main(args) == 2
    err = capsys.readouterr().err
    assert "girth.db:5" in err and "Traceback" not in err
    assert row_counts(engine_db_copy) == before


def test_default_flat_files_round_trip(engine_target, engine_db_copy, tmp_path):
    """Re-importing the shipped files replaces, never duplicates: the default
    database holds them already (built from them, db/people/default.py), and one
    import more leaves every count, id and name as it was."""
    shutil.copytree(DEFAULT_FLAT, tmp_path / "flat")
    files = FlatFiles.in_directory(tmp_path / "flat")
    ids = "SELECT id_num, name FROM person WHERE substr(name, 1, 6) = 'SYNTH_' ORDER BY id_num"
    first = row_counts(engine_db_copy), engine_db_copy.execute(ids).fetchall()
    assert len(first[1]) == 200
    with closing(Database.open(engine_target)) as db:
        assert import_flat_into(db, files) == 200
    assert (row_counts(engine_db_copy), engine_db_copy.execute(ids).fetchall()) == first
