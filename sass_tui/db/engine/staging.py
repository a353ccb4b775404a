"""How an import stores people, decided in one place for every engine
(db/engine/database.py's Database hands its connection here through the
importers of db/people/ and db/populations/virtual.py).  A module of its own,
below the Database service, so that the importers it serves need not import
the service that opens the default database through them."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

if TYPE_CHECKING:
    from sass_tui.db.progress import Cancel

T = TypeVar("T")


def store_people(
    conn: Any, load: Callable[[Any], T], cancel: Cancel | None = None, *, replace_all: bool = False
) -> T:
    """The one place that decides how an import stores people, for the command
    line and the screens alike (db/people/ansur.py's import_ansur_into and
    db/people/flatfile.py's import_flat_into, which QueryLists's imports call, and
    init_postgres): on SQLite `load` runs on
    the file's own connection (its transaction is the import's); on
    PostgreSQL it runs on a SQLite staging file whose people are then copied
    in one transaction (db/engine/postgres.py's import_staged), so a failure or a
    cancel stores nothing.  `replace_all` (PostgreSQL's `sass db init` only;
    SQLite's rebuilds the file, db/people/default.py): everyone stored before goes."""
    # db/engine/dialect.py's dialect_of, which imports db/engine/postgres.py: off sass query.
    if getattr(conn, "dialect", "sqlite") == "postgresql":
        # deferred: db.postgres — off sass query, sass db init (sass_tui/startup.py)
        from sass_tui.db.engine.postgres import import_staged

        return import_staged(conn, load, cancel=cancel, replace_all=replace_all)
    if replace_all:
        raise ValueError(
            "replace_all is PostgreSQL's: a SQLite file is rebuilt (db/people/default.py)"
        )
    return load(conn)
