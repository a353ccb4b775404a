"""The query list and the selected list of the database query spreadsheet
(report §12.3.2): people found by the last query, and people the user picked.

Both lists live in TEMP tables of the connection (SQLite's or PostgreSQL's:
the same SQL, the differences asked of db/engine/dialect.py), so a query list of a
million people costs no Python memory and a page is one indexed read.  Select One
moves a person from the query list to the selected list; a new query replaces
the query list and keeps the selected list (people already selected do not
come back into the query list).  No Textual import here.

The lists are read-only work for the main database: their transactions are
deferred and write only TEMP tables, so they take no write lock on the main
database and go on working while another process imports.

One connection is shared by the screen (paging, selecting) and the workers
that run a query, an import, a fit test or a population; QueryLists is
their Database service: every method that reads or writes takes its lock
(the screen asks `exclusive(wait=False)` and refuses list commands while a
worker holds it rather than wait) and turns an engine's errors into
DatabaseErrors (db/engine/database.py, engine_errors).  No caller sees the
connection or the lock.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from functools import wraps
from pathlib import Path
from typing import TYPE_CHECKING, Any, ParamSpec, TypeVar

from sass_tui.db.engine.addresses import is_url
from sass_tui.db.engine.database import Database, engine_errors
from sass_tui.db.engine.dialect import dialect_of, mark_of
from sass_tui.db.engine.postgres import connect_postgres
from sass_tui.db.engine.schema import DatabaseError, connect, transaction
from sass_tui.db.people.ansur import import_ansur_into
from sass_tui.db.people.flatfile import FlatFiles, import_flat_into
from sass_tui.db.people.individual import fetch_individual, person_record
from sass_tui.db.populations.design import Designed, design
from sass_tui.db.populations.fit import fit_test, limit_histograms
from sass_tui.db.populations.population import population_of
from sass_tui.db.populations.shipped import load_weights
from sass_tui.db.populations.stats import EVERY_MEASURE, stats_table
from sass_tui.db.populations.targets import SHIPPED, list_targets, weighted_count
from sass_tui.db.progress import Cancel, Progress, Steps, interruptible
from sass_tui.db.query import accelerator
from sass_tui.db.query.query import (
    LIST_FIELDS,
    CompiledQuery,
    compile_query,
    demonstration_hint,
    field_column,
)
from sass_tui.model.errors import SassError

if TYPE_CHECKING:
    from sass_tui.db.people.individual import Individual
    from sass_tui.db.populations.fit import FitResult, LimitHistogram
    from sass_tui.db.populations.population import SelectionPopulation
    from sass_tui.db.populations.stats import StatsTable
    from sass_tui.db.populations.targets import TargetWeights, WeightedCount

# What the database may answer a user's request with (QueryError, DatabaseError
# and FlatFileError are SassErrors; engine errors arrive as DatabaseErrors):
# the UI's edges catch these; anything else is a bug and shows as one.
DB_ERRORS = (SassError, OSError)
BUSY = "Working on the database, please wait (Esc cancels)..."

P = ParamSpec("P")
R = TypeVar("R")


class DatabaseBusy(DatabaseError):
    """Another user of the lists (a worker) holds the connection."""


def _serialised(method: Callable[P, R]) -> Callable[P, R]:
    """The method under the lists' lock, engine errors as DatabaseErrors."""

    @wraps(method)
    def locked(*args: P.args, **kwargs: P.kwargs) -> R:
        self = args[0]
        assert isinstance(self, QueryLists)
        if self._owner == threading.get_ident():  # held by this thread already
            return method(*args, **kwargs)
        with self.exclusive():
            return method(*args, **kwargs)

    return locked


# People searched between two progress reports of a query (QueryLists.run_chunk).
RUN_CHUNK = 20_000
QUERY_LIST = "query"
SELECTED_LIST = "selected"
# Unqualified: both engines look among the connection's TEMP tables first.
_TABLES = {QUERY_LIST: "query_list", SELECTED_LIST: "selected_list"}
# Selected people keep the order they were selected in (seq); the query list is in id order.
_ORDER = {QUERY_LIST: "l.id_num", SELECTED_LIST: "l.seq"}
_SELECT = (
    "p.id_num, p.name, p.gender, p.mass, p.stature, p.handedness, p.age, p.source, "
    "sq.strength_type, sq.motion_speed, sq.training_level, sq.fatigue_level, p.branch"
)


# The columns a list may be sorted by (the query screen's sort): each list
# column's key and its SQL.  A sorted list puts the people with no value last
# on both engines (SQLite sorts NULL first, PostgreSQL last) and keeps its own
# order among equals.
SORT_COLUMNS = {
    "name": "p.name",
    "source": "p.source",
    "gender": "p.gender",
    "age": "p.age",
    "mass": "p.mass",
    "stature": "p.stature",
    "branch": "p.branch",
    "handedness": "p.handedness",
    "strength_type": "sq.strength_type",
    "motion_speed": "sq.motion_speed",
    "training_level": "sq.training_level",
    "fatigue_level": "sq.fatigue_level",
}


def field_sql(key: str) -> str:
    """The SQL of a list column (a SORT_COLUMNS key) or of any field of the
    query language (`measure.poplitealheight`, `girth.neck.x`): the person's
    value, NULL when there is none.  QueryError when `key` is neither; the
    table and column names are the compiler's own, never the text typed."""
    if key in SORT_COLUMNS:
        return SORT_COLUMNS[key]
    table, column, _unit = field_column(key)
    if table == "person":
        return f"p.{column}"
    if table == "strength_q":
        return f"sq.{column}"
    return f"(SELECT f.{column} FROM {table} f WHERE f.id_num = p.id_num)"


def order_by(which: str, sort: tuple[str, bool] | None) -> str:
    """The ORDER BY of a list: its own order, or `sort` (a column key or a
    field, descending) first."""
    if sort is None:
        return _ORDER[which]
    column = field_sql(sort[0])
    return f"({column} IS NULL), {column}{' DESC' if sort[1] else ''}, {_ORDER[which]}"


def shown_fields(compiled: CompiledQuery) -> tuple[str, ...]:
    """The fields a query compares that the lists have no column for (its
    measurements, segments, joints), in the query's order: the lists show
    them beside the person's own."""
    fields: dict[str, None] = {}
    for comparison in compiled.tree.comparisons():
        if comparison.table not in ("person", "strength_q"):
            fields.setdefault(comparison.field, None)
    return tuple(fields)


def list_tables(dialect: str) -> tuple[str, str]:
    """The CREATE statements of the lists' TEMP tables; seq numbers the selected
    people in the order they were selected."""
    if dialect == "sqlite":
        key, seq = "INTEGER", "seq INTEGER PRIMARY KEY"  # SQLite's rowid
    else:
        key, seq = "BIGINT", "seq BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY"
    return (
        f"CREATE TEMP TABLE IF NOT EXISTS query_list (id_num {key} PRIMARY KEY)",
        f"CREATE TEMP TABLE IF NOT EXISTS selected_list ({seq}, id_num {key} NOT NULL UNIQUE)",
    )


def lost_lists(counts: dict[str, int]) -> str | None:
    """What a PostgreSQL server restart took from the lists holding `counts`
    people (None: they held nobody)."""
    held = [
        f"the {name} list ({count} {'person' if count == 1 else 'people'})"
        for name, count in (("query", counts[QUERY_LIST]), ("selected", counts[SELECTED_LIST]))
        if count
    ]
    if not held:
        return None
    return (
        "The PostgreSQL server restarted and sass connected again; "
        + " and ".join(held)
        + " went with the old connection."
    )


def _target(conn: Any, name: str | None) -> TargetWeights | None:
    """The target population (or virtual one) `name` and its weights; None without."""
    return None if not name else load_weights(conn, name)


class QueryLists:
    def __init__(self, conn: Any):
        # sqlite3's connection, or db/engine/postgres.py's PostgresConnection
        self._conn: Any = conn
        # People searched between two progress reports of a query (run); a
        # test makes it smaller to see several reports on a small database.
        self.run_chunk = RUN_CHUNK
        # The Database service over the same connection: what it does for the
        # command line (the imports, staged on PostgreSQL) it does for the screens.
        self._database = Database(conn, None)
        # Not reentrant: a screen's exclusive(wait=False) while its own thread
        # holds the lists is refused as well (tests hold them so).
        self._lock = threading.Lock()
        self._owner: int | None = None  # the thread holding _lock
        self.last_query: str | None = None
        # The fields the last query compared that no list column shows
        # (shown_fields): the lists' pages carry them too.
        self.query_fields: tuple[str, ...] = ()
        # The last query compiled: the count, the hint and the weighted count of
        # one run of the query screen parse its text once.
        self._compiled: CompiledQuery | None = None
        # What a server restart took (PostgreSQL), to be told once (take_lost).
        self._lost: str | None = None
        self.dialect = dialect_of(conn)
        self._mark = mark_of(conn)
        self._counts = {QUERY_LIST: 0, SELECTED_LIST: 0}
        if self.dialect == "sqlite":
            conn.execute("PRAGMA temp_store = MEMORY")
        else:

            def lists_lost() -> None:
                # The connection was opened again (a server restart): its TEMP
                # tables were made again, empty; the people the lists held are gone.
                self._lost = lost_lists(self._counts) or self._lost
                self._counts = {QUERY_LIST: 0, SELECTED_LIST: 0}

            conn.on_reconnect.append(lists_lost)
        # A read-only PostgreSQL session made them before it became read-only
        # (PostgresConnection's temp_tables): no CREATE in a read-only transaction.
        if not getattr(conn, "read_only", False):
            for statement in list_tables(self.dialect):
                conn.execute(statement)

    def take_lost(self) -> str | None:
        """What the last server restart took from the lists, once; else None."""
        lost, self._lost = self._lost, None
        return lost

    @classmethod
    def open(cls, target: str | Path, read_only: bool = False) -> QueryLists:
        """The lists of the SQLite file `target`, or of the PostgreSQL database
        it names (`postgresql://...`).  `read_only`: any change to the database
        is refused (SQLite's read-only mode; PostgreSQL's read-only session,
        also when $SASS_READ_ONLY says so: db/engine/postgres.py)."""
        if is_url(target):
            return cls(
                connect_postgres(
                    str(target),
                    read_only=True if read_only else None,
                    temp_tables=list_tables("postgresql"),
                )
            )
        # The query runs in a worker thread; the lock makes sharing the connection safe.
        return cls(connect(target, check_same_thread=False, read_only=read_only))

    @contextmanager
    def _transaction(self) -> Iterator[None]:
        """A transaction of the lists (TEMP tables only): SQLite's deferred one
        takes no lock on the main database."""
        if self.dialect == "sqlite":
            with transaction(self._conn, "DEFERRED"):
                yield
        else:
            with self._conn.transaction():
                yield

    def close(self) -> None:
        with self.exclusive():
            self._conn.close()

    @contextmanager
    def exclusive(self, wait: bool = True) -> Iterator[QueryLists]:
        """Hold the lists for several calls; DatabaseBusy at once (without
        `wait`) while a worker holds them."""
        if not self._lock.acquire(blocking=wait):
            raise DatabaseBusy(BUSY)
        self._owner = threading.get_ident()
        try:
            with engine_errors():
                yield self
        finally:
            self._owner = None
            self._lock.release()

    def count(self, which: str) -> int:
        return self._counts[which]

    # --- running a query -----------------------------------------------------
    @_serialised
    def run(self, text: str, progress: Progress | None = None, cancel: Cancel | None = None) -> int:
        """Replace the query list with the people `text` finds; returns how many.
        A bad query raises QueryError and leaves both lists as they were.

        With `progress` or `cancel` the people are searched in id ranges of
        about `run_chunk` people: `progress(people searched, people in the
        database)` after each, and `cancel` stops it with Cancelled (between
        ranges or inside one), the lists as they were."""
        compiled = self._compile(text)
        where, params = compiled.sql(self.dialect)
        sql = (
            f"INSERT INTO query_list (id_num) SELECT p.id_num FROM {compiled.from_clause()} "
            f"WHERE {where} AND p.id_num NOT IN (SELECT id_num FROM selected_list)"
        )
        with self._transaction():
            found = None
            if self.dialect == "sqlite":
                # Read the main database first: its shared lock, held to COMMIT,
                # keeps writers out, so the column copy (db/query/accelerator.py) finds
                # the people SQLite would; None when SQLite must find them.
                self._conn.execute("SELECT 1 FROM person LIMIT 1").fetchone()
                found = accelerator.answer_in_transaction(self._conn, compiled, ids=True)
            self._conn.execute("DELETE FROM query_list")
            if found is not None:  # the column copy found them: no search, no progress
                count = self._conn.execute(
                    "INSERT INTO query_list (id_num) SELECT value FROM json_each(?) "
                    "WHERE value NOT IN (SELECT id_num FROM selected_list)",
                    ("[" + ",".join(map(str, found)) + "]",),
                ).rowcount
            elif progress is None and cancel is None:
                count = self._conn.execute(sql, params).rowcount
            else:
                count = self._run_in_ranges(
                    sql, params, Steps(progress, cancel, "the query"), cancel
                )
        self._counts[QUERY_LIST] = int(count)
        self.last_query = text
        self.query_fields = shown_fields(compiled)
        return int(count)

    def _run_in_ranges(
        self, sql: str, params: tuple[object, ...], steps: Steps, cancel: Cancel | None
    ) -> int:
        """The query over id ranges, each about `run_chunk` people wide; the people
        searched are estimated from the ids passed (exact at the end)."""
        low, high, total = self._conn.execute(
            "SELECT min(id_num), max(id_num), count(*) FROM person"
        ).fetchone()
        steps(0, total)
        if not total:
            return 0
        ranges = max(1, -(-total // self.run_chunk))
        span = high - low + 1
        cuts = [low + span * k // ranges for k in range(ranges)] + [high + 1]
        ranged = f"{sql} AND p.id_num >= {self._mark} AND p.id_num < {self._mark}"
        count = 0
        with interruptible(self._conn, cancel, "the query"):
            for start, stop in zip(cuts, cuts[1:]):
                count += self._conn.execute(ranged, (*params, start, stop)).rowcount
                steps(total * (stop - low) // span, total)
        return count

    # --- reading -----------------------------------------------------------------
    @_serialised
    def page(
        self, which: str, offset: int, limit: int = 25, sort: tuple[str, bool] | None = None
    ) -> list[dict[str, Any]]:
        """One page of a list, in its own order or sorted by `sort` (a
        column key or a field, descending); each row has the list's columns
        and the fields the last query compared (`query_fields`)."""
        fields = self.query_fields
        extra = "".join(f", {field_sql(field)}" for field in fields)
        sql = (
            f"SELECT {_SELECT}{extra} FROM {_TABLES[which]} l "
            f"JOIN person p ON p.id_num = l.id_num "
            f"LEFT JOIN strength_q sq ON sq.id_num = l.id_num "
            f"ORDER BY {order_by(which, sort)} LIMIT {self._mark} OFFSET {self._mark}"
        )
        names = LIST_FIELDS + fields
        return [
            dict(zip(names, row, strict=True))
            for row in self._conn.execute(sql, (int(limit), int(offset)))
        ]

    @_serialised
    def position(self, which: str, key: str, sort: tuple[str, bool] | None = None) -> int | None:
        """Where in a list (0-based, in the order shown) the person `key`
        names is: a database id, else a name in any case, else the first name
        that starts with it, holds it as a word, or holds it at all.  None:
        nobody in the list."""
        m = self._mark
        numbered = (
            f"SELECT l.id_num, lower(p.name) AS name, "
            f"ROW_NUMBER() OVER (ORDER BY {order_by(which, sort)}) - 1 AS place "
            f"FROM {_TABLES[which]} l JOIN person p ON p.id_num = l.id_num "
            f"LEFT JOIN strength_q sq ON sq.id_num = l.id_num"
        )
        text = " ".join(key.split()).lower()
        escaped = text.replace("\\", "\\\\").replace("%", "\\%").replace("_", "\\_")
        for condition, parameter in (
            (f"id_num = {m}", int(text) if text.isdigit() else -1),
            (f"name = {m}", text),
            (f"name LIKE {m} ESCAPE '\\'", escaped + "%"),
            # A word of the name ("4216" of "virtual nhanes-2017-2020 F 4216"), then any part.
            (f"(' ' || name || ' ') LIKE {m} ESCAPE '\\'", f"% {escaped} %"),
            (f"name LIKE {m} ESCAPE '\\'", f"%{escaped}%"),
        ):
            row = self._conn.execute(
                f"SELECT place FROM ({numbered}) t WHERE {condition} ORDER BY place LIMIT 1",
                (parameter,),
            ).fetchone()
            if row is not None:
                return int(row[0])
        return None

    @_serialised
    def person_record(self, id_num: int) -> dict[str, object]:
        """Everything stored about the person `id_num` (db/people/individual.py's
        person_record: what `sass person` prints)."""
        return person_record(self._conn, id_num)

    @_serialised
    def selected_id(self, index: int) -> int | None:
        """The id of the index-th (0-based) person in the selected list."""
        row = self._conn.execute(
            f"SELECT id_num FROM selected_list ORDER BY seq LIMIT 1 OFFSET {self._mark}",
            (int(index),),
        ).fetchone()
        return None if row is None else row[0]

    # --- moving people between the lists ---------------------------------------------
    @_serialised
    def select_one(self, id_num: int) -> bool:
        """Move one person from the query list to the end of the selected list."""
        m = self._mark
        with self._transaction():
            gone = self._conn.execute(
                f"DELETE FROM query_list WHERE id_num = {m}", (int(id_num),)
            ).rowcount
            added = (
                self._conn.execute(
                    f"INSERT INTO selected_list (id_num) VALUES ({m}) ON CONFLICT DO NOTHING",
                    (int(id_num),),
                ).rowcount
                if gone
                else 0
            )
        self._counts[QUERY_LIST] -= gone
        self._counts[SELECTED_LIST] += added
        return bool(gone)

    @_serialised
    def select_all(self) -> int:
        """Move the whole query list to the selected list; returns how many moved."""
        with self._transaction():
            # WHERE true: SQLite's parser needs it before an upsert's ON CONFLICT.
            moved = self._conn.execute(
                "INSERT INTO selected_list (id_num) "
                "SELECT id_num FROM query_list WHERE true ORDER BY id_num ON CONFLICT DO NOTHING"
            ).rowcount
            self._conn.execute("DELETE FROM query_list")
        self._counts[QUERY_LIST] = 0
        self._counts[SELECTED_LIST] += moved
        return int(moved)

    @_serialised
    def delete_one(self, which: str, id_num: int) -> bool:
        with self._transaction():
            gone = self._conn.execute(
                f"DELETE FROM {_TABLES[which]} WHERE id_num = {self._mark}", (int(id_num),)
            ).rowcount
        self._counts[which] -= gone
        return bool(gone)

    # --- Input DB ------------------------------------------------------------------------
    @_serialised
    def import_files(
        self, files: FlatFiles, progress: Progress | None = None, cancel: Cancel | None = None
    ) -> int:
        """Load flat files (one transaction: a failure or a cancel stores nothing)."""
        return import_flat_into(self._database, files, progress, cancel)

    @_serialised
    def import_ansur(
        self,
        path: Path,
        label: str,
        progress: Progress | None = None,
        cancel: Cancel | None = None,
    ) -> int:
        """Load an ANSUR II format file under the source `label` (one
        transaction: a failure or a cancel stores nothing); returns how many."""
        counts = import_ansur_into(
            self._database, [path], label=label, progress=progress, cancel=cancel
        )
        return sum(counts.values())

    @_serialised
    def selected_ids(self) -> list[int]:
        """The ids of the selected list, in the order they were selected."""
        return [r[0] for r in self._conn.execute("SELECT id_num FROM selected_list ORDER BY seq")]

    # --- the work of the query screen's other commands ------------------------------
    @_serialised
    def run_first_page(
        self,
        text: str,
        page_size: int,
        progress: Progress | None = None,
        cancel: Cancel | None = None,
        sort: tuple[str, bool] | None = None,
    ) -> tuple[int, list[dict[str, Any]]]:
        """run(text), then the query list's first page (sorted by `sort`), with
        nobody in between."""
        count = self.run(text, progress, cancel)
        return count, self.page(QUERY_LIST, 0, page_size, sort)

    @_serialised
    def fetch_person(self, id_num: int) -> Individual:
        """The person `id_num` (e.g. a row of the query list), read whole."""
        return fetch_individual(self._conn, id_num)

    @_serialised
    def fetch_selected(self, index: int) -> Individual:
        """Person `index` (0-based) of the selected list, read whole."""
        id_num = self.selected_id(index)
        if id_num is None:
            raise DatabaseError(f"there is no person {index + 1} in the selected list")
        return fetch_individual(self._conn, id_num)

    @_serialised
    def fit_test(
        self,
        limits: str,
        population: str,
        progress: Progress | None = None,
        cancel: Cancel | None = None,
        target: str | None = None,
    ) -> tuple[FitResult, tuple[LimitHistogram, ...]]:
        """The fit test of `limits` over `population` and its histograms
        (db/populations/fit.py); with a `target`'s name, weighted to it too (db/populations/targets.py)."""
        weights = _target(self._conn, target)
        result = fit_test(
            self._conn, limits, population, progress=progress, cancel=cancel, target=weights
        )
        return result, limit_histograms(self._conn, limits, population, cancel=cancel)

    @_serialised
    def design(
        self,
        limits: str,
        percent: float,
        population: str,
        cancel: Cancel | None = None,
        target: str | None = None,
    ) -> tuple[Designed, tuple[LimitHistogram, ...]]:
        """The `?` of `limits` solved for `percent` of `population` as `sass
        design` solves them (db/populations/design.py), and the histograms of
        the solved limits."""
        designed = design(
            self._conn, limits, percent, population, None, _target(self._conn, target)
        )
        solved = " AND ".join(designed.texts)
        return designed, limit_histograms(self._conn, solved, population, cancel=cancel)

    @_serialised
    def population_of(
        self,
        ids: tuple[int, ...],
        title: str,
        progress: Progress | None = None,
        cancel: Cancel | None = None,
        target: str | None = None,
    ) -> SelectionPopulation:
        """The population file of these people (db/populations/population.py); with a
        `target`'s name, their weighted percentiles (db/populations/targets.py)."""
        return population_of(
            self._conn,
            ids=ids,
            title=title,
            progress=progress,
            cancel=cancel,
            target=_target(self._conn, target),
        )

    @_serialised
    def stats(
        self,
        query: str | None,
        target: str | None = None,
        cancel: Cancel | None = None,
    ) -> StatsTable:
        """The percentile table of every measure over the query's people
        (db/populations/stats.py), weighted to a target or a virtual population by name."""
        with interruptible(self._conn, cancel, "the table"):
            return stats_table(
                self._conn, list(EVERY_MEASURE), query, weights=_target(self._conn, target)
            )

    # --- target populations and the real-people scope ----------------------
    @_serialised
    def read(self, reader: Callable[..., R], *args: Any) -> R:
        """`reader(connection, *args)`, a read of the database (target_names,
        sources, target_people, people_of below) in turn with the lists' work."""
        return reader(self._conn, *args)

    @_serialised
    def weighted_count(self, query: str, target: str) -> WeightedCount:
        """The query's people weighted to the target `target` (db/populations/targets.py)."""
        weights = load_weights(self._conn, target)
        if weights.target.is_virtual:  # its virtual people, whom a query reaches only by name
            query = f"({query}) AND {weights.target.population}"
        return weighted_count(self._conn, self._compile(query), weights)

    @_serialised
    def demonstration_hint(self, text: str) -> str | None:
        """For a query that found no real person: the demonstration people it
        would find (db/query/query.py's demonstration_hint)."""
        return demonstration_hint(self._conn, self._compile(text))

    def _compile(self, text: str) -> CompiledQuery:
        """`text` compiled, or the last query compiled if it is the same text."""
        if self._compiled is None or self._compiled.text != text:
            self._compiled = compile_query(text)
        return self._compiled


# --- reads of the database, run by QueryLists.read ------------------------------------
def target_names(conn: Any) -> list[str]:
    """The names of the target populations and virtual populations
    (`virtual:NAME`) stored (`sass target`), and the shipped ones not made yet."""
    stored = [t.name for t in list_targets(conn)]
    return stored + [name for name in SHIPPED if name not in stored]


def sources(conn: Any) -> list[str]:
    """The sources of the database's people (ansur2, synthetic, an import's
    label), sorted: what a query's source may be."""
    rows = conn.execute(
        "SELECT DISTINCT source FROM person WHERE source IS NOT NULL ORDER BY source"
    )
    return [str(row[0]) for row in rows]


def target_people(conn: Any, name: str) -> tuple[int, ...]:
    """The ids of the people a target (or virtual population) weights, made
    first if it is a shipped one not made yet."""
    weights = load_weights(conn, name)
    return tuple(int(i) for i, w in zip(weights.ids, weights.weights, strict=True) if w > 0)


def people_of(conn: Any, text: str) -> tuple[int, ...]:
    """The ids of the people a query finds (its scope: real people unless it
    names a source), the lists left as they are."""
    compiled = compile_query(text)
    where, params = compiled.sql(dialect_of(conn))
    rows = conn.execute(
        f"SELECT p.id_num FROM {compiled.from_clause()} WHERE {where} ORDER BY p.id_num",
        params,
    )
    return tuple(int(row[0]) for row in rows)
