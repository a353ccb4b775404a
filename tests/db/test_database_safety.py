"""The database survives what users and other processes do to it: `db init`
rebuilds in place, a stale journal is harmless, the schema is checked on open,
a foreign or damaged file is never written, and the query lists work while
another process imports."""

from __future__ import annotations

import io
import os
import signal
import sqlite3
import stat
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest
from _built_once import copy_database_file

from sass_tui.cli import main
from sass_tui.db.engine.dialect import writing
from sass_tui.db.engine.schema import (
    SCHEMA_VERSION,
    DatabaseError,
    connect,
    row_counts,
    transaction,
)
from sass_tui.db.people.default import create_default_database
from sass_tui.db.people.default_people import shipped_ansur_files
from sass_tui.db.people.flatfile import FlatFiles, import_flat_files
from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists
from sass_tui.db.query.query import run_query

pytestmark = pytest.mark.sqlite_only(
    "the SQLite file itself: its journal, locks, a foreign or damaged file"
)

ROOT = Path(__file__).resolve().parents[2]
# NHANES 2017-March 2020 adults with a height and a weight: the shipped
# virtual population `sass db init` stores (tests/cli/test_db.py counts them
# from the published CSV).
NHANES_ADULTS = 8381
PERSON = "99907,JANE_DOE,female,165.0,60.5,left,31,hand-made test person\n"


@pytest.fixture()
def db_path(default_db_file, tmp_path) -> Path:
    path = tmp_path / "sass.db"
    copy_database_file(default_db_file, path)
    return path


def _flat(tmp_path: Path) -> FlatFiles:
    (tmp_path / "person.db").write_text(PERSON)
    return FlatFiles.in_directory(tmp_path)


def _integrity(path: Path) -> str:
    conn = sqlite3.connect(path)
    try:
        return conn.execute("PRAGMA integrity_check").fetchone()[0]
    finally:
        conn.close()


def _count(path: Path, where: str = "1") -> int:
    conn = sqlite3.connect(path)
    try:
        return conn.execute(f"SELECT count(*) FROM person WHERE {where}").fetchone()[0]
    finally:
        conn.close()


# --- the schema is checked on open ---------------------------------------------------


def test_a_foreign_sqlite_file_gets_no_tables(tmp_path, capsys):
    path = tmp_path / "theirs.db"
    conn = sqlite3.connect(path)
    conn.execute("CREATE TABLE invoices (n INTEGER)")
    conn.commit()
    conn.close()
    before = path.read_bytes()
    with pytest.raises(DatabaseError, match="another program"):
        connect(path, create=True)
    files = _flat(tmp_path)
    assert (
        main(
            [
                "db",
                "import-flat",
                "--db",
                str(path),
                "--person",
                str(files.person),
                "--girth",
                "/dev/null",
                "--jntlmt",
                "/dev/null",
                "--cmass",
                "/dev/null",
            ]
        )
        == 2
    )
    assert "another program" in capsys.readouterr().err
    assert main(["db", "init", "--force", "--db", str(path)]) == 2
    assert path.read_bytes() == before


def test_a_file_that_is_not_sqlite_is_refused(tmp_path):
    path = tmp_path / "notes.db"
    path.write_text("not a database\n" * 100)
    with pytest.raises(DatabaseError, match="not a usable sass database"):
        connect(path, create=True)
    assert path.read_text() == "not a database\n" * 100


def test_a_newer_schema_is_refused(db_path, tmp_path):
    raw = sqlite3.connect(db_path)
    raw.execute("UPDATE meta SET value = '99' WHERE key = 'schema_version'")
    raw.commit()
    raw.close()
    with pytest.raises(DatabaseError, match="schema version 99"):
        connect(db_path)
    before = db_path.read_bytes()
    assert (
        main(
            [
                "db",
                "import-flat",
                "--db",
                str(db_path),
                "--person",
                str(_flat(tmp_path).person),
                "--girth",
                "/dev/null",
                "--jntlmt",
                "/dev/null",
                "--cmass",
                "/dev/null",
            ]
        )
        == 2
    )
    assert db_path.read_bytes() == before


def test_a_schema_1_database_is_migrated(db_path):
    raw = sqlite3.connect(db_path)
    raw.executescript(
        "DROP TABLE measure_packed; DROP TABLE measure;"
        + "".join(
            f"ALTER TABLE person DROP COLUMN {c};"
            for c in ("component", "branch", "subjectnumericrace", "dodrace", "ethnicity")
        )
        + "UPDATE meta SET value = '1' WHERE key = 'schema_version';"
    )
    raw.close()
    people = _count(db_path)
    conn = connect(db_path)
    try:
        version = conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()
        assert version == (SCHEMA_VERSION,)
        # any source term reaches every person, the synthetic ones too
        assert run_query(conn, "stature > 0 cm AND source != none").count() == people
        assert run_query(conn, "measure.stature > 0 cm").count() == 0  # nothing measured yet
    finally:
        conn.close()


def test_a_missing_table_is_refused(db_path):
    raw = sqlite3.connect(db_path)
    raw.execute("DROP TABLE q_girth_neck")
    raw.commit()
    raw.close()
    with pytest.raises(DatabaseError, match="q_girth_neck missing"):
        connect(db_path)


def _scribble_over_the_person_table(db_path: Path) -> None:
    """Another program writes over the person table's first page."""
    raw = sqlite3.connect(db_path)
    page_size = raw.execute("PRAGMA page_size").fetchone()[0]
    root = raw.execute("SELECT rootpage FROM sqlite_master WHERE name = 'person'").fetchone()[0]
    raw.close()
    with db_path.open("r+b") as handle:
        handle.seek((root - 1) * page_size + 8)
        handle.write(b"\xff" * 64)


def test_a_damaged_database_refuses_writes(db_path, tmp_path):
    _scribble_over_the_person_table(db_path)
    before = db_path.read_bytes()
    conn = connect(db_path)
    try:
        with pytest.raises(DatabaseError, match="damaged"):
            import_flat_files(conn, _flat(tmp_path))
    finally:
        conn.close()
    assert db_path.read_bytes() == before
    with pytest.raises(DatabaseError, match="damaged"):
        create_default_database(db_path, replace=True)
    assert db_path.read_bytes() == before


def test_a_file_found_whole_is_read_through_again_only_once_something_changed_it(db_path, tmp_path):
    """The first write of a process reads the whole file (PRAGMA quick_check);
    its next writes do not while the file is as that process left it.  Once
    another program has written to it, the next write reads it through
    again, and refuses it damaged."""
    checks: list[str] = []

    def opened() -> sqlite3.Connection:
        conn = connect(db_path)
        conn.set_trace_callback(lambda sql: checks.append(sql) if "quick_check" in sql else None)
        return conn

    conn = opened()
    try:
        for k in range(3):
            with writing(conn):
                conn.execute("INSERT OR REPLACE INTO meta VALUES (?, 'x')", (f"test_{k}",))
    finally:
        conn.close()
    assert len(checks) == 1
    # the other program's write falls in a later tick of the file system's
    # clock than the last write's (a file's times are a few ms coarse)
    written = db_path.stat().st_mtime_ns
    tick = tmp_path / "tick"
    tick.touch()
    while tick.stat().st_mtime_ns <= written:
        tick.touch()
    _scribble_over_the_person_table(db_path)
    before = db_path.read_bytes()
    conn = opened()  # a new connection: SQLite's own page cache holds the old pages
    try:
        with pytest.raises(DatabaseError, match="damaged"):
            with writing(conn):
                conn.execute("INSERT OR REPLACE INTO meta VALUES ('test_3', 'x')")
    finally:
        conn.close()
    assert len(checks) == 2
    assert db_path.read_bytes() == before


# --- db init ------------------------------------------------------------------------


@pytest.mark.slow
def test_db_init_needs_force_to_replace_people(db_path, tmp_path, capsys, few_default_people):
    conn = connect(db_path)
    import_flat_files(conn, _flat(tmp_path))
    conn.close()
    assert main(["db", "init", "--db", str(db_path)]) == 2  # no terminal to ask on
    assert "--force" in capsys.readouterr().err
    assert _count(db_path, "name = 'JANE_DOE'") == 1
    assert main(["db", "init", "--force", "--db", str(db_path)]) == 0
    assert _count(db_path, "name = 'JANE_DOE'") == 0
    assert _count(db_path) == few_default_people.everyone


@pytest.mark.slow
def test_db_init_rebuilds_in_place_under_an_open_connection(db_path, tmp_path, few_default_people):
    """No file is renamed over the database: the same inode, and a connection
    opened before the rebuild reads the new database, not a malformed one."""
    inode = db_path.stat().st_ino
    reader = connect(db_path)
    conn = connect(db_path)
    import_flat_files(conn, _flat(tmp_path))
    conn.close()
    assert run_query(reader, "stature > 0 cm").count() == 6068 + 1  # real people
    create_default_database(db_path, replace=True)
    assert db_path.stat().st_ino == inode
    everyone = run_query(reader, "stature > 0 cm AND source != none").count()
    assert everyone == few_default_people.everyone
    reader.close()
    assert _integrity(db_path) == "ok"
    assert not Path(f"{db_path}-journal").exists()


def test_db_init_builds_an_empty_file_in_place(tmp_path, few_default_people):
    # (what a build from the whole data holds: tests/cli/test_db.py)
    path = tmp_path / "empty.db"
    path.touch()
    assert create_default_database(path) == {
        "synthetic": 200,
        "ansur2": few_default_people.ansur,
        "virtual:nhanes-2017-2020": few_default_people.virtual,
    }
    assert create_default_database(path) == {}  # first use twice: built once


CHILD = textwrap.dedent(
    """
    import sys, time
    from sass_tui.db.people.ansur import import_ansur
    from sass_tui.db.engine.schema import connect
    conn = connect(sys.argv[1])
    conn.execute("PRAGMA cache_size = 20")  # spill pages to the file mid-transaction
    def progress(done, total):
        if done > total // 3:
            print("half way", flush=True)
            time.sleep(60)
    import_ansur(conn, sys.argv[2:], progress=progress, label="killed")
    """
)


@pytest.mark.slow
def test_kill_9_mid_import_then_db_init(db_path, few_default_people):
    """A killed import leaves a hot journal: the database reads as before, and
    `db init` rebuilds it whole."""
    before = row_counts_of(db_path)
    child = subprocess.Popen(
        [sys.executable, "-c", CHILD, str(db_path), *map(str, shipped_ansur_files())],
        stdout=subprocess.PIPE,
        cwd=ROOT,
    )
    assert child.stdout is not None
    assert child.stdout.readline().strip() == b"half way"
    assert Path(f"{db_path}-journal").exists()
    os.kill(child.pid, signal.SIGKILL)
    child.wait()
    assert row_counts_of(db_path) == before  # rolled back, nothing of the import
    assert _integrity(db_path) == "ok"
    assert main(["db", "init", "--force", "--db", str(db_path)]) == 0
    assert _integrity(db_path) == "ok"
    assert _count(db_path, "source = 'killed'") == 0


def row_counts_of(path: Path) -> dict[str, int]:
    conn = connect(path)
    try:
        return row_counts(conn)
    finally:
        conn.close()


IMPORTER = textwrap.dedent(
    """
    import sys
    from sass_tui.db.people.ansur import import_ansur
    from sass_tui.db.engine.schema import connect
    conn = connect(sys.argv[1])
    print("start", flush=True)
    print(import_ansur(conn, sys.argv[2:], label="concurrent"), flush=True)
    """
)


def _start_import(path: Path) -> subprocess.Popen:
    child = subprocess.Popen(
        [sys.executable, "-c", IMPORTER, str(path), *map(str, shipped_ansur_files())],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        cwd=ROOT,
        text=True,
    )
    assert child.stdout is not None and child.stdout.readline().strip() == "start"
    return child


@pytest.mark.slow
def test_db_init_while_another_process_imports(db_path, few_default_people):
    child = _start_import(db_path)
    create_default_database(db_path, replace=True)
    out, err = child.communicate(timeout=120)
    assert _integrity(db_path) == "ok"
    imported = _count(db_path, "source = 'concurrent'")
    if child.returncode:
        # A loaded machine: the rebuild held the lock past the import's busy
        # timeout, and the import was refused before it began, storing nothing.
        assert "is busy: another process is writing to it" in err, err
        assert imported == 0
    # Either the import finished before the rebuild (and was replaced) or after it.
    assert imported in (0, few_default_people.ansur)
    assert _count(db_path, "source = 'ansur2'") == few_default_people.ansur


# --- the lists are read-only for the main database -------------------------------------


def test_lists_work_while_another_process_holds_the_write_lock(db_path):
    lists = QueryLists.open(db_path)
    lists._conn.execute("PRAGMA busy_timeout = 300")  # a lock would fail fast, not hang
    writer = subprocess.Popen(
        [
            sys.executable,
            "-c",
            "import sqlite3, sys, time\n"
            "c = sqlite3.connect(sys.argv[1], isolation_level=None)\n"
            "c.execute('BEGIN IMMEDIATE')\n"
            'c.execute("UPDATE person SET age = age WHERE id_num = 1")\n'
            "print('locked', flush=True)\n"
            "time.sleep(30)\n",
            str(db_path),
        ],
        stdout=subprocess.PIPE,
        text=True,
    )
    try:
        assert writer.stdout is not None and writer.stdout.readline().strip() == "locked"
        found = lists.run("gender = female AND source = ansur2")
        assert found == 1986
        page = lists.page(QUERY_LIST, 0, 25)
        assert lists.select_one(page[0]["id"])
        assert lists.delete_one(QUERY_LIST, page[1]["id"])
        assert lists.select_all() == 1984
        assert lists.delete_one(SELECTED_LIST, page[0]["id"])
        assert lists.count(SELECTED_LIST) == 1984
        assert len(lists.page(SELECTED_LIST, 1000, 25)) == 25
    finally:
        writer.kill()
        writer.wait()
        lists.close()


@pytest.mark.slow
def test_lists_page_while_another_process_imports(db_path):
    lists = QueryLists.open(db_path)
    child = _start_import(db_path)
    rounds = 0
    try:
        while child.poll() is None or rounds < 3:
            found = lists.run("gender = male AND source = ansur2")
            assert found == 4082 - lists.count(SELECTED_LIST)
            assert len(lists.page(QUERY_LIST, (rounds % 100) * 25, 25)) == 25
            assert lists.select_one(lists.page(QUERY_LIST, 0, 1)[0]["id"])
            rounds += 1
            time.sleep(0.01)
        out, err = child.communicate(timeout=120)
        assert child.returncode == 0, err
        assert "'male': 4082" in out
    finally:
        lists.close()
    assert _count(db_path, "source = 'concurrent'") == 6068
    assert _integrity(db_path) == "ok"


# --- progress and the question db init asks on a terminal --------------------------------


class _Terminal(io.StringIO):
    def __init__(self, text: str = "") -> None:
        super().__init__(text)

    def isatty(self) -> bool:
        return True


@pytest.mark.slow
def test_building_reports_progress(tmp_path, few_default_people):
    calls: list[tuple[int, int]] = []
    create_default_database(tmp_path / "p.db", progress=lambda d, t: calls.append((d, t)))
    assert len(calls) >= 3
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)
    # The survey's bytes fill the first half of the bar, the shipped target
    # and virtual population the second.
    survey = sum(f.stat().st_size for f in shipped_ansur_files())
    assert (survey, 2 * survey) in calls
    assert calls[-1] == (2 * survey, 2 * survey)
    assert {t for _, t in calls} == {2 * survey}


@pytest.mark.slow
@pytest.mark.parametrize("answer, status, kept", [("n\n", 1, 1), ("y\n", 0, 0)])
def test_db_init_asks_on_a_terminal(
    db_path, tmp_path, monkeypatch, answer, status, kept, few_default_people
):
    conn = connect(db_path)
    import_flat_files(conn, _flat(tmp_path))
    conn.close()
    err = _Terminal()
    monkeypatch.setattr(sys, "stdin", _Terminal(answer))
    monkeypatch.setattr(sys, "stderr", err)
    assert main(["db", "init", "--db", str(db_path)]) == status
    assert f"holds {6269 + NHANES_ADULTS} people" in err.getvalue() and "[y/N]" in err.getvalue()
    assert _count(db_path, "name = 'JANE_DOE'") == kept
    if status == 0:
        assert "building [" in err.getvalue()  # the progress bar


def test_db_init_while_a_writer_holds_the_lock_changes_nothing(db_path, monkeypatch):
    from sass_tui.db.engine import schema

    monkeypatch.setattr(schema, "BUSY_TIMEOUT_S", 0.3)
    writer = sqlite3.connect(db_path, isolation_level=None)
    writer.execute("BEGIN IMMEDIATE")
    writer.execute("UPDATE person SET age = 99 WHERE id_num = 1")
    try:
        with pytest.raises(DatabaseError, match="busy .*nothing changed"):
            create_default_database(db_path, replace=True)
    finally:
        writer.execute("COMMIT")
        writer.close()
    assert _count(db_path, "age = 99") == 1
    assert _integrity(db_path) == "ok"


def test_a_write_that_waits_past_the_busy_timeout_is_refused_by_name(db_path):
    """Another process holding the write lock longer than the busy timeout: the
    write is refused naming the database, with nothing begun (no raw
    "database is locked")."""
    holder = sqlite3.connect(db_path, isolation_level=None)
    holder.execute("BEGIN IMMEDIATE")
    conn = connect(db_path)
    conn.execute("PRAGMA busy_timeout = 50")
    try:
        with pytest.raises(
            DatabaseError, match=r"is busy: another process is writing to it \(waited 0.05 s\)"
        ):
            with transaction(conn):
                pass
        assert not conn.in_transaction
    finally:
        holder.execute("ROLLBACK")
        holder.close()
        conn.close()


def test_a_path_that_is_no_regular_file_is_refused_and_kept(tmp_path, capsys, monkeypatch):
    """A FIFO, a device, a directory: /dev/null's size is 0 like an empty
    file's, and `sass db init --db /dev/null` (as root) removed the device and
    put a database in its place; a query called it "an empty file".  A FIFO
    stands in for the device here: the test must not need one."""
    fifo = tmp_path / "pipe.db"
    os.mkfifo(fifo)
    folder = tmp_path / "folder.db"
    folder.mkdir()
    for path, kind in ((fifo, "a FIFO (named pipe)"), (folder, "a directory")):
        for argv in (
            ["db", "init"],
            ["db", "init", "--force"],
            ["query", "--count", "mass > 1 kg"],
        ):
            assert main(["--db", str(path), *argv]) == 2, argv
            assert f"{path}: {kind}, not a database file" in capsys.readouterr().err
        monkeypatch.setenv("SASS_DB", str(path))  # the default database, built on first use
        assert main(["query", "--count", "mass > 1 kg"]) == 2
        assert f"{path}: {kind}, not a database file" in capsys.readouterr().err
    assert stat.S_ISFIFO(os.stat(fifo).st_mode) and folder.is_dir()
    assert sorted(tmp_path.iterdir()) == sorted([fifo, folder])  # nothing built beside them
