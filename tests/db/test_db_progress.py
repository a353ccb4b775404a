"""Progress and cancel of the long database work: every function
reports (done, total) and stops on a cancel with nothing written.

Both engines: imports through the Database service into a private copy
(`engine_target`; on PostgreSQL staged in SQLite and copied, db/engine/postgres.py),
the query lists, populations, fit tests and families over the shared
database.  SQLite only: the default file's first build and SQLite's
progress handler (PostgreSQL's statement cancel: test_engines_verbs.py)."""

from __future__ import annotations

import threading
from contextlib import closing
from functools import partial

import pytest
from big_flat_files import write_big_flat_files

from sass_tui.db.engine.database import Database
from sass_tui.db.engine.dialect import dialect_of
from sass_tui.db.engine.schema import row_counts
from sass_tui.db.people.ansur import import_ansur_into
from sass_tui.db.people.default import create_default_database
from sass_tui.db.people.default_people import shipped_ansur_files
from sass_tui.db.people.flatfile import import_flat_into
from sass_tui.db.populations.family import load_family
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.population import population_of
from sass_tui.db.progress import Cancelled, interruptible
from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists


class CancelAfter:
    """A cancel that is set once it has been asked `n` times (deterministic:
    no timing), like a threading.Event the user sets mid-way."""

    def __init__(self, n: int) -> None:
        self.n = n
        self.asked = 0

    def is_set(self) -> bool:
        self.asked += 1
        return self.asked > self.n


def _state(conn):
    """The rows of every table of people, and on SQLite its file's integrity."""
    if dialect_of(conn) != "sqlite":
        return row_counts(conn), "ok"
    return row_counts(conn), conn.execute("PRAGMA integrity_check").fetchone()[0]


def _checked(reports: list[tuple[int, int]]) -> None:
    """Reports rise to their total, which does not change."""
    assert reports, "no progress reported"
    totals = {t for _d, t in reports}
    assert len(totals) == 1
    done = [d for d, _t in reports]
    assert done == sorted(done) and 0 <= done[0] and done[-1] == reports[-1][1]


@pytest.mark.slow
def test_flat_import_reports_lines_and_a_cancel_stores_nothing(
    engine_target, engine_db_copy, tmp_path
):
    conn = engine_db_copy
    files = write_big_flat_files(tmp_path / "big", people=1500)
    db = Database.open(engine_target)
    before = _state(conn)
    reports: list[tuple[int, int]] = []
    cancel = threading.Event()

    def progress(done: int, total: int) -> None:
        reports.append((done, total))
        if len(reports) == 3:
            cancel.set()  # the user presses Escape while it reads

    with (
        closing(db),
        pytest.raises(Cancelled, match="the import was cancelled; nothing was written"),
    ):
        import_flat_into(db, files, progress, cancel)
    assert len(reports) == 3
    assert _state(conn) == before
    # cancelled while storing (the SQLite statement is interrupted): rolled back
    with closing(Database.open(engine_target)) as db, pytest.raises(Cancelled):
        import_flat_into(db, files, None, CancelAfter(1500 * 26 // 500 + 3))
    assert _state(conn) == before
    reports.clear()
    with closing(Database.open(engine_target)) as db:
        assert import_flat_into(db, files, lambda d, t: reports.append((d, t))) == 1500
    _checked(reports)
    assert reports[-1][1] == 1500 + 1500 * 25  # every line of both files
    assert _state(conn)[0]["person"] == before[0]["person"] + 1500


def test_ansur_import_cancelled_is_rolled_back(engine_target, engine_db_copy):
    before = _state(engine_db_copy)
    with closing(Database.open(engine_target)) as db, pytest.raises(Cancelled):
        import_ansur_into(db, shipped_ansur_files(), label="again", cancel=CancelAfter(2))
    assert _state(engine_db_copy) == before


# Where each engine stores an import's people last, before its commit: SQLite's
# import writes them (db/people/flatfile.py); PostgreSQL's copies the staged people
# (db/engine/postgres.py's import_staged).
LAST_STORE = {
    "sqlite": "sass_tui.db.people.flatfile.store_people",
    "postgresql": "sass_tui.db.engine.postgres.copy_people",
}


@pytest.mark.parametrize(
    "open_importer",
    [
        pytest.param(
            lambda target: (db := Database.open(target), partial(import_flat_into, db)),
            id="Database",
        ),
        pytest.param(
            lambda target: (lists := QueryLists.open(target), lists.import_files), id="QueryLists"
        ),
    ],
)
def test_a_cancel_while_the_people_are_stored_stores_nothing(
    engine, engine_target, engine_db_copy, tmp_path, monkeypatch, open_importer
):
    """The user presses Escape as the last rows go in, before the commit: the
    import is cancelled and nothing is stored, on either engine, through the
    Database service (the CLI) and the query screen's lists (Input DB)."""
    before = _state(engine_db_copy)
    cancel = threading.Event()
    module, name = LAST_STORE[engine].rsplit(".", 1)
    store = getattr(__import__(module, fromlist=[name]), name)

    def storing(*args, **kwargs):
        stored = store(*args, **kwargs)
        cancel.set()
        return stored

    monkeypatch.setattr(LAST_STORE[engine], storing)
    files = write_big_flat_files(tmp_path / "big", people=20)
    opened, import_files = open_importer(engine_target)
    with closing(opened), pytest.raises(Cancelled, match="the import was cancelled"):
        import_files(files, None, cancel)
    assert cancel.is_set()
    assert _state(engine_db_copy) == before


@pytest.mark.sqlite_only(
    "the default database is a SQLite file built on first use; PostgreSQL's is made by "
    "`sass db init` (one transaction: tests/db/test_engines.py)"
)
def test_default_database_build_cancelled_leaves_no_people(tmp_path):
    path = tmp_path / "new.db"
    with pytest.raises(Cancelled):
        create_default_database(path, cancel=CancelAfter(1))
    # a new database is built aside (db/people/default.py): a cancelled one leaves no file
    assert list(tmp_path.iterdir()) == []


def test_query_reports_people_searched_and_a_cancel_keeps_the_lists(shared_target):
    lists = QueryLists.open(shared_target)
    lists.run_chunk = 2000  # several ranges of the people
    try:
        assert lists.run("gender = female") > 0
        lists.select_one(lists.page(QUERY_LIST, 0, 1)[0]["id"])
        page = lists.page(QUERY_LIST, 0, 50)
        counts = (lists.count(QUERY_LIST), lists.count(SELECTED_LIST))
        with pytest.raises(Cancelled, match="the query was cancelled"):
            lists.run("gender = male", cancel=CancelAfter(1))
        assert lists.last_query == "gender = female"
        assert (lists.count(QUERY_LIST), lists.count(SELECTED_LIST)) == counts
        assert lists.page(QUERY_LIST, 0, 50) == page
        reports: list[tuple[int, int]] = []
        found = lists.run("gender = male", progress=lambda d, t: reports.append((d, t)))
        _checked(reports)
        (people,) = lists._conn.execute("SELECT count(*) FROM person").fetchone()
        assert reports[-1] == (people, people) and len(reports) > 2
        (male,) = lists._conn.execute(
            "SELECT count(*) FROM person WHERE gender = 'male' AND source != 'synthetic' "
            "AND substr(source, 1, 8) != 'virtual:'"
        ).fetchone()
        assert found == male == lists.count(QUERY_LIST)
    finally:
        lists.close()


def test_population_fit_and_family_report_and_cancel(engine_db):
    reports: list[tuple[int, int]] = []
    population_of(engine_db, "gender = female AND age < 25", progress=lambda *r: reports.append(r))
    _checked(reports)
    with pytest.raises(Cancelled, match="making the population was cancelled"):
        population_of(engine_db, "gender = female AND age < 25", cancel=CancelAfter(10))
    reports.clear()
    fit_test(engine_db, "stature < 190 cm", progress=lambda *r: reports.append(r))
    assert reports == [(0, 3), (1, 3), (2, 3), (3, 3)]
    with pytest.raises(Cancelled, match="the fit test was cancelled"):
        fit_test(engine_db, "stature < 190 cm", cancel=CancelAfter(1))
    with pytest.raises(Cancelled, match="the family was cancelled"):
        load_family(engine_db, "male", ["stature", "mass"], 0.9, cancel=CancelAfter(2))


@pytest.mark.sqlite_only(
    "SQLite's progress handler (PostgreSQL's statement cancel: test_engines_verbs.py)"
)
def test_interruptible_stops_a_long_statement(default_db):
    long = (
        "WITH RECURSIVE n(i) AS (SELECT 1 UNION ALL SELECT i + 1 FROM n WHERE i < 100000000) "
        "SELECT count(*) FROM n"
    )
    cancel = CancelAfter(3)
    with pytest.raises(Cancelled), interruptible(default_db, cancel):
        default_db.execute(long).fetchone()
    assert cancel.asked <= 5  # stopped at once, not after the 10^8 rows
    assert default_db.execute("SELECT 1").fetchone() == (1,)  # the handler is gone
