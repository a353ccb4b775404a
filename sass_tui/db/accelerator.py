"""A column copy of the queried fields, for counting queries on millions of people.

SQLite answers a count by visiting, for each person, one row of every query
table the query names: on 5,000,000 people the report's sample query takes
2-4 s that way.  Here each queried column (`person.gender`,
`q_girth_right_upper_arm.z`, ...) is copied once into a numpy array aligned
on the sorted person ids, and a compiled query's WHERE clause is evaluated
over those arrays: tens of milliseconds at 5,000,000 people
(docs/performance.md, "Database at scale").

The SQLite file stays the store of record; the copy may never disagree with it:

- The copy carries the data version the SQLite file had when the copy was
  last brought up to date: the header's change counter (SQLite bumps it on
  every committed write in rollback-journal mode), page count and schema
  cookie, with the file's size, mtime and inode.  The version is read, the
  copy brought up to date and the query evaluated while one read
  transaction holds SQLite's shared lock, so no writer commits in between.
- A file of schema 4 logs every write to every table a query reads
  (db/schema.py, change_log_triggers): the changed person's id and the
  generation it changed in (sass's bulk writes log each person once, in
  the same transaction, with the triggers quiet: schema.logged_once).  Another data version then means: re-read, in
  that same transaction, the people logged at the copy's generation or
  later (`_sync`), a few milliseconds for a few people.  The log cannot say
  when the schema changed (`db init`, a dropped trigger), when the file holds
  another history (its generation token differs: another database, or an
  older copy of this one) or when more than PATCH_PEOPLE people changed; the
  copy is then built anew, in a background thread (BACKGROUND) while SQLite
  answers, each column read in a short transaction of its own and joined to
  the copy only when its generation is no older than the copy's (what
  changed meanwhile is logged, and re-read at the next count).
- Whatever this module cannot prove equal, SQLite answers: a database in WAL
  mode (its header counter does not move on every write), a connection with
  its own transaction open, a query whose SQL is not a plain AND / OR of
  `alias.column OP ?` comparisons over tables keyed one row per person, a
  column holding a value of another type than the one declared, a text
  column with a collation.  `count` then returns None.
- The WHERE clause has no NOT, so SQL's unknown (a comparison with NULL) can
  be read as false: AND / OR of true / false / unknown is true exactly when
  it is true with every unknown read as false.  NULL is NaN here (a REAL
  column cannot hold NaN in SQLite) and `!=` excludes it explicitly.

Only databases with at least MIN_PEOPLE people use the copy (below that
SQLite is fast, and numpy need not be imported).  The copy lives in memory
for the process and on disk under $XDG_CACHE_HOME/sass/columns/ (one folder
per database file, saved after a build or a patch by the background thread)
for the next process, which brings it up to date through the log as well.
"""

from __future__ import annotations

import os
import sqlite3
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from sass_tui.db.query_tree import And, Comparison

if TYPE_CHECKING:
    from collections.abc import Callable, Iterable

    import numpy as np
    import numpy.typing as npt

    from sass_tui.db.query import CompiledQuery
    from sass_tui.db.query_tree import Expr

MIN_PEOPLE = 200_000
# A text column with more different values than this is left to SQLite.
MAX_WORDS = 200
# Where the copies live; None: $XDG_CACHE_HOME/sass/columns (~/.cache/sass/columns).
CACHE_DIR: Path | None = None


class Unsupported(Exception):
    """The copy cannot answer this query or database provably alike: SQLite answers."""


# --- the query tree ------------------------------------------------------

# The copy evaluates the query's own tree (db/query_tree.py): a Comparison,
# or ("AND" | "OR", [operands]).
Node = Any


def tree_node(expr: Expr) -> Node:
    """The query tree as the copy evaluates it, or Unsupported."""
    if isinstance(expr, Comparison):
        if expr.nocase:
            raise Unsupported("it compares a word without regard to case, which SQLite does")
        return expr
    word = "AND" if isinstance(expr, And) else "OR"
    return (word, [tree_node(term) for term in expr.terms])


# --- the data version ------------------------------------------------------


def data_version(conn: sqlite3.Connection) -> tuple[int, ...]:
    """The key of the copy: header change counter, page count and schema cookie,
    with the file's size, mtime and inode.  Call inside a read transaction."""
    import struct

    path = database_path(conn)
    with open(path, "rb") as f:
        header = f.read(100)
        stat = os.fstat(f.fileno())
    if len(header) < 100 or not header.startswith(b"SQLite format 3\0"):
        raise Unsupported("no SQLite header")
    if header[18] != 1 or header[19] != 1:
        raise Unsupported("not in rollback-journal mode (WAL): the change counter may not move")
    counter, pages = struct.unpack(">II", header[24:32])
    (cookie,) = struct.unpack(">I", header[40:44])
    return (counter, pages, cookie, stat.st_size, stat.st_mtime_ns, stat.st_ino, stat.st_dev)


def database_path(conn: sqlite3.Connection) -> Path:
    for _seq, name, file in conn.execute("PRAGMA database_list"):
        if name == "main":
            if not file:
                raise Unsupported("an in-memory or temporary database")
            return Path(file)
    raise Unsupported("no main database")  # pragma: no cover - SQLite always has one


# --- the columns -----------------------------------------------------------


@dataclass
class TextColumn:
    codes: npt.NDArray[np.int32]  # index into words, -1 for NULL
    words: list[str]


Column = Any  # a float64 array (NaN for NULL) or a TextColumn, aligned on the store's ids


@dataclass
class ColumnStore:
    """The copy of one database file.

    Invariant (the change log's promise): for every person not logged in
    change_log at generation `gen` or later, `ids` holds the person exactly
    when the person table does, and every column holds the person's value.
    Whatever changed since is re-read from SQLite by `_sync` inside the
    reading transaction before any answer (`key` unchanged: nothing changed).
    A store of a file without the log (`logged` False) is valid only while
    `key` is the file's data version.
    """

    key: tuple[int, ...]
    gen: int
    token: int | None
    logged: bool
    ids: npt.NDArray[np.int64]
    columns: dict[tuple[str, str], Column] = field(default_factory=dict)
    refused: set[tuple[str, str]] = field(default_factory=set)
    saved_key: tuple[int, ...] | None = None  # the key of the copy on disk

    @property
    def cookie(self) -> int:
        return self.key[2]


def _generation(conn: sqlite3.Connection, gen: int | None = None) -> tuple[int, int | None]:
    """The current generation and its token (or generation `gen`'s token; None if absent)."""
    if gen is None:
        row = conn.execute(
            "SELECT gen, token FROM change_gens ORDER BY gen DESC LIMIT 1"
        ).fetchone()
    else:
        row = conn.execute("SELECT gen, token FROM change_gens WHERE gen = ?", (gen,)).fetchone()
    return (int(row[0]), int(row[1])) if row else (0 if gen is None else gen, None)


def _has_change_log(conn: sqlite3.Connection) -> bool:
    """Whether the file's triggers log every write to every table a query reads,
    exactly as this sass writes them (anything else: no incremental copy)."""
    from sass_tui.db.schema import change_log_triggers

    found = {
        name: sql
        for name, sql in conn.execute(
            "SELECT name, sql FROM sqlite_master WHERE type = 'trigger' "
            "AND (name LIKE 'log\\_%' ESCAPE '\\' OR name = 'change_note_insert')"
        )
    }
    expected = change_log_triggers()
    return not _log_quiet(conn) and all(
        found.get(name, "").replace("IF NOT EXISTS ", "") == sql.replace("IF NOT EXISTS ", "")
        for name, sql in expected.items()
    )


def _moved_by_bulk_writes(conn: sqlite3.Connection, old: int, new: int) -> bool:
    """Whether the schema cookie went from `old` to `new` only by sass's bulk
    writes, each of which dropped the per-row triggers, logged every person
    it wrote and created the triggers again in one transaction, recording
    its move in change_schema (schema.logged_once); and the log is whole
    now.  Any other schema change (a trigger dropped by another program, db
    init) breaks the chain."""
    try:
        while old != new:
            row = conn.execute(
                "SELECT to_cookie FROM change_schema WHERE from_cookie = ?", (old,)
            ).fetchone()
            if row is None or not old < int(row[0]) <= new:
                return False
            old = int(row[0])
    except sqlite3.OperationalError:  # no change_schema: not a file of this schema
        return False
    return _has_change_log(conn)


def _log_quiet(conn: sqlite3.Connection) -> bool:
    """Whether a committed row in change_bulk keeps the triggers quiet (sass's
    bulk writer never commits one: another program did, and writes may go
    unlogged)."""
    try:
        return conn.execute("SELECT 1 FROM change_bulk LIMIT 1").fetchone() is not None
    except sqlite3.OperationalError:  # no such table: not a file of this schema
        return True


def _base(conn: sqlite3.Connection, key: tuple[int, ...]) -> ColumnStore:
    """A store holding the person ids only (inside the caller's read transaction)."""
    logged = _has_change_log(conn)
    gen, token = _generation(conn) if logged else (0, None)
    ids = _fetch_ints(conn, "SELECT id_num FROM person ORDER BY id_num")
    return ColumnStore(key=key, gen=gen, token=token, logged=logged, ids=ids)


def _read_column(
    conn: sqlite3.Connection,
    table: str,
    column: str,
    ids: npt.NDArray[np.int64],
    only: npt.NDArray[np.int64] | None = None,
    words: list[str] | None = None,
) -> tuple[npt.NDArray[np.intp], Any, list[str] | None]:
    """The column's values read from SQLite: (positions in ids, values there,
    the words of a text column).  `only`: just those people (a patch).
    Positions of people not in ids are left out."""
    import numpy as np

    kind = _column_kind(conn, table, column)
    where = f"{column} IS NOT NULL"
    params: list[object] = []
    if only is not None:
        import json

        where += " AND id_num IN (SELECT value FROM json_each(?))"
        params.append(json.dumps(only.tolist()))
    if kind == "real":
        # Anything but a REAL value (text, a blob) becomes 'not real', which
        # float() refuses: such a column cannot be copied and SQLite answers.
        cursor = conn.execute(
            f"SELECT id_num, CASE typeof({column}) WHEN 'real' THEN {column} "
            f"ELSE 'not real' END FROM {table} WHERE {where}",
            params,
        )
        try:
            rows = _fetch_pairs(cursor, np.float64)
        except ValueError:
            raise Unsupported(f"{table}.{column} holds a value that is not REAL") from None
        values = rows["v"]
        new_words = None
    else:
        # The distinct words first, then each row's word number computed by
        # SQLite (a CASE over the words, with the column's own BINARY
        # comparison): no Python work per row.  A value that is not text
        # becomes -2 and refuses the copy.
        new_words = list(words or [])
        for (w,) in conn.execute(
            f"SELECT DISTINCT {column} FROM {table} WHERE typeof({column}) = 'text'"
            + ("" if only is None else " AND id_num IN (SELECT value FROM json_each(?))"),
            params,
        ):
            if w not in new_words:
                new_words.append(w)
        if len(new_words) > MAX_WORDS:
            raise Unsupported(f"{table}.{column} has more than {MAX_WORDS} different values")
        cases = "".join(f" WHEN {column} = ? THEN {k}" for k in range(len(new_words)))
        cursor = conn.execute(
            f"SELECT id_num, CASE WHEN typeof({column}) <> 'text' THEN -2{cases} ELSE -3 END "
            f"FROM {table} WHERE {where}",
            [*new_words, *params],
        )
        rows = _fetch_pairs(cursor, np.int32)
        if len(rows) and int(rows["v"].min()) < 0:
            raise Unsupported(f"{table}.{column} holds a value that is not TEXT")
        values = rows["v"]
    at, known = _positions(ids, rows["id"])
    return at[known], values[known], new_words


def _new_column(
    conn: sqlite3.Connection, table: str, column: str, ids: npt.NDArray[np.int64]
) -> Column:
    import numpy as np

    at, values, words = _read_column(conn, table, column, ids)
    if words is None:
        out = np.full(len(ids), np.nan)
        out[at] = values
        return out
    codes = np.full(len(ids), -1, dtype=np.int32)
    codes[at] = values
    return TextColumn(codes, words)


def _positions(
    people: npt.NDArray[np.int64], ids: npt.NDArray[np.int64]
) -> tuple[npt.NDArray[np.intp], npt.NDArray[np.bool_]]:
    """Where each id sits in the sorted people, and which ids are there at all."""
    import numpy as np

    at = np.searchsorted(people, ids)
    if not len(people):
        return at, at < 0
    at_clipped = np.minimum(at, len(people) - 1)
    return at_clipped, people[at_clipped] == ids


# --- following the writes ----------------------------------------------------

# Re-read the people changed since the copy while they are at most this many
# (or this share of everyone); more, and the copy is rebuilt.
PATCH_PEOPLE = 20_000
PATCH_SHARE = 0.05


def _sync(conn: sqlite3.Connection, store: ColumnStore, key: tuple[int, ...]) -> bool:
    """Bring the store up to the file's data (inside the caller's read
    transaction).  False: the change log cannot say what changed (or too
    much did), the store must be rebuilt."""
    import numpy as np

    if store.key == key:
        return True
    if not store.logged:
        return False
    if store.cookie != key[2] and not _moved_by_bulk_writes(conn, store.cookie, key[2]):
        return False  # the schema changed (db init, a dropped trigger)
    if _log_quiet(conn):
        return False  # the triggers are kept quiet: the log may miss writes
    if _generation(conn, store.gen)[1] != store.token:
        return False  # another history: another database, or an older copy of this one
    gen, token = _generation(conn)
    changed = np.sort(
        _fetch_ints(conn, f"SELECT id_num FROM change_log WHERE gen >= {int(store.gen)}")
    )
    if len(changed) > max(PATCH_PEOPLE, PATCH_SHARE * len(store.ids)):
        return False
    if len(changed):
        import json

        present = _fetch_ints(
            conn,
            "SELECT id_num FROM person WHERE id_num IN (SELECT value FROM json_each(?)) "
            "ORDER BY id_num",
            (json.dumps(changed.tolist()),),
        )
        at, was_there = _positions(store.ids, changed)
        plan = _splice_plan(at[was_there], np.searchsorted(store.ids, present), len(store.ids))
        new_ids = _splice(store.ids, plan, present)
        columns: dict[tuple[str, str], Column] = {}
        for (table, column), old in store.columns.items():
            text = isinstance(old, TextColumn)
            values = old.codes if text else old
            base = _splice(
                values, plan, np.full(len(present), -1 if text else np.nan, values.dtype)
            )
            try:
                at_new, fresh, words = _read_column(
                    conn, table, column, new_ids, present, old.words if text else None
                )
            except Unsupported:
                continue  # this column is left out; asked again, it is rebuilt or refused
            base[at_new] = fresh
            columns[(table, column)] = TextColumn(base, words or []) if text else base
        store.ids, store.columns = new_ids, columns
        store.refused = set()
    store.key, store.gen, store.token = key, gen, token
    return True


def _splice_plan(
    gone: npt.NDArray[np.intp], inserts: npt.NDArray[np.intp], length: int
) -> list[tuple[bool, int, int]]:
    """How to make the new arrays from the old: (False, a, b) keeps old[a:b],
    (True, a, b) puts new[a:b]; `gone` (sorted) are the old positions
    dropped, `inserts` (non-decreasing) the old position each new entry goes
    before.  One pass of copies per array (a few ms at 5,000,000 people),
    where masks and np.insert took three."""
    plan: list[tuple[bool, int, int]] = []
    drops, places = gone.tolist(), inserts.tolist()
    i = j = prev = 0
    end = length + 1
    while i < len(drops) or j < len(places):
        q = min(drops[i] if i < len(drops) else end, places[j] if j < len(places) else end)
        if prev < q:
            plan.append((False, prev, q))
        k = j
        while k < len(places) and places[k] == q:
            k += 1
        if k > j:
            plan.append((True, j, k))
            j = k
        if i < len(drops) and drops[i] == q:
            i += 1
            prev = q + 1
        else:
            prev = q
    if prev < length:
        plan.append((False, prev, length))
    return plan


def _splice(old: Any, plan: list[tuple[bool, int, int]], new: Any) -> Any:
    import numpy as np

    pieces = [new[a:b] if fresh else old[a:b] for fresh, a, b in plan]
    return np.concatenate(pieces) if pieces else np.zeros(0, dtype=old.dtype)


# --- building in the background -----------------------------------------------

# Build a missing copy in a background thread while SQLite answers (True), or
# in the caller (False: tests and benchmarks, and `wait()` after the fact).
BACKGROUND = True
_LOCK = threading.RLock()
_STORES: dict[Path, ColumnStore] = {}
_BUILDS: dict[Path, threading.Thread] = {}
_PENDING: dict[Path, set[tuple[str, str]]] = {}


def wait() -> None:
    """Wait for every background build to finish."""
    while True:
        with _LOCK:
            threads = list(_BUILDS.values())
        if not threads:
            return
        for thread in threads:
            thread.join()


def _start_build(path: Path, wanted: set[tuple[str, str]]) -> None:
    """Have the background thread of this file build (and save) the store and
    these columns; one thread per file, asked again while it runs it goes on."""
    with _LOCK:
        _PENDING.setdefault(path, set()).update(wanted)
        if path in _BUILDS:
            return
        thread = threading.Thread(
            target=_build_in_background, args=(path,), name="column copy", daemon=True
        )
        _BUILDS[path] = thread
    thread.start()


def _build_in_background(path: Path) -> None:
    """The missing store and columns, each read in a short transaction of its
    own (no long lock against writers), then joined to the store under _LOCK
    after the store is brought up to date in one more transaction."""
    conn = None
    try:
        conn = sqlite3.connect(
            f"{path.resolve().as_uri()}?mode=ro", uri=True, isolation_level=None, timeout=10.0
        )
        while True:
            with _LOCK:
                wanted = _PENDING.pop(path, None)
                if wanted is None:
                    _BUILDS.pop(path, None)
                    return
            try:
                _build(conn, path, wanted)
            except (Unsupported, OSError, sqlite3.Error, ValueError):
                pass  # SQLite goes on answering
    except sqlite3.Error:
        pass
    finally:
        if conn is not None:
            conn.close()
        with _LOCK:
            if _BUILDS.get(path) is threading.current_thread():
                _BUILDS.pop(path, None)
                _PENDING.pop(path, None)


def _build(
    conn: sqlite3.Connection,
    path: Path,
    wanted: set[tuple[str, str]],
    progress: Callable[[int, int], None] | None = None,
) -> tuple[ColumnStore, bool]:
    """The store of this file brought up to date (or built anew: the bool)
    with these columns, then saved; `progress(done, total)` after each step."""
    rebuilt = False
    with _LOCK:
        found = _STORES.get(path)
        if found is not None and not _read(conn, lambda: _sync(conn, found, data_version(conn))):
            found = None
    if found is None:
        rebuilt = True
        found = _read(conn, lambda: _base(conn, data_version(conn)))
        with _LOCK:
            _STORES[path] = found
    store: ColumnStore = found
    steps = sorted(wanted)
    for done, (table, column) in enumerate(steps):
        if progress is not None:
            progress(done, len(steps))
        with _LOCK:
            if (table, column) in store.columns or _STORES.get(path) is not store:
                continue
            ids, gen = store.ids, store.gen

        def read(table: str = table, column: str = column) -> tuple[Column, int, bool]:
            key = data_version(conn)
            now = _generation(conn)[0] if store.logged else gen
            return _new_column(conn, table, column, ids), now, key == store.key

        try:
            values, read_gen, same_key = _read(conn, read)
        except Unsupported:
            with _LOCK:
                store.refused.add((table, column))
            continue
        with _LOCK:
            # The column is right for every person not logged since read_gen;
            # the store for every person not logged since store.gen.  Joined
            # when the column is no older than the store's generation.
            if (
                _STORES.get(path) is store
                and store.ids is ids
                and (read_gen >= store.gen if store.logged else same_key)
            ):
                store.columns[(table, column)] = values
                store.saved_key = None
    if progress is not None:
        progress(len(steps), len(steps))
    _save(path, store)
    return store, rebuilt


def _read(conn: sqlite3.Connection, fn: Any) -> Any:
    """fn() inside one read transaction (the shared lock held throughout)."""
    conn.execute("BEGIN")
    try:
        conn.execute("SELECT 1 FROM person LIMIT 1").fetchone()
        return fn()
    finally:
        conn.execute("COMMIT")


# --- on disk -----------------------------------------------------------------


def _cache_folder(path: Path) -> Path:
    import hashlib

    base = CACHE_DIR
    if base is None:
        xdg = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        base = Path(xdg) / "sass" / "columns"
    digest = hashlib.sha256(str(path.resolve()).encode()).hexdigest()[:16]
    return base / digest


def _save(path: Path, store: ColumnStore) -> None:
    """Write the store to a new folder and drop the older ones (errors ignored:
    the disk copy only saves the next process a build)."""
    import json
    import shutil
    import uuid

    import numpy as np

    with _LOCK:  # the arrays are never changed in place: a snapshot is enough
        if _STORES.get(path) is not store or store.saved_key == store.key:
            return
        key, gen, token, logged, ids = store.key, store.gen, store.token, store.logged, store.ids
        saved = dict(store.columns)
    folder = _cache_folder(path)
    name = f"{gen:012d}-{uuid.uuid4().hex[:8]}"
    tmp = folder / f"tmp-{name}"
    try:
        tmp.mkdir(parents=True)
        np.save(tmp / "person.id_num.npy", ids)
        columns = []
        for (table, column), values in saved.items():
            text = isinstance(values, TextColumn)
            np.save(tmp / f"{table}.{column}.npy", values.codes if text else values)
            if text:
                (tmp / f"{table}.{column}.json").write_text(json.dumps(values.words))
            columns.append([table, column, "text" if text else "real"])
        meta = {"key": list(key), "gen": gen, "token": token, "logged": logged, "columns": columns}
        (tmp / "meta.json").write_text(json.dumps(meta))
        os.replace(tmp, folder / name)
    except OSError:
        shutil.rmtree(tmp, ignore_errors=True)
        return
    with _LOCK:
        if store.key == key:
            store.saved_key = key
    for old in folder.iterdir():
        if old.name != name:
            shutil.rmtree(old, ignore_errors=True)


def _load(path: Path) -> ColumnStore | None:
    """The newest whole copy on disk, or None (absent, damaged or another format)."""
    import json

    import numpy as np

    folder = _cache_folder(path)
    try:
        names = sorted((p for p in folder.iterdir() if not p.name.startswith("tmp-")), reverse=True)
    except OSError:
        return None
    for copy in names[:1]:
        try:
            meta = json.loads((copy / "meta.json").read_text())
            ids = _load_array(copy / "person.id_num.npy", np.int64, None)
            if ids is None:
                return None
            store = ColumnStore(
                key=tuple(int(k) for k in meta["key"]),
                gen=int(meta["gen"]),
                token=None if meta["token"] is None else int(meta["token"]),
                logged=bool(meta["logged"]),
                ids=ids,
            )
            store.saved_key = store.key
            for table, column, kind in meta["columns"]:
                values = _load_array(
                    copy / f"{table}.{column}.npy",
                    np.float64 if kind == "real" else np.int32,
                    len(ids),
                )
                if values is None:
                    continue  # that column is read again
                if kind == "text":
                    words = json.loads((copy / f"{table}.{column}.json").read_text())
                    if not isinstance(words, list) or not all(isinstance(w, str) for w in words):
                        continue
                    if len(values) and int(values.max(initial=-1)) >= len(words):
                        continue
                    values = TextColumn(values, words)
                store.columns[(table, column)] = values
            return store
        except (OSError, ValueError, KeyError, TypeError):
            return None
    return None


def _load_array(path: Path, dtype: Any, length: int | None) -> Any:
    """A saved array of that type and length, or None (absent, damaged or other)."""
    import numpy as np

    try:
        array = np.load(path, mmap_mode="r")
    except (OSError, ValueError):
        return None
    if array.dtype != dtype or array.ndim != 1 or (length is not None and len(array) != length):
        return None
    return array


# --- reading SQLite into arrays ---------------------------------------------------


def _fetch_ints(conn: sqlite3.Connection, sql: str, params: tuple[object, ...] = ()) -> Any:
    import numpy as np

    cursor = conn.execute(sql, params)
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter((r[0] for r in rows), dtype=np.int64, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=np.int64)


def _fetch_pairs(cursor: sqlite3.Cursor, value_type: Any) -> Any:
    import numpy as np

    dtype = np.dtype([("id", np.int64), ("v", value_type)])
    chunks = []
    while rows := cursor.fetchmany(65536):
        chunks.append(np.fromiter(rows, dtype=dtype, count=len(rows)))
    return np.concatenate(chunks) if chunks else np.zeros(0, dtype=dtype)


def _column_kind(conn: sqlite3.Connection, table: str, column: str) -> str:
    """'real' or 'text' from the declared type; Unsupported for anything else."""
    for _cid, name, declared, *_rest in conn.execute(f"PRAGMA table_info({table})"):
        if name == column:
            declared = declared.upper()
            if declared == "REAL":
                return "real"
            if declared == "TEXT":
                ddl = conn.execute(
                    "SELECT sql FROM sqlite_master WHERE type = 'table' AND name = ?", (table,)
                ).fetchone()[0]
                if "COLLATE" in ddl.upper():
                    raise Unsupported(f"{table} has a collation")
                return "text"
            raise Unsupported(f"{table}.{column} is declared {declared}")
    raise Unsupported(f"{table} has no column {column}")


def _one_row_per_person(conn: sqlite3.Connection, table: str) -> bool:
    """Whether id_num alone is the table's primary key (so the LEFT JOIN keeps one row a person)."""
    keys = [r[1] for r in conn.execute(f"PRAGMA table_info({table})") if r[5]]
    return keys == ["id_num"]


# --- evaluating --------------------------------------------------------------


def _wanted(node: Node) -> set[tuple[str, str]]:
    if isinstance(node, Comparison):
        return {(node.table, node.column)}
    return set().union(*(_wanted(item) for item in node[1]))


def _evaluate(node: Node, store: ColumnStore) -> Any:
    import numpy as np

    if not isinstance(node, Comparison):
        word, items = node
        result = _evaluate(items[0], store)
        for item in items[1:]:
            other = _evaluate(item, store)
            result = (result & other) if word == "AND" else (result | other)
        return result
    column = store.columns[(node.table, node.column)]
    op, value = node.op, node.value
    if isinstance(column, TextColumn):
        if not isinstance(value, str):
            raise Unsupported("a text column compared with a number")
        # SQLite's BINARY collation compares UTF-8 bytes: the order of code points.
        matches = np.array(
            [_compare(word, op, value) for word in column.words] + [False], dtype=bool
        )
        return matches[column.codes]  # code -1 (NULL) picks the final False
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise Unsupported("a number column compared with text")
    if isinstance(value, int) and abs(value) > 2**53:
        raise Unsupported("an integer a double cannot hold exactly")
    number = float(value)
    if op == "!=":
        return (column != number) & ~np.isnan(column)
    return {
        "<": np.less,
        ">": np.greater,
        "<=": np.less_equal,
        ">=": np.greater_equal,
        "=": np.equal,
    }[op](column, number)


def _compare(a: str, op: str, b: str) -> bool:
    if op == "=":
        return a == b
    if op == "!=":
        return a != b
    if op == "<":
        return a < b
    if op == ">":
        return a > b
    if op == "<=":
        return a <= b
    return a >= b


# --- the entry point ---------------------------------------------------------


def _large_enough(conn: sqlite3.Connection) -> bool:
    # Two subqueries: SQLite reads a lone min() or max() off the B-tree's edge,
    # but scans the whole table for both in one SELECT.
    low, high = conn.execute(
        "SELECT (SELECT min(id_num) FROM person), (SELECT max(id_num) FROM person)"
    ).fetchone()
    return low is not None and high - low + 1 >= MIN_PEOPLE


def _matches(conn: sqlite3.Connection, compiled: CompiledQuery) -> tuple[Any, ColumnStore] | None:
    """The match mask over the store's ids, None while the copy is being built
    (Unsupported: SQLite must answer).  Call inside a read transaction that
    has written nothing to the main database."""
    from sass_tui.db.schema import logged_tables

    aliases = {"p": "person"} | {alias: table for alias, table in compiled.tables}
    expected = "person p" + "".join(
        f" LEFT JOIN {table} {alias} ON {alias}.id_num = p.id_num"
        for alias, table in compiled.tables
    )
    if compiled.from_clause() != expected:
        raise Unsupported("a join of another shape")
    for table in aliases.values():
        if table != "person" and not _one_row_per_person(conn, table):
            raise Unsupported(f"{table} is not one row per person")
    tree = tree_node(compiled.tree)
    wanted = _wanted(tree)
    path = database_path(conn)
    key = data_version(conn)
    with _LOCK:
        store = _STORES.get(path)
        if store is None:
            store = _load(path)
        if store is None or not _sync(conn, store, key):
            store = None
            _STORES.pop(path, None)
            if not BACKGROUND:
                store = _base(conn, key)
        if store is not None:
            _STORES[path] = store
            if store.logged and not set(aliases.values()) <= set(logged_tables()):
                raise Unsupported("a table the change log does not follow")
            if wanted & store.refused:
                raise Unsupported("a column the copy cannot hold")
            missing = wanted - set(store.columns)
            if missing and not BACKGROUND:
                for table, column in sorted(missing):
                    store.columns[(table, column)] = _new_column(conn, table, column, store.ids)
                store.saved_key = None
                missing = set()
            if not missing:
                mask = _evaluate(tree, store)
                if store.key != store.saved_key:
                    if BACKGROUND:
                        _start_build(path, set())  # saves the copy for the next process
                    else:
                        _save(path, store)
                return mask, store
    _start_build(path, wanted)
    return None


# How this process's last count or id list was answered: "copy", or
# "sqlite: " and why (tests and `sass db copy` show it; no timing needed).
last_answer = ""


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
        found = _matches(conn, compiled)
        if found is None:
            last_answer = "sqlite: the copy is being built"
            return None
        mask, store = found
        last_answer = "copy"
        if ids:
            return store.ids[mask].tolist()
        return int(mask.sum())
    except (Unsupported, OSError, sqlite3.Error, ValueError) as exc:
        last_answer = f"sqlite: {exc}"
        return None


def count(conn: sqlite3.Connection, compiled: CompiledQuery) -> int | None:
    """How many people match, from the column copy; None when SQLite must answer."""
    result: int | None = _answer(conn, compiled, ids=False)
    return result


def ids(conn: sqlite3.Connection, compiled: CompiledQuery) -> list[int] | None:
    """The matching ids in ascending order, from the column copy; None when SQLite must answer."""
    result: list[int] | None = _answer(conn, compiled, ids=True)
    return result


# --- building it now (`sass db copy`) -------------------------------------------

# The columns `sass db copy` copies besides those the copy holds and those its
# queries name: the person's own numbers and words (source compares without
# case, a collation the copy leaves to SQLite).
DEFAULT_COLUMNS = (
    ("person", "gender"),
    ("person", "stature"),
    ("person", "mass"),
    ("person", "age"),
    ("person", "handedness"),
)


@dataclass(frozen=True)
class Refreshed:
    """What `refresh` did: the copy's people and columns, and how it got there."""

    people: int
    columns: tuple[tuple[str, str], ...]
    refused: tuple[tuple[str, str], ...]  # left to SQLite (a value of another type, ...)
    how: str  # "built", "brought up to date" or "already up to date"
    folder: Path


def columns_named(compiled: CompiledQuery) -> set[tuple[str, str]]:
    """The (table, column) pairs a compiled query reads; Unsupported if the
    copy cannot answer it (SQLite will)."""
    return _wanted(tree_node(compiled.tree))


def refresh(
    conn: sqlite3.Connection,
    wanted: Iterable[tuple[str, str]] = (),
    progress: Callable[[int, int], None] | None = None,
) -> Refreshed:
    """Build or bring up to date the column copy of conn's database now, in
    the caller (a one-shot process's background build would die with it), and
    save it for the next process: the columns it held, DEFAULT_COLUMNS and
    `wanted`.  Whatever the size of the database (counts use the copy from
    MIN_PEOPLE people).  DatabaseError when no copy can follow this file."""
    from sass_tui.db.schema import DatabaseError

    if conn.in_transaction:
        raise DatabaseError("the column copy is made outside a transaction")
    try:
        path = database_path(conn)
        key = _read(conn, lambda: data_version(conn))
    except Unsupported as exc:
        raise DatabaseError(f"no column copy can follow this database: {exc}") from None
    with _LOCK:
        store = _STORES.get(path)
        if store is None:
            store = _load(path)
            if store is not None:
                _STORES[path] = store
        held = set() if store is None else set(store.columns)
        current = store is not None and store.key == key and store.saved_key == key
    want = held | set(DEFAULT_COLUMNS) | set(wanted)
    try:
        store, rebuilt = _build(conn, path, want, progress)
    except Unsupported as exc:
        raise DatabaseError(f"no column copy can follow this database: {exc}") from None
    folder = _cache_folder(path)
    with _LOCK:
        columns = tuple(sorted(store.columns))
        if store.saved_key != store.key:
            raise DatabaseError(f"cannot write the column copy in {folder}")
        refused = tuple(sorted(want & store.refused))
        people = len(store.ids)
    if rebuilt:
        how = "built"
    elif current and held >= want:
        how = "already up to date"
    else:
        how = "brought up to date"
    return Refreshed(people, columns, refused, how, folder)


def forget(path: Path) -> None:
    """Drop the copy of the database at `path`, in memory and on disk (after
    `db init`: no later history can use it; errors ignored)."""
    import shutil

    with _LOCK:
        _STORES.pop(path, None)
    shutil.rmtree(_cache_folder(path), ignore_errors=True)
