"""`sass db copy`: the DuckDB column copy (sass_tui/db/query/accelerator.py) built now, so
that a one-shot `sass query` in a fresh process counts from it.

The copy answers counts from accelerator.MIN_PEOPLE people; the processes
here lower it to 0 so the default database (6,268 people) uses it, and say
how they answered (accelerator.last_answer) instead of being timed.
"""

from __future__ import annotations

import os
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest
from _built_once import copy_database_file

from sass_tui.cli import main
from sass_tui.db.engine.schema import connect
from sass_tui.db.query import accelerator, copy_file
from sass_tui.db.query.query import compile_query

pytestmark = pytest.mark.sqlite_only("the DuckDB column copy of a SQLite file")

QUERY = "gender = male AND girth.right_upper_arm.z > 28 cm AND stature > 170 cm"

# `sass ARGS` in a new Python process whose copy threshold is 0; it prints
# how its last count was answered on stderr.
CHILD = (
    "import sys\n"
    "from sass_tui.db.query import accelerator\n"
    "accelerator.MIN_PEOPLE = 0\n"
    "from sass_tui.cli import main\n"
    "status = main(sys.argv[1:])\n"
    "print('answered by:', accelerator.last_answer, file=sys.stderr)\n"
    "sys.exit(status)\n"
)


def sass(cache: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, XDG_CACHE_HOME=str(cache))
    return subprocess.run(
        [sys.executable, "-c", CHILD, *argv],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
    )


def people_in(path: Path) -> int:
    conn = sqlite3.connect(path)
    try:
        return int(conn.execute("SELECT count(*) FROM person").fetchone()[0])
    finally:
        conn.close()


def sqlite_count(path: Path, text: str) -> int:
    compiled = compile_query(text)
    conn = sqlite3.connect(path)
    try:
        sql = f"SELECT count(*) FROM {compiled.from_clause()} WHERE {compiled.where}"
        return int(conn.execute(sql, compiled.params).fetchone()[0])
    finally:
        conn.close()


@pytest.fixture()
def db_path(default_db_file, tmp_path) -> Path:
    copy = tmp_path / "people.db"
    copy_database_file(default_db_file, copy)
    return copy


@pytest.fixture()
def copy_in_process(tmp_path, monkeypatch):
    """This process counts from the copy whatever the database's size, building
    it in the caller into a private cache; no copy open when the test starts or ends."""
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    monkeypatch.setattr(copy_file, "BACKGROUND", False)
    monkeypatch.setattr(copy_file, "CACHE_DIR", tmp_path / "columns")
    copy_file.OPEN_COPIES.clear()
    yield
    copy_file.OPEN_COPIES.clear()


def test_without_db_copy_a_fresh_query_process_counts_with_sqlite(db_path, tmp_path):
    """The problem: the background build dies with the one-shot process."""
    done = sass(tmp_path / "cache", "query", "--db", str(db_path), "--count", QUERY)
    assert done.returncode == 0, done.stderr
    assert int(done.stdout) == sqlite_count(db_path, QUERY)
    assert "answered by: sqlite: the copy is being built" in done.stderr


def test_after_db_copy_a_fresh_query_process_counts_from_the_copy(db_path, tmp_path):
    cache = tmp_path / "cache"
    built = sass(cache, "db", "copy", "--db", str(db_path), "girth.right_upper_arm.z > 28 cm")
    assert built.returncode == 0, built.stderr
    everyone = people_in(db_path)  # the virtual people too: the copy holds every person
    assert f"built: {everyone} people, 7 columns" in built.stdout
    assert "q_girth_right_upper_arm.z" in built.stdout
    assert "Traceback" not in built.stderr
    counted = sass(cache, "query", "--db", str(db_path), "--count", QUERY)
    assert counted.returncode == 0, counted.stderr
    assert "answered by: copy" in counted.stderr
    assert int(counted.stdout) == sqlite_count(db_path, QUERY)
    again = sass(cache, "db", "copy", "--db", str(db_path))
    assert f"already up to date: {everyone} people" in again.stdout


@pytest.mark.slow
def test_db_copy_follows_a_write_then_the_fresh_process_agrees(db_path, tmp_path):
    cache = tmp_path / "cache"
    assert sass(cache, "db", "copy", "--db", str(db_path), QUERY).returncode == 0
    raw = sqlite3.connect(db_path)
    with raw:
        raw.execute("DELETE FROM person WHERE id_num IN (SELECT id_num FROM person LIMIT 7)")
        raw.execute("UPDATE person SET stature = 199.0 WHERE gender = 'male' AND id_num % 5 = 0")
    raw.close()
    refreshed = sass(cache, "db", "copy", "--db", str(db_path))
    assert f" built: {people_in(db_path)} people" in refreshed.stdout, refreshed.stdout  # whole
    counted = sass(cache, "query", "--db", str(db_path), "--count", QUERY)
    assert "answered by: copy" in counted.stderr
    assert int(counted.stdout) == sqlite_count(db_path, QUERY)


def test_a_loaded_copy_is_not_written_again(db_path, copy_in_process):
    """A new process that loads the disk copy and counts leaves it as it is
    (it was rewritten whole, 140 MB at 5,000,000 people, by every process)."""
    conn = connect(db_path)
    try:
        done = accelerator.refresh(conn, accelerator.columns_named(compile_query(QUERY)))
        before = sorted(p.name for p in done.folder.iterdir())
        copy_file.OPEN_COPIES.clear()  # as a new process
        compiled = compile_query(QUERY)
        assert accelerator.count(conn, compiled) == sqlite_count(db_path, QUERY)
        assert accelerator.last_answer == "copy"
        assert sorted(p.name for p in done.folder.iterdir()) == before
    finally:
        conn.close()


@pytest.mark.slow
def test_db_init_drops_the_old_copy(db_path, tmp_path, monkeypatch, few_default_people):
    cache = tmp_path / "cache"
    built = sass(cache, "db", "copy", "--db", str(db_path))
    folder = Path(built.stdout.rsplit(" in ", 1)[1].strip())
    assert folder.is_dir()
    monkeypatch.setattr(copy_file, "CACHE_DIR", cache / "sass" / "columns")
    assert main(["db", "init", "--force", "--db", str(db_path)]) == 0
    assert not folder.exists()


def test_db_copy_of_a_missing_database_is_a_message(tmp_path, capsys):
    assert main(["db", "copy", "--db", str(tmp_path / "none.db")]) == 2
    err = capsys.readouterr().err
    assert "none.db: no database there" in err
    assert "Traceback" not in err
    assert not (tmp_path / "none.db").exists()


def test_db_copy_of_a_file_that_is_not_a_database_is_a_message(tmp_path, capsys):
    junk = tmp_path / "junk.db"
    junk.write_text("not SQLite\n" * 50)
    assert main(["db", "copy", "--db", str(junk)]) == 2
    err = capsys.readouterr().err
    assert "junk.db" in err and "Traceback" not in err


def test_db_copy_of_a_wal_database_says_why(db_path, tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(copy_file, "CACHE_DIR", tmp_path / "columns")
    raw = sqlite3.connect(db_path)
    raw.execute("PRAGMA journal_mode = WAL")
    raw.close()
    assert main(["db", "copy", "--db", str(db_path)]) == 2
    err = capsys.readouterr().err
    assert "no column copy can follow this database" in err and "WAL" in err


def test_db_copy_of_a_query_the_copy_cannot_answer_says_so(db_path, capsys):
    assert main(["db", "copy", "--db", str(db_path), "source = 'Zürich'"]) == 2
    err = capsys.readouterr().err
    assert "the column copy cannot answer this query" in err
    assert "not ASCII compared without regard to case" in err  # not the SQL it compiles to
    assert "COLLATE" not in err and "counts it with SQLite" in err


def test_copies_are_attached_to_one_duckdb_and_detached_when_dropped(
    db_path, copy_in_process, monkeypatch
):
    """Each copy built or opened is ATTACHed to the process's one in-memory
    DuckDB (db/query/column_copy.py): no database instance of its own (25 ms
    and a thread pool apiece), and none left attached once it is dropped."""
    import duckdb

    from sass_tui.db.people.replacing import forget_column_copy
    from sass_tui.db.query import column_copy

    instances: list[object] = []
    real_connect = duckdb.connect

    def counted(*args, **kwargs):
        instances.append(args)
        return real_connect(*args, **kwargs)

    monkeypatch.setattr(duckdb, "connect", counted)
    monkeypatch.setattr(column_copy, "_INSTANCE", {})
    conn = connect(db_path)
    try:
        for text in (QUERY, "girth.neck.y > 20 cm", "mass > 80 kg AND gender = female"):
            assert accelerator.count(conn, compile_query(text)) == sqlite_count(db_path, text)
            assert accelerator.last_answer == "copy"
        with conn:
            conn.execute("DELETE FROM person WHERE id_num IN (SELECT id_num FROM person LIMIT 3)")
        assert accelerator.count(conn, compile_query(QUERY)) == sqlite_count(db_path, QUERY)
        assert instances == [()]  # one in-memory instance for builds and opens alike
        duck = column_copy._INSTANCE["duckdb"]

        def attached() -> list[str]:
            rows = duck.execute("SELECT database_name FROM duckdb_databases()").fetchall()
            return sorted(name for (name,) in rows if name.startswith(("copy_", "building_")))

        assert len(attached()) == 1  # the copy in use; the older ones and the builds detached
        forget_column_copy(db_path.resolve())
        assert attached() == []
    finally:
        conn.close()
