"""Counts over millions of people from DuckDB, reading a copy of the queried columns.

SQLite answers a count by visiting, for each person, one row of every query
table the query names: on 5,000,000 people the report's sample query takes
seconds that way.  DuckDB (an established column engine, `pip install
'sass-tui[fast]'`) answers the same query tree (db/query_tree.py, its
"duckdb" dialect) over one wide table of the queried columns in tens of
milliseconds (docs/performance.md, "Database at scale").  DuckDB cannot read
the SQLite file here (its SQLite reader is an extension it downloads at run
time), so the columns are copied once into a DuckDB file under
$XDG_CACHE_HOME/sass/columns/ (one folder per database file) and the copy
carries the data version of the SQLite file it was read from.

The SQLite file stays the store of record; the copy may never disagree with it:

- The data version is the header's change counter (SQLite bumps it on every
  committed write in rollback-journal mode), page count and schema cookie,
  with the file's size, mtime and inode.  It is read, compared with the
  copy's and the query answered while one read transaction holds SQLite's
  shared lock, so no writer commits in between.  Any other version: the
  copy is built anew (in a background thread while SQLite answers; in the
  caller for `sass db copy`), whoever wrote the file.  No trigger follows
  the writes: a copy is all or nothing.
- Whatever cannot be proved equal, SQLite answers: a database in WAL mode
  (the header counter does not move on every write), a connection with its
  own transaction open, a column holding a value of another type than the
  one declared, a text column with a collation, more than MAX_WORDS
  different words or a word that is not ASCII (DuckDB's lower() and
  SQLite's NOCASE agree on ASCII only), a query table that is not one row
  per person; DuckDB not installed.  `count` then returns None.
- SQL's unknown is the same in both engines: a missing value is NULL in the
  copy (never NaN, which DuckDB orders above every number).

Only databases with at least MIN_PEOPLE people use the copy (below that
SQLite is fast, and neither numpy nor duckdb need be imported).
"""

from __future__ import annotations

import hashlib
import json
import os
import sqlite3
import struct
import threading
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from sass_tui.db.query_tree import Comparison, columns, to_sql
from sass_tui.db.schema import DatabaseError

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable

    from sass_tui.db.query import CompiledQuery

MIN_PEOPLE = 200_000
# A text column with more different values than this is left to SQLite.
MAX_WORDS = 200
# Where the copies live; None: $XDG_CACHE_HOME/sass/columns (~/.cache/sass/columns).
CACHE_DIR: Path | None = None
# Build a missing copy in a background thread while SQLite answers (True), or
# in the caller (False: tests and benchmarks).
BACKGROUND = True
COPY_FILE = "copy.duckdb"
# The columns every copy holds besides those its queries name: the person's own.
DEFAULT_COLUMNS = (
    ("person", "gender"),
    ("person", "stature"),
    ("person", "mass"),
    ("person", "age"),
    ("person", "handedness"),
)


class Unsupported(Exception):
    """The copy cannot answer this query or database provably alike: SQLite answers."""


# --- the data version ------------------------------------------------------


def data_version(conn: sqlite3.Connection) -> tuple[int, ...]:
    """The key of the copy: header change counter, page count and schema cookie,
    with the file's size, mtime and inode.  Call inside a read transaction."""
    path = database_path(conn)
    with open(path, "rb") as f:
        header = f.read(100)
        stat = os.fstat(f.fileno())
    if len(header) < 100 or not header.startswith(b"SQLite format 3\0"):
        raise Unsupported("no SQLite header")
    if header[18] != 1 or header[19] != 1:
        raise Unsupported("not in rollback-journal mode (WAL): the change counter may not move")
    counter, pages = struct.unpack(">II", header[24:32])
    (cookie,) = struct.unpack(">I", header[40:44])
    return (counter, pages, cookie, stat.st_size, stat.st_mtime_ns, stat.st_ino, stat.st_dev)


def database_path(conn: sqlite3.Connection) -> Path:
    for _seq, name, file in conn.execute("PRAGMA database_list"):
        if name == "main":
            if not file:
                raise Unsupported("an in-memory or temporary database")
            return Path(file)
    raise Unsupported("no main database")  # pragma: no cover - SQLite always has one


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
    # deferred: numpy — off sass query --count (sass_tui/startup.py)
    import numpy as np

    cursor = conn.execute(sql)
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter((r[0] for r in rows), dtype=np.int64, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=np.int64)


def _fetch_pairs(cursor: sqlite3.Cursor, value_type: Any) -> Any:
    # deferred: numpy — off sass query --count (sass_tui/startup.py)
    import numpy as np

    dtype = np.dtype([("id", np.int64), ("v", value_type)])
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter(rows, dtype=dtype, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=dtype)


def _read_column(conn: sqlite3.Connection, table: str, column: str, ids: Any) -> tuple[Any, Any]:
    """One column aligned on the sorted person ids: (float64 values with NaN for
    NULL, None) or (int32 word numbers with -1 for NULL, the words)."""
    # deferred: numpy — off sass query --count (sass_tui/startup.py)
    import numpy as np

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


def _cache_folder(path: Path) -> Path:
    base = CACHE_DIR
    if base is None:
        xdg = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        base = Path(xdg) / "sass" / "columns"
    digest = hashlib.sha256(str(path.resolve()).encode()).hexdigest()[:16]
    return base / digest


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
    # deferred: uuid — off sass query --count, sass db init (sass_tui/startup.py)
    import uuid

    # deferred: duckdb — off sass query --count, sass db init (sass_tui/startup.py)
    import duckdb

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
    folder = _cache_folder(path)
    folder.mkdir(parents=True, exist_ok=True)
    tmp = folder / f"tmp-{uuid.uuid4().hex[:8]}.duckdb"
    try:
        duck = duckdb.connect(str(tmp))
        try:
            duck.register("sqlite_columns", arrays)
            duck.execute(
                f"CREATE TABLE people AS SELECT {', '.join(select)} FROM sqlite_columns", params
            )
            duck.execute(
                "CREATE TABLE copy_meta AS SELECT ?::VARCHAR AS key, ?::VARCHAR AS refused",
                [json.dumps(list(key)), json.dumps(refused)],
            )
        finally:
            duck.close()
        os.replace(tmp, folder / COPY_FILE)
    finally:
        tmp.unlink(missing_ok=True)
    if progress is not None:
        progress(len(ordered), len(ordered))


@dataclass
class _Copy:
    """An open copy: the DuckDB connection (read only) and what it holds."""

    stamp: tuple[int, int, int]  # the copy file's inode, mtime and size when opened
    duck: Any
    key: tuple[int, ...]
    columns: frozenset[tuple[str, str]]
    refused: frozenset[tuple[str, str]]
    people: int


_LOCK = threading.RLock()
_STORES: dict[Path, _Copy] = {}
_BUILDS: dict[Path, threading.Thread] = {}
_PENDING: dict[Path, set[tuple[str, str]]] = {}


def _open_copy(path: Path) -> _Copy | None:
    """The copy of `path` on disk, opened (or the one open already), None if
    absent or unreadable.  Call with _LOCK held."""
    # deferred: duckdb — off sass query --count, sass db init (sass_tui/startup.py)
    import duckdb

    file = _cache_folder(path) / COPY_FILE
    try:
        stat = file.stat()
    except OSError:
        stat = None
    stamp = None if stat is None else (stat.st_ino, stat.st_mtime_ns, stat.st_size)
    held = _STORES.get(path)
    if held is not None and held.stamp == stamp:
        return held
    if held is not None:
        held.duck.close()
        del _STORES[path]
    if stamp is None:
        return None
    try:
        duck = duckdb.connect(str(file), read_only=True)
    except duckdb.Error:
        return None
    try:
        meta = duck.execute("SELECT key, refused, (SELECT count(*) FROM people) FROM copy_meta")
        key, refused, people = meta.fetchone() or ("", "", 0)
        names = [row[0] for row in duck.execute("DESCRIBE people").fetchall()]
    except (duckdb.Error, TypeError, ValueError):
        duck.close()
        return None
    held_columns = frozenset(
        tuple(name.split(".", 1)) for name in names if name != "id_num" and "." in name
    )
    copy = _Copy(
        stamp,
        duck,
        tuple(json.loads(key)),
        frozenset((t, c) for t, c in held_columns),
        frozenset((t, c) for t, c in json.loads(refused)),
        int(people),
    )
    _STORES[path] = copy
    return copy


def wait() -> None:
    """Wait for every background build to finish."""
    while True:
        with _LOCK:
            threads = list(_BUILDS.values())
        if not threads:
            return
        for thread in threads:
            thread.join()


def _start_build(path: Path, wanted: set[tuple[str, str]]) -> None:
    """Have one background thread of this file build the copy with these columns."""
    with _LOCK:
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
            with _LOCK:
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
        with _LOCK:
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

# How this process's last count or id list was answered: "copy", or
# "sqlite: " and why (tests and `sass db copy` show it; no timing needed).
last_answer = ""


def columns_named(compiled: CompiledQuery) -> set[tuple[str, str]]:
    """The (table, column) pairs a compiled query reads; Unsupported if the
    copy cannot answer it (SQLite will)."""
    for comparison in compiled.tree.comparisons():
        if comparison.nocase and not str(comparison.value).isascii():
            raise Unsupported("a word that is not ASCII compared without regard to case")
    return set(columns(compiled.tree))


def _large_enough(conn: sqlite3.Connection) -> bool:
    # Two subqueries: SQLite reads a lone min() or max() off the B-tree's edge,
    # but scans the whole table for both in one SELECT.
    low, high = conn.execute(
        "SELECT (SELECT min(id_num) FROM person), (SELECT max(id_num) FROM person)"
    ).fetchone()
    return low is not None and high - low + 1 >= MIN_PEOPLE


def _matches(conn: sqlite3.Connection, compiled: CompiledQuery, ids: bool) -> Any:
    """The answer from the copy, None while it is being built (Unsupported:
    SQLite must answer).  Call inside a read transaction that has written
    nothing to the main database."""
    try:
        # deferred: duckdb — off sass query --count, sass db init (sass_tui/startup.py)
        import duckdb  # noqa: F401  (the optional extra: without it SQLite answers)
    except ImportError:
        raise Unsupported("DuckDB is not installed (pip install 'sass-tui[fast]')") from None
    wanted = columns_named(compiled)
    path = database_path(conn)
    key = data_version(conn)
    with _LOCK:
        copy = _open_copy(path)
        if copy is not None and copy.key == key and wanted & copy.refused:
            raise Unsupported("a column the copy cannot hold")
        if copy is None or copy.key != key or not wanted <= copy.columns:
            if BACKGROUND:
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
                    f"SELECT id_num FROM people WHERE {where} ORDER BY id_num", params
                ).fetchnumpy()["id_num"]
                return [int(i) for i in found.tolist()]
            row = cursor.execute(f"SELECT count(*) FROM people WHERE {where}", params).fetchone()
            return int(row[0]) if row else 0
        finally:
            cursor.close()


def _answer(conn: sqlite3.Connection, compiled: CompiledQuery, ids: bool) -> Any:
    global last_answer
    if conn.in_transaction:
        last_answer = "sqlite: a transaction of the caller's is open"
        return None
    if not _large_enough(conn):
        last_answer = f"sqlite: fewer than {MIN_PEOPLE} people"
        return None
    conn.execute("BEGIN")
    try:
        # The shared lock from this read holds off every writer until COMMIT.
        conn.execute("SELECT 1 FROM person LIMIT 1").fetchone()
        return answer_in_transaction(conn, compiled, ids)
    finally:
        conn.execute("COMMIT")


def answer_in_transaction(conn: sqlite3.Connection, compiled: CompiledQuery, ids: bool) -> Any:
    """count() or ids() inside the caller's read transaction, which must hold
    the shared lock (have read the main database) and have written nothing
    to it; None when SQLite must answer."""
    global last_answer
    if not _large_enough(conn):
        last_answer = f"sqlite: fewer than {MIN_PEOPLE} people"
        return None
    try:
        found = _matches(conn, compiled, ids)
    except (Unsupported, OSError, sqlite3.Error, ValueError) as exc:
        last_answer = f"sqlite: {exc}"
        return None
    except Exception as exc:  # DuckDB's own errors (duckdb.Error): SQLite answers
        if type(exc).__module__.split(".")[0] not in ("duckdb", "_duckdb"):
            raise
        last_answer = f"sqlite: {exc}"
        return None
    last_answer = "sqlite: the copy is being built" if found is None else "copy"
    return found


def count(conn: sqlite3.Connection, compiled: CompiledQuery) -> int | None:
    """How many people match, from the copy; None when SQLite must answer."""
    result: int | None = _answer(conn, compiled, ids=False)
    return result


def ids(conn: sqlite3.Connection, compiled: CompiledQuery) -> list[int] | None:
    """The matching ids in ascending order, from the copy; None when SQLite must answer."""
    result: list[int] | None = _answer(conn, compiled, ids=True)
    return result


# --- building it now (`sass db copy`) -------------------------------------------


@dataclass(frozen=True)
class Refreshed:
    """What `refresh` did: the copy's people and columns, and how it got there."""

    people: int
    columns: tuple[tuple[str, str], ...]
    refused: tuple[tuple[str, str], ...]  # left to SQLite (a value of another type, ...)
    how: str  # "built" or "already up to date"
    folder: Path


def refresh(
    conn: sqlite3.Connection,
    wanted: Iterable[tuple[str, str]] = (),
    progress: Callable[[int, int], None] | None = None,
) -> Refreshed:
    """Build the copy of conn's database now, in the caller (a one-shot
    process's background build would die with it), unless it is up to date:
    the columns it held, DEFAULT_COLUMNS and `wanted`.  Whatever the size of
    the database (counts use the copy from MIN_PEOPLE people).
    DatabaseError when no copy can follow this file."""
    if conn.in_transaction:
        raise DatabaseError("the column copy is made outside a transaction")
    try:
        # deferred: duckdb — off sass query --count, sass db init (sass_tui/startup.py)
        import duckdb  # noqa: F401
    except ImportError:
        raise DatabaseError("the column copy needs DuckDB: pip install 'sass-tui[fast]'") from None
    try:
        path = database_path(conn)
        folder = _cache_folder(path)

        def build() -> str:
            key = data_version(conn)
            with _LOCK:
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
    with _LOCK:
        copy = _open_copy(path)
        if copy is None:
            raise DatabaseError(f"cannot read the column copy in {folder}")
        return Refreshed(
            copy.people, tuple(sorted(copy.columns)), tuple(sorted(copy.refused)), how, folder
        )


def forget(path: Path) -> None:
    """Drop the copy of the database at `path`, in memory and on disk (after
    `db init`: no later history can use it; errors ignored)."""
    # deferred: shutil — off sass query --count (sass_tui/startup.py)
    import shutil

    with _LOCK:
        held = _STORES.pop(path, None)
        if held is not None:
            held.duck.close()
    shutil.rmtree(_cache_folder(path), ignore_errors=True)
