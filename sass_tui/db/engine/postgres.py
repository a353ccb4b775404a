"""PostgreSQL: one people database shared by a lab (`--db postgresql://user@host/db`).

The driver is psycopg 3 (`pip install 'sass-tui[postgres]'`), imported only
here and only when a PostgreSQL address is given.

- The schema is SQLite's (db/engine/schema.py), read back from an in-memory SQLite
  database built from the same DDL and written out in PostgreSQL's types:
  one definition of the tables for both engines.  SQLite's measure_packed
  (a read cache of the measure table, kept by triggers) is not made.
  `meta.schema_version` is SCHEMA_VERSION; MIGRATIONS lists the steps from
  older PostgreSQL schemas (none yet: version 5 is the first).
- An import is parsed and checked by the SQLite import (db/people/ansur.py,
  db/people/flatfile.py, db/people/default.py) into a private staging file, then copied
  in ONE PostgreSQL transaction: a reader sees the database before it or
  after it, never half; a client killed mid-import leaves it as it was (the
  server rolls the transaction back).  Imports take a transaction-level
  advisory lock, so concurrent writers from several machines take their
  turns; a person is known by its natural key `source_key` (the source's
  label and the subject), UNIQUE in the table, so a re-import replaces the
  person under the same id and no person is ever stored twice.
- Queries are the query tree compiled in the "postgresql" dialect
  (db/query/query_tree.py); PostgreSQL counts with its own parallel scans.
- A connection lost between two statements (the server restarted) is opened
  again once for the next statement or transaction begun outside a
  transaction (nothing of it has run yet); a server that is gone is a
  DatabaseError that says so.  What lived in the old session (the query
  screen's TEMP tables, db/query/lists.py) is made again.
- Read-only (`sass serve --read-only`, or any process whose $SASS_READ_ONLY
  is 1: model/served.py) is the server's: the session's TEMP tables are
  made, then `SET SESSION CHARACTERISTICS AS TRANSACTION READ ONLY` makes
  every later transaction read-only, and PostgreSQL refuses any change to a
  table that is not temporary (SET TRANSACTION in its manual: INSERT, UPDATE
  and DELETE on temporary tables stay allowed, CREATE does not).  A write of
  sass that reaches it even through a bug is refused, nothing changed.
"""

from __future__ import annotations

import logging
import os
import shutil
import sqlite3
import tempfile
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import ExitStack, contextmanager
from pathlib import Path
from typing import Any, TypeVar

from sass_tui.db.engine.addresses import shown
from sass_tui.db.engine.dialect import WRITE_LOCK
from sass_tui.db.engine.schema import (
    PERSON_TABLES,
    SCHEMA_VERSION,
    SQLITE_ONLY_TABLES,
    STORED_UNITS,
    TARGET_TABLES,
    DatabaseError,
    connect,
    schema_statements,
)
from sass_tui.db.progress import Cancel, interruptible
from sass_tui.db.query.query_tree import Dialect
from sass_tui.model.files.atomic import process_alive
from sass_tui.model.served import served_read_only

# Older PostgreSQL schema version -> the statements that bring it to the next one.
MIGRATIONS: dict[str, tuple[str, ...]] = {}
CONNECT_TIMEOUT_S = 10
T = TypeVar("T")
# SQLite's declared types -> PostgreSQL's.
_TYPES = {"INTEGER": "BIGINT", "REAL": "DOUBLE PRECISION", "TEXT": "TEXT", "BLOB": "BYTEA"}


def _driver() -> Any:
    try:
        # deferred: psycopg — off sass query, sass query --count, sass person … (sass_tui/startup.py)
        import psycopg
    except ImportError:
        raise DatabaseError(
            "a PostgreSQL database needs the psycopg driver: pip install 'sass-tui[postgres]'"
        ) from None
    _quiet_copy_teardown()
    return psycopg


def _quiet_copy_teardown() -> None:
    """psycopg logs the error it meets while ending a COPY that another error
    broke ("error ignored terminating <psycopg.Copy [BAD]>": a server gone,
    a cancel) and raises the first; with no logging set up, Python printed
    that line on the terminal before sass's own message about the first.
    Only that record of psycopg's logger is dropped; its others go on."""
    driver_log = logging.getLogger("psycopg")
    if _drop_copy_teardown not in driver_log.filters:
        driver_log.addFilter(_drop_copy_teardown)


def _drop_copy_teardown(record: object) -> bool:
    return not str(getattr(record, "msg", "")).startswith("error ignored terminating")


# PostgreSQL's SQLSTATE for a change refused in a read-only transaction.
READ_ONLY_SQLSTATE = "25006"


class PostgresConnection:
    """A psycopg connection in autocommit mode, with sqlite3's `execute` shape
    (`%s` placeholders) and engine errors turned into DatabaseErrors.

    `read_only` (None: as $SASS_READ_ONLY says, model/served.py): every
    transaction of the session is read-only, after `temp_tables` (CREATE TEMP
    TABLE statements, made at each connect) exist."""

    dialect: Dialect = "postgresql"

    def __init__(
        self, url: str, *, read_only: bool | None = None, temp_tables: Sequence[str] = ()
    ) -> None:
        self.url = url
        self.read_only = served_read_only() if read_only is None else read_only
        self._temp_tables = tuple(temp_tables)
        self._psycopg = _driver()
        self._depth = 0  # open transaction() blocks
        # Called after the connection was opened again (a server restart): what
        # lived in the old session, e.g. the lists' rows (db/query/lists.py), is gone.
        self.on_reconnect: list[Callable[[], None]] = []
        self._conn = self._connect()

    def _connect(self) -> Any:
        """A new session: its TEMP tables made, then read-only when asked."""
        try:
            conn = self._psycopg.connect(
                self.url, autocommit=True, connect_timeout=CONNECT_TIMEOUT_S
            )
        except self._psycopg.Error as exc:
            raise DatabaseError(
                f"{shown(self.url)}: cannot reach the PostgreSQL server ({_first_line(exc, self.url)}); "
                "check that it is running and that the address, user and database are right"
            ) from None
        try:
            for statement in self._temp_tables:
                conn.execute(statement)
            if self.read_only:
                conn.execute("SET SESSION CHARACTERISTICS AS TRANSACTION READ ONLY")
        except self._psycopg.Error as exc:
            conn.close()
            raise DatabaseError(f"{shown(self.url)}: {_first_line(exc, self.url)}") from None
        return conn

    def _reconnect(self) -> None:
        """The connection broke between two statements (a server restart): open
        it again (DatabaseError when the server is still gone) and tell those
        who kept something in the old session."""
        self._conn.close()
        self._conn = self._connect()
        for reopened in self.on_reconnect:
            reopened()

    def _lost(self) -> bool:
        """Whether the connection was closed under us, outside any transaction
        of ours: then nothing of the statement that found it ran."""
        return not self._depth and (self._conn.broken or self._conn.closed)

    def identity(self) -> str:
        """The database as the server told it: host, port, database and user
        (the defaults and $PG* variables resolved; never the password)."""
        info = self._conn.info
        return f"postgresql {info.host}:{info.port}/{info.dbname} user {info.user}"

    def refuse_writes(self, what: str) -> None:
        """A DatabaseError before `what` (a change) starts, when read-only: the
        server would refuse it anyway, after the work of preparing it."""
        if self.read_only:
            raise DatabaseError(read_only_message(shown(self.url), what))

    @property
    def in_transaction(self) -> bool:
        return self._depth > 0

    def execute(self, sql: str, params: Sequence[object] = ()) -> Any:
        """Run one statement; the cursor (iterate it, or fetchone / fetchall)."""
        try:
            return self._conn.execute(sql, tuple(params))
        except self._psycopg.OperationalError as exc:
            if not self._lost():
                raise self.error(exc) from None
        except self._psycopg.Error as exc:
            raise self.error(exc) from None
        self._reconnect()
        try:
            return self._conn.execute(sql, tuple(params))
        except self._psycopg.Error as exc:
            raise self.error(exc) from None

    def executemany(self, sql: str, rows: Iterable[Sequence[object]]) -> None:
        """Run one statement for each row (pipelined by psycopg; inside the caller's
        transaction, as a write is)."""
        try:
            with self._conn.cursor() as cursor:
                cursor.executemany(sql, [tuple(row) for row in rows])
        except self._psycopg.Error as exc:
            raise self.error(exc) from None

    def cancel_statement(self) -> None:
        """Ask the server to cancel the statement running now (from another
        thread; db/progress.py's interruptible).  Its execute raises a
        DatabaseError; a transaction around it rolls back."""
        try:
            self._conn.cancel()
        except self._psycopg.Error:
            pass  # nothing running, or the connection is gone: nothing to cancel

    def error(self, exc: BaseException) -> DatabaseError:
        """A driver error as a message a user can act on."""
        if isinstance(exc, DatabaseError):
            return exc
        where = shown(self.url)
        if getattr(exc, "sqlstate", None) == READ_ONLY_SQLSTATE:
            return DatabaseError(read_only_message(where, "this change"))
        if self._conn.broken or self._conn.closed:
            return DatabaseError(
                f"{where}: the PostgreSQL server closed the connection ({_first_line(exc, self.url)}); "
                "nothing of the interrupted command was stored; run it again when the "
                "server is back"
            )
        return DatabaseError(f"{where}: {_first_line(exc, self.url)}")

    @contextmanager
    def transaction(self) -> Iterator[PostgresConnection]:
        """One transaction: committed at the end, rolled back on any error.  A
        connection found closed at its BEGIN is opened again once (nothing of
        the transaction has run)."""
        with ExitStack() as stack:
            try:
                try:
                    stack.enter_context(self._conn.transaction())
                except self._psycopg.OperationalError:
                    if not self._lost():
                        raise
                    self._reconnect()
                    stack.enter_context(self._conn.transaction())
                self._depth += 1
                try:
                    yield self
                finally:
                    self._depth -= 1
                stack.close()  # COMMIT here, its errors turned into messages below
            except self._psycopg.Error as exc:
                raise self.error(exc) from None

    def copy_rows(
        self,
        table: str,
        columns: Sequence[str],
        rows: Iterable[Sequence[object]],
        types: Sequence[str] | None = None,
    ) -> int:
        """COPY rows into a table (inside the caller's transaction); how many.
        With the columns' PostgreSQL `types`, in COPY's binary format: a double
        goes as its 8 bytes instead of being printed and parsed again (a
        `sass db init`'s copy of 5 million values: 5.7 s -> 1.9 s)."""
        count = 0
        statement = f"COPY {table} ({', '.join(columns)}) FROM STDIN" + (
            "" if types is None else " (FORMAT BINARY)"
        )
        try:
            with self._conn.cursor() as cursor:
                with cursor.copy(statement) as copy:
                    if types is not None:
                        copy.set_types(types)
                    for row in rows:
                        copy.write_row(row)
                        count += 1
        except self._psycopg.Error as exc:
            raise self.error(exc) from None
        except (TypeError, ValueError, OverflowError) as exc:
            # The binary format's dumpers check each value's Python type
            # where the text format left it to the server to refuse.
            raise DatabaseError(
                f"{shown(self.url)}: row {count + 1} of {table} has a value its column "
                f"cannot hold ({', '.join(columns)} as {', '.join(types or ())}): {exc}; "
                "nothing was stored"
            ) from None
        return count

    def close(self) -> None:
        self._conn.close()


def read_only_message(where: str, what: str) -> str:
    return (
        f"{where}: the database is open read-only (sass serve --read-only): {what} "
        "was refused; nothing changed"
    )


def _first_line(exc: BaseException, url: str) -> str:
    """The driver's message, its first line, with the address in it (libpq
    quotes a URI it cannot read whole) shown without its password."""
    text = str(exc).strip()
    first = text.splitlines()[0] if text else type(exc).__name__
    return first.replace(url, shown(url))


def connect_postgres(
    url: str,
    *,
    create: bool = False,
    read_only: bool | None = None,
    temp_tables: Sequence[str] = (),
) -> PostgresConnection:
    """Open the database at `url`: its schema made when `create` and absent,
    checked (and migrated) otherwise; `read_only` and `temp_tables` as
    PostgresConnection's."""
    conn = PostgresConnection(url, read_only=read_only, temp_tables=temp_tables)
    try:
        _check_schema(conn, create)
    except BaseException:
        conn.close()
        raise
    return conn


def _has_schema(conn: PostgresConnection) -> bool:
    row = conn.execute("SELECT to_regclass('meta') IS NOT NULL").fetchone()
    return bool(row[0])


def _check_schema(conn: PostgresConnection, create: bool) -> None:
    if not _has_schema(conn):
        if not create:
            raise DatabaseError(
                f"{shown(conn.url)}: no sass schema in this database "
                f"(create it with `sass db init --db {shown(conn.url)}`)"
            )
        with conn.transaction():
            conn.execute("SELECT pg_advisory_xact_lock(%s)", (WRITE_LOCK,))
            if not _has_schema(conn):  # another process made it meanwhile
                create_schema(conn)
        return
    with conn.transaction():
        conn.execute("SELECT pg_advisory_xact_lock(%s)", (WRITE_LOCK,))
        row = conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()
        version = row[0] if row else None
        while version in MIGRATIONS:
            for statement in MIGRATIONS[version]:
                conn.execute(statement)
            version = str(int(version) + 1)
            conn.execute("UPDATE meta SET value = %s WHERE key = 'schema_version'", (version,))
    if version != SCHEMA_VERSION:
        raise DatabaseError(
            f"{shown(conn.url)}: a sass database of schema version {version}, this sass "
            f"reads version {SCHEMA_VERSION}: use the sass that made it, or rebuild it "
            f"with `sass db init --force --db {shown(conn.url)}` (deletes its people)"
        )


def postgres_ddl() -> list[str]:
    """The CREATE statements of SQLite's schema in PostgreSQL's types: tables
    with their primary keys, NOT NULL and UNIQUE columns, and their indexes."""
    memory = sqlite3.connect(":memory:")
    try:
        for statement in schema_statements():
            memory.execute(statement)
        tables = [
            name
            for (name,) in memory.execute(
                "SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY rowid"
            )
            if name not in SQLITE_ONLY_TABLES
        ]
        out: list[str] = []
        indexes: list[str] = []
        for table in tables:
            info = memory.execute(f"PRAGMA table_info({table})").fetchall()
            keys = [name for _cid, name, *_rest, pk in sorted(info, key=lambda r: r[5]) if pk]
            unique: set[str] = set()
            for _seq, index, is_unique, origin, _partial in memory.execute(
                f"PRAGMA index_list({table})"
            ):
                columns = [r[2] for r in memory.execute(f"PRAGMA index_info({index})")]
                if origin == "u" and len(columns) == 1:
                    unique.add(columns[0])
                elif origin == "c":
                    kind = "UNIQUE INDEX" if is_unique else "INDEX"
                    indexes.append(f"CREATE {kind} {index} ON {table} ({', '.join(columns)})")
            lines = [
                f"{name} {_TYPES[declared.upper()]}"
                + (" NOT NULL" if notnull and not (pk and len(keys) == 1) else "")
                + (" UNIQUE" if name in unique else "")
                for _cid, name, declared, notnull, _default, pk in info
            ]
            if keys:
                lines.append(f"PRIMARY KEY ({', '.join(keys)})")
            out.append(f"CREATE TABLE {table} ({', '.join(lines)})")
        return out + indexes
    finally:
        memory.close()


def create_schema(conn: PostgresConnection) -> None:
    """Make the tables (inside the caller's transaction)."""
    for statement in postgres_ddl():
        conn.execute(statement)
    conn.execute("INSERT INTO meta VALUES ('schema_version', %s)", (SCHEMA_VERSION,))
    conn.execute("INSERT INTO meta VALUES ('units', %s)", (STORED_UNITS,))


def _tables_of_people() -> tuple[str, ...]:
    """The tables a person's rows are in, person last (deleted after its rows)."""
    return tuple(t for t in PERSON_TABLES if t not in SQLITE_ONLY_TABLES) + ("person",)


def recreate_schema(conn: PostgresConnection) -> None:
    """Drop sass's tables and make them afresh (inside the caller's transaction)."""
    for table in ("meta", *TARGET_TABLES, *_tables_of_people()):
        conn.execute(f"DROP TABLE IF EXISTS {table} CASCADE")
    create_schema(conn)


def people_count(conn: PostgresConnection) -> int:
    return int(conn.execute("SELECT count(*) FROM person").fetchone()[0])


# --- imports -------------------------------------------------------------------


# A staging folder is named for the process that made it, so that one a
# killed import left behind (the people of a whole ANSUR II import, 23 MB)
# is removed by the next import once that process is gone, as model/files/atomic.py
# sweeps its temporaries.
STAGING_PREFIX = "sass-staging-"


def sweep_staging(folder: Path) -> list[Path]:
    """Remove the staging folders in `folder` whose process is gone; returns them."""
    swept: list[Path] = []
    try:
        entries = list(folder.glob(f"{STAGING_PREFIX}*-*"))
    except OSError:
        return swept
    for entry in entries:
        pid = entry.name[len(STAGING_PREFIX) :].split("-", 1)[0]
        if pid.isdigit() and not process_alive(int(pid)) and entry.is_dir():
            shutil.rmtree(entry, ignore_errors=True)
            swept.append(entry)
    return swept


def import_staged(
    conn: PostgresConnection,
    stage: Callable[[sqlite3.Connection], T],
    *,
    replace_all: bool = False,
    staging_file: Path | None = None,
    cancel: Cancel | None = None,
) -> T:
    """`stage` imports into a private SQLite file (its parsing and checks, its
    errors); then its people are copied into PostgreSQL in one transaction.
    `replace_all`: everyone stored before goes (`sass db init`).  `cancel`
    (handed to `stage` too) also stops the copy, up to its commit, with
    Cancelled and the transaction rolled back: nothing stored, as a cancel
    of SQLite's import (db/progress.py's interruptible)."""
    conn.refuse_writes("an import")
    sweep_staging(Path(tempfile.gettempdir()))
    with tempfile.TemporaryDirectory(prefix=f"{STAGING_PREFIX}{os.getpid()}-") as folder:
        path = staging_file or Path(folder) / "staging.db"
        staging = connect(path, create=True, read_only=False)  # a private file
        try:
            result = stage(staging)
            with conn.transaction():
                conn.execute("SELECT pg_advisory_xact_lock(%s)", (WRITE_LOCK,))
                with interruptible(conn, cancel, "the import"):
                    if replace_all:
                        recreate_schema(conn)
                    copy_people(staging, conn)
        finally:
            staging.close()
    return result


def copy_people(staging: sqlite3.Connection, conn: PostgresConnection) -> int:
    """Every person of the staging file into PostgreSQL (inside the caller's
    transaction, under WRITE_LOCK): a person whose source_key is stored
    already is replaced under its id, one without a key keeps its own id
    (the flat files' numbering, as SQLite's import does), and every other
    person gets a new id after the last.  Returns how many."""
    staged = staging.execute("SELECT id_num, source_key FROM person ORDER BY id_num").fetchall()
    if not staged:
        return 0
    _replace_virtual_people(staging, conn)
    keys = [key for _id, key in staged if key is not None]
    known = dict(
        conn.execute(
            "SELECT source_key, id_num FROM person WHERE source_key = ANY(%s)", (keys,)
        ).fetchall()
    )
    (last,) = conn.execute("SELECT coalesce(max(id_num), 0) FROM person").fetchone()
    own = [int(i) for i, key in staged if key is None]
    next_id = max([int(last), *own]) + 1
    new_id: dict[int, int] = {}
    for id_num, key in staged:
        if key is None:
            new_id[id_num] = id_num
        elif key in known:
            new_id[id_num] = int(known[key])
        else:
            new_id[id_num] = next_id
            next_id += 1
    # Only the ids stored already have rows to delete (each table's rows
    # reference a person): asked once, not once a table (sending the ids of
    # 14,649 people to each of ~100 tables took 2 s of a `sass db init`).
    stored = [
        int(i)
        for (i,) in conn.execute(
            "SELECT id_num FROM person WHERE id_num = ANY(%s)", (sorted(set(new_id.values())),)
        ).fetchall()
    ]
    if stored:
        for table in _tables_of_people():
            conn.execute(f"DELETE FROM {table} WHERE id_num = ANY(%s)", (stored,))
    # The ids as stored, joined to each table's rows by SQLite: the rows go
    # from its cursor to the COPY as they are, without a Python step a row.
    staging.execute(
        "CREATE TEMP TABLE IF NOT EXISTS stored_id (staged INTEGER PRIMARY KEY, stored INTEGER)"
    )
    staging.execute("DELETE FROM stored_id")
    staging.executemany("INSERT INTO stored_id VALUES (?, ?)", new_id.items())
    for table in ("person", *_tables_of_people()[:-1]):
        info = staging.execute(f"PRAGMA table_info({table})").fetchall()
        columns = [name for _cid, name, *_rest in info]
        selected = ", ".join(
            "stored_id.stored" if name == "id_num" else f"{table}.{name}" for name in columns
        )
        rows = staging.execute(
            f"SELECT {selected} FROM {table} JOIN stored_id ON stored_id.staged = {table}.id_num"
        )
        types = [_TYPES[declared.upper()].lower() for _cid, _name, declared, *_rest in info]
        conn.copy_rows(table, columns, rows, types)
    _copy_targets(staging, conn, new_id)
    return len(staged)


def _replace_virtual_people(staging: sqlite3.Connection, conn: PostgresConnection) -> None:
    """A virtual population staged (db/populations/virtual.py) replaces every person of
    its source: a smaller sample leaves none of the old ones behind."""
    sources = [
        row[0]
        for row in staging.execute(
            "SELECT DISTINCT source FROM person WHERE source LIKE 'virtual:%'"
        ).fetchall()
    ]
    if not sources:
        return
    gone = [
        int(row[0])
        for row in conn.execute(
            "SELECT id_num FROM person WHERE source = ANY(%s)", (sources,)
        ).fetchall()
    ]
    for table in _tables_of_people():
        conn.execute(f"DELETE FROM {table} WHERE id_num = ANY(%s)", (gone,))


def _copy_targets(
    staging: sqlite3.Connection, conn: PostgresConnection, new_id: dict[int, int]
) -> None:
    """The targets staged with their people (the shipped ones of `sass db
    init`, a virtual population's weights), their ids as copied."""
    for row in staging.execute("SELECT * FROM target").fetchall():
        name = row[0]
        conn.execute("DELETE FROM target_weight WHERE target = %s", (name,))
        conn.execute("DELETE FROM target WHERE name = %s", (name,))
        conn.execute(f"INSERT INTO target VALUES ({', '.join(['%s'] * len(row))})", tuple(row))
        weights = staging.execute(
            "SELECT target, id_num, weight FROM target_weight WHERE target = ?", (name,)
        )
        conn.copy_rows(
            "target_weight",
            ("target", "id_num", "weight"),
            ((t, new_id[i], w) for t, i, w in weights if i in new_id),
        )
