"""A command parses each query text it is given once and passes the parsed
query on: `sass query` (its count, rows, the demonstration hint, a target's
weighted count), `sass fit`, `sass family`, `sass population`, `sass
target`, and the query screen's lists.  Each parse of the query parser
(db/query/_query_parser.py, generated from db/query/query_grammar.py) is counted by the text it read."""

from __future__ import annotations

from collections import Counter

import pytest
from _built_once import copy_database_file
from test_targets import civilian_women, write_sample

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.query import _query_parser
from sass_tui.db.query.lists import QueryLists
from sass_tui.db.query.query import compile_query, demonstration_hint, parser

STRENGTH = "gender = male AND strength.elbow_flexion.max > 20 ft-lb"


@pytest.fixture
def parses(monkeypatch) -> Counter[str]:
    """How many times the query parser read each text."""
    counted: Counter[str] = Counter()
    query_parser = parser()
    real_parse = _query_parser.Lark.parse

    def counting(self, text, *args, **kwargs):
        if self is query_parser:
            counted[text] += 1
        return real_parse(self, text, *args, **kwargs)

    monkeypatch.setattr(_query_parser.Lark, "parse", counting)
    return counted


@pytest.fixture(scope="module")
def with_target(default_db_file, tmp_path_factory) -> str:
    """A copy of the default database with a stored target `civ` of women."""
    folder = tmp_path_factory.mktemp("parsed-once")
    db = folder / "sass.db"
    copy_database_file(default_db_file, db)
    sample = write_sample(folder / "civilian.csv", civilian_women(300))
    argv = ["target", "civ", "--db", str(db), "--gender", "female", "--sample", str(sample)]
    argv += ["--population", "source = ansur2 AND age >= 18"]
    assert main(argv) == 0
    return str(db)


@pytest.mark.parametrize(
    "argv",
    [
        ["query", "--count", STRENGTH],  # no real person: the count, then the hint
        ["query", "--format", "csv", STRENGTH],  # the rows, then the hint
        ["query", "stature BETWEEN 150 cm AND 152 cm"],
        ["query", "--count", "--target", "civ", "NOT stature > 170 cm"],
    ],
    ids=["count and hint", "rows and hint", "rows", "weighted count"],
)
def test_sass_query_parses_its_query_once(with_target, parses, capsys, argv):
    assert main([argv[0], "--db", with_target, *argv[1:]]) == 0
    said = capsys.readouterr()
    assert said.out
    assert parses == Counter({argv[-1]: 1})
    if argv[-1] == STRENGTH:
        assert "synthetic demonstration people match" in said.err


@pytest.mark.slow
def test_sass_fit_parses_its_limits_and_population_once(with_target, parses, capsys):
    limits, population = "stature <= 190 cm AND mass <= 110 kg", "gender = female OR age < 30"
    argv = ["fit", "--db", with_target, "--population", population, "--target", "civ", limits]
    assert main(argv) == 0
    assert "stature <= 190 cm" in capsys.readouterr().out
    # The target's stored population is parsed too, once: it is the database's text.
    base = "(source = ansur2 AND age >= 18) AND gender = female"
    assert parses == Counter({limits: 1, population: 1, base: 1})


@pytest.mark.slow
def test_sass_family_parses_its_population_once(with_target, parses, tmp_path, capsys):
    population = "branch != 'Combat Arms'"
    argv = ["family", "--db", with_target, "--gender", "female", "--measures", "stature,mass"]
    assert main([*argv, "--population", population, "-o", str(tmp_path / "family")]) == 0
    assert parses[population] == 1  # (the prediction model's own population is its text)


@pytest.mark.slow
def test_sass_population_parses_its_query_once(with_target, parses, tmp_path, capsys):
    query = "gender = female AND stature BETWEEN 150 cm AND 175 cm"
    assert (
        main(["population", "--db", with_target, "--query", query, "-o", str(tmp_path / "P.dat")])
        == 0
    )
    assert parses == Counter({query: 1})


@pytest.mark.slow
def test_sass_target_parses_its_population_once(with_target, parses, tmp_path, capsys):
    population = "source = ansur2 AND NOT branch = 'Combat Arms'"
    sample = write_sample(tmp_path / "civilian.csv", civilian_women(200, seed=5))
    argv = ["target", "civ2", "--db", with_target, "--gender", "female"]
    assert main([*argv, "--sample", str(sample), "--population", population]) == 0
    assert parses[population] == 1
    assert set(parses) <= {population, "gender = female"}


def test_the_query_screens_lists_parse_a_query_once(with_target, parses):
    db = Database.open(with_target)
    try:
        with db.connection() as conn:
            lists = QueryLists(conn)
            assert lists.run(STRENGTH) == 0
            assert lists.demonstration_hint(STRENGTH)
            assert lists.weighted_count(STRENGTH, "civ").count == 0
    finally:
        db.close()
    assert parses == Counter({STRENGTH: 1})


def test_the_hint_from_the_parsed_query_is_the_hint_from_its_text(default_db_file):
    db = Database.open(str(default_db_file))
    try:
        with db.connection() as conn:
            compiled = compile_query(STRENGTH)
            hint = demonstration_hint(conn, compiled, 0)
            assert hint is not None
            reach = hint.rsplit(": ", 1)[1]
            assert reach == f"({STRENGTH}) AND source = synthetic"
            assert demonstration_hint(conn, STRENGTH) == hint
            assert int(hint.split("; ")[1].split()[0]) == db.count(compile_query(reach))
    finally:
        db.close()
