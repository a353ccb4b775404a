"""What differs between the engines a function of this layer runs on, in one
place: which engine a connection is, a list of ids as one parameter, and a
write transaction.  A function serves both engines by asking these (and the
query tree's `to_sql(expr, dialect)` / `placeholder(dialect)`), never by a
copy per engine.
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any

from sass_tui.db.engine.schema import check_writable, note_written, transaction
from sass_tui.db.query.query_tree import Dialect, placeholder

# pg_advisory_xact_lock key of sass's writers (db/engine/postgres.py): "SASS" in ASCII.
WRITE_LOCK = 0x53415353


def dialect_of(conn: Any) -> Dialect:
    """The engine of `conn`: sqlite3's connection, or db/engine/postgres.py's PostgresConnection."""
    dialect: Dialect = getattr(conn, "dialect", "sqlite")
    return dialect


def mark_of(conn: Any) -> str:
    """The connection's parameter placeholder (`?` or `%s`)."""
    return placeholder(dialect_of(conn))


def ids_in(conn: Any, column: str, ids: Sequence[int]) -> tuple[str, object]:
    """`column` is one of `ids`, as a condition and its one parameter whatever
    the number of ids (no limit on the number of placeholders): SQLite reads
    a JSON array, PostgreSQL takes an array."""
    numbers = [int(i) for i in ids]
    if dialect_of(conn) == "sqlite":
        return f"{column} IN (SELECT value FROM json_each(?))", json.dumps(numbers)
    return f"{column} = ANY(%s)", numbers


def total(conn: Any, expression: str) -> str:
    """A column's total for a key that must change with the data and only with
    it (db/populations/predict.py's data_key).  SQLite: total(x), a float summed in row
    order.  PostgreSQL: the exact sum of the values in millionths (a float's
    edit below a millionth of its unit is not seen): a parallel scan adds
    floats in a varying order, and their float sum's last bits differed
    between two runs over the same people.  An exact numeric sum would do too,
    several times slower than the integer one.  A value beyond 1e12 (a flat
    file's girth may hold any finite number) counts as +-1e12: no overflow."""
    if dialect_of(conn) == "sqlite":
        return f"total({expression})"
    x = f"({expression})"
    return (
        f"coalesce(sum((CASE WHEN abs({x}) < 1e12 THEN {x} * 1e6 "
        f"ELSE sign({x}) * 1e18 END)::bigint), 0)"
    )


@contextmanager
def writing(conn: Any) -> Iterator[Any]:
    """One write transaction: committed at the end, rolled back on any error.
    SQLite: the file checked first (db/engine/schema.py's check_writable), BEGIN
    IMMEDIATE.  PostgreSQL: under the writers' advisory lock (db/engine/postgres.py)."""
    if dialect_of(conn) == "sqlite":
        check_writable(conn)
        with transaction(conn):
            yield conn
        note_written(conn)
        return
    # Read-only (sass serve --read-only) is left to the server: it refuses the
    # first change (db/engine/postgres.py), and the transaction rolls back.
    with conn.transaction():
        conn.execute("SELECT pg_advisory_xact_lock(%s)", (WRITE_LOCK,))
        yield conn
