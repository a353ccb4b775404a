"""The anthropometric database: SQLite schema and connections (the bulk
storage of people, with numpy, is db/people/people_store.py).

The relations are those of report §12.3.3 ("Input DB"): person, girth,
center_of_mass, joint_limits, strength_par, shoulder_strgh, elbow_strgh,
wrist_strgh, with the report's field names.  Values are stored in canonical
units: lengths cm, masses kg, angles deg, strengths N-m, speeds deg/s; NULL is
"no value" (the flat files' 999.0).

Besides the relations, every person has one row in each *query table*: one
narrow table per girth row, joint-limit row, center-of-mass row and strength
motion (`q_girth_right_upper_arm` with x, y, z; `q_strength_elbow_flexion`
with the motion's maximum) and `strength_q` (the parameters of the first
experiment).  They are written in the same transaction as the relations.  A
query then reads, per person, a few short rows by integer key: on 1,000,000
people the report's sample query took 0.8 s against the long relations,
0.6 s against one wide table per group, and 0.3 s against narrow tables
(docs/performance.md, "Database").

No Textual import here.
"""

from __future__ import annotations

import os
import sqlite3
import stat
from pathlib import Path
from typing import Any

from sass_tui.db.engine.addresses import is_url, sqlite_only
from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import data_dir, file_kind
from sass_tui.model.measures import MEASURES
from sass_tui.model.names import (
    CENTER_OF_MASS_ROWS,
    GIRTH_ROWS,
    JOINT_LIMIT_ROWS,
)
from sass_tui.model.served import READ_ONLY_ENV, served_read_only
from sass_tui.model.vocabulary import EXPERIMENT_PARAMETERS, MOTION_NAMES

SCHEMA_VERSION = "6"
AXES = ("x", "y", "z")

GIRTH_NAMES = tuple(r.name for r in GIRTH_ROWS)
JOINT_LIMIT_NAMES = tuple(r.name for r in JOINT_LIMIT_ROWS)
CENTER_OF_MASS_NAMES = tuple(r.name for r in CENTER_OF_MASS_ROWS)
# Figure 12 also lists segments that carry only a mass (upper torso, hips,
# sterna, top of head); the girth relation keeps them, queries do not see them.
MASS_ONLY_SEGMENTS = (
    "upper_torso",
    "right_hip",
    "left_hip",
    "right_sternum",
    "left_sternum",
    "top_head",
)

# Which experiment column holds which motion: positive / negative direction of
# each axis (report §12.3.3 pstrgh / nstrgh; axis meanings as report §10.3's
# joint-limit table: x abduction, y flexion, z rotation / pronation).
SHOULDER_MOTIONS = {
    "x": ("shoulder_abduction", "shoulder_adduction"),
    "y": ("shoulder_flexion", "shoulder_extension"),
    "z": ("shoulder_medial_rotation", "shoulder_lateral_rotation"),
}
ELBOW_MOTIONS = ("elbow_flexion", "elbow_extension")
WRIST_MOTIONS = {
    "x": ("wrist_radial_deviation", "wrist_ulnar_deviation"),
    "y": ("wrist_flexion", "wrist_extension"),
    "z": ("forearm_pronation", "forearm_supination"),
}


class DatabaseError(ValueError, SassError):
    """A database that cannot be used, or a write that was refused (nothing changed)."""


STRENGTH_PARAMETERS = list(EXPERIMENT_PARAMETERS)
STRENGTH_Q_COLUMNS = STRENGTH_PARAMETERS + [f"{m}_max" for m in MOTION_NAMES]

# query-table name of each (group, row); the axis columns are x, y, z (max for strength)
QUERY_TABLES: dict[str, dict[str, str]] = {
    "girth": {name: f"q_girth_{name}" for name in GIRTH_NAMES},
    "joint_limits": {name: f"q_joint_limit_{name}" for name in JOINT_LIMIT_NAMES},
    "center_of_mass": {name: f"q_center_of_mass_{name}" for name in CENTER_OF_MASS_NAMES},
    "strength": {name: f"q_strength_{name}" for name in MOTION_NAMES},
}


def _ddl() -> str:
    axis_tables = "".join(
        f"CREATE TABLE {table} (id_num INTEGER PRIMARY KEY, x REAL, y REAL, z REAL);\n"
        for group in ("girth", "joint_limits", "center_of_mass")
        for table in QUERY_TABLES[group].values()
    )
    strength_tables = "".join(
        f"CREATE TABLE {table} (id_num INTEGER PRIMARY KEY, max REAL);\n"
        for table in QUERY_TABLES["strength"].values()
    )
    measure_columns = ",\n  ".join(f"{name} REAL" for name in MEASURES)
    return f"""
CREATE TABLE meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
-- person: stature cm, mass kg, age years.  source says where the data come from;
-- source_key is the person's key in that source (re-imports replace, never duplicate).
CREATE TABLE person (
  id_num INTEGER PRIMARY KEY,
  name TEXT NOT NULL,
  gender TEXT NOT NULL CHECK (gender IN ('male', 'female')),
  stature REAL,
  mass REAL,
  handedness TEXT CHECK (handedness IN ('right', 'left', 'either')),
  age REAL,
  source TEXT NOT NULL,
  source_key TEXT UNIQUE,
  component TEXT,
  branch TEXT,
  subjectnumericrace INTEGER,
  dodrace INTEGER,
  ethnicity TEXT
);
-- measure: the ANSUR II measurements by the survey's names, lower case, in
-- canonical units (cm; weightkg in kg).  One row per person measured.
CREATE TABLE measure (
  id_num INTEGER PRIMARY KEY REFERENCES person (id_num),
  {measure_columns}
);
-- measure_packed: each measure row as one BLOB of float64 in MEASURES order
-- (NaN = NULL), written by store_people: load_values reads 6,068 people's 93
-- values in one fetch of 6,068 blobs instead of 564,000 cells (~5x faster).
-- The triggers mark a row stale (data NULL) whenever measure changes by any
-- other path; readers then take that person's values from measure itself.
CREATE TABLE measure_packed (id_num INTEGER PRIMARY KEY, data BLOB);
CREATE TRIGGER measure_packed_insert AFTER INSERT ON measure BEGIN
  INSERT OR REPLACE INTO measure_packed VALUES (NEW.id_num, NULL);
END;
CREATE TRIGGER measure_packed_update AFTER UPDATE ON measure BEGIN
  DELETE FROM measure_packed WHERE id_num = OLD.id_num;
  INSERT OR REPLACE INTO measure_packed VALUES (NEW.id_num, NULL);
END;
CREATE TRIGGER measure_packed_delete AFTER DELETE ON measure BEGIN
  DELETE FROM measure_packed WHERE id_num = OLD.id_num;
END;
-- No index leads with gender: half the people match, and walking such an index
-- visits the query tables in random order instead of id order (3x slower).
CREATE INDEX person_stature ON person (stature);
CREATE INDEX person_mass ON person (mass);
-- girth: thickness (x), width (y), length (z) in cm, mass in kg.
CREATE TABLE girth (
  id_num INTEGER NOT NULL REFERENCES person (id_num),
  seg_name TEXT NOT NULL,
  thickness REAL, width REAL, length REAL, mass REAL,
  PRIMARY KEY (id_num, seg_name)
) WITHOUT ROWID;
-- center_of_mass: cm.
CREATE TABLE center_of_mass (
  id_num INTEGER NOT NULL REFERENCES person (id_num),
  seg_name TEXT NOT NULL,
  cmass_x REAL, cmass_y REAL, cmass_z REAL,
  PRIMARY KEY (id_num, seg_name)
) WITHOUT ROWID;
-- joint_limits: deg; seg_name is the joint-limit row (right_shoulder_ul).
CREATE TABLE joint_limits (
  id_num INTEGER NOT NULL REFERENCES person (id_num),
  seg_name TEXT NOT NULL,
  jlimit_x REAL, jlimit_y REAL, jlimit_z REAL,
  PRIMARY KEY (id_num, seg_name)
) WITHOUT ROWID;
-- strength_par: speed deg/s; the *_unit fields record the stored units.
CREATE TABLE strength_par (
  id_num INTEGER NOT NULL REFERENCES person (id_num),
  exp_num INTEGER NOT NULL,
  side_of_limb TEXT NOT NULL CHECK (side_of_limb IN ('right', 'left')),
  strgh_type TEXT NOT NULL CHECK (strgh_type IN ('isometric', 'isokinetic', 'isotonic')),
  speed REAL, fatigue REAL, training REAL,
  angle_unit TEXT NOT NULL DEFAULT 'deg',
  strgh_unit TEXT NOT NULL DEFAULT 'N-m',
  speed_unit TEXT NOT NULL DEFAULT 'deg/s',
  PRIMARY KEY (id_num, exp_num)
) WITHOUT ROWID;
-- *_strgh: angles deg, pstrgh / nstrgh N-m.
CREATE TABLE shoulder_strgh (
  id_num INTEGER NOT NULL, exp_num INTEGER NOT NULL,
  shoulder_ang_x REAL, shoulder_ang_y REAL, shoulder_ang_z REAL, elbow_ang REAL,
  axis TEXT NOT NULL CHECK (axis IN ('x', 'y', 'z')),
  pstrgh REAL, nstrgh REAL,
  PRIMARY KEY (id_num, exp_num, axis),
  FOREIGN KEY (id_num, exp_num) REFERENCES strength_par (id_num, exp_num)
) WITHOUT ROWID;
CREATE TABLE elbow_strgh (
  id_num INTEGER NOT NULL, exp_num INTEGER NOT NULL,
  elbow_ang REAL, shoulder_ang_x REAL, shoulder_ang_y REAL, shoulder_ang_z REAL,
  wrist_ang_x REAL, wrist_ang_y REAL, wrist_ang_z REAL,
  pstrgh REAL, nstrgh REAL,
  PRIMARY KEY (id_num, exp_num),
  FOREIGN KEY (id_num, exp_num) REFERENCES strength_par (id_num, exp_num)
) WITHOUT ROWID;
CREATE TABLE wrist_strgh (
  id_num INTEGER NOT NULL, exp_num INTEGER NOT NULL,
  wrist_ang_x REAL, wrist_ang_y REAL, wrist_ang_z REAL, elbow_ang REAL,
  axis TEXT NOT NULL CHECK (axis IN ('x', 'y', 'z')),
  pstrgh REAL, nstrgh REAL,
  PRIMARY KEY (id_num, exp_num, axis),
  FOREIGN KEY (id_num, exp_num) REFERENCES strength_par (id_num, exp_num)
) WITHOUT ROWID;
-- Query tables (derived; same units as the relations).
CREATE TABLE strength_q (
  id_num INTEGER PRIMARY KEY,
  strength_type TEXT, motion_speed REAL, training_level REAL, fatigue_level REAL
);
{axis_tables}{strength_tables}{TARGET_DDL}"""


# --- target populations (schema 6; sass_tui/db/populations/targets.py) -------------------
# A target is a name, what it was made from and how well it matches
# (`summary`, JSON), and one weight per person of its base population.
TARGET_TABLES = ("target", "target_weight")
TARGET_DDL = """CREATE TABLE IF NOT EXISTS target (
  name TEXT PRIMARY KEY,
  gender TEXT NOT NULL,
  population TEXT NOT NULL,
  fields TEXT NOT NULL,
  sample TEXT NOT NULL,
  sample_rows INTEGER NOT NULL,
  people INTEGER NOT NULL,
  effective_n REAL NOT NULL,
  summary TEXT NOT NULL,
  created TEXT NOT NULL
);
CREATE TABLE IF NOT EXISTS target_weight (
  target TEXT NOT NULL,
  id_num INTEGER NOT NULL,
  weight REAL NOT NULL,
  PRIMARY KEY (target, id_num)
) WITHOUT ROWID;
"""


# --- the change log of schemas 3 and 4 (dropped by schema 5) -----------------
#
# Schemas 3 and 4 logged every write to every query table in change_log, by
# triggers, for the home-made column copy; the copy is now DuckDB's, rebuilt
# whole after any write (db/query/accelerator.py), and no trigger follows writes.
_CHANGE_LOG_TABLES = ("change_gens", "change_log", "change_bulk", "change_schema")


RELATIONS = (
    "person",
    "girth",
    "center_of_mass",
    "joint_limits",
    "strength_par",
    "shoulder_strgh",
    "elbow_strgh",
    "wrist_strgh",
)
PERSON_TABLES = (
    RELATIONS[1:]
    + ("measure", "measure_packed", "strength_q")
    + tuple(table for tables in QUERY_TABLES.values() for table in tables.values())
)
# SQLite's read cache of the measures (db/people/values.py); PostgreSQL has no twin.
SQLITE_ONLY_TABLES = ("measure_packed",)


# --- where the database lives ---------------------------------------------


def default_db_path() -> Path:
    """$SASS_DB, else sass.db in the user's data directory (model/files/paths.py's
    data_dir: $XDG_DATA_HOME/sass/sass.db, ~/.local/share/sass/sass.db on Linux).
    DatabaseError when $SASS_DB is a PostgreSQL address (callers that take
    one look at it first: db/engine/database.py's configured_target)."""
    if is_url(os.environ.get("SASS_DB")):
        raise DatabaseError(sqlite_only("this command") + "; $SASS_DB names a PostgreSQL database")
    if os.environ.get("SASS_DB"):
        return Path(os.environ["SASS_DB"])
    return data_dir() / "sass.db"


# Attributes of a person besides the model's (ANSUR II's survey fields).
PERSON_ATTRIBUTES = ("component", "branch", "subjectnumericrace", "dodrace", "ethnicity")
# Tables every sass database of this version holds.
EXPECTED_TABLES = frozenset(("meta",) + TARGET_TABLES + RELATIONS + PERSON_TABLES)
BUSY_TIMEOUT_S = 10.0


def check_database_file(path: Path) -> None:
    """Refuse a path that is there but is no regular file: a directory, a
    FIFO, a device.  /dev/null's size is 0, as an empty file's: `sass db init
    --db /dev/null` (as root) put its database in the device's place, and a
    query called the device "an empty file"."""
    try:
        mode = os.stat(path).st_mode
    except OSError:
        return  # missing (a new database), or said by SQLite when it opens it
    if not stat.S_ISREG(mode):
        raise DatabaseError(f"{path}: {file_kind(mode)}, not a database file")


def connect(
    path: str | Path,
    *,
    create: bool = False,
    check_same_thread: bool = True,
    rebuild: bool = False,
    read_only: bool | None = None,
) -> sqlite3.Connection:
    """Open a sass database (autocommit mode: writers use transaction()).

    The schema is created only in a file that holds nothing yet; a SQLite file
    of some other program is refused untouched, and so is a sass database of a
    newer schema.  A database of schema 1 is migrated (columns and the
    measure table added, nothing removed).  `rebuild` (db init) accepts any
    sass database, whatever its version or state, since it is about to be
    rebuilt.  `read_only` (`sass serve --read-only`) opens the file in
    SQLite's read-only mode: any write to it fails (TEMP tables, where the
    query lists live, still work); None (the default) is $SASS_READ_ONLY's
    answer, as on PostgreSQL (db/engine/postgres.py), and then a database is not
    created either."""
    path = Path(path)
    check_database_file(path)
    if read_only is None:
        read_only = served_read_only()
        if read_only and create:
            raise DatabaseError(
                f"cannot write {path}: the database is open read-only "
                f"(${READ_ONLY_ENV}=1); nothing changed"
            )
    new_file = not path.exists()
    if new_file and not create:
        raise DatabaseError(
            f"{path}: no database there (create it with `sass db init --db {path}`)"
        )
    if create:
        path.parent.mkdir(parents=True, exist_ok=True)
        if new_file:
            _check_not_read_only(path)
    target, uri = (path.resolve().as_uri() + "?mode=ro", True) if read_only else (str(path), False)
    try:
        conn = sqlite3.connect(
            target,
            uri=uri,
            isolation_level=None,
            check_same_thread=check_same_thread,
            timeout=BUSY_TIMEOUT_S,
        )
    except sqlite3.Error as exc:
        raise DatabaseError(f"{path}: cannot open the database ({exc})") from None
    try:
        conn.execute("PRAGMA cache_size = -65536")
        # No memory map: on a cold file each page fault made the kernel read far
        # around the page (1.1 GB read for 200 people fetched at 1,000,000 against
        # 7 MB with read(); scans no faster mapped; docs/performance.md,
        # "Database at scale").
        _check_schema(conn, path, create, rebuild)
    except sqlite3.DatabaseError as exc:
        conn.close()
        if new_file:  # a database that could not be made leaves no file behind
            _remove_new_database(path)
        refused = write_refused(exc, path)
        if refused is not None:
            raise refused from None
        raise DatabaseError(f"{path}: not a usable sass database ({exc})") from None
    except BaseException:
        conn.close()
        if new_file:
            _remove_new_database(path)
        raise
    return conn


def _remove_new_database(path: Path) -> None:
    """Remove the file connect() created (and its journal), if it is still empty
    of tables: a schema another process committed meanwhile stays."""
    for leftover in (path, path.with_name(path.name + "-journal")):
        try:
            if leftover is path and leftover.stat().st_size:
                probe = sqlite3.connect(f"file:{path}?mode=ro", uri=True)
                try:
                    if _tables(probe):
                        return
                finally:
                    probe.close()
            leftover.unlink()
        except (OSError, sqlite3.Error):
            pass


def write_refused(exc: BaseException, path: str | Path) -> DatabaseError | None:
    """The message for a write the file system refused (a full disk, a
    read-only file, an I/O error), naming the database; None for any other
    error.  SQLite has rolled the transaction back: nothing changed."""
    if not isinstance(exc, sqlite3.Error):
        return None
    code = getattr(exc, "sqlite_errorcode", 0) & 0xFF
    if code == sqlite3.SQLITE_FULL:
        why = "the disk is full"
    elif code == sqlite3.SQLITE_READONLY:
        why = "the database is read-only"
    elif code == sqlite3.SQLITE_IOERR:
        why = "the disk reported an error"
    elif code == sqlite3.SQLITE_CANTOPEN:
        why = "a file beside it cannot be created (its directory is full or read-only)"
    else:
        return None
    return DatabaseError(f"cannot write {path}: {why} ({exc}); nothing changed")


def _tables(conn: sqlite3.Connection) -> set[str]:
    return {
        name
        for (name,) in conn.execute("SELECT name FROM sqlite_master WHERE name NOT LIKE 'sqlite_%'")
    }


def _check_schema(conn: sqlite3.Connection, path: Path, create: bool, rebuild: bool) -> None:
    names = _tables(conn)
    if not names:
        if not create:
            raise DatabaseError(
                f"{path}: an empty file, not a sass database "
                f"(create one with `sass db init --db {path}`)"
            )
        create_schema(conn)
        return
    if "meta" not in names:
        raise DatabaseError(
            f"{path}: a SQLite file of another program (no sass schema); "
            "sass does not add tables to it: give another file"
        )
    if rebuild:
        return
    row = conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()
    version = row[0] if row else None
    if version == "1":
        migrate_1_to_2(conn)
        version = "2"
    if version in ("2", "3", "4", "5"):
        migrate_to_6(conn)
        names = _tables(conn)
    elif version != SCHEMA_VERSION:
        raise DatabaseError(
            f"{path}: a sass database of schema version {version}, "
            f"this sass reads version {SCHEMA_VERSION}: use the sass that made it, "
            f"or rebuild it with `sass db init --force --db {path}` (deletes its people)"
        )
    missing = sorted(EXPECTED_TABLES - names)
    if missing:
        raise DatabaseError(
            f"{path}: a damaged sass database (table{'s' if len(missing) > 1 else ''} "
            f"{', '.join(missing[:5])}{', …' if len(missing) > 5 else ''} missing); "
            f"rebuild it with `sass db init --force --db {path}`"
        )


def migrate_1_to_2(conn: sqlite3.Connection) -> None:
    """Schema 1 -> 2: the person attributes and the measure table (no data lost)."""
    with transaction(conn):
        row = conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()
        if row is None or row[0] != "1":  # another process migrated it meanwhile
            return
        for column, kind in zip(PERSON_ATTRIBUTES, ("TEXT", "TEXT", "INTEGER", "INTEGER", "TEXT")):
            conn.execute(f"ALTER TABLE person ADD COLUMN {column} {kind}")
        for statement in schema_statements():
            code = " ".join(
                line for line in statement.splitlines() if not line.lstrip().startswith("--")
            ).lstrip()
            if code.startswith(("CREATE TABLE measure", "CREATE TRIGGER measure")):
                conn.execute(statement)
        conn.execute("UPDATE meta SET value = '2' WHERE key = 'schema_version'")


def migrate_to_6(conn: sqlite3.Connection) -> None:
    """Schemas 2 to 5 -> 6: the change log of schemas 3 to 5 dropped (its
    tables, view and triggers; the column copy no longer follows writes) and
    the target populations' tables made; no person's data changed."""
    with transaction(conn):
        row = conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone()
        if row is None or row[0] not in ("2", "3", "4", "5"):  # migrated meanwhile
            return
        triggers = [
            name
            for (name,) in conn.execute(
                "SELECT name FROM sqlite_master WHERE type = 'trigger' "
                "AND (name LIKE 'log\\_%' ESCAPE '\\' OR name = 'change_note_insert')"
            ).fetchall()
        ]
        for name in triggers:
            conn.execute(f'DROP TRIGGER "{name}"')
        conn.execute("DROP VIEW IF EXISTS change_note")
        for table in _CHANGE_LOG_TABLES:
            conn.execute(f"DROP TABLE IF EXISTS {table}")
        for statement in schema_statements():
            if "CREATE TABLE IF NOT EXISTS target" in statement:
                conn.execute(statement)
        conn.execute("UPDATE meta SET value = '6' WHERE key = 'schema_version'")


def schema_statements() -> list[str]:
    statements: list[str] = []
    pending = ""
    for piece in _ddl().split(";\n"):
        pending += piece + ";\n"
        if sqlite3.complete_statement(pending):  # a trigger's body holds ";\n" too
            if pending.strip(" ;\n"):
                statements.append(pending)
            pending = ""
    return statements


def create_schema(conn: sqlite3.Connection) -> None:
    """Create the tables in an empty database (a no-op if another process just did)."""
    with transaction(conn):
        if _tables(conn):
            return
        _create_tables(conn)


# The units every stored value is in, recorded in the meta table of either engine.
STORED_UNITS = "length cm, mass kg, angle deg, strength N-m, speed deg/s, age years"


def _create_tables(conn: sqlite3.Connection) -> None:
    for statement in schema_statements():
        conn.execute(statement)
    conn.execute("INSERT INTO meta VALUES ('schema_version', ?)", (SCHEMA_VERSION,))
    conn.execute("INSERT INTO meta VALUES ('units', ?)", (STORED_UNITS,))


def recreate_schema(conn: sqlite3.Connection) -> None:
    """Drop every table and create the schema afresh (inside the caller's
    exclusive transaction: other processes see the old database or the new one)."""
    for (name,) in conn.execute("SELECT name FROM sqlite_master WHERE type = 'view'").fetchall():
        conn.execute(f'DROP VIEW "{name}"')  # schema 3 and 4's change_note
    for (name,) in conn.execute(
        "SELECT name FROM sqlite_master WHERE type = 'table' AND name NOT LIKE 'sqlite_%'"
    ).fetchall():
        conn.execute(f'DROP TABLE "{name}"')
    _create_tables(conn)


# The files this process found whole, by path: (device, inode, size,
# modification time) as they were then.  The check reads the whole file
# (0.15-0.25 s for the default database, more at scale), so a file in the
# same state is not read through again; a change by any other program or
# process shows in its size or time and is checked again.  A write of this
# process's own to a file it checked leaves it whole (`note_written`).
_FOUND_WHOLE: dict[str, tuple[int, int, int, int]] = {}
_FOUND_WHOLE_KEPT = 16  # files remembered at most


def _file_state(where: str) -> tuple[int, int, int, int] | None:
    try:
        status = os.stat(where)
    except OSError:  # an in-memory database, or no file there
        return None
    return (status.st_dev, status.st_ino, status.st_size, status.st_mtime_ns)


def check_writable(conn: sqlite3.Connection, path: str | Path | None = None) -> None:
    """Refuse to write to a damaged database (`PRAGMA quick_check`, the
    integrity check without the index cross-check: O(size), ~0.1 s for ANSUR
    II), unless this process found the file whole and nothing changed it since."""
    where = path if path is not None else _db_file(conn)
    _check_not_read_only(Path(where))
    key = os.path.realpath(where)
    state = _file_state(key)
    if state is not None and _FOUND_WHOLE.get(key) == state:
        return
    try:
        result = [row[0] for row in conn.execute("PRAGMA quick_check(5)")]
    except sqlite3.DatabaseError as exc:
        raise DatabaseError(f"{where}: the database is damaged ({exc}); nothing written") from None
    if result != ["ok"]:
        raise DatabaseError(
            f"{where}: the database is damaged ({'; '.join(result)}); nothing written. "
            "Move it away and run `sass db init` for a new one"
        )
    if state is not None:
        _FOUND_WHOLE.pop(key, None)
        _FOUND_WHOLE[key] = state
        while len(_FOUND_WHOLE) > _FOUND_WHOLE_KEPT:
            del _FOUND_WHOLE[next(iter(_FOUND_WHOLE))]


def note_written(conn: sqlite3.Connection) -> None:
    """After a write transaction of this process's own has committed: a file
    found whole before it is whole as it is now."""
    key = os.path.realpath(_db_file(conn))
    if key in _FOUND_WHOLE:
        state = _file_state(key)
        if state is None:
            del _FOUND_WHOLE[key]
        else:
            _FOUND_WHOLE[key] = state


def _check_not_read_only(path: Path) -> None:
    """A write needs the file and its directory (the rollback journal) writable:
    refuse before starting, saying which and why."""
    if str(path) in (":memory:", ""):  # an in-memory database
        return
    for target, what in ((path, "the database"), (path.parent, "its directory")):
        if target.exists() and not os.access(target, os.W_OK):
            try:
                read_only_fs = bool(os.statvfs(target).f_flag & os.ST_RDONLY)
            except (OSError, AttributeError):  # no statvfs (Windows)
                read_only_fs = False
            why = "on a read-only file system" if read_only_fs else "not writable by you"
            still = " (queries and Disp. Indv. still read it)" if path.exists() else ""
            raise DatabaseError(f"cannot write {path}: {what} is {why}; nothing changed{still}")


def _db_file(conn: sqlite3.Connection) -> str:
    for _seq, name, file in conn.execute("PRAGMA database_list"):
        if name == "main":
            return file or ":memory:"
    return "database"


class transaction:
    """BEGIN IMMEDIATE ... COMMIT, or ROLLBACK on any exception (nothing half-written).

    `mode` "EXCLUSIVE" also keeps readers out until COMMIT (db init); ""
    (deferred) takes no lock on the main database before it is touched: what
    writes to TEMP tables only uses (the query lists), so that they work while
    another process imports."""

    def __init__(self, conn: sqlite3.Connection, mode: str = "IMMEDIATE"):
        self.conn = conn
        self.mode = mode

    def __enter__(self) -> sqlite3.Connection:
        try:
            self.conn.execute(f"BEGIN {self.mode}")
        except sqlite3.Error as exc:
            self._raise_refused(exc)
            if getattr(exc, "sqlite_errorcode", 0) & 0xFF == sqlite3.SQLITE_BUSY:
                # Another process held the write lock past the busy timeout
                # (a long `db init` or import): nothing was begun, so nothing changed.
                raise DatabaseError(
                    f"{_db_file(self.conn)} is busy: another process is writing to it "
                    f"(waited {self.conn.execute('PRAGMA busy_timeout').fetchone()[0] / 1000:g} s); "
                    "nothing changed, try again when it has finished"
                ) from None
            raise
        return self.conn

    def __exit__(self, exc_type: object, exc: BaseException | None, tb: object) -> None:
        if exc is None:
            try:
                self.conn.execute("COMMIT")
            except sqlite3.Error as error:
                self._rollback()
                self._raise_refused(error)
                raise
            return
        self._rollback()
        self._raise_refused(exc)

    def _rollback(self) -> None:
        if self.conn.in_transaction:
            self.conn.execute("ROLLBACK")

    def _raise_refused(self, exc: BaseException) -> None:
        """A full disk or a read-only file: say so, naming the database."""
        refused = write_refused(exc, _db_file(self.conn))
        if refused is not None:
            raise refused from None


def row_counts(conn: Any) -> dict[str, int]:
    """The rows of each table of people, on either engine."""
    sqlite = isinstance(conn, sqlite3.Connection)
    return {
        t: conn.execute(f"SELECT count(*) FROM {t}").fetchone()[0]
        for t in PERSON_TABLES + ("person",)
        if sqlite or t not in SQLITE_ONLY_TABLES
    }


# --- bulk storage ---------------------------------------------------------

# A row of SQLite values (numbers, text, None), as inserted or fetched.
SqlRow = tuple[Any, ...]


def strength_summary(
    par: list[SqlRow],
    shoulder: list[SqlRow],
    elbow: list[SqlRow],
    wrist: list[SqlRow],
    ids: list[int],
) -> list[SqlRow]:
    """Per person: id, the parameters of the first experiment (what the query
    list shows), then each motion's maximum over all experiments (None if none)."""
    motion_index: dict[str, int] = {m: k for k, m in enumerate(MOTION_NAMES)}
    first: dict[int, SqlRow] = {}
    for i, exp, _side, kind, speed, fatigue, training in par:
        if i not in first or exp < first[i][0]:
            first[i] = (exp, kind, speed, training, fatigue)
    maxima: dict[int, list[float | None]] = {i: [None] * len(MOTION_NAMES) for i in first}

    def note(i: int, motion: str, value: float | None) -> None:
        if value is None or value != value:
            return
        slot = maxima[i]
        k = motion_index[motion]
        current = slot[k]
        if current is None or value > current:
            slot[k] = value

    for i, _exp, *_angles, axis, p, n in shoulder:
        note(i, SHOULDER_MOTIONS[axis][0], p)
        note(i, SHOULDER_MOTIONS[axis][1], n)
    for i, *_rest, p, n in elbow:
        note(i, ELBOW_MOTIONS[0], p)
        note(i, ELBOW_MOTIONS[1], n)
    for i, _exp, *_angles, axis, p, n in wrist:
        note(i, WRIST_MOTIONS[axis][0], p)
        note(i, WRIST_MOTIONS[axis][1], n)
    return [(ids[i], *first[i][1:], *maxima[i]) for i in sorted(first)]
