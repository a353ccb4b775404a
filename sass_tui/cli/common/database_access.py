"""The database a verb's `--db` names (or $SASS_DB, or the default file),
opened for the verb.  Every verb that reads the database imports this module
at its top; the verbs that open one only for an option (`--person` through
cli/common/person_option.py, `--target` through cli/task_people.py) or once their
options are checked (`sass serve`, through cli/serving.py) import it then,
which keeps the db package off their start-up paths (sass_tui/startup.py)."""

from __future__ import annotations

import argparse
import sys

from sass_tui.cli.common.options import warn_of_a_password
from sass_tui.cli.common.progress import progress_for
from sass_tui.db.engine.addresses import POSTGRES_COMMANDS, is_url, sqlite_only
from sass_tui.db.engine.database import Database, configured_target
from sass_tui.db.engine.schema import DatabaseError, default_db_path
from sass_tui.db.people.default import needs_building
from sass_tui.model.files.paths import user_path


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
    database for the verbs of POSTGRES_COMMANDS (db/engine/addresses.py; for the
    others an address is refused, saying which verbs serve it)."""
    if (
        is_url(configured_target(getattr(args, "db", None)))
        and args.command not in POSTGRES_COMMANDS
    ):
        raise DatabaseError(sqlite_only(f"`sass {args.command}`"))
    db = open_database(args, create=create)
    with db.connection() as conn:
        return conn
