"""ANSUR II in the default database: the shipped files, the 93 measurements,
the survey's attributes and the query language, checked against a direct
computation over the published CSV files in ../shared (csv module only), on
both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import gzip
import time

import numpy as np
import pytest
from _paths import DATASETS

from sass_tui.db.engine.dialect import mark_of
from sass_tui.db.people.values import load_values
from sass_tui.db.query.query import QueryError, compile_query, field_names, run_query
from sass_tui.model.measures import MEASURE_UNITS, MEASURES

FILES = ("ANSUR_II_MALE_Public.csv", "ANSUR_II_FEMALE_Public.csv")


@pytest.fixture(scope="module")
def survey(ansur_dir) -> list[dict[str, str]]:
    """Every subject as published, keys lower case, plus the name sass gives them."""
    rows = []
    for name in FILES:
        with (ansur_dir / name).open(encoding="cp1252", newline="") as handle:
            for row in csv.DictReader(handle):
                row = {k.lower(): v for k, v in row.items()}
                letter = "M" if row["gender"] == "Male" else "F"
                row["name"] = f"ANSUR II {letter} {row['subjectid']}"
                rows.append(row)
    return rows


@pytest.mark.parametrize("name", FILES)
def test_shipped_files_are_the_published_ones(ansur_dir, name):
    shipped = DATASETS / "ansur2" / f"{name}.gz"
    assert gzip.decompress(shipped.read_bytes()) == (ansur_dir / name).read_bytes()


def test_measure_table_has_one_column_per_measure(engine_db):
    columns = [d[0] for d in engine_db.execute("SELECT * FROM measure LIMIT 0").description]
    assert columns == ["id_num", *MEASURES]


def _stored(conn, survey_row, *columns):
    """The person's stored values of these measure columns (one value for one column)."""
    row = conn.execute(
        f"SELECT {', '.join(f'm.{c}' for c in columns)} FROM measure m "
        f"JOIN person p ON p.id_num = m.id_num WHERE p.name = {mark_of(conn)}",
        (survey_row["name"],),
    ).fetchone()
    return row[0] if len(columns) == 1 else tuple(row)


def test_every_measure_is_stored_in_canonical_units(engine_db, survey):
    for row in survey[:: len(survey) // 25]:
        stored = _stored(engine_db, row, *MEASURES)
        for name, value in zip(MEASURES, stored, strict=True):
            published = float(row[name])
            expected = published / 10 if name != "interpupillarybreadth" else published / 100
            assert value == pytest.approx(expected, abs=1e-9), name


def test_tenth_units_convert(engine_db, survey):
    """weightkg is published in 0.1 kg, interpupillarybreadth in 0.1 mm."""
    first = survey[0]
    assert first["weightkg"] == "815" and first["interpupillarybreadth"] == "685"
    assert _stored(engine_db, first, "weightkg") == pytest.approx(81.5)
    assert _stored(engine_db, first, "interpupillarybreadth") == pytest.approx(6.85)
    mass = engine_db.execute(
        f"SELECT mass FROM person WHERE name = {mark_of(engine_db)}", (first["name"],)
    )
    assert mass.fetchone()[0] == pytest.approx(81.5)
    weights = [float(r["weightkg"]) / 10 for r in survey]
    assert 35 < min(weights) and max(weights) < 150  # kg, not 0.1 kg or g
    ipd = [float(r["interpupillarybreadth"]) / 100 for r in survey]
    assert 5 < min(ipd) and max(ipd) < 8  # cm: 0.1 mm / 100


def _count(rows, predicate) -> int:
    return sum(1 for r in rows if predicate(r))


CASES = [
    ("measure.sittingheight > 95 cm", lambda r: float(r["sittingheight"]) > 950),
    ("measure.weightkg < 80 kg", lambda r: float(r["weightkg"]) < 800),
    ("measure.interpupillarybreadth >= 6.5 cm", lambda r: float(r["interpupillarybreadth"]) >= 650),
    ("measure.span > 75 in", lambda r: float(r["span"]) > 75 * 25.4),
    ("measure.footlength <= 250 mm", lambda r: float(r["footlength"]) <= 250),
    ("age < 25", lambda r: float(r["age"]) < 25),
    ("age >= 40 AND gender = female", lambda r: float(r["age"]) >= 40 and r["gender"] == "Female"),
    ("component = 'Army National Guard'", lambda r: r["component"] == "Army National Guard"),
    ("branch = 'Combat Arms'", lambda r: r["branch"] == "Combat Arms"),
    ('branch = "combat support"', lambda r: r["branch"] == "Combat Support"),
    ("branch != 'COMBAT ARMS'", lambda r: r["branch"] != "Combat Arms"),
    ("writingpreference = left", lambda r: r["writingpreference"] == "Left hand"),
    ("dodrace = 2", lambda r: r["dodrace"] == "2"),
    ("subjectnumericrace = 1", lambda r: r["subjectnumericrace"] == "1"),
    ("ethnicity = 'mexican'", lambda r: r["ethnicity"] == "Mexican"),
    (
        "gender = male AND measure.stature > 180 cm AND branch = 'Combat Arms'",
        lambda r: (
            r["gender"] == "Male" and float(r["stature"]) > 1800 and r["branch"] == "Combat Arms"
        ),
    ),
]


@pytest.mark.parametrize("text, predicate", CASES, ids=[c[0] for c in CASES])
def test_query_counts_match_the_csv(engine_db, survey, text, predicate):
    expected = _count(survey, predicate)
    assert expected > 0
    assert run_query(engine_db, f"source = ansur2 AND ({text})").count() == expected


def test_source_labels(engine_db, survey):
    assert run_query(engine_db, "source = ansur2").count() == len(survey) == 6068
    assert run_query(engine_db, "source = 'ANSUR2'").count() == 6068
    synthetic = run_query(engine_db, "source = synthetic").count()
    assert synthetic == 200
    virtual = run_query(engine_db, 'source = "virtual:nhanes-2017-2020"').count()
    assert virtual == 8381  # the shipped virtual population sass db init stores
    # without a source term a query reaches the real people only; any source term, everyone
    assert run_query(engine_db, "stature > 0 cm").count() == 6068
    everyone = run_query(engine_db, "stature > 0 cm AND source != none").count()
    assert everyone == 6068 + synthetic + virtual


@pytest.mark.parametrize(
    "text, fragment, column",
    [
        ("measure.sittinghieght > 90 cm", "did you mean sittingheight", 9),
        ("measure.Stature > 1 kg", "kg is not a unit of length", 21),
        ("measure.nosuch > 1", "unknown measurement 'nosuch'", 9),
        ("measure > 1", "expected measure.NAME", 1),
        ("branch > 'Combat Arms'", "only be compared with = or !=", 8),
        ("branch = 3", "needs a text value in quotes", 10),
        ("gender = 'males'", "gender is one of male, female", 10),
    ],
)
def test_query_errors_name_the_column(text, fragment, column):
    with pytest.raises(QueryError) as caught:
        compile_query(text)
    assert fragment in str(caught.value)
    assert caught.value.column == column


def test_quoted_words_are_accepted_for_choices(engine_db):
    assert (
        run_query(engine_db, "gender = 'FEMALE'").count()
        == run_query(engine_db, "gender = female").count()
    )


def test_quoted_text_is_never_sql(engine_db):
    before = engine_db.execute("SELECT count(*) FROM person").fetchone()[0]
    query = run_query(engine_db, "branch = 'x\"; DROP TABLE person; --'")
    assert query.count() == 0
    assert engine_db.execute("SELECT count(*) FROM person").fetchone()[0] == before


def test_field_names_cover_every_measure():
    names = dict(field_names())
    for name in MEASURES:
        assert names[f"measure.{name}"] == MEASURE_UNITS[name]
    assert names["branch"] == "text" and names["stature"] == "cm"
    for name in names:
        if names[name] != "text":
            compile_query(f"{name} > 0")


def test_load_values_equals_the_csv(engine_db, survey):
    fields = ["stature", "mass", "age", *(f"measure.{m}" for m in MEASURES)]
    start = time.perf_counter()
    values = load_values(engine_db, fields, "source = ansur2")
    elapsed = time.perf_counter() - start
    assert values.matrix.shape == (6068, len(fields))
    by_name = {r["name"]: r for r in survey}
    for k in range(0, 6068, 97):
        row = by_name[values.names[k]]
        assert values.genders[k] == row["gender"].lower()
        expected = [float(row["stature"]) / 10, float(row["weightkg"]) / 10, float(row["age"])]
        expected += [
            float(row[m]) / (100 if m == "interpupillarybreadth" else 10) for m in MEASURES
        ]
        assert values.matrix[k] == pytest.approx(expected)
    assert values.units[:3] == ("cm", "kg", "")
    assert elapsed < 5  # a sanity bound; the speed is measured in benchmarks/


def test_load_values_of_unmeasured_people_are_nan(engine_db):
    values = load_values(
        engine_db,
        ["measure.sittingheight", "girth.right_upper_arm.z", "center_of_mass.right_foot.x"],
        "source = synthetic",
    )
    assert len(values) == 200
    assert np.isnan(values.matrix[:, 0]).all()
    assert not np.isnan(values.matrix[:, 1]).any()
    assert not np.isnan(values.matrix[:, 2]).all()


def test_load_values_follow_changes_made_behind_the_packed_rows(engine_db_copy):
    """An UPDATE of measure by plain SQL must not leave load_values stale (on
    SQLite, behind its packed rows)."""
    conn = engine_db_copy
    first = conn.execute("SELECT min(id_num) FROM measure").fetchone()[0]
    conn.execute(
        f"UPDATE measure SET sittingheight = 12.5 WHERE id_num = {mark_of(conn)}", (first,)
    )
    values = load_values(conn, ["measure.sittingheight", "measure.stature"], "source = ansur2")
    index = list(values.ids).index(first)
    assert values.matrix[index, 0] == 12.5
    assert values.matrix[index, 1] > 140


def test_load_values_refuses_text_fields_and_unknown_names(engine_db):
    with pytest.raises(QueryError, match="words, not numbers"):
        load_values(engine_db, ["branch"])
    with pytest.raises(QueryError, match="did you mean sittingheight"):
        load_values(engine_db, ["measure.sitingheight"])
    empty = load_values(engine_db, ["stature"], "stature > 1000 cm")
    assert empty.matrix.shape == (0, 1)


# --- the parser takes any text: a query or a QueryError, never anything else ----------

from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

QUERY_WORDS = st.sampled_from(
    [
        "measure.sittingheight",
        "measure.weightkg",
        "branch",
        "source",
        "component",
        "age",
        "gender",
        "dodrace",
        "=",
        "!=",
        ">",
        "<=",
        "AND",
        "OR",
        "(",
        ")",
        "'Combat Arms'",
        '"x y"',
        "'",
        "95",
        "cm",
        "kg",
        "ansur2",
        "female",
        "measure.",
        "measure.sitingheight",
    ]
)


@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(words=st.lists(QUERY_WORDS, min_size=1, max_size=9))
def test_query_words_compile_or_fail_cleanly(engine_db, words):
    text = " ".join(words)
    try:
        query = run_query(engine_db, text)
    except QueryError as exc:
        assert exc.column is None or 1 <= exc.column <= len(text) + 1
        return
    # a query naming source reaches every stored person, the virtual ones too
    stored = engine_db.execute("SELECT count(*) FROM person").fetchone()[0]
    assert 0 <= query.count() <= stored


@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(value=st.text(max_size=20).filter(lambda t: "'" not in t))
def test_any_quoted_text_is_a_parameter(value):
    try:
        compiled = compile_query(f"branch = '{value}'")
    except QueryError:
        return  # e.g. characters the grammar does not take
    # the value, then the real-people scope (no demonstration, no virtual people)
    assert compiled.params == (value, "synthetic", "virtual:%")
    assert "'" not in compiled.where and '"' not in compiled.where  # no literal in the SQL


def test_deep_and_long_queries_are_refused_with_a_message(engine_db):
    deep = "(" * 247 + "age > 1" + ")" * 247
    with pytest.raises(QueryError, match="nested more than 50 deep") as caught:
        compile_query(deep)
    assert caught.value.column == 51
    long = " OR ".join(f"age = {k}" for k in range(1000))
    with pytest.raises(QueryError, match="more than 200 comparisons"):
        compile_query(long)
    fine = " OR ".join(f"age = {k}" for k in range(200))
    assert run_query(engine_db, "(" * 50 + fine + ")" * 50).count() > 0
    assert compile_query("branch = '((((((((((((((((((((((((((((((((((((((((((((((((((((('")
