"""A full file system and a read-only one: every write is refused with a
message that names the file, never a traceback; the database is unchanged and
passes `PRAGMA integrity_check`; no temporary file, journal or half-made
database is left behind; reading goes on.

The file systems are real: a tmpfs mounted for the test, filled to the last
byte (or to a few pages) or remounted read-only (tests/_tmpfs.py; skipped
where this process may not mount).
"""

from __future__ import annotations

import hashlib
import sqlite3
from pathlib import Path

import pytest
from _tmpfs import fill, mounted_tmpfs, remount_read_only

from sass_tui.cli import main
from sass_tui.db.engine.schema import connect
from sass_tui.db.people.default_people import shipped_ansur_files
from sass_tui.db.people.flatfile import FlatFiles, import_flat_files

pytestmark = pytest.mark.sqlite_only("file-system faults under a SQLite file")

PERSON = "99907,JANE_DOE,female,165.0,60.5,left,31,hand-made test person\n"


@pytest.fixture()
def person_file(tmp_path) -> Path:
    path = tmp_path / "person.db"
    path.write_text(PERSON)
    return path


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _integrity(path: Path) -> str:
    conn = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
    try:
        return str(conn.execute("PRAGMA integrity_check").fetchone()[0])
    finally:
        conn.close()


def _empty_file(beside: Path) -> str:
    """An empty group file (not /dev/null: the readers take regular files only)."""
    empty = beside.with_name("empty.db")
    empty.write_text("")
    return str(empty)


def _flat_import(db: Path, person: Path) -> list[str]:
    empty = _empty_file(person)
    return [
        "db",
        "import-flat",
        "--db",
        str(db),
        "--person",
        str(person),
        "--girth",
        empty,
        "--jntlmt",
        empty,
        "--cmass",
        empty,
    ]


# (name, argv from (mount, db, person file), the file the message must name)
WRITES = {
    "import-ansur": (
        lambda mnt, db, p: [
            "db",
            "import-ansur",
            "--db",
            str(db),
            *map(str, shipped_ansur_files()),
        ],
        lambda mnt, db: db,
    ),
    "import-flat": (lambda mnt, db, p: _flat_import(db, p), lambda mnt, db: db),
    "db init": (lambda mnt, db, p: ["db", "init", "--force", "--db", str(db)], lambda mnt, db: db),
    "import into a new database": (
        lambda mnt, db, p: _flat_import(mnt / "new.db", p),
        lambda mnt, db: mnt / "new.db",
    ),
    "fig -o": (lambda mnt, db, p: ["fig", "-o", str(mnt / "x.fig")], lambda mnt, db: mnt / "x.fig"),
    "population -o": (
        lambda mnt, db, p: [
            "population",
            "--db",
            str(db),
            "--query",
            "gender = female AND source = synthetic",  # the small database's 200 people
            "-o",
            str(mnt / "p.dat"),
        ],
        lambda mnt, db: mnt / "p.dat",
    ),
}


@pytest.mark.parametrize("name", list(WRITES))
def test_a_full_file_system_refuses_each_write_naming_the_file(
    name, tmpfs_with_db, person_file, capsys
):
    mnt, db = tmpfs_with_db
    fill(mnt)
    argv, target = WRITES[name]
    before = sorted(p.name for p in mnt.iterdir())
    digest = _digest(db)
    assert main(argv(mnt, db, person_file)) == 2
    err = capsys.readouterr().err
    assert str(target(mnt, db)) in err, err
    assert "disk is full" in err or "No space left on device" in err, err
    assert "Traceback" not in err and "database error" not in err, err
    assert len(err.strip().splitlines()) == 1, err  # one line: the message
    assert _digest(db) == digest and _integrity(db) == "ok"
    # no temporary file, journal or half-made database left behind
    assert sorted(p.name for p in mnt.iterdir()) == before


@pytest.mark.parametrize("name", ["import-ansur", "db init"])
def test_a_write_that_runs_out_of_space_half_way_leaves_the_database_as_it_was(
    name, tmpfs_with_db, person_file, capsys
):
    """A few pages free: the import starts, then the disk fills under it."""
    mnt, db = tmpfs_with_db
    fill(mnt, leave=256 * 1024)
    argv, target = WRITES[name]
    before = sorted(p.name for p in mnt.iterdir())
    digest = _digest(db)
    assert main(argv(mnt, db, person_file)) == 2
    err = capsys.readouterr().err
    assert f"cannot write {db}: the disk is full" in err, err
    assert "Traceback" not in err
    assert _digest(db) == digest and _integrity(db) == "ok"
    assert sorted(p.name for p in mnt.iterdir()) == before
    # and once there is room again, the database takes an import
    (mnt / "filler").unlink()
    assert main(_flat_import(db, person_file)) == 0, capsys.readouterr().err
    assert "imported 1 people" in capsys.readouterr().out
    assert _integrity(db) == "ok"


def test_a_read_only_file_system_still_answers_queries_and_refuses_writes(
    tmpfs_with_db, person_file, capsys
):
    mnt, db = tmpfs_with_db
    remount_read_only(mnt)
    digest = _digest(db)
    # reading works: a query, a person, a population written elsewhere
    assert (
        main(
            [
                "query",
                "--db",
                str(db),
                "gender = female AND stature > 150 cm AND source = synthetic",
            ]
        )
        == 0
    )
    assert "SYNTH_F_" in capsys.readouterr().out
    assert main(["person", "--db", str(db), "17"]) == 0
    assert "SYNTH_M_017" in capsys.readouterr().out
    assert main(["query", "--db", str(db), "--format", "json", "source = synthetic"]) == 0
    out = person_file.parent / "young.dat"
    assert (
        main(
            [
                "population",
                "--db",
                str(db),
                "--query",
                "age < 30 AND source = synthetic",
                "-o",
                str(out),
            ]
        )
        == 0
    )
    assert out.is_file()
    capsys.readouterr()
    # every write says the database is read-only, names it, and changes nothing
    for name in ("import-flat", "import-ansur", "db init", "import into a new database"):
        argv, target = WRITES[name]
        assert main(argv(mnt, db, person_file)) == 2, name
        err = capsys.readouterr().err
        assert f"cannot write {target(mnt, db)}" in err, err
        assert "read-only file system" in err, err
        assert "Traceback" not in err and "database error" not in err, err
    assert sorted(p.name for p in mnt.iterdir()) == ["sass.db"]
    assert _digest(db) == digest and _integrity(db) == "ok"


def test_the_library_refuses_a_read_only_database_before_writing(tmpfs_with_db, person_file):
    """The check is in the db layer (check_writable), for the TUI as for the CLI."""
    from sass_tui.db.engine.schema import DatabaseError

    mnt, db = tmpfs_with_db
    remount_read_only(mnt)
    conn = connect(db)
    try:
        with pytest.raises(DatabaseError, match="read-only file system"):
            import_flat_files(
                conn,
                FlatFiles(
                    person=person_file,
                    girth=Path(_empty_file(person_file)),
                    joint_limits=Path(_empty_file(person_file)),
                    center_of_mass=Path(_empty_file(person_file)),
                ),
            )
        assert conn.execute("SELECT count(*) FROM person").fetchone()[0] == 200
    finally:
        conn.close()


@pytest.mark.slow
def test_a_first_build_the_disk_cut_short_is_finished_by_the_next_run(
    tmp_path, monkeypatch, capsys, few_default_people
):
    """The default database is built on first use; a disk that fills half-way
    left its schema with nobody in it, and every later query said "0 people"."""
    # Room for the default database (59 MB with the shipped virtual people).
    with mounted_tmpfs(tmp_path / "mnt", 120 * 1024 * 1024) as mnt:
        db = mnt / "sass.db"
        monkeypatch.setenv("SASS_DB", str(db))
        filler = fill(mnt, leave=1024 * 1024)
        assert main(["query", "gender = male"]) == 2
        err = capsys.readouterr().err
        assert f"cannot write {db}: the disk is full" in err and "Traceback" not in err, err
        filler.unlink()
        assert main(["query", "--format", "json", "gender = male"]) == 0
        people = capsys.readouterr().out
        assert '"ANSUR II M ' in people
        assert _integrity(db) == "ok"
