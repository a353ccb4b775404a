"""Schema 6: no change-log triggers, and the target populations' tables;
files of schemas 2-5 lose their change log and gain the target tables on
opening, and keep every person."""

from __future__ import annotations

import sqlite3

import pytest
from _built_once import copy_database_file

from sass_tui.db.engine.schema import SCHEMA_VERSION, TARGET_TABLES, connect, row_counts

pytestmark = pytest.mark.sqlite_only("the migration of older SQLite files")

# What schemas 3 and 4 added (db/engine/schema.py before schema 5), enough of it to
# be dropped: the tables, the view, the one logging trigger and a per-table one.
OLD_CHANGE_LOG = """
CREATE TABLE change_gens (gen INTEGER PRIMARY KEY, token INTEGER NOT NULL);
CREATE TABLE change_log (id_num INTEGER PRIMARY KEY, gen INTEGER NOT NULL);
CREATE INDEX change_log_gen ON change_log (gen);
CREATE TABLE change_bulk (one INTEGER PRIMARY KEY);
CREATE TABLE change_schema (from_cookie INTEGER PRIMARY KEY, to_cookie INTEGER NOT NULL);
CREATE VIEW change_note AS SELECT 0 AS id_num;
CREATE TRIGGER change_note_insert INSTEAD OF INSERT ON change_note BEGIN
  INSERT OR REPLACE INTO change_log SELECT NEW.id_num, coalesce(max(gen), 0) FROM change_gens;
END;
CREATE TRIGGER log_person_update AFTER UPDATE ON person
BEGIN INSERT INTO change_note VALUES (OLD.id_num); INSERT INTO change_note VALUES (NEW.id_num); END;
CREATE TRIGGER log_q_girth_neck_insert AFTER INSERT ON q_girth_neck
BEGIN INSERT INTO change_note VALUES (NEW.id_num); END;
"""


def test_schema_version_is_6():
    assert SCHEMA_VERSION == "6"


# A schema 5 file had either the change log (with the target tables) or neither.
@pytest.mark.parametrize("old", ["2", "3", "4", "5"])
def test_an_older_file_loses_the_change_log_and_keeps_its_people(default_db_file, tmp_path, old):
    path = tmp_path / "old.db"
    copy_database_file(default_db_file, path)
    raw = sqlite3.connect(path)
    people = row_counts(raw)
    for table in TARGET_TABLES:  # made by schema 6 (or 5 with the change log)
        raw.execute(f"DROP TABLE {table}")
    if old != "2":  # schema 2 had no change log
        raw.executescript(OLD_CHANGE_LOG)
    raw.execute("UPDATE meta SET value = ? WHERE key = 'schema_version'", (old,))
    raw.commit()
    raw.close()
    conn = connect(path)
    try:
        assert conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone() == (
            "6",
        )
        tables = {name for (name,) in conn.execute("SELECT name FROM sqlite_master")}
        assert set(TARGET_TABLES) <= tables
        left = conn.execute(
            "SELECT name FROM sqlite_master WHERE name LIKE 'change%' OR name LIKE 'log\\_%' "
            "ESCAPE '\\'"
        ).fetchall()
        assert left == []
        assert row_counts(conn) == people
        # a write fires nothing that is gone
        conn.execute("UPDATE person SET stature = stature WHERE id_num = 1")
    finally:
        conn.close()


def test_a_new_file_has_no_trigger_but_the_measure_packing(tmp_path):
    conn = connect(tmp_path / "new.db", create=True)
    try:
        triggers = {
            name
            for (name,) in conn.execute("SELECT name FROM sqlite_master WHERE type = 'trigger'")
        }
        assert triggers == {
            "measure_packed_insert",
            "measure_packed_update",
            "measure_packed_delete",
        }
    finally:
        conn.close()
