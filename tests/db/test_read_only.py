"""`sass serve --read-only`: a database opened read-only (SQLite's mode=ro)
answers queries (the query lists are TEMP tables) and refuses every change,
leaving the file as it was."""

from __future__ import annotations

import hashlib
import sqlite3

import pytest
from _built_once import copy_database_file
from big_flat_files import write_big_flat_files

from sass_tui.db.engine.schema import connect
from sass_tui.db.query.lists import DB_ERRORS, QUERY_LIST, SELECTED_LIST, QueryLists

pytestmark = pytest.mark.sqlite_only("SQLite's read-only open (mode=ro) of a file")


def digest(path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def test_a_read_only_database_is_queried_and_never_changed(default_db_file, tmp_path):
    path = tmp_path / "sass.db"
    copy_database_file(default_db_file, path)
    before = digest(path)
    with connect(path) as conn:  # the same question, read-write (real people: db/query/scope.py)
        males = conn.execute(
            "SELECT count(*) FROM person WHERE gender = 'male' AND source != 'synthetic' "
            "AND substr(source, 1, 8) != 'virtual:'"
        ).fetchone()[0]
    assert males > 0
    lists = QueryLists.open(path, read_only=True)
    try:
        assert lists.run("gender = male") == males
        assert lists.count(QUERY_LIST) == males
        lists.select_all()
        assert lists.count(SELECTED_LIST) == males
        with pytest.raises(DB_ERRORS):
            lists.import_files(write_big_flat_files(tmp_path / "flat", people=3))
        with pytest.raises(sqlite3.OperationalError, match="readonly"):
            lists._conn.execute("DELETE FROM person")
    finally:
        lists.close()
    assert digest(path) == before
