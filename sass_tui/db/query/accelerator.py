"""Counts over millions of people from DuckDB, reading a copy of the queried columns.

SQLite answers a count by visiting, for each person, one row of every query
table the query names: on 5,000,000 people the report's sample query takes
seconds that way.  DuckDB (an established column engine, `pip install
'sass-tui[fast]'`) answers the same query tree (db/query/query_tree.py, its
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
SQLite is fast, and neither numpy nor duckdb need be imported).  This module
is the light front `sass query --count` imports: the copy is built and read
in db/query/column_copy.py (numpy, DuckDB), reached only past that size or by
`sass db copy`; what both need is in db/query/copy_file.py.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from sass_tui.db.engine.schema import DatabaseError

# Unsupported and database_path are the command line's too (`sass db copy`).
from sass_tui.db.query.copy_file import Unsupported as Unsupported
from sass_tui.db.query.copy_file import database_path as database_path
from sass_tui.db.query.query_tree import columns

if TYPE_CHECKING:
    from sass_tui.db.query.column_copy import Refreshed
    from sass_tui.db.query.query import CompiledQuery

MIN_PEOPLE = 200_000


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
        # deferred: db.column_copy (duckdb, numpy, uuid) — off sass query --count, sass db init (sass_tui/startup.py)
        from sass_tui.db.query.column_copy import matches
    except ImportError:  # the optional extra: without it SQLite answers
        raise Unsupported("DuckDB is not installed (pip install 'sass-tui[fast]')") from None
    return matches(conn, compiled, columns_named(compiled), ids)


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


def refresh(
    conn: sqlite3.Connection,
    wanted: Iterable[tuple[str, str]] = (),
    progress: Callable[[int, int], None] | None = None,
) -> Refreshed:
    """Build the copy of conn's database now, in the caller (a one-shot
    process's background build would die with it), unless it is up to date
    (db/query/column_copy.py's refresh_now).  DatabaseError when no copy can follow
    this file."""
    if conn.in_transaction:
        raise DatabaseError("the column copy is made outside a transaction")
    try:
        # deferred: db.column_copy (duckdb, numpy, uuid) — off sass query --count, sass db init (sass_tui/startup.py)
        from sass_tui.db.query.column_copy import refresh_now
    except ImportError:
        raise DatabaseError("the column copy needs DuckDB: pip install 'sass-tui[fast]'") from None
    return refresh_now(conn, wanted, progress)
