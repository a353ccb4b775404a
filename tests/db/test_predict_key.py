"""The prediction cache's key (db/populations/predict.py's data_key): computed
again after any commit, by this connection, another one or another process,
and taken from what this process computed before only while the SQLite
file's change counter shows no commit since."""

from __future__ import annotations

import shutil
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest

from sass_tui.db.engine.schema import connect, transaction
from sass_tui.db.populations import predict
from sass_tui.db.populations.predict import data_key


@pytest.fixture()
def db(small_db_file, tmp_path) -> Path:
    copy = tmp_path / "small.db"
    shutil.copyfile(small_db_file, copy)
    return copy


def reads_of_people(conn: sqlite3.Connection, population: str | None = None) -> tuple[str, int]:
    """data_key's answer and how many statements it ran on the person table."""
    statements: list[str] = []
    conn.set_trace_callback(statements.append)
    try:
        key = data_key(conn) if population is None else data_key(conn, population)
    finally:
        conn.set_trace_callback(None)
    return key, sum("FROM person" in statement for statement in statements)


def computed_afresh(path: Path) -> str:
    """The key of the file as another process computes it (nothing remembered)."""
    code = (
        "import sys; from sass_tui.db.engine.schema import connect; "
        "from sass_tui.db.populations.predict import data_key; "
        "print(data_key(connect(sys.argv[1])))"
    )
    return subprocess.run(
        [sys.executable, "-c", code, str(path)], capture_output=True, text=True, check=True
    ).stdout.strip()


def test_an_unchanged_file_gives_the_key_computed_before_without_reading_the_people(db):
    conn = connect(db)
    first, reads = reads_of_people(conn)
    assert reads == 1  # the file is new to this process
    again, reads = reads_of_people(conn)
    assert (again, reads) == (first, 0)
    other = connect(db)  # another connection to the same file: the same
    assert reads_of_people(other) == (first, 0)
    assert first == computed_afresh(db)
    # another population is another key, computed
    women, reads = reads_of_people(conn, "gender = female")
    assert women != first and reads == 1
    # spaces do not make another population
    assert reads_of_people(conn, "gender  =  female ") == (women, 0)


def test_a_commit_by_this_connection_another_or_another_process_changes_the_key(db):
    conn = connect(db)
    keys = [data_key(conn)]
    person = conn.execute("SELECT min(id_num) FROM person").fetchone()[0]

    def edited() -> str:
        key, reads = reads_of_people(conn)
        assert reads == 1 and key not in keys
        keys.append(key)
        return key

    # two edits in a row that keep the file's size: the change counter tells them apart
    for _ in range(2):
        with transaction(conn):
            conn.execute("UPDATE person SET stature = stature + 1 WHERE id_num = ?", (person,))
        edited()
    other = connect(db)
    with transaction(other):
        other.execute("UPDATE person SET mass = mass + 1 WHERE id_num = ?", (person,))
    edited()
    code = (
        "import sqlite3, sys; c = sqlite3.connect(sys.argv[1]); "
        f"c.execute('UPDATE person SET mass = mass + 1 WHERE id_num = {person}'); c.commit()"
    )
    subprocess.run([sys.executable, "-c", code, str(db)], check=True)
    assert edited() == computed_afresh(db)


def test_uncommitted_writes_count_and_are_not_remembered(db):
    conn = connect(db)
    before = data_key(conn)
    conn.execute("BEGIN")
    conn.execute("UPDATE person SET stature = stature + 1")
    inside, reads = reads_of_people(conn)
    assert inside != before and reads == 1
    conn.execute("ROLLBACK")
    assert reads_of_people(conn) == (before, 0)


def test_a_file_in_wal_mode_is_read_each_time(db):
    conn = connect(db)
    assert conn.execute("PRAGMA journal_mode = WAL").fetchone() == ("wal",)
    first, reads = reads_of_people(conn)
    assert reads == 1
    assert reads_of_people(conn) == (first, 1)
    # a commit in WAL mode may leave the header's counter as it was
    with transaction(conn):
        conn.execute("UPDATE person SET stature = stature + 1")
    assert reads_of_people(conn)[0] != first


def test_the_remembered_keys_are_bounded(db, tmp_path):
    for k in range(predict._KEYS_KEPT + 4):
        data_key(connect(db), f"id_num > {k}")
    assert len(predict._KEYS) <= predict._KEYS_KEPT
