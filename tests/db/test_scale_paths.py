"""The DuckDB column copy (sass_tui/db/query/accelerator.py) answers exactly as SQLite does,
and never out of step with the SQLite file after a write.

A generated database of 3,000 people with every group, NULLs and missing
rows; the accelerator's size threshold is lowered to 0 so it answers here.
"""

from __future__ import annotations

import shutil
import sqlite3
from pathlib import Path

import numpy as np
import pytest
from _built_once import built_once
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from sass_tui.db.engine.schema import (
    CENTER_OF_MASS_NAMES,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    QUERY_TABLES,
    STRENGTH_PARAMETERS,
    connect,
    recreate_schema,
    transaction,
)
from sass_tui.db.people.individual import fetch_individual
from sass_tui.db.people.people_store import PeopleBatch, delete_people, store_people
from sass_tui.db.query import accelerator, column_copy, copy_file
from sass_tui.db.query.query import CompiledQuery, Query, compile_query, run_query
from sass_tui.model.strength.strength import MOTION_NAMES
from sass_tui.model.vocabulary import PERSON_HANDEDNESS, STRENGTH_TYPES

pytestmark = pytest.mark.sqlite_only("the DuckDB column copy of a SQLite file")

PEOPLE = 3000


def generated_batch(rng: np.random.Generator, ids: np.ndarray) -> PeopleBatch:
    n = len(ids)

    def holes(values: np.ndarray, share: float) -> np.ndarray:
        values[rng.random(values.shape) < share] = np.nan
        return values

    handedness = [
        None if r < 0.05 else PERSON_HANDEDNESS[int(r * 100) % 3] for r in rng.random(n).tolist()
    ]
    strength_par, shoulder, elbow, wrist = [], [], [], []
    for i in range(n):
        for exp in range(1, int(rng.integers(0, 3)) + 1):
            kind = STRENGTH_TYPES[int(rng.integers(0, 3))]
            speed = float(rng.choice([0.0, 30.0, 60.0, 180.0]))
            strength_par.append((i, exp, "right", kind, speed, float(rng.integers(0, 4)), 1.0))
            p, q = (rng.gamma(4.0, 12.0, 2)).round(1).tolist()
            elbow.append((i, exp, 90.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, p, None if q < 20 else q))
            for axis in "xyz":
                if rng.random() < 0.7:
                    a, b = rng.gamma(5.0, 10.0, 2).round(1).tolist()
                    shoulder.append((i, exp, 0.0, 0.0, 0.0, 90.0, axis, a, b))
                if rng.random() < 0.5:
                    a, b = rng.gamma(2.0, 4.0, 2).round(2).tolist()
                    wrist.append((i, exp, 0.0, 0.0, 0.0, 90.0, axis, a, b))
    girth = holes(rng.normal(20.0, 8.0, (n, len(GIRTH_NAMES), 4)).round(1), 0.03)
    joint_limits = holes(rng.normal(60.0, 40.0, (n, len(JOINT_LIMIT_NAMES), 3)).round(0), 0.05)
    center_of_mass = holes(rng.normal(5.0, 3.0, (n, len(CENTER_OF_MASS_NAMES), 3)).round(2), 0.05)
    joint_limits[rng.random(n) < 0.3] = np.nan  # people without any joint limits
    return PeopleBatch(
        id_num=ids,
        name=[f"P{i}" for i in ids.tolist()],
        gender=["male" if r < 0.5 else "female" for r in rng.random(n).tolist()],
        stature=holes(rng.normal(172.0, 9.0, n).round(1), 0.02),
        mass=holes(rng.normal(75.0, 12.0, n).round(1), 0.02),
        handedness=handedness,
        age=holes(rng.integers(18, 60, n).astype(float), 0.02),
        source=["generated test"] * n,
        source_key=[None] * n,
        girth=girth,
        joint_limits=joint_limits,
        center_of_mass=center_of_mass,
        strength_par=strength_par,
        shoulder=shoulder,
        elbow=elbow,
        wrist=wrist,
    )


@pytest.fixture(scope="session")
def generated_db_file(tmp_path_factory) -> Path:
    """PEOPLE generated people, built once a run (tests/_built_once.py); never written."""

    def build(folder: Path) -> None:
        conn = connect(folder / "generated.db", create=True)
        rng = np.random.default_rng(16)
        # ids with gaps, as after deletions and imports from several sources
        ids = np.sort(rng.choice(np.arange(1, 3 * PEOPLE), PEOPLE, replace=False))
        with transaction(conn):
            store_people(conn, generated_batch(rng, ids), replace=False)
        conn.close()

    return built_once(tmp_path_factory, "scale", build) / "generated.db"


@pytest.fixture()
def accelerated(monkeypatch, tmp_path):
    """The accelerator answering on any size, its disk copies in tmp_path."""
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    monkeypatch.setattr(copy_file, "BACKGROUND", False)
    monkeypatch.setattr(copy_file, "CACHE_DIR", tmp_path / "columns")
    copy_file.OPEN_COPIES.clear()
    yield tmp_path / "columns"
    copy_file.OPEN_COPIES.clear()


@pytest.fixture()
def db(generated_db_file, tmp_path, accelerated):
    copy = tmp_path / "generated.db"
    shutil.copyfile(generated_db_file, copy)
    conn = connect(copy)
    yield conn
    conn.close()


def sqlite_count(conn: sqlite3.Connection, compiled: CompiledQuery) -> int:
    sql = f"SELECT count(*) FROM {compiled.from_clause()} WHERE {compiled.where}"
    return conn.execute(sql, compiled.params).fetchone()[0]


def sqlite_ids(conn: sqlite3.Connection, compiled: CompiledQuery) -> list[int]:
    sql = f"SELECT p.id_num FROM {compiled.from_clause()} WHERE {compiled.where} ORDER BY p.id_num"
    return [r[0] for r in conn.execute(sql, compiled.params)]


def assert_same(conn: sqlite3.Connection, text: str) -> int:
    compiled = compile_query(text)
    expected = sqlite_count(conn, compiled)
    assert accelerator.count(conn, compiled) == expected, text
    assert accelerator.ids(conn, compiled) == sqlite_ids(conn, compiled), text
    assert run_query(conn, text).count() == expected
    return expected


QUERIES = [
    "gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb",
    "gender = female",
    "gender != male",
    "handedness = left OR handedness = either",
    "handedness != right",
    "stature > 70 in",
    "stature <= 172 cm AND mass >= 70 kg",
    "stature = 172 cm",
    "stature != 172 cm",
    "age < 30 OR age >= 50",
    "age != 40",
    "mass > 80 kg OR (gender = female AND stature > 175 cm)",
    "strength_type = isokinetic",
    "strength_type != isometric",
    "motion_speed > 30 deg/s",
    "motion_speed = 0",
    "training_level >= 2 OR fatigue_level < 2",
    "fatigue_level != 1",
    "girth.neck.x < 15 cm AND girth.neck.y > 20 cm",
    "girth.bottom_head.z != 20 cm",
    "joint_limit.right_shoulder_ul.x > 60 OR joint_limit.left_hip_ll.z <= 0",
    "joint_limit.right_shoulder_ul.y != 60",
    "center_of_mass.bottom_head.y > 5 cm",
    "center_of_mass.bottom_head.y >= 5 cm AND center_of_mass.bottom_head.x <= 5 cm",
    "strength.shoulder_abduction.max > 50 N-m",
    "strength.elbow_extension.max != 40 N-m",
    "strength.wrist_flexion.max > 5 ft-lb AND (gender = male OR age > 40)",
    "((gender = male) AND ((stature > 170 cm)))",
    "gender = male AND gender = female",
    "stature > 1000 cm",
    "(gender = male OR handedness = left) AND (girth.neck.x > 20 cm OR strength.elbow_flexion.max < 30 N-m)",
]


@pytest.mark.parametrize("text", QUERIES)
def test_copy_counts_and_lists_as_sqlite(db, text):
    assert_same(db, text)


@pytest.mark.slow
def test_the_queries_reach_every_group(db):
    """Guard against a vacuous comparison: most queries match some people, not all."""
    counts = [assert_same(db, text) for text in QUERIES]
    assert sum(0 < c < PEOPLE for c in counts) >= len(QUERIES) - 3


# Fields and the values their comparisons take: stored values (so = and !=
# meet real ties) and values around them.
FIELDS = (
    [("gender", w) for w in ("male", "female")]
    + [("handedness", w) for w in PERSON_HANDEDNESS]
    + [("strength_type", w) for w in STRENGTH_TYPES]
    + [(f, None) for f in ("stature", "mass", "age", "motion_speed", "training_level")]
    + [(f"girth.{GIRTH_NAMES[k]}.{a}", None) for k in (0, 7, 24) for a in "xyz"]
    + [(f"joint_limit.{JOINT_LIMIT_NAMES[k]}.{a}", None) for k in (0, 39) for a in "xz"]
    + [(f"center_of_mass.{CENTER_OF_MASS_NAMES[k]}.y", None) for k in (0, 20)]
    + [(f"strength.{m}.max", None) for m in MOTION_NAMES[::3]]
)


@st.composite
def queries(draw, conn: sqlite3.Connection, depth: int = 0) -> str:
    if depth < 2 and draw(st.booleans()):
        parts = draw(st.lists(queries(conn, depth + 1), min_size=2, max_size=3))
        word = draw(st.sampled_from([" AND ", " OR "]))
        return "(" + word.join(parts) + ")"
    field, word = draw(st.sampled_from(FIELDS))
    if word is not None:
        return f"{field} {draw(st.sampled_from(['=', '!=']))} {word}"
    compiled = compile_query(f"{field} > 0")
    alias, column = compiled.where.strip("()").split(" ")[0].split(".")
    table = dict(compiled.tables).get(alias, "person")
    value = conn.execute(
        f"SELECT {column} FROM {table} WHERE {column} IS NOT NULL ORDER BY id_num LIMIT 1 OFFSET ?",
        (draw(st.integers(0, 500)),),
    ).fetchone()[0]
    op = draw(st.sampled_from(["<", ">", "<=", ">=", "=", "!="]))
    return f"{field} {op} {value!r}"


@pytest.mark.slow
def test_random_queries_agree(generated_db_file, tmp_path_factory, monkeypatch):
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    monkeypatch.setattr(copy_file, "BACKGROUND", False)
    monkeypatch.setattr(copy_file, "CACHE_DIR", tmp_path_factory.mktemp("columns"))
    copy_file.OPEN_COPIES.clear()
    conn = connect(generated_db_file)

    @settings(max_examples=80, deadline=None, suppress_health_check=list(HealthCheck))
    @given(queries(conn))
    def agree(text):
        compiled = compile_query(text)
        assert accelerator.count(conn, compiled) == sqlite_count(conn, compiled), text

    try:
        agree()
    finally:
        conn.close()
        copy_file.OPEN_COPIES.clear()


SAMPLE = (
    "gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb"
)


def test_answer_follows_writes_through_sass(db):
    compiled = compile_query(SAMPLE)
    before = accelerator.count(db, compiled)
    assert before == sqlite_count(db, compiled) > 0
    matching = accelerator.ids(db, compiled)
    with transaction(db):
        delete_people(db, matching[:10])
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled) == before - 10
    # new people, every one a match, stored under fresh ids
    rng = np.random.default_rng(7)
    batch = generated_batch(rng, np.arange(100_001, 100_051))
    batch.gender = ["male"] * 50
    batch.girth[:, GIRTH_NAMES.index("right_upper_arm"), 2] = 40.0
    batch.strength_par = [(i, 1, "right", "isometric", 0.0, 0.0, 0.0) for i in range(50)]
    batch.elbow = [(i, 1, 90.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 100.0, 50.0) for i in range(50)]
    batch.shoulder, batch.wrist = [], []
    with transaction(db):
        store_people(db, batch)
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled) == before + 40
    assert accelerator.ids(db, compiled)[-50:] == list(range(100_001, 100_051))


def test_answer_follows_a_write_from_another_connection(db):
    compiled = compile_query("stature > 180 cm")
    before = accelerator.count(db, compiled)
    path = accelerator.database_path(db)
    other = sqlite3.connect(path)
    other.execute("UPDATE person SET stature = 200.0 WHERE stature <= 180")
    other.commit()
    other.close()
    after = accelerator.count(db, compiled)
    assert after == sqlite_count(db, compiled) > before


def test_answer_follows_a_write_in_another_process_with_journal_off(db):
    """The copy on disk, written by one process, is not taken by the next after a write."""
    compiled = compile_query("girth.neck.x > 25 cm")
    before = accelerator.count(db, compiled)
    path = accelerator.database_path(db)
    other = sqlite3.connect(path, isolation_level=None)
    other.execute("PRAGMA journal_mode = OFF")
    other.execute("UPDATE q_girth_neck SET x = 30.0 WHERE x <= 25")
    other.close()
    copy_file.OPEN_COPIES.clear()  # as a new process: only the disk copy is left
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled) > before


def test_disk_copy_is_reused_by_the_next_process(db, accelerated):
    compiled = compile_query(SAMPLE)
    expected = accelerator.count(db, compiled)
    (copy,) = accelerated.rglob(copy_file.COPY_FILE)
    written = copy.stat().st_mtime_ns
    copy_file.OPEN_COPIES.clear()
    assert accelerator.count(db, compiled) == expected
    assert accelerator.last_answer == "copy"
    assert copy.stat().st_mtime_ns == written  # read, not written again


def test_damaged_disk_copy_is_rebuilt(db, accelerated):
    compiled = compile_query(SAMPLE)
    expected = accelerator.count(db, compiled)
    (copy,) = accelerated.rglob(copy_file.COPY_FILE)
    copy_file.OPEN_COPIES.clear()
    copy.write_bytes(copy.read_bytes()[:5000])  # cut short
    assert accelerator.count(db, compiled) == expected == sqlite_count(db, compiled)
    assert accelerator.last_answer == "copy"


def test_another_database_copied_over_the_file(db, tmp_path, generated_db_file):
    compiled = compile_query("gender = male")
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    path = accelerator.database_path(db)
    db.close()
    other = tmp_path / "other.db"
    shutil.copyfile(generated_db_file, other)
    conn = sqlite3.connect(other)
    conn.execute("UPDATE person SET gender = 'male'")
    conn.commit()
    conn.close()
    shutil.copyfile(other, path)
    conn = connect(path)
    try:
        assert accelerator.count(conn, compiled) == sqlite_count(conn, compiled) == PEOPLE
    finally:
        conn.close()


def test_own_uncommitted_write_is_seen(db):
    compiled = compile_query("gender = female")
    db.execute("BEGIN")
    db.execute("UPDATE person SET gender = 'female'")
    assert accelerator.count(db, compiled) is None  # the copy cannot know: SQLite answers
    assert Query(db, compiled).count() == PEOPLE
    db.execute("ROLLBACK")
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled) < PEOPLE


def test_wal_database_is_answered_by_sqlite(db):
    db.execute("PRAGMA journal_mode = WAL")
    compiled = compile_query(SAMPLE)
    assert accelerator.count(db, compiled) is None
    assert Query(db, compiled).count() == sqlite_count(db, compiled)


def test_values_of_another_type_are_answered_by_sqlite(db):
    compiled = compile_query("girth.neck.x > 25 cm")
    assert accelerator.count(db, compiled) is not None
    # SQLite keeps text in a REAL column, and text sorts above every number
    db.execute("UPDATE q_girth_neck SET x = 'wide' WHERE id_num = (SELECT min(id_num) FROM person)")
    assert accelerator.count(db, compiled) is None
    assert Query(db, compiled).count() == sqlite_count(db, compiled)
    compiled = compile_query("strength_type != isometric")
    db.execute(
        "UPDATE strength_q SET strength_type = x'00' WHERE id_num = (SELECT min(id_num) FROM strength_q)"
    )
    assert accelerator.count(db, compiled) is None
    assert Query(db, compiled).count() == sqlite_count(db, compiled)


def test_small_databases_do_not_use_the_copy(db, monkeypatch):
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 10 * PEOPLE)
    assert accelerator.count(db, compile_query("gender = male")) is None


def test_query_tables_cover_the_copy():
    """Every query table is one row per person (what the copy requires)."""
    assert all(
        table.startswith("q_") for group in QUERY_TABLES.values() for table in group.values()
    )


def test_fetched_strength_summary_is_the_query_tables(generated_db_file):
    """fetch_individual computes the strength summary from the experiments
    instead of reading strength_q and q_strength_*: the same numbers, for
    every person (with none, one or two experiments)."""
    conn = connect(generated_db_file)
    try:
        ids = [r[0] for r in conn.execute("SELECT id_num FROM person ORDER BY id_num")]
        with_strength = 0
        for id_num in ids:
            row = conn.execute(
                f"SELECT {', '.join(STRENGTH_PARAMETERS)} FROM strength_q WHERE id_num = ?",
                (id_num,),
            ).fetchone()
            expected = {}
            if row is not None:
                with_strength += 1
                expected = dict(zip(STRENGTH_PARAMETERS, row))
                for motion, table in QUERY_TABLES["strength"].items():
                    found = conn.execute(
                        f"SELECT max FROM {table} WHERE id_num = ?", (id_num,)
                    ).fetchone()
                    expected[f"{motion}_max"] = found[0] if found else None
            assert fetch_individual(conn, id_num).strength == expected, id_num
        assert 0 < with_strength < len(ids)
    finally:
        conn.close()


# --- following writes: the change log ----------------------------------------------

# Queries over every kind of table the log follows (person, text and numbers, the
# query tables, strength_q); each step of a write sequence checks all of them.
WRITE_QUERIES = [
    SAMPLE,
    "gender = female OR stature > 180 cm",
    "girth.neck.x > 20 cm",
    "strength_type = isokinetic OR handedness = left",
    "center_of_mass.bottom_head.y > 5 cm AND age < 40",
]
SMALL = 300


@pytest.fixture(scope="session")
def small_db_file(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("small") / "small.db"
    conn = connect(path, create=True)
    with transaction(conn):
        store_people(conn, generated_batch(np.random.default_rng(3), np.arange(1, SMALL + 1) * 3))
    conn.close()
    return path


def assert_copy_is_sqlite(conn: sqlite3.Connection) -> None:
    if not _people(conn):  # nobody: SQLite answers (and finds nobody)
        assert accelerator.count(conn, compile_query(SAMPLE)) is None
        return
    for text in WRITE_QUERIES:
        compiled = compile_query(text)
        assert accelerator.count(conn, compiled) == sqlite_count(conn, compiled), text
        assert accelerator.ids(conn, compiled) == sqlite_ids(conn, compiled), text


def _people(conn: sqlite3.Connection) -> list[int]:
    return [r[0] for r in conn.execute("SELECT id_num FROM person ORDER BY id_num")]


def _write(conn: sqlite3.Connection, path: Path, step: tuple, rng: np.random.Generator) -> None:
    """One write: through sass (delete, add, replace as a flat-file import
    does, db init) or by another connection in plain SQL."""
    kind, size = step
    people = _people(conn)
    some = [int(i) for i in rng.choice(people, min(size, len(people)), replace=False)]
    fresh = np.arange(size) + max(people + [0]) + 1
    if kind == "delete":
        with transaction(conn):
            delete_people(conn, some)
    elif kind == "add":
        with transaction(conn):
            store_people(conn, generated_batch(rng, fresh))
    elif kind == "replace":  # the same ids, other data (a flat-file import replaces)
        with transaction(conn):
            store_people(conn, generated_batch(rng, np.array(sorted(some), dtype=np.int64)))
    elif kind == "bulk replace":  # the same, and some deleted, in one transaction
        with transaction(conn):
            store_people(conn, generated_batch(rng, np.array(sorted(some), dtype=np.int64)))
            delete_people(conn, some[: len(some) // 2])
    elif kind == "init":  # `sass db init --force`, then a few people
        with transaction(conn, "EXCLUSIVE"):
            recreate_schema(conn)
            store_people(conn, generated_batch(rng, np.arange(1, 5 * size) * 7))
    elif some:  # another connection's write (nothing to do when nobody is left)
        other = sqlite3.connect(path, isolation_level=None)
        marks = ", ".join("?" * len(some))
        if kind == "sql update":
            other.execute(f"UPDATE person SET gender = 'female' WHERE id_num IN ({marks})", some)
            other.execute(f"UPDATE q_girth_neck SET x = x + 3 WHERE id_num IN ({marks})", some)
            other.execute(
                f"UPDATE strength_q SET strength_type = 'isokinetic' WHERE id_num IN ({marks})",
                some,
            )
        elif kind == "sql insert":  # query rows for people who had none, or new values
            other.executemany(
                "INSERT OR REPLACE INTO q_center_of_mass_bottom_head VALUES (?, 1, 9, 1)",
                [(i,) for i in some],
            )
        elif kind == "sql delete":
            other.execute(f"DELETE FROM q_girth_neck WHERE id_num IN ({marks})", some)
            other.execute("DELETE FROM person WHERE id_num = ?", some[:1])
        elif kind == "sql renumber":  # an UPDATE of the key itself: both ids change
            for i, new in zip(some, fresh.tolist()):
                other.execute("UPDATE q_girth_neck SET id_num = ? WHERE id_num = ?", (new, i))
                other.execute("UPDATE person SET id_num = ? WHERE id_num = ?", (new, i))
        other.close()


WRITES = st.tuples(
    st.sampled_from(
        ["delete", "add", "replace", "bulk replace", "sql update", "sql insert", "sql delete"]
        + ["sql renumber"]
        + ["init", "new process"]
    ),
    st.integers(1, 12),
)


@pytest.mark.slow
def test_random_writes_keep_the_copy_equal_to_sqlite(small_db_file, tmp_path_factory, monkeypatch):
    """After any sequence of writes, by sass or another program, every count
    and id list from the copy is SQLite's."""
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    monkeypatch.setattr(copy_file, "BACKGROUND", False)

    @settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
    @given(st.lists(WRITES, min_size=1, max_size=6), st.integers(0, 2**32 - 1))
    # Found by a run: a write by another connection once nobody is left.
    @example(steps=[("init", 1), ("delete", 4), ("sql delete", 1)], seed=0)
    def writes_agree(steps, seed):
        folder = tmp_path_factory.mktemp("writes")
        monkeypatch.setattr(copy_file, "CACHE_DIR", folder / "columns")
        copy_file.OPEN_COPIES.clear()
        path = folder / "small.db"
        shutil.copyfile(small_db_file, path)
        conn = connect(path)
        rng = np.random.default_rng(seed)
        try:
            assert_copy_is_sqlite(conn)
            for step in steps:
                if step[0] == "new process":  # a write, then a new process: the disk copy is older
                    _write(conn, path, ("sql update", step[1]), rng)
                    copy_file.OPEN_COPIES.clear()
                else:
                    _write(conn, path, step, rng)
                assert_copy_is_sqlite(conn)
        finally:
            conn.close()
            copy_file.OPEN_COPIES.clear()

    writes_agree()


def test_a_rebuild_runs_in_the_background_while_sqlite_answers(db, monkeypatch):
    monkeypatch.setattr(copy_file, "BACKGROUND", True)
    compiled = compile_query(SAMPLE)
    assert accelerator.count(db, compiled) is None  # no copy yet: one is being built
    assert Query(db, compiled).count() == sqlite_count(db, compiled)
    column_copy.wait()
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    # a write during a build: whichever comes first, the answer is SQLite's
    other = compile_query("girth.neck.y > 20 cm")
    assert accelerator.count(db, other) is None  # this column is being read
    with transaction(db):
        delete_people(db, sqlite_ids(db, other)[:5])
    column_copy.wait()  # the build may have read before the write: then a new build
    assert accelerator.count(db, other) in (None, sqlite_count(db, other))
    column_copy.wait()
    assert accelerator.count(db, other) == sqlite_count(db, other)
    # `db init`: SQLite answers until the copy is rebuilt
    with transaction(db, "EXCLUSIVE"):
        recreate_schema(db)
        store_people(db, generated_batch(np.random.default_rng(9), np.arange(1, 101)))
    assert accelerator.count(db, compiled) is None
    assert Query(db, compiled).count() == sqlite_count(db, compiled)
    column_copy.wait()
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)


def test_query_lists_are_found_by_the_copy(db, monkeypatch):
    """The query screen's list (QueryLists.run) takes its people from the
    copy: the same people, in the same order, as SQLite, selected people left
    out, and after a write as well."""
    from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists

    answered = []
    answer = accelerator.answer_in_transaction
    monkeypatch.setattr(
        accelerator,
        "answer_in_transaction",
        lambda *a, **k: (lambda r: answered.append(r is not None) or r)(answer(*a, **k)),
    )
    lists = QueryLists(db)

    def listed(which: str) -> list[int]:
        return [row["id"] for row in lists.page(which, 0, 10 * PEOPLE)]

    for text in QUERIES[:8]:
        compiled = compile_query(text)
        expected = sqlite_ids(db, compiled)
        assert lists.run(text) == len(expected) == lists.count(QUERY_LIST), text
        assert listed(QUERY_LIST) == expected, text
    assert answered and all(answered)
    lists.run(SAMPLE)
    chosen = listed(QUERY_LIST)[:5]
    for id_num in chosen:
        assert lists.select_one(id_num)
    with transaction(db):  # a write after the copy was made: followed
        delete_people(db, listed(QUERY_LIST)[:7])
    expected = [i for i in sqlite_ids(db, compile_query(SAMPLE)) if i not in chosen]
    assert lists.run(SAMPLE) == len(expected)
    assert listed(QUERY_LIST) == expected
    assert listed(SELECTED_LIST) == chosen
    assert answered[-1]


def test_a_flat_file_import_then_an_accelerated_count_equals_sql(db, tmp_path):
    from big_flat_files import write_big_flat_files

    from sass_tui.db.people.flatfile import import_flat_files

    assert_copy_is_sqlite(db)
    import_flat_files(db, write_big_flat_files(tmp_path / "flat", people=300))
    assert_copy_is_sqlite(db)
    import_flat_files(db, write_big_flat_files(tmp_path / "flat2", people=150))  # replaces
    assert_copy_is_sqlite(db)


def test_an_ansur_import_then_an_accelerated_count_equals_sql(db, ansur_dir):
    from sass_tui.db.people.ansur import import_ansur

    assert_copy_is_sqlite(db)
    import_ansur(db, [ansur_dir / "ANSUR_II_FEMALE_Public.csv"], label="test")
    for text in [*WRITE_QUERIES, "measure.stature > 160 cm AND gender = female"]:
        compiled = compile_query(text)
        assert accelerator.count(db, compiled) == sqlite_count(db, compiled), text


def test_an_import_cancelled_mid_write_leaves_copy_and_file_alike(db, tmp_path):
    from big_flat_files import write_big_flat_files

    from sass_tui.db.people.flatfile import import_flat_files
    from sass_tui.db.progress import Cancelled

    class Later:
        """Set at its fifth look while storing: mid-statement, inside store_people."""

        looks = 0

        def is_set(self) -> bool:
            if db.in_transaction:
                self.looks += 1
            return self.looks >= 5

    assert_copy_is_sqlite(db)
    files = write_big_flat_files(tmp_path / "flat", people=400)
    people = _people(db)
    with pytest.raises(Cancelled):
        import_flat_files(db, files, cancel=Later())
    assert _people(db) == people
    assert_copy_is_sqlite(db)


def test_a_crash_mid_import_leaves_copy_and_file_alike(db, tmp_path):
    """A process killed inside store_people, its pages already in the file:
    the next reader rolls the hot journal back, and the copy agrees."""
    import subprocess
    import sys

    assert_copy_is_sqlite(db)
    path = accelerator.database_path(db)
    people = _people(db)
    child = (
        "import os, sys\n"
        "import numpy as np\n"
        f"sys.path.insert(0, {str(Path(__file__).parent)!r})\n"
        f"sys.path.insert(0, {str(Path(__file__).parents[1])!r})\n"  # tests/_built_once.py
        "from test_scale_paths import generated_batch\n"
        "from sass_tui.db.people.people_store import store_people\n"
        "from sass_tui.db.engine.schema import connect, transaction\n"
        "conn = connect(sys.argv[1])\n"
        "conn.execute('PRAGMA cache_size = 5')\n"  # pages spill to the file before COMMIT
        "batch = generated_batch(np.random.default_rng(4), np.arange(600_001, 600_301))\n"
        "ticks = [0]\n"
        "def crash():\n"
        "    ticks[0] += 1\n"
        "    if ticks[0] > 3000:\n"
        "        os._exit(7)\n"
        "    return 0\n"
        "with transaction(conn):\n"
        "    conn.set_progress_handler(crash, 100)\n"
        "    store_people(conn, batch)\n"
        "sys.exit(0)\n"
    )
    done = subprocess.run([sys.executable, "-c", child, str(path)], capture_output=True, text=True)
    assert done.returncode == 7, done.stderr
    assert Path(f"{path}-journal").exists()  # a hot journal: the crash was mid-write
    assert_copy_is_sqlite(db)
    assert _people(db) == people


def test_an_individual_is_fetched_as_one_snapshot(db):
    """A write that another process tries to commit between two of
    fetch_individual's reads waits until the fetch is done: the person and
    their girth rows come from the same state of the file."""
    path = accelerator.database_path(db)
    pid = int(db.execute("SELECT id_num FROM girth GROUP BY id_num LIMIT 1").fetchone()[0])
    other = sqlite3.connect(path, isolation_level=None, timeout=0)
    refused = []

    def write_between(sql: str) -> None:
        if "FROM girth" in sql and not refused:
            try:
                other.execute("BEGIN IMMEDIATE")
                other.execute("DELETE FROM girth WHERE id_num = ?", (pid,))
                other.execute("COMMIT")
                refused.append(False)
            except sqlite3.OperationalError:
                other.execute("ROLLBACK")
                refused.append(True)

    db.set_trace_callback(write_between)
    try:
        person = fetch_individual(db, pid)
    finally:
        db.set_trace_callback(None)
        other.close()
    assert refused == [True]
    assert not np.isnan(person.groups["girth"]).all()  # the rows as the person was read
    assert not db.in_transaction


def test_an_individual_fetched_inside_a_transaction_leaves_it_open(db):
    pid = int(db.execute("SELECT min(id_num) FROM person").fetchone()[0])
    with transaction(db):
        db.execute("UPDATE person SET name = 'renamed' WHERE id_num = ?", (pid,))
        assert fetch_individual(db, pid).name == "renamed"  # its own write, seen
        assert db.in_transaction
    assert fetch_individual(db, pid).name == "renamed"
