"""The column copy itself: SQLite's columns read into numpy arrays, the
DuckDB file written from them and read back, the background builds, and the
answers from it (db/query/accelerator.py's docstring says when and why).

A module of its own so that numpy, duckdb and uuid are imported at its top
and only when a copy is used: db/query/accelerator.py reaches it once a database
holds accelerator.MIN_PEOPLE people, never below (off the `sass query
--count` and `sass db init` rows of sass_tui/startup.py).
"""

from __future__ import annotations

import itertools
import json
import os
import sqlite3
import threading
import uuid
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import duckdb
import numpy as np

from sass_tui.db.engine.schema import DatabaseError
from sass_tui.db.query import copy_file
from sass_tui.db.query.copy_file import (
    COPY_FILE,
    LOCK,
    Unsupported,
    cache_folder,
    data_version,
    database_path,
)
from sass_tui.db.query.query_tree import Comparison, to_sql

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable

    from sass_tui.db.query.query import CompiledQuery

# A text column with more different values than this is left to SQLite.
MAX_WORDS = 200
# The columns every copy holds besides those its queries name: the person's own.
DEFAULT_COLUMNS = (
    ("person", "gender"),
    ("person", "stature"),
    ("person", "mass"),
    ("person", "age"),
    ("person", "handedness"),
)


# This process's one DuckDB, in memory, made when a copy is first used: each
# copy file is ATTACHed to it under an alias of its own (1 ms) instead of
# opened as a database of its own (25 ms apiece: an instance with its threads
# and buffer pool).  Every user takes a cursor of its own (DuckDB's
# connections are not shared between threads).
_INSTANCE: dict[str, Any] = {}
_INSTANCE_LOCK = threading.Lock()
_ALIASES = itertools.count(1)


def _duckdb_cursor() -> Any:
    with _INSTANCE_LOCK:
        if "duckdb" not in _INSTANCE:
            _INSTANCE["duckdb"] = duckdb.connect()
        return _INSTANCE["duckdb"].cursor()


def _file_literal(path: Path) -> str:
    return "'" + str(path).replace("'", "''") + "'"


# --- reading SQLite's columns --------------------------------------------------


def _column_kind(conn: sqlite3.Connection, table: str, column: str) -> str:
    """'number' or 'text' from the declared type; Unsupported for anything else."""
    for _cid, name, declared, *_rest in conn.execute(f"PRAGMA table_info({table})"):
        if name == column:
            declared = declared.upper()
            if declared in ("REAL", "INTEGER"):
                return "number"
            if declared == "TEXT":
                ddl = conn.execute(
                    "SELECT sql FROM sqlite_master WHERE type = 'table' AND name = ?", (table,)
                ).fetchone()[0]
                if "COLLATE" in ddl.upper():
                    raise Unsupported(f"{table} has a collation")
                return "text"
            raise Unsupported(f"{table}.{column} is declared {declared}")
    raise Unsupported(f"{table} has no column {column}")


def _one_row_per_person(conn: sqlite3.Connection, table: str) -> bool:
    """Whether id_num alone is the table's primary key (so the LEFT JOIN keeps one row a person)."""
    keys = [r[1] for r in conn.execute(f"PRAGMA table_info({table})") if r[5]]
    return keys == ["id_num"]


def _fetch_ints(conn: sqlite3.Connection, sql: str) -> Any:
    cursor = conn.execute(sql)
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter((r[0] for r in rows), dtype=np.int64, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=np.int64)


def _fetch_pairs(cursor: sqlite3.Cursor, value_type: Any) -> Any:
    dtype = np.dtype([("id", np.int64), ("v", value_type)])
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter(rows, dtype=dtype, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=dtype)


def _read_column(conn: sqlite3.Connection, table: str, column: str, ids: Any) -> tuple[Any, Any]:
    """One column aligned on the sorted person ids: (float64 values with NaN for
    NULL, None) or (int32 word numbers with -1 for NULL, the words)."""
    if not _one_row_per_person(conn, table):
        raise Unsupported(f"{table} is not one row per person")
    kind = _column_kind(conn, table, column)
    if kind == "number":
        # Anything but a number (text, a blob) becomes 'not a number', which
        # float() refuses: such a column cannot be copied and SQLite answers.
        cursor = conn.execute(
            f"SELECT id_num, CASE WHEN typeof({column}) IN ('real', 'integer') THEN {column} "
            f"ELSE 'not a number' END FROM {table} WHERE {column} IS NOT NULL"
        )
        try:
            rows = _fetch_pairs(cursor, np.float64)
        except ValueError:
            raise Unsupported(f"{table}.{column} holds a value that is not a number") from None
        out = np.full(len(ids), np.nan)
        words = None
    else:
        # The distinct words first, then each row's word number computed by
        # SQLite (a CASE over the words, with the column's own BINARY
        # comparison): no Python work per row.  A value that is not text
        # becomes -2 and refuses the copy.
        words = [
            w
            for (w,) in conn.execute(
                f"SELECT DISTINCT {column} FROM {table} WHERE typeof({column}) = 'text'"
            )
        ]
        if len(words) > MAX_WORDS:
            raise Unsupported(f"{table}.{column} has more than {MAX_WORDS} different values")
        if not all(w.isascii() for w in words):
            raise Unsupported(f"{table}.{column} holds a word that is not ASCII")
        cases = "".join(f" WHEN {column} = ? THEN {k}" for k in range(len(words)))
        cursor = conn.execute(
            f"SELECT id_num, CASE WHEN typeof({column}) <> 'text' THEN -2{cases} ELSE -3 END "
            f"FROM {table} WHERE {column} IS NOT NULL",
            words,
        )
        rows = _fetch_pairs(cursor, np.int32)
        if len(rows) and int(rows["v"].min()) < 0:
            raise Unsupported(f"{table}.{column} holds a value that is not TEXT")
        out = np.full(len(ids), -1, dtype=np.int32)
    at = np.searchsorted(ids, rows["id"])
    known = at < len(ids)
    known[known] = ids[at[known]] == rows["id"][known]
    out[at[known]] = rows["v"][known]
    return out, words


# --- the copy on disk ----------------------------------------------------------


def _name(table: str, column: str) -> str:
    """The copy's column for a query table's column (both are schema names, never user text)."""
    return f'"{table}.{column}"'


def _column_sql(comparison: Comparison) -> str:
    return _name(comparison.table, comparison.column)


def _build(
    conn: sqlite3.Connection,
    path: Path,
    want: set[tuple[str, str]],
    progress: Callable[[int, int], None] | None = None,
) -> None:
    """Read `want` from SQLite inside the caller's read transaction and write
    the copy (a new file renamed over the old: readers never see half a copy)."""
    key = data_version(conn)
    ids = _fetch_ints(conn, "SELECT id_num FROM person ORDER BY id_num")
    arrays: dict[str, Any] = {"id_num": ids}
    select = ["id_num"]
    params: list[object] = []
    refused: list[list[str]] = []
    ordered = sorted(want)
    for i, (table, column) in enumerate(ordered):
        if progress is not None:
            progress(i, len(ordered))
        try:
            values, words = _read_column(conn, table, column, ids)
        except Unsupported:
            refused.append([table, column])
            continue
        arrays[f"c{i}"] = values
        if words is None:
            select.append(
                f"CASE WHEN isnan(c{i}) THEN NULL ELSE c{i} END AS {_name(table, column)}"
            )
        else:
            select.append(
                f"CASE WHEN c{i} < 0 THEN NULL ELSE (?::VARCHAR[])[c{i} + 1] END "
                f"AS {_name(table, column)}"
            )
            params.append(words)
    folder = cache_folder(path)
    folder.mkdir(parents=True, exist_ok=True)
    tmp = folder / f"tmp-{uuid.uuid4().hex[:8]}.duckdb"
    alias = f"building_{next(_ALIASES)}"
    try:
        duck = _duckdb_cursor()
        try:
            duck.execute(f"ATTACH {_file_literal(tmp)} AS {alias}")
            try:
                duck.register("sqlite_columns", arrays)
                duck.execute(
                    f"CREATE TABLE {alias}.people AS SELECT {', '.join(select)} "
                    "FROM sqlite_columns",
                    params,
                )
                duck.execute(
                    f"CREATE TABLE {alias}.copy_meta AS "
                    "SELECT ?::VARCHAR AS key, ?::VARCHAR AS refused",
                    [json.dumps(list(key)), json.dumps(refused)],
                )
            finally:
                duck.execute(f"DETACH {alias}")  # written out and closed
        finally:
            duck.close()
        os.replace(tmp, folder / COPY_FILE)
    finally:
        tmp.unlink(missing_ok=True)
    if progress is not None:
        progress(len(ordered), len(ordered))


@dataclass
class CopyHeld:
    """An open copy: attached read-only under `alias` to the process's DuckDB
    (`duck`, a cursor of its own), and what it holds."""

    stamp: tuple[int, int, int]  # the copy file's inode, mtime and size when opened
    duck: Any
    alias: str
    key: tuple[int, ...]
    columns: frozenset[tuple[str, str]]
    refused: frozenset[tuple[str, str]]
    people: int

    def close(self) -> None:
        _detach(self.duck, self.alias)


def _detach(duck: Any, alias: str) -> None:
    """Detach a copy attached by `duck` (a cursor of the process's DuckDB) and close it."""
    try:
        duck.execute(f"DETACH {alias}")
    except duckdb.Error:  # pragma: no cover - attached by this cursor
        pass
    duck.close()


_BUILDS: dict[Path, threading.Thread] = {}
_PENDING: dict[Path, set[tuple[str, str]]] = {}


def _open_copy(path: Path) -> CopyHeld | None:
    """The copy of `path` on disk, opened (or the one open already), None if
    absent or unreadable.  Call with LOCK held."""
    file = cache_folder(path) / COPY_FILE
    try:
        stat = file.stat()
    except OSError:
        stat = None
    stamp = None if stat is None else (stat.st_ino, stat.st_mtime_ns, stat.st_size)
    held: CopyHeld | None = copy_file.OPEN_COPIES.get(path)
    if held is not None and held.stamp == stamp:
        return held
    if held is not None:
        held.close()
        del copy_file.OPEN_COPIES[path]
    if stamp is None:
        return None
    alias = f"copy_{next(_ALIASES)}"
    duck = _duckdb_cursor()
    try:
        duck.execute(f"ATTACH {_file_literal(file)} AS {alias} (READ_ONLY)")
    except duckdb.Error:
        duck.close()
        return None
    try:
        meta = duck.execute(
            f"SELECT key, refused, (SELECT count(*) FROM {alias}.people) FROM {alias}.copy_meta"
        )
        key, refused, people = meta.fetchone() or ("", "", 0)
        names = [row[0] for row in duck.execute(f"DESCRIBE {alias}.people").fetchall()]
    except (duckdb.Error, TypeError, ValueError):
        _detach(duck, alias)
        return None
    held_columns = frozenset(
        tuple(name.split(".", 1)) for name in names if name != "id_num" and "." in name
    )
    copy = CopyHeld(
        stamp,
        duck,
        alias,
        tuple(json.loads(key)),
        frozenset((t, c) for t, c in held_columns),
        frozenset((t, c) for t, c in json.loads(refused)),
        int(people),
    )
    copy_file.OPEN_COPIES[path] = copy
    return copy


def wait() -> None:
    """Wait for every background build to finish."""
    while True:
        with LOCK:
            threads = list(_BUILDS.values())
        if not threads:
            return
        for thread in threads:
            thread.join()


def _start_build(path: Path, wanted: set[tuple[str, str]]) -> None:
    """Have one background thread of this file build the copy with these columns."""
    with LOCK:
        _PENDING.setdefault(path, set()).update(wanted)
        if path in _BUILDS:
            return
        thread = threading.Thread(
            target=_build_in_background, args=(path,), name="column copy", daemon=True
        )
        _BUILDS[path] = thread
    thread.start()


def _build_in_background(path: Path) -> None:
    conn = None
    try:
        conn = sqlite3.connect(
            f"{path.resolve().as_uri()}?mode=ro", uri=True, isolation_level=None, timeout=10.0
        )
        while True:
            with LOCK:
                wanted = _PENDING.pop(path, None)
                if wanted is None:
                    _BUILDS.pop(path, None)
                    return
                held = _open_copy(path)
            want = wanted | set(DEFAULT_COLUMNS) | (set() if held is None else set(held.columns))
            try:
                _read(conn, lambda: _build(conn, path, want))
            except (Unsupported, OSError, sqlite3.Error, ValueError, ImportError):
                pass  # SQLite goes on answering
    except sqlite3.Error:
        pass
    finally:
        if conn is not None:
            conn.close()
        with LOCK:
            if _BUILDS.get(path) is threading.current_thread():
                _BUILDS.pop(path, None)
                _PENDING.pop(path, None)


def _read(conn: sqlite3.Connection, fn: Callable[[], Any]) -> Any:
    """fn() inside one read transaction (the shared lock held throughout)."""
    conn.execute("BEGIN")
    try:
        conn.execute("SELECT 1 FROM person LIMIT 1").fetchone()
        return fn()
    finally:
        conn.execute("COMMIT")


# --- answering -----------------------------------------------------------------


def matches(
    conn: sqlite3.Connection, compiled: CompiledQuery, wanted: set[tuple[str, str]], ids: bool
) -> Any:
    """The answer from the copy to `compiled` (which reads the columns
    `wanted`), None while it is being built (Unsupported: SQLite must answer).  Call inside a read transaction that has written
    nothing to the main database."""
    path = database_path(conn)
    key = data_version(conn)
    with LOCK:
        copy = _open_copy(path)
        if copy is not None and copy.key == key and wanted & copy.refused:
            raise Unsupported("a column the copy cannot hold")
        if copy is None or copy.key != key or not wanted <= copy.columns:
            if copy_file.BACKGROUND:
                _start_build(path, wanted)
                return None
            held = set() if copy is None else set(copy.columns)
            _build(conn, path, wanted | held | set(DEFAULT_COLUMNS))
            copy = _open_copy(path)
            if copy is None or copy.key != key:  # pragma: no cover - the file just written
                raise Unsupported("the copy could not be written")
            if wanted & copy.refused:
                raise Unsupported("a column the copy cannot hold")
        where, params = to_sql(compiled.tree, "duckdb", column_sql=_column_sql)
        cursor = copy.duck.cursor()
        try:
            if ids:
                found = cursor.execute(
                    f"SELECT id_num FROM {copy.alias}.people WHERE {where} ORDER BY id_num",
                    params,
                ).fetchnumpy()["id_num"]
                return [int(i) for i in found.tolist()]
            row = cursor.execute(
                f"SELECT count(*) FROM {copy.alias}.people WHERE {where}", params
            ).fetchone()
            return int(row[0]) if row else 0
        finally:
            cursor.close()


# --- building it now (`sass db copy`) -------------------------------------------


@dataclass(frozen=True)
class Refreshed:
    """What `refresh` did: the copy's people and columns, and how it got there."""

    people: int
    columns: tuple[tuple[str, str], ...]
    refused: tuple[tuple[str, str], ...]  # left to SQLite (a value of another type, ...)
    how: str  # "built" or "already up to date"
    folder: Path


def refresh_now(
    conn: sqlite3.Connection,
    wanted: Iterable[tuple[str, str]] = (),
    progress: Callable[[int, int], None] | None = None,
) -> Refreshed:
    """db/query/accelerator.py's refresh, outside a transaction: build the copy of
    conn's database now, in the caller (a one-shot
    process's background build would die with it), unless it is up to date:
    the columns it held, DEFAULT_COLUMNS and `wanted`.  Whatever the size of
    the database (counts use the copy from MIN_PEOPLE people).
    DatabaseError when no copy can follow this file."""
    try:
        path = database_path(conn)
        folder = cache_folder(path)

        def build() -> str:
            key = data_version(conn)
            with LOCK:
                copy = _open_copy(path)
                held = set() if copy is None else set(copy.columns | copy.refused)
                want = held | set(DEFAULT_COLUMNS) | set(wanted)
                if copy is not None and copy.key == key and want <= held:
                    return "already up to date"
                _build(conn, path, want, progress)
            return "built"

        how = _read(conn, build)
    except Unsupported as exc:
        raise DatabaseError(f"no column copy can follow this database: {exc}") from None
    except OSError as exc:
        raise DatabaseError(f"cannot write the column copy in {folder}: {exc}") from None
    with LOCK:
        copy = _open_copy(path)
        if copy is None:
            raise DatabaseError(f"cannot read the column copy in {folder}")
        return Refreshed(
            copy.people, tuple(sorted(copy.columns)), tuple(sorted(copy.refused)), how, folder
        )
