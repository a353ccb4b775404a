"""The database a verb's `--db` names (or $SASS_DB, or the default file),
opened for the verb.  Every verb that reads the database imports this module
at its top; the verbs that open one only for an option (`sass serve --db`,
and `--person` through cli/person_option.py) import it when the option is
given, which keeps the db package off their start-up paths (sass_tui/startup.py)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sass_tui.cli.options import warn_of_a_password
from sass_tui.cli.progress import progress_for
from sass_tui.db.addresses import POSTGRES_COMMANDS, is_url, sqlite_only
from sass_tui.db.database import Database, configured_target
from sass_tui.db.default import needs_building
from sass_tui.db.schema import DatabaseError, default_db_path
from sass_tui.model.paths import user_path


def open_database(args: argparse.Namespace, create: bool = False) -> Database:
    """The Database `--db` (or $SASS_DB) names, or the default file (built on
    first use, with a progress bar on a terminal)."""
    warn_of_a_password(args)
    target = configured_target(getattr(args, "db", None))
    bar = None
    if target is None and needs_building(default_db_path()):
        bar = progress_for(sys.stderr, f"building {default_db_path()}")
    if target is not None and not is_url(target):
        target = user_path(target)
    db = Database.open(target, create=create, progress=bar)
    if bar:
        bar.finish()
    return db


def open_db(args: argparse.Namespace, create: bool = False):  # -> the db layer's connection
    """The connection of the database `--db` names, or of the default one, for
    the db layer's functions that take one: a SQLite file, or a PostgreSQL
    database for the verbs of POSTGRES_COMMANDS (db/addresses.py; for the
    others an address is refused, saying which verbs serve it)."""
    if (
        is_url(configured_target(getattr(args, "db", None)))
        and args.command not in POSTGRES_COMMANDS
    ):
        raise DatabaseError(sqlite_only(f"`sass {args.command}`"))
    db = open_database(args, create=create)
    with db.connection() as conn:
        return conn


def database_path(args: argparse.Namespace, read_only: bool) -> Path | str | None:
    """The database the sessions open: a SQLite file, or a PostgreSQL address
    (`--db` or $SASS_DB).  A read-only database is opened (and the default
    file built on first use) here, since a session cannot build it and a
    server that cannot be reached is better said once than in every session.
    Each session's connections to a PostgreSQL database are then read-only
    by the server's rule ($SASS_READ_ONLY, db/postgres.py)."""
    db = getattr(args, "db", None)
    target = configured_target(db)
    if is_url(target):
        if read_only:
            # deferred: db.postgres — off sass query, sass db init (sass_tui/startup.py): psycopg only for an address
            from sass_tui.db.postgres import connect_postgres

            connect_postgres(str(target), read_only=True).close()
        return str(target)
    if not read_only:
        return user_path(db).resolve() if db else None
    open_db(args).close()
    return user_path(db).resolve() if db else default_db_path().resolve()
