"""NOT, BETWEEN, compound units (`6 ft 2 in`) and "did you mean" for fields.

Counts on both engines (tests/db/conftest.py) against a direct count over
the published ANSUR II CSV (stature in mm, weightkg in tenths of a kg); the
negation's SQL against the engine's own `NOT (...)`; a hypothesis round trip
of the parser over every form."""

from __future__ import annotations

import csv

import pint
import pytest
from _built_once import copy_database_file
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.db.engine.dialect import dialect_of
from sass_tui.db.engine.schema import connect
from sass_tui.db.query import accelerator
from sass_tui.db.query.query import (
    QueryError,
    compile_conjuncts,
    compile_query,
    parse_query,
    run_query,
)
from sass_tui.db.query.query_tree import And, Comparison, Or, negation, to_sql

FILES = {"male": "ANSUR_II_MALE_Public.csv", "female": "ANSUR_II_FEMALE_Public.csv"}
UNITS = pint.UnitRegistry()


@pytest.fixture(scope="module")
def survey(ansur_dir) -> list[dict[str, str]]:
    rows = []
    for gender, name in FILES.items():
        with (ansur_dir / name).open(encoding="utf-8-sig", errors="replace") as handle:
            rows += [{**r, "gender": gender} for r in csv.DictReader(handle)]
    return rows


def mm(text: str) -> float:
    """`6 ft + 2 in` in mm, by pint (independent of sass's unit table)."""
    return float(UNITS.Quantity(text).to("mm").magnitude)


SIX_FT_TWO, FIVE_FT_TWO, FIVE_FT_SIX_AND_A_HALF = (
    mm("6 ft + 2 in"),
    mm("5 ft + 2 in"),
    mm("5 ft + 6.5 in"),
)


# query -> the same selection over the CSV
CASES = [
    (
        "stature BETWEEN 160 cm AND 180 cm",
        lambda r: 1600 <= int(r["stature"]) <= 1800,
    ),
    (
        "NOT branch = 'Combat Arms'",
        lambda r: r["Branch"].lower() != "combat arms",
    ),
    (
        "gender = female AND NOT stature BETWEEN 150 cm AND 175 cm",
        lambda r: r["gender"] == "female" and not 1500 <= int(r["stature"]) <= 1750,
    ),
    (
        "NOT (gender = male OR mass > 70 kg)",
        lambda r: r["gender"] != "male" and not int(r["weightkg"]) / 10 > 70,
    ),
    (
        "stature > 6 ft 2 in",
        lambda r: int(r["stature"]) > SIX_FT_TWO,
    ),
    (
        "stature between 5 ft 2 in and 5 ft 6.5 in and not gender = male",
        lambda r: (
            FIVE_FT_TWO <= int(r["stature"]) <= FIVE_FT_SIX_AND_A_HALF and r["gender"] == "female"
        ),
    ),
]


@pytest.mark.parametrize(("text", "selects"), CASES, ids=[c[0] for c in CASES])
def test_the_count_is_the_csv_counted_directly(engine_db, survey, text, selects):
    expected = sum(1 for row in survey if selects(row))
    assert run_query(engine_db, text).count() == expected > 0


def test_between_is_greater_or_equal_and_less_or_equal():
    between = compile_query("stature BETWEEN 160 cm AND 180 cm")
    spelled = compile_query("stature >= 160 cm AND stature <= 180 cm")
    assert between.tree == spelled.tree
    assert between.where == spelled.where and between.params == spelled.params


def test_not_free_text_equal_keeps_people_without_a_value_as_not_equal_does():
    assert compile_query("NOT branch = 'Combat Arms'").tree == (
        compile_query("branch != 'Combat Arms'").tree
    )


def test_not_binds_tighter_than_and():
    assert parse_query("NOT gender = male AND stature > 1 m") == And(
        (
            Comparison("gender", "person", "gender", "!=", "male"),
            Comparison("stature", "person", "stature", ">", 100.0),
        )
    )


def test_compound_units_add_up():
    value = compile_query("stature > 6 ft 2 in").params[0]
    assert value == pytest.approx(UNITS.Quantity(74, "inch").to("cm").magnitude)
    value = compile_query("measure.sittingheight < 2 ft 11.5 in").params[0]
    assert value == pytest.approx(UNITS.Quantity(35.5, "inch").to("cm").magnitude)
    value = compile_query("stature >= 1 m 72 cm").params[0]
    assert value == pytest.approx(172.0)


@pytest.mark.parametrize(
    ("text", "column", "says"),
    [
        ("weight > 80 kg", 1, "unknown field 'weight'; did you mean mass?"),
        ("height < 170 cm", 1, "did you mean stature?"),
        ("statrue > 1 m", 1, "did you mean stature?"),
        ("sittingheight > 90 cm", 1, "did you mean measure.sittingheight?"),
        ("measure.sittinghieght > 90 cm", 9, "did you mean sittingheight?"),
        ("girth.rigth_upper_arm.z > 28 cm", 7, "did you mean right_upper_arm or"),
        ("strength.elbow_flex.max > 1", 10, "did you mean elbow_flexion or elbow_extension?"),
        ("stature BETWEEN 180 cm AND 160 cm", 17, "selects nobody; write the smaller"),
        ("gender BETWEEN male AND female", 16, "BETWEEN takes two numbers, not 'male'"),
        ("stature > 6 ft 2", 16, "each number of '6 ft 2' needs its unit"),
        ("age BETWEEN 20 years AND 30", 16, "age takes no unit, found 'years'"),
        ("NOT", 4, "the query ends too early"),
        ("stature BETWEEN 1 m", 20, "the query ends too early; expected AND"),
        ("NOT branch > 'Combat Arms'", 12, "can only be compared with = or !="),
        ("stature > 1 m, mass < 90 kg", 14, "unexpected character ','; join conditions with AND"),
        ("stature > 1 m && mass < 9", 15, "unexpected character '&'; join conditions with AND"),
        ("stature > 1 m $", 15, "unexpected character '$'"),
    ],
)
def test_a_bad_query_says_where_and_what(text, column, says):
    with pytest.raises(QueryError) as caught:
        compile_query(text)
    assert caught.value.column == column, str(caught.value)
    assert says in str(caught.value)


def test_not_is_bounded_as_parentheses_are():
    text = "NOT " * 51 + "gender = male"
    with pytest.raises(QueryError, match="NOT more than 50 times"):
        compile_query(text)
    assert compile_query("NOT " * 50 + "gender = male").tree is not None


def test_between_counts_as_two_comparisons():
    text = " OR ".join(["stature BETWEEN 1 m AND 2 m"] * 101)
    with pytest.raises(QueryError, match="more than 200 comparisons"):
        compile_query(text)


# --- the negation against each engine's own NOT ---------------------------------

NUMERIC = ["stature", "mass", "age", "measure.sittingheight"]


@st.composite
def numeric_trees(draw, depth: int = 0) -> str:
    """Queries over numeric fields only (free text's != is not SQL's NOT: above)."""
    if depth < 2 and draw(st.booleans()):
        parts = draw(st.lists(numeric_trees(depth + 1), min_size=2, max_size=3))
        return "(" + draw(st.sampled_from([" AND ", " OR "])).join(parts) + ")"
    field = draw(st.sampled_from(NUMERIC))
    value = draw(st.integers(min_value=0, max_value=200))
    if draw(st.booleans()):
        return f"{field} BETWEEN {value} AND {value + draw(st.integers(0, 50))}"
    return f"{field} {draw(st.sampled_from(['<', '>', '<=', '>=', '=', '!=']))} {value}"


@pytest.mark.slow
@settings(
    max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(numeric_trees())
def test_the_negation_selects_what_the_engines_not_selects(shared_db, text):
    tree = parse_query(text)
    dialect = dialect_of(shared_db)
    where, params = to_sql(tree, dialect)
    negated, negated_params = to_sql(negation(tree), dialect)
    compiled = compile_query(f"source = ansur2 AND {text}")
    join = compiled.from_clause()

    def count(condition: str, values: list[object]) -> int:
        sql = f"SELECT count(*) FROM {join} WHERE {condition}"
        result: int = shared_db.execute(sql, values).fetchone()[0]
        return result

    assert count(negated, negated_params) == count(f"NOT ({where})", params)


# --- round trip: any tree written as text parses back to itself ------------------

FIELDS = {
    "stature": ("person", "stature"),
    "mass": ("person", "mass"),
    "measure.sittingheight": ("measure", "sittingheight"),
}


@st.composite
def trees(draw, depth: int = 0):
    """(text, tree): a query and the tree it must parse to."""
    kind = draw(
        st.sampled_from(["compare", "between", "not", "group"] if depth < 3 else ["compare"])
    )
    if kind == "group":
        parts = draw(st.lists(trees(depth + 1), min_size=2, max_size=3))
        node, word = draw(st.sampled_from([(And, "AND"), (Or, "OR")]))
        text = f" {draw(st.sampled_from([word, word.lower()]))} ".join(f"({t})" for t, _ in parts)
        return text, node(tuple(tree for _, tree in parts))
    if kind == "not":
        text, tree = draw(trees(depth + 1))
        return f"{draw(st.sampled_from(['NOT', 'not', 'Not']))} ({text})", negation(tree)
    field = draw(st.sampled_from(sorted(FIELDS)))
    table, column = FIELDS[field]
    low = draw(st.integers(min_value=0, max_value=500))
    if kind == "between":
        high = low + draw(st.integers(min_value=0, max_value=500))
        text = f"{field} {draw(st.sampled_from(['BETWEEN', 'between']))} {low} AND {high}"
        return text, And(
            (
                Comparison(field, table, column, ">=", float(low)),
                Comparison(field, table, column, "<=", float(high)),
            )
        )
    op = draw(st.sampled_from(["<", ">", "<=", ">=", "=", "!="]))
    return f"{field} {op} {low}", Comparison(field, table, column, op, float(low))


def flattened(tree):
    """The parser joins `(a AND b) AND c` as one And of three: compare flattened."""
    if isinstance(tree, Comparison):
        return tree
    terms = []
    for term in tree.terms:
        term = flattened(term)
        terms += term.terms if type(term) is type(tree) else [term]
    return type(tree)(tuple(terms))


@pytest.mark.slow
@settings(max_examples=200, deadline=None)
@given(trees())
def test_any_tree_written_out_parses_back_to_itself(case):
    text, tree = case
    assert flattened(parse_query(text)) == flattened(tree)


# --- the DuckDB column copy (db/query/accelerator.py) reads them as SQLite does -------

DUCKDB_QUERIES = [
    "NOT (gender = male OR branch = 'Combat Arms') AND stature BETWEEN 5 ft 2 in AND 5 ft 8 in",
    "measure.sittingheight BETWEEN 85 cm AND 95 cm AND NOT mass > 80 kg",
]


@pytest.mark.sqlite_only("the DuckDB column copy of a SQLite file")
@pytest.mark.parametrize("text", DUCKDB_QUERIES)
def test_the_duckdb_copy_counts_not_and_between_as_sqlite_does(
    default_db_file, tmp_path, monkeypatch, capsys, text
):
    pytest.importorskip("duckdb")
    path = tmp_path / "people.db"
    copy_database_file(default_db_file, path)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "cache"))
    monkeypatch.setattr(accelerator, "MIN_PEOPLE", 0)
    assert main(["db", "copy", "--db", str(path), text]) == 0
    capsys.readouterr()
    compiled = compile_query(text)
    conn = connect(path)
    try:
        by_copy = accelerator.count(conn, compiled)
        assert accelerator.last_answer == "copy"
        sql = f"SELECT count(*) FROM {compiled.from_clause()} WHERE {compiled.where}"
        assert by_copy == conn.execute(sql, compiled.params).fetchone()[0] > 0
    finally:
        conn.close()


# --- any string of the language's words compiles or is refused saying where ------

WORDS = [
    *("NOT", "not", "BETWEEN", "AND", "OR", "(", ")", "=", "<", ">=", "!=", "≤"),
    *("stature", "gender", "branch", "age", "measure.sittingheight", "girth.neck.z"),
    *("1", "2.5", "-3", "1e400", "6", "ft", "in", "cm", "kg", "years", "'x'", "male"),
]


@pytest.mark.slow
@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(WORDS), max_size=14))
def test_any_string_of_words_compiles_or_is_refused_with_its_column(words):
    text = " ".join(words)
    for compile_text in (compile_query, compile_conjuncts):
        try:
            compile_text(text)
        except QueryError as exc:
            assert exc.column is None or 1 <= exc.column <= len(text) + 1, (text, str(exc))
