"""The prediction model of a database: fitted once, cached.

`open_predictor(conn)` returns the `Predictor` (sass_tui/model/population/prediction.py)
fitted on the database's people.  The fit is saved as `<database>.predict.npz`
beside a SQLite file, and for a PostgreSQL database in the user's cache
directory (model/files/paths.py's cache_dir: `predict/<hash>.predict.npz`, the
hash of the server, port, database and user the connection reached, never
its password).  It is reused while the data it was fitted on are unchanged:
the file records a key (a hash of the people's count, ids, genders and the
totals of every column the fit reads), recomputed from the database on each
open — 85 ms of SQL for the default people, against loading and fitting every
value (about 2 s) — unless the SQLite file shows no commit since this process
last computed it (`data_key`).

What the CLI (`sass predict`) and the TUI call:

    predictor = open_predictor(conn)                       # cached fit
    predictor = open_predictor(conn, population="branch = 'Combat Arms'")  # fitted on a query
    predictor.fields("male")                               # names, for completion
    known = predictor.parse_known("male", split_known("stature=180 cm, mass=85kg"))
    prediction = predictor.predict("male", known, nearest=5)
    prediction.values["girth.right_upper_arm.z"]           # Estimate(value, low, high, unit, known)
    prediction.group_values(GIRTH, "low")                  # (rows, 3) interval ends per cell
    prediction.figure(population_figure)                   # Disp. Indv.-style Figure
    prediction.label()                                     # "predicted from stature 180 cm, ..."
    prediction.nearest                                     # [Neighbour(id, name, distance)]

No Textual, no argument parsing, no printing.
"""

from __future__ import annotations

import hashlib
import os
import sqlite3
from pathlib import Path

from sass_tui.db.engine.dialect import dialect_of, total
from sass_tui.db.people.values import load_values
from sass_tui.model.files.paths import cache_dir
from sass_tui.model.population.prediction import MODEL_VERSION, Predictor, predicted_fields

CACHE_SUFFIX = ".predict.npz"
# The people a prediction learns from unless the user names others: everyone,
# through the query language, so its default scope (real people, unless the
# query names a source) applies; each gender's model takes its own people.
DEFAULT_POPULATION = "gender = male OR gender = female"


def database_file(conn: sqlite3.Connection) -> Path | None:
    """The file of the connection's main database (None: in memory, or a
    PostgreSQL database)."""
    if dialect_of(conn) != "sqlite":
        return None
    for _, name, file in conn.execute("PRAGMA database_list"):
        if name == "main":
            return Path(file) if file else None
    return None


def cache_path(conn: sqlite3.Connection) -> Path | None:
    """Where the database's fit is cached (None: a database in memory)."""
    if dialect_of(conn) == "postgresql":
        return server_cache_path(conn.identity())  # type: ignore[attr-defined]
    db = database_file(conn)
    return None if db is None else file_cache_path(db)


def file_cache_path(db: Path) -> Path:
    """Where the fit of the SQLite file `db` is cached: beside it."""
    return db.with_name(db.name + CACHE_SUFFIX)


def server_cache_path(identity: str) -> Path:
    """The cache file of the PostgreSQL database `identity` names (db/engine/postgres.py's
    PostgresConnection.identity: server, port, database and user, no password)."""
    digest = hashlib.sha256(identity.encode()).hexdigest()[:32]
    return cache_dir() / "predict" / f"{digest}{CACHE_SUFFIX}"


def _columns(conn: sqlite3.Connection, table: str) -> list[str]:
    return [column[0] for column in conn.execute(f"SELECT * FROM {table} LIMIT 0").description]


# The keys this process computed, by the SQLite file's version (`_file_version`)
# and the population: the key reads every table of people (85 ms for the default
# database), and each prediction in the TUI asks for it again though nothing
# was written in between.
_KEYS: dict[tuple[object, ...], str] = {}
_KEYS_KEPT = 16


def _file_version(conn: sqlite3.Connection) -> tuple[object, ...] | None:
    """The connection's SQLite file as it stands: its device, inode, size,
    modification time and file change counter, the header's 4 bytes at offset
    24 that every commit in rollback-journal mode increments (sqlite.org/
    fileformat.html, 1.3.5).  None when that cannot vouch for the data: a
    database in memory or on PostgreSQL, a file in WAL mode (header bytes 18-19
    are 2: its commits may leave the counter), or this connection inside a
    transaction (its writes are not committed yet)."""
    if conn.in_transaction:
        return None
    path = database_file(conn)
    if path is None:
        return None
    try:
        with open(path, "rb") as file:
            status = os.fstat(file.fileno())
            header = file.read(28)
    except OSError:
        return None
    if len(header) < 28 or header[18:20] != b"\x01\x01":
        return None
    counter = int.from_bytes(header[24:28], "big")
    return (status.st_dev, status.st_ino, status.st_size, status.st_mtime_ns, counter)


def data_key(conn: sqlite3.Connection, population: str = DEFAULT_POPULATION) -> str:
    """A hash that changes when people are added, removed or their values
    edited, or another population is asked for; for a SQLite file with no
    commit since this process computed it, the key computed then."""
    population = " ".join(population.split())
    version = _file_version(conn)
    if version is None:
        return _computed_key(conn, population)
    memo = (*version, population)
    key = _KEYS.get(memo)
    if key is None:
        key = _computed_key(conn, population)
        # a commit by another process while the key was computed: not kept
        if _file_version(conn) == version:
            _KEYS[memo] = key
            while len(_KEYS) > _KEYS_KEPT:
                del _KEYS[next(iter(_KEYS))]
    return key


def _computed_key(conn: sqlite3.Connection, population: str) -> str:
    fields = predicted_fields()
    # "real people": the fit learns from real people unless the population names a
    # source (db/query/scope.py); a cache fitted before, on the synthetic people too, is not reused.
    parts: list[object] = [MODEL_VERSION, fields, "real people", population]

    def totals(table: str, columns: list[str]) -> None:
        sums = ", ".join(total(conn, column) for column in ["id_num", *columns])
        parts.extend(conn.execute(f"SELECT count(*), {sums} FROM {table}").fetchone())

    totals("person", ["CASE WHEN gender = 'male' THEN id_num ELSE 0 END", "stature", "mass"])
    measure = [c for c in _columns(conn, "measure") if c != "id_num"]
    if measure:
        totals("measure", [f'"{c}"' for c in measure])
    totals("girth", ["thickness", "width", "length"])
    totals("center_of_mass", ["cmass_x", "cmass_y", "cmass_z"])
    return hashlib.sha256(repr(parts).encode()).hexdigest()


def fit_predictor(
    conn: sqlite3.Connection, key: str = "", population: str = DEFAULT_POPULATION
) -> Predictor:
    """Fit the model on the people the query `population` selects (no cache; real
    people unless it names a source, db/query/scope.py)."""
    fields = predicted_fields()
    values = load_values(conn, fields, population)
    return Predictor.fit(values, fields, key=key)


def open_predictor(
    conn: sqlite3.Connection, *, cache: bool = True, population: str | None = None
) -> Predictor:
    """The prediction model fitted on the people the query `population`
    selects (DEFAULT_POPULATION when None): from the cache file when it is
    current (the same data and population), else fitted now and saved there
    (a database in memory or in a directory that cannot be written is simply
    not cached; the cache holds one population, the last asked for)."""
    population = DEFAULT_POPULATION if population is None else population
    key = data_key(conn, population)
    path = cache_path(conn) if cache else None
    if path is not None:
        cached = Predictor.load(path, key)
        if cached is not None:
            return cached
    predictor = fit_predictor(conn, key, population)
    if path is not None:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)  # the cache directory, at first use
            predictor.save(path)
        except OSError:
            pass  # a read-only place: predict without a cache
    return predictor
