"""Real people by default: a query without a `source` term counts, lists,
summarizes and fits the real people only (db/query/scope.py); `source = synthetic`
reaches the 200 demonstration people.  Expected counts come straight from the
published CSV in ../shared.  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json

import pytest

from sass_tui.cli import main
from sass_tui.db.people.values import load_values
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.population import population_of
from sass_tui.db.query.lists import QUERY_LIST, QueryLists
from sass_tui.db.query.query import demonstration_hint, run_query

FILES = {"male": "ANSUR_II_MALE_Public.csv", "female": "ANSUR_II_FEMALE_Public.csv"}


@pytest.fixture(scope="module")
def survey(ansur_dir) -> list[dict[str, str]]:
    rows = []
    for gender, name in FILES.items():
        with (ansur_dir / name).open(encoding="utf-8-sig", errors="replace") as handle:
            rows += [{**r, "gender": gender} for r in csv.DictReader(handle)]
    return rows


# query -> the same selection over the CSV (stature in mm, Age in years)
CASES = [
    ("gender = female AND age >= 40", lambda r: r["gender"] == "female" and int(r["Age"]) >= 40),
    ("gender = male", lambda r: r["gender"] == "male"),
    ("stature > 180 cm", lambda r: int(r["stature"]) > 1800),
    ("age < 25 OR stature < 155 cm", lambda r: int(r["Age"]) < 25 or int(r["stature"]) < 1550),
]


@pytest.mark.parametrize("text, predicate", CASES, ids=[c[0] for c in CASES])
def test_default_counts_are_the_surveys(engine_db, survey, text, predicate):
    expected = sum(1 for r in survey if predicate(r))
    assert run_query(engine_db, text).count() == expected
    assert len(run_query(engine_db, text).ids()) == expected
    assert all(p["source"] == "ansur2" for p in run_query(engine_db, text).iter_all(500))


def test_the_issue_count(engine_db, survey):
    expected = sum(1 for r in survey if r["gender"] == "female" and int(r["Age"]) >= 40)
    assert expected == 306
    assert run_query(engine_db, "gender = female AND age >= 40").count() == 306


def test_naming_source_synthetic_reaches_exactly_the_200(engine_db):
    query = run_query(engine_db, "source = synthetic")
    assert query.count() == 200
    people = list(query.iter_all(64))
    assert len(people) == 200 and {p["source"] for p in people} == {"synthetic"}
    (stored,) = engine_db.execute(
        "SELECT count(*) FROM person WHERE source = 'synthetic'"
    ).fetchone()
    assert stored == 200
    # any source term leaves the choice to the query
    (virtual,) = engine_db.execute(
        "SELECT count(*) FROM person WHERE source = 'virtual:nhanes-2017-2020'"
    ).fetchone()
    assert run_query(engine_db, "stature > 0 cm AND source != ansur2").count() == 200 + virtual


def test_every_path_works_on_real_people(engine_db, shared_target, survey):
    women = sum(1 for r in survey if r["gender"] == "female")
    lists = QueryLists(engine_db)
    assert lists.run("gender = female") == women == lists.count(QUERY_LIST)
    assert population_of(engine_db, "gender = female").counts == {"female": women}
    fit = fit_test(engine_db, "stature < 500 cm", "gender = female")
    assert fit.population_size == women
    # what predict learns from: every person, real ones only
    assert len(load_values(engine_db, ["stature"])) == len(survey) == 6068
    synthetic = load_values(engine_db, ["stature"], "source = synthetic")
    assert len(synthetic) == 200


def test_a_strength_query_that_finds_no_real_person_says_who_would(
    engine_db, shared_target, capsys
):
    text = "gender = male AND strength.elbow_flexion.max > 20 ft-lb"
    assert run_query(engine_db, text).count() == 0
    reach = f"({text}) AND source = synthetic"
    demonstration = run_query(engine_db, reach).count()
    assert demonstration > 0
    hint = demonstration_hint(engine_db, text)
    assert hint is not None and reach in hint and f"{demonstration} synthetic" in hint
    assert "strength" in hint
    assert main(["query", "--db", shared_target, "--count", text]) == 0
    said = capsys.readouterr()
    assert said.out.strip() == "0" and reach in said.err
    assert main(["query", "--db", shared_target, "--format", "json", reach]) == 0
    listed = json.loads(capsys.readouterr().out)
    assert listed["count"] == demonstration
    assert {p["source"] for p in listed["persons"]} == {"synthetic"}
    # a query that finds nobody anywhere, or that names a source, gets no hint
    assert demonstration_hint(engine_db, "stature > 900 cm") is None
    assert demonstration_hint(engine_db, f"{text} AND source = ansur2") is None
