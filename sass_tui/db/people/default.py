"""The default database: where it lives and how it is built.

The default database holds the 6,068 people of the ANSUR II public survey
(datasets/ansur2, the two files as published, gzip-compressed), source
`ansur2`, and the synthetic people with strength experiments (datasets/db),
source `synthetic`.

A database that is there is rebuilt *in place*, in one exclusive
transaction: every table dropped and created afresh, then filled.  Another
process sees the old database or the new one, never a mixture; a process
importing meanwhile finishes first (or `db init` waits for it), and no file
is ever renamed over a database somebody may hold open (a stale rollback
journal then belongs to the same file, and SQLite rolls it back as it
should).  A new one (no file, or an empty one) is built *aside*, in a
temporary file beside it named as model/files/atomic.py names its temporaries,
and linked into place only once it is whole: a full disk half-way leaves no
database (it once left a schema with nobody in it, which answered every
query with "0 people"), and a killed build's temporary is swept by the next.

Nothing here parses arguments or prints; the CLI and the TUI call these.
"""

from __future__ import annotations

import os
import sqlite3
from pathlib import Path

from sass_tui.db.engine.schema import (
    DatabaseError,
    check_database_file,
    check_writable,
    connect,
    default_db_path,
    recreate_schema,
    write_refused,
)
from sass_tui.db.progress import Cancel, Progress, Steps
from sass_tui.db.query.scope import DEMONSTRATION_SOURCE
from sass_tui.model.files.atomic import remove_stale_temporaries, temporary_name

SYNTHETIC_LABEL = DEMONSTRATION_SOURCE  # what a query reaches only when it names it


def open_database(
    path: str | Path | None = None, *, create: bool = False, progress: Progress | None = None
) -> sqlite3.Connection:
    """Open `path`, or the default database (built from the shipped data on
    first use, reporting `progress(done, total)` as it goes)."""
    if path is not None:
        return connect(Path(path).expanduser() if _expandable(path) else path, create=create)
    return default_database(progress)


def _expandable(path: str | Path) -> bool:
    try:
        Path(path).expanduser()
    except RuntimeError:
        return False
    return True


def default_database(progress: Progress | None = None) -> sqlite3.Connection:
    """Open the default database, creating it from the shipped data sets on first use."""
    path = default_db_path()
    conn = _open_built(path)
    if conn is None:
        create_default_database(path, progress)
        conn = connect(path)
    return conn


def _open_built(path: Path) -> sqlite3.Connection | None:
    """`path` opened if it holds a built default database; None if it is
    missing or empty, or a first build was cut short (a full disk): its
    schema with nobody in it.  Only such a build leaves a sass database
    without people (`sass db init` and every import store some), and it would
    answer every query with "0 people".  A file that is no usable database
    raises DatabaseError, saying what is wrong with it."""
    if needs_building(path):
        return None
    conn = connect(path)
    try:
        if holds_people(conn):
            return conn
    except BaseException:
        conn.close()
        raise
    conn.close()
    return None


def needs_building(path: Path) -> bool:
    """No database at `path` yet: no file, or an empty regular one (a device
    such as /dev/null is empty too, and is refused, never replaced)."""
    if not path.exists():
        return True
    check_database_file(path)
    return path.stat().st_size == 0


def default_needs_building(path: Path) -> bool:
    """The default database at `path` must be built (see _open_built)."""
    try:
        conn = _open_built(path)
    except DatabaseError:
        return False  # opening it again says what is wrong with it
    if conn is None:
        return True
    conn.close()
    return False


def holds_people(conn: sqlite3.Connection) -> bool:
    return conn.execute("SELECT 1 FROM person LIMIT 1").fetchone() is not None


def people_count(conn: sqlite3.Connection) -> int:
    return int(conn.execute("SELECT count(*) FROM person").fetchone()[0])


def create_default_database(
    path: str | Path,
    progress: Progress | None = None,
    *,
    replace: bool = False,
    cancel: Cancel | None = None,
) -> dict[str, int]:
    """Build the default database at `path` in place (see the module's docstring).

    Without `replace`, a database that already holds people is left as it is
    (returns {}): first use by two processes at once builds it once, and no
    caller wipes an import by accident.
    Returns the people stored per source label."""
    path = Path(path)
    if needs_building(path):
        built = _build_aside(path, Steps(progress, cancel, "building the default database"))
        if built is not None:
            return built
        # another process made the file meanwhile: leave it, or rebuild it in place
    conn = connect(path, create=True, rebuild=True)
    try:
        # A cancel (Cancelled at the next chunk of the survey) rolls it all back.
        return _build(conn, path, Steps(progress, cancel, "building the default database"), replace)
    except sqlite3.Error as exc:
        refused = write_refused(exc, path)  # a full disk: rolled back, say so
        if refused is None:
            raise
        raise refused from None
    finally:
        conn.close()


def _build_aside(path: Path, progress: Progress | None) -> dict[str, int] | None:
    """Build a new database beside `path` and link it into place; None when
    another process made `path` meanwhile (theirs is kept, ours dropped)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    remove_stale_temporaries(path)
    aside = temporary_name(path)
    try:
        try:
            conn = connect(aside, create=True, rebuild=True)
        except DatabaseError as exc:  # its messages name the file users know
            raise DatabaseError(str(exc).replace(str(aside), str(path))) from None
        try:
            counts = _build(conn, path, progress, replace=True)
        except sqlite3.Error as exc:
            refused = write_refused(exc, path)
            if refused is None:
                raise
            raise refused from None
        finally:
            conn.close()
        if path.is_file() and path.stat().st_size == 0:
            path.unlink()  # an empty file is no database: ours takes its place
        try:
            os.link(aside, path)  # never over a file another process made meanwhile
        except FileExistsError:
            return None
        except OSError:  # a file system without hard links
            if path.exists():
                return None
            os.replace(aside, path)
        return counts
    finally:
        for leftover in (aside, aside.with_name(aside.name + "-journal")):
            try:
                leftover.unlink()
            except FileNotFoundError:
                pass


def _build(
    conn: sqlite3.Connection, path: Path, progress: Progress | None, replace: bool
) -> dict[str, int]:
    check_writable(conn, path)
    try:
        conn.execute("BEGIN EXCLUSIVE")
    except sqlite3.OperationalError as exc:
        if write_refused(exc, path) is not None:
            raise
        raise DatabaseError(
            f"{path} is busy ({exc}): another process is writing to it; "
            "nothing changed, try again when it has finished"
        ) from None
    try:
        if not replace and people_count(conn):
            conn.execute("ROLLBACK")
            return {}
        recreate_schema(conn)
        counts = fill_default(conn, progress)
        conn.execute("COMMIT")
    except BaseException:
        if conn.in_transaction:
            conn.execute("ROLLBACK")
        raise
    return counts


def fill_default(conn: sqlite3.Connection, progress: Progress | None = None) -> dict[str, int]:
    """Store the shipped people, the shipped target and the virtual population
    made from them inside the caller's transaction (db/people/default_people.py's
    store_default_people); the people stored per source.  For SQLite's build
    here and PostgreSQL's staging file (db/engine/database.py's init_postgres)."""
    # deferred: db.default_people (db.ansur, db.flatfile, db.virtual, numpy) — off sass query, sass query --count, sass person … (sass_tui/startup.py)
    from sass_tui.db.people.default_people import store_default_people

    return store_default_people(conn, progress)
