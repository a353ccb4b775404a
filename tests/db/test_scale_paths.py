"""The column copy (sass_tui/db/accelerator.py) answers exactly as SQLite does,
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
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from sass_tui.db import accelerator, schema
from sass_tui.db.individual import fetch_individual
from sass_tui.db.query import CompiledQuery, Query, compile_query, run_query
from sass_tui.db.schema import (
    CENTER_OF_MASS_NAMES,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    QUERY_TABLES,
    QUIET_WHEN,
    SCHEMA_VERSION,
    STRENGTH_PARAMETERS,
    PeopleBatch,
    change_log_triggers,
    connect,
    delete_people,
    recreate_schema,
    store_people,
    transaction,
)
from sass_tui.model.strength import MOTION_NAMES
from sass_tui.model.vocabulary import PERSON_HANDEDNESS, STRENGTH_TYPES

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
    path = tmp_path_factory.mktemp("scale") / "generated.db"
    conn = connect(path, create=True)
    rng = np.random.default_rng(16)
    # ids with gaps, as after deletions and imports from several sources
    ids = np.sort(rng.choice(np.arange(1, 3 * PEOPLE), PEOPLE, replace=False))
    with transaction(conn):
        store_people(conn, generated_batch(rng, ids), replace=False)
    conn.close()
    return path


@pytest.fixture()
def accelerated(monkeypatch, tmp_path):
    """The accelerator answering on any size, its disk copies in tmp_path."""
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    monkeypatch.setattr(accelerator, "BACKGROUND", False)
    monkeypatch.setattr(accelerator, "CACHE_DIR", tmp_path / "columns")
    accelerator._STORES.clear()
    yield tmp_path / "columns"
    accelerator._STORES.clear()


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


def test_random_queries_agree(generated_db_file, tmp_path_factory, monkeypatch):
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    monkeypatch.setattr(accelerator, "BACKGROUND", False)
    monkeypatch.setattr(accelerator, "CACHE_DIR", tmp_path_factory.mktemp("columns"))
    accelerator._STORES.clear()
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
        accelerator._STORES.clear()


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
    accelerator._STORES.clear()  # as a new process: only the disk copy is left
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled) > before


def test_disk_copy_is_reused_by_the_next_process(db, accelerated):
    compiled = compile_query(SAMPLE)
    expected = accelerator.count(db, compiled)
    copies = sorted(p.name for p in accelerated.rglob("*.npy"))
    assert "person.gender.npy" in copies and "q_girth_right_upper_arm.z.npy" in copies
    accelerator._STORES.clear()
    assert accelerator.count(db, compiled) == expected
    assert sorted(p.name for p in accelerated.rglob("*.npy")) == copies


def test_damaged_disk_copy_is_rebuilt(db, accelerated):
    compiled = compile_query(SAMPLE)
    expected = accelerator.count(db, compiled)
    (column,) = accelerated.rglob("q_girth_right_upper_arm.z.npy")
    column.write_bytes(column.read_bytes()[:200])  # cut short
    (words,) = accelerated.rglob("person.gender.json")
    words.write_text("not json")
    accelerator._STORES.clear()
    assert accelerator.count(db, compiled) == expected == sqlite_count(db, compiled)
    (column,) = accelerated.rglob("q_girth_right_upper_arm.z.npy")
    assert len(np.load(column)) == PEOPLE  # written again, whole


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


def test_sql_it_does_not_understand_is_answered_by_sqlite(db):
    plain = compile_query("stature > 170 cm")
    for where, params in (
        ("NOT (p.stature > ?)", (170.0,)),
        ("p.stature > ? + 1", (170.0,)),
        ("p.stature > ?", ()),
        ("p.stature > ? OR p.name LIKE ?", (170.0, "P1%")),
        ("p.name > ?", (170.0,)),
        ("p.id_num > ?", (10,)),
    ):
        odd = CompiledQuery(plain.text, where, params, plain.tables)
        assert accelerator.count(db, odd) is None, where
    long_join = CompiledQuery("", "t0.thickness > ?", (10.0,), (("t0", "girth"),))
    assert accelerator.count(db, long_join) is None


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
    elif kind == "bulk replace":  # the same, by the large-write path: triggers dropped
        threshold = schema.DROP_TRIGGERS_FROM
        schema.DROP_TRIGGERS_FROM = 1
        try:
            with transaction(conn):
                store_people(conn, generated_batch(rng, np.array(sorted(some), dtype=np.int64)))
                delete_people(conn, some[: len(some) // 2])
        finally:
            schema.DROP_TRIGGERS_FROM = threshold
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
    """After any sequence of writes, every count and id list from the copy is
    SQLite's; and the copy is rebuilt only after `db init` (every other write
    is followed through the change log)."""
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    monkeypatch.setattr(accelerator, "BACKGROUND", False)
    builds = []
    base = accelerator._base
    monkeypatch.setattr(accelerator, "_base", lambda *a: builds.append(1) or base(*a))

    @settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
    @given(st.lists(WRITES, min_size=1, max_size=6), st.integers(0, 2**32 - 1))
    # Found by a run: a write by another connection once nobody is left.
    @example(steps=[("init", 1), ("delete", 4), ("sql delete", 1)], seed=0)
    def writes_agree(steps, seed):
        folder = tmp_path_factory.mktemp("writes")
        monkeypatch.setattr(accelerator, "CACHE_DIR", folder / "columns")
        accelerator._STORES.clear()
        path = folder / "small.db"
        shutil.copyfile(small_db_file, path)
        conn = connect(path)
        rng = np.random.default_rng(seed)
        try:
            assert_copy_is_sqlite(conn)
            for step in steps:
                builds.clear()
                if step[0] == "new process":  # a write, then a new process: the disk copy is older
                    _write(conn, path, ("sql update", step[1]), rng)
                    accelerator._STORES.clear()
                else:
                    _write(conn, path, step, rng)
                assert_copy_is_sqlite(conn)
                assert len(builds) == (step[0] == "init"), step
        finally:
            conn.close()
            accelerator._STORES.clear()

    writes_agree()


def test_a_small_write_is_followed_without_reading_everything(db, monkeypatch):
    """After deleting and importing a few people, the copy re-reads those
    people only: no column is read whole again."""
    compiled = compile_query(SAMPLE)
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    whole_reads = []
    new_column = accelerator._new_column
    monkeypatch.setattr(
        accelerator, "_new_column", lambda *a: whole_reads.append(a[1:3]) or new_column(*a)
    )
    matching = accelerator.ids(db, compiled)
    with transaction(db):
        delete_people(db, matching[:3])
        store_people(db, generated_batch(np.random.default_rng(5), np.arange(200_001, 200_004)))
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    assert accelerator.ids(db, compiled) == sqlite_ids(db, compiled)
    assert whole_reads == []


def test_a_rebuild_runs_in_the_background_while_sqlite_answers(db, monkeypatch):
    monkeypatch.setattr(accelerator, "BACKGROUND", True)
    compiled = compile_query(SAMPLE)
    assert accelerator.count(db, compiled) is None  # no copy yet: one is being built
    assert Query(db, compiled).count() == sqlite_count(db, compiled)
    accelerator.wait()
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    # a write during a build: whichever comes first, the answer is SQLite's
    other = compile_query("girth.neck.y > 20 cm")
    assert accelerator.count(db, other) is None  # this column is being read
    with transaction(db):
        delete_people(db, sqlite_ids(db, other)[:5])
    accelerator.wait()
    assert accelerator.count(db, other) == sqlite_count(db, other)
    # `db init`: the log cannot say what changed; SQLite answers until the copy is rebuilt
    with transaction(db, "EXCLUSIVE"):
        recreate_schema(db)
        store_people(db, generated_batch(np.random.default_rng(9), np.arange(1, 101)))
    assert accelerator.count(db, compiled) is None
    assert Query(db, compiled).count() == sqlite_count(db, compiled)
    accelerator.wait()
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)


@pytest.mark.slow
def test_a_schema_2_database_gets_the_change_log(db):
    path = accelerator.database_path(db)
    raw = sqlite3.connect(path, isolation_level=None)
    for (name,) in raw.execute(
        "SELECT name FROM sqlite_master WHERE type = 'trigger' AND name LIKE 'log%'"
    ).fetchall():
        raw.execute(f"DROP TRIGGER {name}")
    raw.executescript(
        "DROP TRIGGER change_note_insert; DROP VIEW change_note; DROP TABLE change_log;"
        "DROP TABLE change_gens; DROP TABLE change_bulk; DROP TABLE change_schema;"
        "UPDATE meta SET value = '2' WHERE key = 'schema_version';"
    )
    raw.close()
    conn = connect(path)
    try:
        assert conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone() == (
            SCHEMA_VERSION,
        )
        assert accelerator._has_change_log(conn)
        assert_copy_is_sqlite(conn)
    finally:
        conn.close()


def test_a_schema_3_database_gets_the_quiet_triggers(db):
    """Schema 3's triggers logged every row, with no way to keep them quiet:
    opened, the file gets schema 4's, and a bulk import is then logged once."""
    path = accelerator.database_path(db)
    raw = sqlite3.connect(path, isolation_level=None)
    raw.execute("BEGIN")
    raw.execute("DROP TRIGGER change_note_insert")
    raw.execute(change_log_triggers()["change_note_insert"].replace(f"{QUIET_WHEN}AND ", ""))
    raw.execute("DROP TABLE change_bulk")
    raw.execute("UPDATE meta SET value = '3' WHERE key = 'schema_version'")
    raw.execute("COMMIT")
    raw.close()
    conn = connect(path)
    try:
        assert conn.execute("SELECT value FROM meta WHERE key = 'schema_version'").fetchone() == (
            SCHEMA_VERSION,
        )
        assert accelerator._has_change_log(conn)
        assert_copy_is_sqlite(conn)
        with transaction(conn):
            store_people(conn, generated_batch(np.random.default_rng(3), np.arange(1, 40)))
        assert_copy_is_sqlite(conn)
    finally:
        conn.close()


def test_a_missing_trigger_means_no_following(db, monkeypatch):
    """A file whose log is not whole is copied again after every write."""
    db.execute("DROP TRIGGER log_q_girth_neck_update")
    assert not accelerator._has_change_log(db)
    compiled = compile_query("girth.neck.x > 20 cm")
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    db.execute("UPDATE q_girth_neck SET x = 99 WHERE x < 20")
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)


def test_query_lists_are_found_by_the_copy(db, monkeypatch):
    """The query screen's list (QueryLists.run) takes its people from the
    copy: the same people, in the same order, as SQLite, selected people left
    out, and after a write as well."""
    from sass_tui.db.lists import QUERY_LIST, SELECTED_LIST, QueryLists

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


@settings(max_examples=300, deadline=None)
@given(
    st.sets(st.integers(0, 60), max_size=30),
    st.sets(st.integers(0, 60), max_size=20),
    st.data(),
)
@pytest.mark.slow
def test_splicing_the_ids_is_the_set_change(old, changed, data):
    """The patch's splice: the old ids, less every changed id, plus the changed
    ids still stored, in order; the values keep their ids."""
    present = data.draw(st.sets(st.sampled_from(sorted(changed)))) if changed else set()
    old_ids = np.array(sorted(old), dtype=np.int64)
    changed_ids = np.array(sorted(changed), dtype=np.int64)
    present_ids = np.array(sorted(present), dtype=np.int64)
    at, was_there = accelerator._positions(old_ids, changed_ids)
    plan = accelerator._splice_plan(
        at[was_there], np.searchsorted(old_ids, present_ids), len(old_ids)
    )
    new_ids = accelerator._splice(old_ids, plan, present_ids)
    assert new_ids.tolist() == sorted((old - changed) | present)
    values = accelerator._splice(old_ids * 10.0, plan, np.full(len(present_ids), np.nan))
    assert [v == i * 10.0 for i, v in zip(new_ids, values)] == [
        i not in changed for i in new_ids.tolist()
    ]


# --- bulk writes: the triggers quiet, each person logged once (schema 4) ------


@pytest.fixture(params=["flag", "dropped triggers"])
def bulk(request, monkeypatch):
    """Each bulk path: the quiet flag (small writes), or the per-row triggers
    dropped and created again (from DROP_TRIGGERS_FROM people, here 1); the
    copy must follow either by the log, never rebuild (`builds`)."""
    threshold = 10**9 if request.param == "flag" else 1
    monkeypatch.setattr(schema, "DROP_TRIGGERS_FROM", threshold)
    builds: list[int] = []
    base = accelerator._base
    monkeypatch.setattr(accelerator, "_base", lambda *a: builds.append(1) or base(*a))
    return threshold, builds


def _instructions(conn: sqlite3.Connection, write) -> int:
    """SQLite VM instructions (in hundreds) a write runs: its work without a clock."""
    count = [0]

    def tick() -> int:
        count[0] += 1
        return 0

    conn.set_progress_handler(tick, 100)
    try:
        write()
    finally:
        conn.set_progress_handler(None, 100)
    return count[0]


def test_a_bulk_write_skips_the_per_row_log_and_the_copy_follows(db, monkeypatch):
    """store_people keeps the triggers quiet and logs each person once: about
    three quarters of the SQLite work of logging every row (the triggers still
    of an import), and the copy follows it by the log (no rebuild)."""
    compiled = compile_query(SAMPLE)
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    builds = []
    base = accelerator._base
    monkeypatch.setattr(accelerator, "_base", lambda *a: builds.append(1) or base(*a))

    def store(first: int) -> None:
        with transaction(db):
            batch = generated_batch(np.random.default_rng(first), np.arange(first, first + 200))
            store_people(db, batch)

    quiet = _instructions(db, lambda: store(300_001))
    assert db.execute("SELECT count(*) FROM change_bulk").fetchone() == (0,)
    assert_copy_is_sqlite(db)
    with monkeypatch.context() as m:  # every row logged by its trigger, as schema 3 did
        m.setattr(schema.logged_once, "__enter__", lambda self: None)
        per_row = _instructions(db, lambda: store(400_001))
    assert_copy_is_sqlite(db)
    assert quiet < 0.8 * per_row, (quiet, per_row)
    assert builds == []
    logged = db.execute("SELECT count(*) FROM change_log WHERE id_num >= 300001").fetchone()
    assert logged == (400,)


def test_a_flat_file_import_then_an_accelerated_count_equals_sql(db, tmp_path, bulk):
    from big_flat_files import write_big_flat_files

    from sass_tui.db.flatfile import import_flat_files

    assert_copy_is_sqlite(db)
    bulk[1].clear()
    import_flat_files(db, write_big_flat_files(tmp_path / "flat", people=300))
    assert_copy_is_sqlite(db)
    import_flat_files(db, write_big_flat_files(tmp_path / "flat2", people=150))  # replaces
    assert_copy_is_sqlite(db)
    assert db.execute("SELECT count(*) FROM change_bulk").fetchone() == (0,)
    assert accelerator._has_change_log(db)
    assert bulk[1] == []  # followed by the log, not rebuilt


def test_an_ansur_import_then_an_accelerated_count_equals_sql(db, ansur_dir, bulk):
    from sass_tui.db.ansur import import_ansur

    assert_copy_is_sqlite(db)
    bulk[1].clear()
    import_ansur(db, [ansur_dir / "ANSUR_II_FEMALE_Public.csv"], label="test")
    for text in [*WRITE_QUERIES, "measure.stature > 160 cm AND gender = female"]:
        compiled = compile_query(text)
        assert accelerator.count(db, compiled) == sqlite_count(db, compiled), text
    assert bulk[1] == []


def test_an_import_cancelled_mid_write_leaves_copy_and_file_alike(db, tmp_path, bulk):
    from big_flat_files import write_big_flat_files

    from sass_tui.db.flatfile import import_flat_files
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
    assert db.execute("SELECT count(*) FROM change_bulk").fetchone() == (0,)
    assert accelerator._has_change_log(db)
    assert_copy_is_sqlite(db)


def test_a_failed_bulk_write_that_the_caller_commits_is_still_logged(db, bulk):
    """An error mid-write that the caller catches, then commits: what was
    written is in the file, and its people are in the log."""
    assert_copy_is_sqlite(db)
    fresh = np.arange(500_001, 500_051)
    batch = generated_batch(np.random.default_rng(8), fresh)
    batch.extra_girth = [(0, GIRTH_NAMES[0], 1.0, 2.0, 3.0, 4.0)]  # its girth row again
    with transaction(db):
        with pytest.raises(sqlite3.IntegrityError):
            store_people(db, batch)
    assert set(_people(db)) >= set(fresh.tolist())  # person rows committed
    assert db.execute("SELECT count(*) FROM change_bulk").fetchone() == (0,)
    assert accelerator._has_change_log(db)  # the dropped triggers are back
    assert_copy_is_sqlite(db)


def test_a_crash_mid_import_leaves_copy_and_file_alike(db, tmp_path, bulk):
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
        "from test_scale_paths import generated_batch\n"
        "from sass_tui.db import schema\n"
        "from sass_tui.db.schema import connect, store_people, transaction\n"
        f"schema.DROP_TRIGGERS_FROM = {bulk[0]}\n"
        "conn = connect(sys.argv[1])\n"
        "conn.execute('PRAGMA cache_size = 5')\n"  # pages spill to the file before COMMIT
        "batch = generated_batch(np.random.default_rng(4), np.arange(600_001, 600_301))\n"
        "ticks = [0]\n"
        "def crash():\n"
        "    ticks[0] += 1\n"
        "    if ticks[0] > 400:\n"
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
    assert db.execute("SELECT count(*) FROM change_bulk").fetchone() == (0,)
    assert accelerator._has_change_log(db)


@pytest.mark.slow
def test_a_bulk_write_of_many_people_fires_no_trigger_and_is_followed(db, monkeypatch):
    """From DROP_TRIGGERS_FROM people the per-row triggers are dropped for
    the write: under half the SQLite work of the quiet flag's path, and the
    copy accepts the schema cookie's recorded move (no rebuild)."""
    compiled = compile_query(SAMPLE)
    assert accelerator.count(db, compiled) == sqlite_count(db, compiled)
    builds = []
    base = accelerator._base
    monkeypatch.setattr(accelerator, "_base", lambda *a: builds.append(1) or base(*a))
    batch = generated_batch(np.random.default_rng(12), np.arange(700_001, 702_001))

    def store(first: int) -> None:
        batch.id_num = np.arange(first, first + len(batch))
        with transaction(db):
            store_people(db, batch)

    monkeypatch.setattr(schema, "DROP_TRIGGERS_FROM", 10**9)
    flagged = _instructions(db, lambda: store(700_001))
    monkeypatch.setattr(schema, "DROP_TRIGGERS_FROM", 2000)
    cookie = schema.schema_cookie(db)
    dropped = _instructions(db, lambda: store(710_001))
    assert schema.schema_cookie(db) > cookie
    assert db.execute("SELECT to_cookie FROM change_schema WHERE from_cookie = ?", (cookie,))
    assert accelerator._has_change_log(db)
    assert_copy_is_sqlite(db)
    assert builds == []
    assert dropped < 0.8 * flagged, (dropped, flagged)


def test_a_trigger_dropped_and_created_again_by_another_program_means_a_rebuild(db, monkeypatch):
    """A schema change that no bulk write recorded (another program dropped a
    trigger, wrote, and created it again): the log may miss that write."""
    assert_copy_is_sqlite(db)
    builds = []
    base = accelerator._base
    monkeypatch.setattr(accelerator, "_base", lambda *a: builds.append(1) or base(*a))
    other = sqlite3.connect(accelerator.database_path(db), isolation_level=None)
    sql = other.execute(
        "SELECT sql FROM sqlite_master WHERE name = 'log_person_update'"
    ).fetchone()[0]
    other.execute("DROP TRIGGER log_person_update")
    other.execute("UPDATE person SET gender = 'female' WHERE gender = 'male' AND id_num % 4 = 1")
    other.execute(sql)
    other.close()
    assert accelerator._has_change_log(db)
    assert_copy_is_sqlite(db)
    assert builds == [1]


def test_a_committed_quiet_flag_stops_the_following(db):
    """Another program that commits a row in change_bulk keeps the triggers
    quiet for every writer: the copy no longer trusts the log."""
    assert_copy_is_sqlite(db)
    other = sqlite3.connect(accelerator.database_path(db), isolation_level=None)
    other.execute("INSERT INTO change_bulk VALUES (1)")
    other.execute("UPDATE person SET gender = 'female' WHERE gender = 'male' AND id_num % 3 = 0")
    other.close()
    assert not accelerator._has_change_log(db)
    assert_copy_is_sqlite(db)


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
