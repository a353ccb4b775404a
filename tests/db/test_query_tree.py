"""The query is parsed once into a typed tree, and every engine's SQL is compiled
from that tree: nothing in sass_tui/db parses generated SQL back."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sass_tui.db.engine.dialect import dialect_of
from sass_tui.db.query.query import QueryError, compile_conjuncts, compile_query
from sass_tui.db.query.query_tree import And, Comparison, Or, names_field, to_sql
from sass_tui.db.query.scope import NOT_VIRTUAL, REAL_PEOPLE

DB = Path(__file__).resolve().parents[2] / "sass_tui" / "db"


def test_no_regular_expression_in_the_database_layer():
    # lark's generated lexer (_query_parser.py) reads the user's query text, never SQL.
    for path in sorted(DB.glob("*.py")):
        if path.name == "_query_parser.py":
            continue
        tree = ast.parse(path.read_text(), str(path))
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                assert all(a.name != "re" for a in node.names), path
            if isinstance(node, ast.ImportFrom):
                assert node.module != "re", path


def test_the_report_sample_is_one_tree():
    compiled = compile_query(
        "gender = male AND girth.right_upper_arm.z > 11 in AND strength.elbow_flexion.max > 20 ft-lb"
    )
    tree = compiled.tree
    assert isinstance(tree, And)
    # The real-people scope (db/query/scope.py) is two more terms of the same tree:
    # no demonstration people, no virtual people.
    gender, girth, strength, scope, not_virtual = tree.terms
    assert scope == REAL_PEOPLE and not_virtual == NOT_VIRTUAL
    assert gender == Comparison("gender", "person", "gender", "=", "male")
    assert isinstance(girth, Comparison) and girth.op == ">" and girth.column == "z"
    assert girth.value == pytest.approx(11 * 2.54)  # inches -> the stored cm
    assert isinstance(strength, Comparison)
    assert strength.value == pytest.approx(20 * 1.3558179483314004)  # ft-lb -> N m
    assert not compiled.names_field("source")
    assert compiled.names_field("gender")


def test_source_named_anywhere():
    assert names_field(compile_query("stature > 1 OR (age > 2 AND source = ansur2)").tree, "source")
    assert not names_field(compile_query("stature > 1 OR age > 2").tree, "source")


def test_dialects_differ_only_in_placeholders_and_case_folding():
    scoped = compile_query("branch != 'Combat Arms' OR (stature > 170 cm AND gender = male)").tree
    assert isinstance(scoped, And) and scoped.terms[-2:] == (REAL_PEOPLE, NOT_VIRTUAL)
    tree = scoped.terms[0]
    assert isinstance(tree, Or)
    sqlite_sql, params = to_sql(tree, "sqlite")
    pg_sql, pg_params = to_sql(tree, "postgresql")
    assert params == pg_params == ["Combat Arms", 170.0, "male"]
    assert sqlite_sql == (
        "((p.branch IS NULL OR p.branch != ? COLLATE NOCASE) OR (p.stature > ? AND p.gender = ?))"
    )
    assert pg_sql == (
        "((p.branch IS NULL OR lower(p.branch) != lower(%s)) OR (p.stature > %s AND p.gender = %s))"
    )


def test_conjuncts_share_one_set_of_tables():
    terms = compile_conjuncts("girth.neck.z < 40 cm AND measure.stature < 1800 mm")
    assert [t.tables for t in terms] == [terms[0].tables] * 2
    assert {table for _alias, table in terms[0].tables} == {"q_girth_neck", "measure"}


NUMERIC = ["stature", "mass", "age", "measure.sittingheight", "girth.neck.z"]
WORDS = {"gender": ["male", "female", "MALE"], "source": ["ansur2", "'Synthetic'", "nobody"]}


@st.composite
def queries(draw, depth: int = 0) -> str:
    if depth < 2 and draw(st.booleans()):
        parts = draw(st.lists(queries(depth + 1), min_size=2, max_size=3))
        joiner = draw(st.sampled_from([" AND ", " OR ", " and ", " or "]))
        return "(" + joiner.join(parts) + ")"
    if draw(st.booleans()):
        field = draw(st.sampled_from(NUMERIC))
        op = draw(st.sampled_from(["<", ">", "<=", ">=", "=", "!=", "<>", "≤", "≥"]))
        value = draw(st.floats(min_value=-1e4, max_value=1e4, allow_nan=False))
        return f"{field} {op} {value!r}"
    field = draw(st.sampled_from(sorted(WORDS)))
    return f"{field} {draw(st.sampled_from(['=', '!=']))} {draw(st.sampled_from(WORDS[field]))}"


@settings(
    max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(queries())
def test_any_query_compiles_to_sql_each_engine_runs(shared_db, text):
    # Every tree's SQL, in the engine's dialect, is valid SQL with one parameter
    # per comparison (on both engines: tests/db/conftest.py).
    try:
        compiled = compile_query(text)
    except QueryError:
        return
    assert len(compiled.params) == sum(1 for _ in compiled.tree.comparisons())
    where, params = compiled.sql(dialect_of(shared_db))
    assert params == compiled.params
    shared_db.execute(
        f"SELECT count(*) FROM {compiled.from_clause()} WHERE {where}", params
    ).fetchone()
