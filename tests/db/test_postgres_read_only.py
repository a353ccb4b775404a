"""`sass serve --read-only` on a PostgreSQL database: the server makes every
transaction of the session read-only once the query lists' TEMP tables exist.
The lists, fit tests, person pages and predictions answer as on a read-write
connection; every change (an import, Input DB, a target made or dropped, a
raw DELETE as a bug would send) is refused with a message saying the
database is read-only, and nothing changes.  The tests run a throwaway
cluster (tests/_postgres.py's `cluster` fixture)."""

from __future__ import annotations

from types import SimpleNamespace

import pytest
from big_flat_files import write_big_flat_files
from test_targets import civilian_women, write_sample

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.engine.schema import DatabaseError
from sass_tui.db.people.ansur import import_ansur_into
from sass_tui.db.people.individual import person_records
from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists, target_names
from sass_tui.model.served import READ_ONLY_ENV

QUERY = "gender = female AND stature > 170 cm"
LIMITS = "stature <= 185 cm AND mass <= 100 kg"
READ_ONLY = "the database is open read-only"


@pytest.fixture(scope="module")
def shared(cluster, postgres_template, tmp_path_factory) -> str:
    """A database after `sass db init`, holding one target (`civ`)."""
    url = cluster.create_database("read_only", postgres_template)
    sample = write_sample(tmp_path_factory.mktemp("sample") / "civ.csv", civilian_women(400))
    assert main(["target", "civ", "--gender", "female", "--sample", str(sample), "--db", url]) == 0
    return url


def held(url: str) -> tuple[int, int, int]:
    """People, targets and target weights stored, read on a connection of its own."""
    db = Database.open(url)
    try:
        with db.connection() as conn:
            return tuple(  # type: ignore[return-value]
                int(conn.execute(f"SELECT count(*) FROM {table}").fetchone()[0])
                for table in ("person", "target", "target_weight")
            )
    finally:
        db.close()


def work_of(lists: QueryLists) -> dict[str, object]:
    """What the query screen asks of its lists, and the answers."""
    count, first = lists.run_first_page(QUERY, 25)
    lists.select_one(first[0]["id"])
    lists.delete_one(QUERY_LIST, first[1]["id"])
    fit, _histograms = lists.fit_test(LIMITS, "gender = female")
    person = lists.fetch_selected(0)
    lists.select_all()
    population = lists.population_of(tuple(lists.selected_ids()), "selected")
    return {
        "count": count,
        "first": first,
        "lists": (lists.count(QUERY_LIST), lists.count(SELECTED_LIST)),
        "selected": lists.page(SELECTED_LIST, 0, 5),
        "fit": (fit.weighted_percent, fit.population_size),
        "person": (person.id_num, person.name, person.stature),
        "population": (population.counts, population.modelled),
        "weighted": lists.weighted_count(QUERY, "civ"),
        "targets": lists.read(target_names),
    }


@pytest.mark.slow
def test_read_only_lists_answer_as_read_write_ones(shared):
    before = held(shared)
    writable = QueryLists.open(shared)
    try:
        expected = work_of(writable)
    finally:
        writable.close()
    lists = QueryLists.open(shared, read_only=True)
    try:
        assert work_of(lists) == expected
        assert expected["count"] > 25 and expected["fit"][1] > 1000  # type: ignore[index]
    finally:
        lists.close()
    assert held(shared) == before


@pytest.mark.slow
def test_every_change_on_a_read_only_session_is_refused(shared, ansur_dir, tmp_path):
    before = held(shared)
    lists = QueryLists.open(shared, read_only=True)
    try:
        assert lists.run(QUERY) > 0
        with pytest.raises(DatabaseError, match=READ_ONLY):
            lists.import_ansur(ansur_dir / "ANSUR_II_FEMALE_Public.csv", "desk")
        with pytest.raises(DatabaseError, match=READ_ONLY):
            lists.import_files(write_big_flat_files(tmp_path / "flat", people=3))
        # What a bug would send past sass's own refusals: the server refuses it.
        with lists.exclusive():
            for statement in (
                "DELETE FROM person",
                "UPDATE person SET stature = 1",
                "DELETE FROM target",
                "CREATE TABLE mischief (x int)",
            ):
                with pytest.raises(DatabaseError, match=READ_ONLY):
                    lists._conn.execute(statement)
        # The session goes on: its lists are TEMP tables, which it may change.
        assert lists.run(QUERY) > 0 and lists.select_all() > 0
    finally:
        lists.close()
    assert held(shared) == before


@pytest.mark.slow
def test_a_served_read_only_process_changes_nothing(
    shared, ansur_dir, tmp_path, monkeypatch, capsys
):
    """$SASS_READ_ONLY=1 (what `sass serve --read-only` gives each session)
    makes every PostgreSQL connection of the process read-only: the verbs'
    Database too, not only the query screen's lists."""
    before = held(shared)
    monkeypatch.setenv(READ_ONLY_ENV, "1")
    sample = write_sample(tmp_path / "civ2.csv", civilian_women(300))
    made = ["target", "civ2", "--gender", "female", "--sample", str(sample), "--db", shared]
    for argv in (
        made,
        ["target", "--drop", "civ", "--db", shared],
        [
            "db",
            "import-ansur",
            "--source",
            "desk",
            str(ansur_dir / "ANSUR_II_MALE_Public.csv"),
            "--db",
            shared,
        ],
    ):
        assert main(argv) == 2, argv
        err = capsys.readouterr().err
        assert READ_ONLY in err and "Traceback" not in err, (argv, err)
    assert main(["query", "--count", "--db", shared, QUERY]) == 0
    assert int(capsys.readouterr().out) > 0
    db = Database.open(shared)
    try:
        with pytest.raises(DatabaseError, match=READ_ONLY):
            import_ansur_into(db, [ansur_dir / "ANSUR_II_MALE_Public.csv"], label="desk")
        assert person_records(db, ["17"])[0]
    finally:
        db.close()
    assert held(shared) == before


def test_sass_serve_read_only_takes_an_address(shared, monkeypatch):
    """The sessions of `sass serve --read-only --db postgresql://...` are told
    the address and that it is read-only; the server is tried once, here."""
    from sass_tui.cli.serving import database_path

    assert database_path(SimpleNamespace(db=shared), read_only=True) == shared
    monkeypatch.setenv("SASS_DB", shared)
    assert database_path(SimpleNamespace(db=None), read_only=True) == shared
    gone = "postgresql://lab:s3cret@127.0.0.1:1/none"
    with pytest.raises(DatabaseError, match="cannot reach the PostgreSQL server") as raised:
        database_path(SimpleNamespace(db=gone), read_only=True)
    assert "s3cret" not in str(raised.value)
