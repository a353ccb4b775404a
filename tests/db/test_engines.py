"""SQLite and PostgreSQL give the same answers after `sass db init`, and
PostgreSQL holds under concurrent writers, a killed client and a restarted
server.  The PostgreSQL tests run a throwaway cluster (tests/_postgres.py)
and skip, saying why, where no server binaries or no psycopg are installed."""

from __future__ import annotations

import csv
import gzip
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from _postgres import why_not

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.engine.schema import DatabaseError

ROOT = Path(__file__).resolve().parents[2]
SHIPPED_ANSUR = ROOT / "datasets" / "ansur2"

# Ten queries over every kind of field: the report's sample, words, free
# text (case-blind), numbers in other units, measurements, OR and groups.
# Only the synthetic demonstration people carry strength, joint limits and
# centers of mass: those queries name their source (real people otherwise).
QUERIES = [
    "gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb"
    " AND source = synthetic",
    "gender = female AND measure.stature > 1650 mm",
    "source = ANSUR2 AND measure.sittingheight > 95 cm AND branch = 'Combat Arms'",
    "source != ansur2 AND stature > 180 cm",
    "handedness = left OR handedness = either",
    "mass > 100 kg OR (gender = female AND stature > 72 in)",
    "age < 25 AND component = 'Regular Army'",
    "joint_limit.right_shoulder_ul.x > 180 AND center_of_mass.bottom_head.y >= 0 cm"
    " AND source = synthetic",
    "strength_type = isometric AND strength.shoulder_abduction.max > 40 N-m AND source = synthetic",
    "(dodrace = 2 OR subjectnumericrace = 3) AND measure.weightkg <= 60 kg",
]

needs_postgres = pytest.mark.skipif(why_not() is not None, reason=f"PostgreSQL: {why_not()}")

# The fixtures `cluster` and `initialised` (both engines after `sass db init`): tests/conftest.py.


def answers(target: str, text: str) -> tuple[int, list[dict]]:
    db = Database.open(target)
    try:
        return db.count(text), db.page(text, 0, 25)
    finally:
        db.close()


def same_page(a: list[dict], b: list[dict]) -> bool:
    def rounded(row: dict) -> dict:
        return {k: round(v, 9) if isinstance(v, float) else v for k, v in row.items()}

    return [rounded(r) for r in a] == [rounded(r) for r in b]


@pytest.mark.parametrize("text", QUERIES)
def test_the_same_counts_and_first_pages_on_both_engines(initialised, text):
    count, page = answers(initialised["sqlite"], text)
    pg_count, pg_page = answers(initialised["postgresql"], text)
    assert pg_count == count
    assert same_page(pg_page, page)
    assert len(page) == min(count, 25)


def test_the_queries_select_some_but_not_everyone(initialised):
    """Guard against vacuous agreement: each query selects some people, not all."""
    db = Database.open(initialised["sqlite"])
    try:
        everyone = db.people_count()
        counts = [db.count(text) for text in QUERIES]
    finally:
        db.close()
    assert all(0 < c < everyone for c in counts), counts


@pytest.mark.parametrize("engine", ["sqlite", "postgresql"])
def test_a_count_is_the_survey_csv_counted_directly(initialised, engine):
    """Women of the shipped ANSUR II file taller than 1650 mm, counted from the
    CSV itself (an independent reading of the survey)."""
    with gzip.open(SHIPPED_ANSUR / "ANSUR_II_FEMALE_Public.csv.gz", "rt", encoding="latin-1") as f:
        expected = sum(int(row["stature"]) > 1650 for row in csv.DictReader(f))
    count, _page = answers(
        initialised[engine], "source = ansur2 AND gender = female AND measure.stature > 1650 mm"
    )
    assert count == expected > 0


# --- PostgreSQL under load and faults ---------------------------------------------


def sass(*argv: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "sass_tui", *argv],
        capture_output=True,
        text=True,
        timeout=300,
        env=env,
    )


READER = """
import os, sys
from sass_tui.db.engine.database import Database
url, labels, full, stop = sys.argv[1], sys.argv[2].split(","), int(sys.argv[3]), sys.argv[4]
db = Database.open(url)
seen = set()
while not os.path.exists(stop):
    for label in labels:
        n = db.count(f"source = {label}")
        seen.add(n)
        if n not in (0, full):
            print("half an import seen:", label, n)
            sys.exit(1)
print(sorted(seen))
"""


@pytest.mark.slow
@needs_postgres
def test_four_imports_at_once_and_four_readers(cluster, postgres_template, ansur_dir, tmp_path):
    """Four `sass db import-ansur` processes at once, four readers counting
    throughout: every reader sees each label with none or all of its women,
    and at the end each label holds exactly its women, no person twice.
    The survey is the first 300 women of the ANSUR II file: each import is
    still one chunk (db/people/ansur.py's CHUNK_ROWS) stored in one transaction of
    several COPYs, as with the whole file (1,986 women), which took 20 s of
    CPU, most of it the readers counting while the imports ran; now 6 s."""
    url = cluster.create_database("load", postgres_template)  # after `sass db init`
    female = tmp_path / "ANSUR_II_FEMALE_Public.csv"
    with (ansur_dir / "ANSUR_II_FEMALE_Public.csv").open(encoding="latin-1") as f:
        female.write_text("".join(line for _, line in zip(range(301), f)), encoding="latin-1")
    with female.open(encoding="latin-1") as f:
        women = sum(1 for _ in csv.DictReader(f))
    assert women == 300
    labels = [f"lab{k}" for k in range(4)]
    stop = tmp_path / "stop"
    readers = [
        subprocess.Popen(
            [sys.executable, "-c", READER, url, ",".join(labels), str(women), str(stop)],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for _ in range(4)
    ]
    writers = [
        subprocess.Popen(
            [
                sys.executable,
                "-m",
                "sass_tui",
                "db",
                "import-ansur",
                "--db",
                url,
                "--source",
                label,
                str(female),
            ],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for label in labels
    ]
    for writer in writers:
        out, err = writer.communicate(timeout=300)
        assert writer.returncode == 0, err
        assert f"imported 0 men and {women} women" in out
    stop.touch()
    for reader in readers:
        out, err = reader.communicate(timeout=60)
        assert reader.returncode == 0 and "half an import" not in out, (out, err)
        assert out.strip() in ("[0]", f"[0, {women}]", f"[{women}]"), out  # what it saw
    db = Database.open(url)
    try:
        for label in labels:
            assert db.count(f"source = {label}") == women
        ids = [row[0] for row in db.person_rows("source != nobody")]
        assert len(ids) == len(set(ids)) == db.people_count()
    finally:
        db.close()


@pytest.mark.slow
@needs_postgres
def test_a_reimport_replaces_and_never_duplicates(cluster, ansur_dir):
    url = cluster.create_database("reimport")
    female = str(ansur_dir / "ANSUR_II_FEMALE_Public.csv")
    assert main(["db", "import-ansur", "--db", url, "--source", "mine", female]) == 0
    db = Database.open(url)
    try:
        first = [row[0] for row in db.person_rows("source = mine")]
        assert main(["db", "import-ansur", "--db", url, "--source", "mine", female]) == 0
        assert [row[0] for row in db.person_rows("source = mine")] == first
    finally:
        db.close()


KILLED = """
import os, signal, sys
from sass_tui.db.engine import postgres
from sass_tui.cli import main
copy_rows = postgres.PostgresConnection.copy_rows
calls = []
def copy_then_die(self, table, columns, rows, types=None):
    calls.append(table)
    if len(calls) == 3:  # person and a table already sent, inside the transaction
        os.kill(os.getpid(), signal.SIGKILL)
    return copy_rows(self, table, columns, rows, types)
postgres.PostgresConnection.copy_rows = copy_then_die
sys.exit(main(sys.argv[1:]))
"""


@pytest.mark.slow
@needs_postgres
def test_a_client_killed_mid_import_leaves_the_database_as_before(
    cluster, postgres_template, ansur_dir
):
    url = cluster.create_database("killed", postgres_template)  # after `sass db init`
    db = Database.open(url)
    try:
        before = db.people_count()
        female = str(ansur_dir / "ANSUR_II_FEMALE_Public.csv")
        done = subprocess.run(
            [
                sys.executable,
                "-c",
                KILLED,
                "db",
                "import-ansur",
                "--db",
                url,
                "--source",
                "x",
                female,
            ],
            capture_output=True,
            text=True,
            timeout=300,
        )
        assert done.returncode == -signal.SIGKILL, done.stderr
        assert db.people_count() == before
        assert db.count("source = x") == 0
        # the dead client's lock went with it: the next import goes through
        assert main(["db", "import-ansur", "--db", url, "--source", "x", female]) == 0
        assert db.count("source = x") > 0
    finally:
        db.close()


@pytest.mark.slow
@needs_postgres
def test_a_server_restarted_between_two_commands(cluster, postgres_template, capsys):
    url = cluster.create_database("restarted", postgres_template)  # after `sass db init`
    query = "gender = female AND stature > 170 cm"
    db = Database.open(url)
    try:
        first = db.count(query)
        cluster.restart()
        # the same Database: its connection broke, the next statement reconnects
        assert db.count(query) == first
        # a new command connects anew
        assert main(["query", "--count", "--db", url, query]) == 0
        assert capsys.readouterr().out.strip() == str(first)
        cluster.stop()
        try:
            with pytest.raises(DatabaseError, match="server closed the connection|cannot reach"):
                db.count(query)
            assert main(["query", "--count", "--db", url, query]) == 2
            err = capsys.readouterr().err
            assert "cannot reach the PostgreSQL server" in err and "Traceback" not in err
        finally:
            cluster.start()
    finally:
        db.close()


@pytest.mark.slow
@needs_postgres
def test_sass_db_env_names_the_server(cluster, postgres_template):
    url = cluster.create_database("from_env", postgres_template)  # after `sass db init`
    env = dict(os.environ, SASS_DB=url)
    # `db init` finds the people of the server's database (no file of that name)
    # and, with no terminal to ask on, wants --force to replace them
    refused = sass("db", "init", env=env)
    assert refused.returncode == 2 and "--force" in refused.stderr, refused.stderr
    assert "people" in refused.stderr
    counted = sass("query", "--count", "source = synthetic", env=env)
    assert counted.returncode == 0, counted.stderr
    assert int(counted.stdout) > 0


@needs_postgres
def test_a_newer_schema_is_refused_with_a_message(cluster):
    import psycopg

    url = cluster.create_database("newer")
    Database.open(url, create=True).close()
    with psycopg.connect(url, autocommit=True) as raw:
        raw.execute("UPDATE meta SET value = '99' WHERE key = 'schema_version'")
    with pytest.raises(DatabaseError, match="schema version 99"):
        Database.open(url)


def test_an_unreachable_server_is_a_message(capsys):
    pytest.importorskip("psycopg")
    url = "postgresql://nobody@127.0.0.1:1/none"
    assert main(["query", "--count", "--db", url, "stature > 1"]) == 2
    err = capsys.readouterr().err
    assert "cannot reach the PostgreSQL server" in err and "Traceback" not in err


def test_the_password_is_never_shown(capsys):
    pytest.importorskip("psycopg")
    url = "postgresql://lab:s3cret@127.0.0.1:1/none"
    assert main(["query", "--count", "--db", url, "stature > 1"]) == 2
    err = capsys.readouterr().err
    assert "s3cret" not in err and "lab:***@127.0.0.1:1" in err


@pytest.mark.parametrize("form", ["csv", "json", "table"])
def test_sass_query_prints_the_same_on_both_engines(initialised, capsys, form):
    text = "source = synthetic AND stature > 185 cm OR measure.stature > 1950 mm"
    printed = {}
    for engine, target in initialised.items():
        assert main(["query", "--format", form, "--db", target, text]) == 0
        printed[engine] = capsys.readouterr().out
    assert printed["postgresql"] == printed["sqlite"]
    assert printed["sqlite"].count("\n") > 3


def test_sass_person_prints_the_same_on_both_engines(initialised, capsys):
    # a synthetic person with strength experiments, an ANSUR II one by name in another case
    keys = ["17", "ansur ii m 10032"]
    printed = {}
    for engine, target in initialised.items():
        for form in ("json", "table"):
            assert main(["person", "--format", form, "--db", target, *keys]) == 0
        printed[engine] = capsys.readouterr().out
    assert printed["postgresql"] == printed["sqlite"]
    assert '"measures"' in printed["sqlite"] and "strength." in printed["sqlite"]
