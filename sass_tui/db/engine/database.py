"""The Database service: the one owner of a database connection, its
transactions, its lock and the differences between the engines.

`Database.open(target)` opens a SQLite file (a path; the default database
when None) or a PostgreSQL database (`postgresql://user@host/db`; also from
$SASS_DB).  The command line's verbs and the screens ask it for answers
(`query`, `count`, `predictor`, ...) or hand it to this layer's functions
that take one (the imports of db/people/ansur.py and db/people/flatfile.py, the family of
db/populations/family.py, the records of db/people/individual.py: each module imports what it
needs at its top, reached only by the verb or screen that needs it), and
never see a connection; functions of this layer that take a connection are
handed it here (`connection()`).  Engine errors leave as DatabaseErrors (`engine_error`).
"""

from __future__ import annotations

import os
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

from sass_tui.db.engine.addresses import is_url, shown
from sass_tui.db.engine.schema import DatabaseError, transaction
from sass_tui.db.engine.staging import store_people
from sass_tui.db.people.default import fill_default, open_database

if TYPE_CHECKING:
    from sass_tui.db.progress import Progress
    from sass_tui.db.query.query import CompiledQuery, Query
    from sass_tui.db.query.query_tree import Dialect
    from sass_tui.model.population.prediction import Predictor

T = TypeVar("T")


def configured_target(given: str | Path | None) -> str | Path | None:
    """What `--db` names, else $SASS_DB, else None (the default file).  A
    PostgreSQL address stays text (a Path would fold its `//`)."""
    if given is not None and str(given):
        return given
    env = os.environ.get("SASS_DB")
    if env and is_url(env):
        return env
    return None


def engine_error(exc: BaseException) -> DatabaseError | None:
    """An engine's own error (sqlite3's, psycopg's, duckdb's) as a message a
    user can act on; None for anything else (a bug, shown as one)."""
    if isinstance(exc, DatabaseError):
        return exc
    sqlite3 = sys.modules.get("sqlite3")
    if sqlite3 is not None and isinstance(exc, sqlite3.Error):
        if isinstance(exc, sqlite3.OperationalError) and "locked" in str(exc):
            return DatabaseError(
                f"the database is busy ({exc}): another process is writing to it; "
                "nothing changed, try again when it has finished"
            )
        return DatabaseError(f"database error: {exc}")
    for module in ("psycopg", "duckdb"):
        driver = sys.modules.get(module)
        if driver is not None and isinstance(exc, driver.Error):
            first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
            return DatabaseError(f"database error ({module}): {first}")
    return None


@contextmanager
def engine_errors() -> Iterator[None]:
    """Engine errors raised inside become DatabaseErrors."""
    try:
        yield
    except Exception as exc:
        error = engine_error(exc)
        if error is None or error is exc:
            raise
        raise error from None


class Database:
    """One open database (SQLite or PostgreSQL) and the lock that serialises
    its users (a screen and its workers share one connection)."""

    def __init__(self, conn: Any, target: str | Path | None) -> None:
        self._conn = conn
        self.target = target
        self.dialect: Dialect = getattr(conn, "dialect", "sqlite")
        self.lock = threading.RLock()

    @classmethod
    def open(
        cls,
        target: str | Path | None = None,
        *,
        create: bool = False,
        progress: Progress | None = None,
    ) -> Database:
        """The database `target` names (see configured_target)."""
        target = configured_target(target)
        if is_url(target):
            # deferred: db.postgres — off sass query, sass db init (sass_tui/startup.py)
            from sass_tui.db.engine.postgres import connect_postgres

            return cls(connect_postgres(str(target), create=create), target)
        with engine_errors():
            return cls(open_database(target, create=create, progress=progress), target)

    @property
    def name(self) -> str:
        """The database as shown to a user (a PostgreSQL address without its password)."""
        if is_url(self.target):
            return shown(str(self.target))
        if self.dialect == "sqlite":
            for _seq, name, file in self._conn.execute("PRAGMA database_list"):
                if name == "main":
                    return str(file)
        return str(self.target)

    @contextmanager
    def connection(self) -> Iterator[Any]:
        """The connection, under the lock, engine errors as DatabaseErrors: for
        this layer's functions that take one (`with db.connection() as conn:`)."""
        with self.lock, engine_errors():
            yield self._conn

    def close(self) -> None:
        with self.lock:
            self._conn.close()

    # --- reading -------------------------------------------------------------

    def query(self, query: str | CompiledQuery) -> Query:
        # deferred: db.query — off sass person, sass db init (sass_tui/startup.py)
        from sass_tui.db.query.query import Query, compile_query

        compiled = compile_query(query) if isinstance(query, str) else query
        return Query(self._conn, compiled)

    def count(self, query: str | CompiledQuery) -> int:
        with self.connection():
            return self.query(query).count()

    def page(self, query: str | CompiledQuery, offset: int = 0, limit: int = 25) -> list[Any]:
        with self.connection():
            return self.query(query).page(offset, limit)

    def person_rows(self, query: str | CompiledQuery) -> list[tuple[Any, ...]]:
        """Every selected person in PERSON_FIELDS order (db/query/query.py), id order."""
        with self.connection():
            return list(self.query(query).person_rows())

    def people_count(self) -> int:
        with self.connection() as conn:
            return int(conn.execute("SELECT count(*) FROM person").fetchone()[0])

    def predictor(self) -> Predictor:
        """The database's prediction model (db/populations/predict.py)."""
        # deferred: db.predict — off sass query, sass query --count, sass person … (sass_tui/startup.py)
        from sass_tui.db.populations.predict import open_predictor

        with self.connection() as conn:
            return open_predictor(conn)


def init_postgres(url: str, progress: Progress | None = None, *, force: bool) -> dict[str, int]:
    """`sass db init` on PostgreSQL: the schema made (or migrated) and the
    default people stored in one transaction, replacing everyone (with
    `force`; without it a database holding people is refused)."""
    database = Database.open(url, create=True)
    try:
        held = database.people_count()
        if held and not force:
            raise DatabaseError(
                f"{shown(url)} holds {held} people; `sass db init --force` replaces them "
                "(imports included)"
            )

        def stage(staging: Any) -> dict[str, int]:
            with transaction(staging):
                return fill_default(staging, progress)

        with database.connection() as conn:
            return store_people(conn, stage, replace_all=True)
    finally:
        database.close()
