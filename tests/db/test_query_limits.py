"""A query's depth and size are bounded with a message that points at the
token (unbounded, 247 nested parentheses raised RecursionError, an OR of
1,000 terms SQLite's "Expression tree is too large").  The queries at the
limits run on both engines (tests/db/conftest.py)."""

from __future__ import annotations

import pytest

from sass_tui.cli import main
from sass_tui.db.engine.schema import QUERY_TABLES
from sass_tui.db.query.query import Query, QueryError, compile_query
from sass_tui.db.query.query_limits import MAX_COMPARISONS, MAX_JOINED_TABLES, MAX_NESTING


def test_deep_nesting_is_refused_at_the_parenthesis():
    text = "(" * 247 + "stature > 170" + ")" * 247
    with pytest.raises(QueryError, match=f"nested more than {MAX_NESTING} deep") as info:
        compile_query(text)
    assert info.value.column == MAX_NESTING + 1


def test_nesting_at_the_limit_runs(engine_db):
    text = "(" * MAX_NESTING + "stature > 170 cm" + ")" * MAX_NESTING
    # The parentheses change nothing: the count is the table's own (person.stature is
    # in cm), over the real people a query without a source term reaches (db/query/scope.py).
    real = "source != 'synthetic' AND substr(source, 1, 8) != 'virtual:'"
    (expected,) = engine_db.execute(
        f"SELECT count(*) FROM person WHERE stature > 170 AND {real}"
    ).fetchone()
    assert (
        0 < expected < engine_db.execute(f"SELECT count(*) FROM person WHERE {real}").fetchone()[0]
    )
    assert Query(engine_db, compile_query(text)).count() == expected


def test_a_thousand_ors_are_refused_at_the_first_extra_comparison():
    terms = [f"stature > {i}" for i in range(1000)]
    text = " OR ".join(terms)
    with pytest.raises(QueryError, match=f"more than {MAX_COMPARISONS} comparisons") as info:
        compile_query(text)
    extra = " OR ".join(terms[:MAX_COMPARISONS]) + " OR "
    assert info.value.column == len(extra) + len("stature ") + 1


def test_the_largest_query_allowed_runs(engine_db):
    # MAX_COMPARISONS terms, each inside MAX_NESTING - 1 parentheses, mixing
    # AND and OR: neither SQLite's expression depth limit nor PostgreSQL's
    # max_stack_depth is reached.
    one = "(" * (MAX_NESTING - 1) + "stature > 1 cm AND mass > 1 kg" + ")" * (MAX_NESTING - 1)
    text = " OR ".join([one] * (MAX_COMPARISONS // 2))
    assert Query(engine_db, compile_query(text)).count() > 0


def test_too_many_joined_tables_are_refused_at_the_field(engine_db):
    fields = [f"girth.{r}.x" for r in QUERY_TABLES["girth"]]
    fields += [f"joint_limit.{r}.x" for r in QUERY_TABLES["joint_limits"]]
    fields += [f"center_of_mass.{r}.x" for r in QUERY_TABLES["center_of_mass"]]
    text = " OR ".join(f"{f} > 1" for f in fields)
    with pytest.raises(QueryError, match="more than 63 different") as info:
        compile_query(text)
    assert text[info.value.column - 1 :].startswith(fields[MAX_JOINED_TABLES])
    # Only the synthetic demonstration people have these values: the query names them.
    allowed = "(" + " OR ".join(f"{f} > 1" for f in fields[:MAX_JOINED_TABLES])
    allowed += ") AND source = synthetic"
    # Counted straight from the query tables: the synthetic people with x > 1 in any of the 63.
    tables = [
        table
        for group in ("girth", "joint_limits", "center_of_mass")
        for table in QUERY_TABLES[group].values()
    ][:MAX_JOINED_TABLES]
    union = " UNION ".join(f"SELECT id_num FROM {table} WHERE x > 1" for table in tables)
    (expected,) = engine_db.execute(
        f"SELECT count(*) FROM person WHERE source = 'synthetic' AND id_num IN ({union})"
    ).fetchone()
    assert expected > 0
    assert Query(engine_db, compile_query(allowed)).count() == expected


@pytest.mark.parametrize("number", ["1e400", "-1e309", "1e16"])
def test_non_finite_numbers_are_refused(number):
    with pytest.raises(QueryError, match="not a usable number") as info:
        compile_query(f"stature > {number} cm")
    assert info.value.column == len("stature > ") + 1


def test_the_cli_prints_the_limit_not_a_traceback(capsys):
    assert main(["query", "(" * 300 + "stature > 1" + ")" * 300]) == 2
    err = capsys.readouterr().err
    assert "nested more than" in err and "Traceback" not in err
