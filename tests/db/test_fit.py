"""The fit test counts real people: every share equals a direct count over the ANSUR II CSV,
on both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.db.engine.dialect import mark_of
from sass_tui.db.populations.fit import FitError, check_mix, fit_test
from sass_tui.db.query.query import QueryError, compile_conjuncts, compile_query, run_query

# Every person of the default database has a stature; the source term reaches the
# synthetic people too (a query without one reaches only real people), and
# leaves out the shipped virtual ones `sass db init` stores.
EVERYONE = 'stature > 0 AND source != "virtual:nhanes-2017-2020"'


def _read_csv(ansur_dir: Path) -> dict[str, dict[str, np.ndarray]]:
    """Per gender, the columns the tests use, in sass's canonical units, read with csv."""
    out = {}
    for gender, name in (("male", "MALE"), ("female", "FEMALE")):
        with open(ansur_dir / f"ANSUR_II_{name}_Public.csv", encoding="cp1252", newline="") as f:
            rows = [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(f)]
        out[gender] = {
            "stature": np.array([float(r["stature"]) / 10 for r in rows]),
            "mass": np.array([float(r["weightkg"]) / 10 for r in rows]),
            # girth.neck.x is the neck's diameter: circumference / pi (report §10.1)
            "neck": np.array([float(r["neckcircumference"]) / 10 / math.pi for r in rows]),
            "sitting": np.array([float(r["sittingheight"]) / 10 for r in rows]),
            "hip": np.array([float(r["hipbreadthsitting"]) / 10 for r in rows]),
        }
    return out


@pytest.fixture(scope="session")
def ansur_columns(ansur_dir):
    return _read_csv(ansur_dir)


@pytest.fixture()
def ansur_db_file(shared_target) -> str:
    """The default database (the ANSUR II people and the synthetic people, with
    strengths) on each engine: its address."""
    return shared_target


@pytest.fixture()
def ansur_db(shared_db):
    return shared_db


@pytest.fixture()
def mixed_db(ansur_db):
    return ansur_db


# limits in the query language, and the same limits over the CSV columns
LIMIT_SETS = [
    (  # the seat of docs/accommodation.md
        "stature <= 190 cm AND measure.sittingheight <= 100 cm "
        "AND measure.hipbreadthsitting <= 45 cm AND mass <= 110 kg",
        [
            lambda c: c["stature"] <= 190,
            lambda c: c["sitting"] <= 100,
            lambda c: c["hip"] <= 45,
            lambda c: c["mass"] <= 110,
        ],
    ),
    (
        "stature <= 190 cm AND mass <= 110 kg",
        [lambda c: c["stature"] <= 190, lambda c: c["mass"] <= 110],
    ),
    (
        "stature >= 160 cm AND stature <= 185 cm AND mass < 95 kg AND girth.neck.x <= 12.5",
        [
            lambda c: c["stature"] >= 160,
            lambda c: c["stature"] <= 185,
            lambda c: c["mass"] < 95,
            lambda c: c["neck"] <= 12.5,
        ],
    ),
    (
        "mass > 60 kg AND (stature < 170 cm OR girth.neck.x < 12)",
        [lambda c: c["mass"] > 60, lambda c: (c["stature"] < 170) | (c["neck"] < 12)],
    ),
]


def _expected(columns, predicates):
    passes = [p(columns) for p in predicates]
    fit = np.logical_and.reduce(passes)
    return fit, passes


@pytest.mark.parametrize("limits,predicates", LIMIT_SETS)
@pytest.mark.parametrize(
    "mix", [None, {"male": 0.5, "female": 0.5}, {"male": 0.8, "female": 0.2}, {"female": 1.0}]
)
def test_shares_equal_a_direct_count_over_the_csv(ansur_db, ansur_columns, limits, predicates, mix):
    result = fit_test(ansur_db, limits, mix=mix)  # the default population: ANSUR II
    assert result.population == "source = ansur2"
    weights = check_mix(mix)
    weighted = 0.0
    naive_weighted = 0.0
    for gender in ("male", "female"):
        columns = ansur_columns[gender]
        fit, passes = _expected(columns, predicates)
        share = result.genders[gender]
        assert share.n == len(fit)
        assert share.not_measured == 0
        assert share.fit == int(fit.sum())
        assert share.percent == pytest.approx(100 * fit.mean(), abs=1e-9)
        naive = 100 * math.prod(float(p.mean()) for p in passes)
        assert share.naive_percent == pytest.approx(naive, abs=1e-9)
        weighted += weights.get(gender, 0.0) * 100 * fit.mean()
        naive_weighted += weights.get(gender, 0.0) * naive
        for k, b in enumerate(result.by_limit):
            assert b.percent[gender] == pytest.approx(100 * passes[k].mean(), abs=1e-9)
    assert result.weighted_percent == pytest.approx(weighted, abs=1e-9)
    assert result.naive_percent == pytest.approx(naive_weighted, abs=1e-9)
    assert result.mix == pytest.approx(weights)
    # per limit: excluded alone / only limit to exclude, both genders together
    both = {
        key: np.concatenate([ansur_columns["male"][key], ansur_columns["female"][key]])
        for key in ansur_columns["male"]
    }
    passes = np.array([p(both) for p in predicates])
    fails = ~passes
    for k, b in enumerate(result.by_limit):
        assert b.excluded == int(fails[k].sum())
        assert b.only_limit == int((fails[k] & (fails.sum(axis=0) == 1)).sum())
        assert b.not_measured == 0


def test_naive_estimate_is_the_product_of_the_single_limit_shares(ansur_db):
    limits = compile_conjuncts(LIMIT_SETS[2][0])
    together = fit_test(ansur_db, LIMIT_SETS[2][0])
    alone = [fit_test(ansur_db, t.text) for t in limits]
    for gender in ("male", "female"):
        product = 100 * math.prod(a.genders[gender].percent / 100 for a in alone)
        assert together.genders[gender].naive_percent == pytest.approx(product, abs=1e-9)
    # the real share is not the naive one: the limits are correlated
    assert any(
        abs(together.genders[g].percent - together.genders[g].naive_percent) > 1
        for g in ("male", "female")
    )
    assert together.naive_percent == pytest.approx(
        0.5
        * sum(
            100 * math.prod(a.genders[g].percent / 100 for a in alone) for g in ("male", "female")
        )
    )


def test_people_lacking_a_limited_value_are_left_out_and_counted(mixed_db):
    limits = "stature <= 185 cm AND strength.elbow_flexion.max > 40"
    result = fit_test(mixed_db, limits, EVERYONE, failing=True)
    strength_people = run_query(
        mixed_db, "strength.elbow_flexion.max > -1e9 AND source != none"
    ).ids()
    everyone = run_query(mixed_db, EVERYONE).ids()
    assert len(strength_people) > 0
    unmeasured = len(everyone) - len(strength_people)
    assert unmeasured >= 6068  # every ANSUR II person lacks strength
    assert result.not_measured == unmeasured
    assert result.by_limit[1].not_measured == unmeasured
    assert result.by_limit[0].not_measured == 0
    for gender in ("male", "female"):
        measured = run_query(
            mixed_db, f"gender = {gender} AND strength.elbow_flexion.max > -1e9 AND source != none"
        ).count()
        fitting = run_query(mixed_db, f"gender = {gender} AND {limits} AND source != none").count()
        share = result.genders[gender]
        assert share.n == measured  # the unmeasured are not in the share
        assert share.fit == fitting
        assert share.percent == pytest.approx(100 * fitting / measured)
    # the failing list names only definite failures, with the limits they fail
    failing = {f.id: f.limits for f in result.failing}
    tall = set(run_query(mixed_db, f"stature > 185 cm AND {EVERYONE}").ids())
    weak = set(run_query(mixed_db, "strength.elbow_flexion.max <= 40 AND source != none").ids())
    assert set(failing) == tall | weak
    for person_id, failed in failing.items():
        assert ("stature <= 185 cm" in failed) == (person_id in tall)
        assert ("strength.elbow_flexion.max > 40" in failed) == (person_id in weak)


def test_population_query_chooses_the_people(ansur_db, ansur_columns):
    result = fit_test(
        ansur_db, "mass <= 80 kg", "source = ansur2 AND gender = female AND stature > 165 cm"
    )
    columns = ansur_columns["female"]
    chosen = columns["stature"] > 165
    assert set(result.genders) == {"female"}
    assert result.genders["female"].n == int(chosen.sum())
    assert result.genders["female"].fit == int((chosen & (columns["mass"] <= 80)).sum())
    # only women: the weighted share is theirs, whatever the mix says
    assert result.mix == {"female": 1.0}
    assert result.weighted_percent == result.genders["female"].percent


def test_synthetic_people_count_only_when_asked_for(ansur_db):
    ansur = fit_test(ansur_db, "mass <= 100 kg")
    assert ansur.population_size == 6068
    synthetic = fit_test(ansur_db, "mass <= 100 kg", "source = synthetic")
    assert synthetic.population_size == run_query(ansur_db, "source = synthetic").count() > 0
    both = fit_test(ansur_db, "mass <= 100 kg", EVERYONE)
    for g in ("male", "female"):
        assert both.genders[g].fit == ansur.genders[g].fit + synthetic.genders[g].fit


def test_json_is_the_issue_shape(ansur_db):
    result = fit_test(ansur_db, "stature <= 190 cm AND mass <= 110 kg", failing=True)
    data = json.loads(json.dumps(result.to_json(), allow_nan=False))
    assert set(data) >= {"limits", "mix", "accommodated", "naive_percent", "by_limit", "failing"}
    assert data["limits"] == ["stature <= 190 cm", "mass <= 110 kg"]
    assert set(data["accommodated"]) == {"male", "female", "weighted"}
    assert set(data["accommodated"]["male"]) >= {"n", "fit", "percent"}
    assert set(data["by_limit"][0]) >= {"limit", "excluded", "only_limit"}
    assert {f["id"] for f in data["failing"]} == {f.id for f in result.failing}
    assert all(set(f) >= {"id", "limits"} for f in data["failing"])


@pytest.mark.parametrize(
    "mix,message",
    [
        ({"male": -1.0}, ">= 0"),
        ({"male": 0.0, "female": 0.0}, "add up to 0"),
        ({"male": float("nan")}, ">= 0"),
        ({"other": 1.0}, "unknown gender"),
    ],
)
def test_bad_mix_is_refused(mix, message):
    with pytest.raises(FitError, match=message):
        check_mix(mix)


def test_a_query_wholly_in_parentheses_is_one_term():
    assert [c.text for c in compile_conjuncts(" ((stature < 3 cm AND mass > 3 kg)) ")] == [
        "(stature < 3 cm AND mass > 3 kg)"
    ]
    assert len(compile_conjuncts("(stature < 3 cm) AND (mass > 3 kg)")) == 2


def test_top_level_or_is_refused_pointing_at_it():
    with pytest.raises(QueryError, match="OR at the top level") as info:
        compile_conjuncts("stature < 190 cm OR mass < 100 kg")
    assert info.value.column == len("stature < 190 cm ") + 1


def test_empty_population_is_an_error(ansur_db):
    with pytest.raises(FitError, match="selects nobody"):
        fit_test(ansur_db, "mass < 100 kg", "stature < 1 cm")


_TERMS = st.sampled_from(
    [
        "stature <= 190 cm",
        "mass > 50 kg",
        "gender = male",
        "girth.neck.x < 13",
        "(stature < 170 cm OR mass > 90 kg)",
        "(mass < 80 kg AND stature > 150 cm)",
    ]
)


@given(st.lists(_TERMS, min_size=1, max_size=6))
def test_conjuncts_are_the_and_terms(terms):
    text = " AND ".join(terms)
    compiled = compile_conjuncts(text)
    # a parenthesised group (AND or OR) is one term
    assert [c.text for c in compiled] == terms
    whole = compile_query(text)
    # the whole query also holds the real-people scope's two parameters (db/query/scope.py:
    # not the demonstration people, not the virtual people)
    assert sum(len(c.params) for c in compiled) == len(whole.params) - 2


def _sass(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "sass_tui", *args], capture_output=True, text=True, timeout=120
    )


def test_cli_json_matches_the_engine(ansur_db_file, ansur_db):
    limits = "stature <= 190 cm AND mass <= 110 kg"
    done = _sass(
        "fit", "--db", ansur_db_file, "--mix", "male=0.7,female=0.3", "--format", "json",
        limits,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    data = json.loads(done.stdout)
    expected = fit_test(ansur_db, limits, mix={"male": 0.7, "female": 0.3}).to_json()
    assert data == expected
    assert data["failing"] is None


def test_cli_table_and_errors(ansur_db_file):
    done = _sass("fit", "--db", ansur_db_file, "--failing",
                 "stature <= 190 cm AND mass <= 110 kg")  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "weighted" in done.stdout and "only limit" in done.stdout
    assert "people fail a limit" in done.stdout
    bad = _sass("fit", "--db", ansur_db_file, "--population", "statur > 3", "mass < 3")
    assert bad.returncode == 2
    assert "sass fit: error: --population" in bad.stderr and "Traceback" not in bad.stderr
    bad = _sass("fit", "--db", ansur_db_file, "--mix", "male=1,x=2", "mass < 3")
    assert bad.returncode == 2 and "GENDER=WEIGHT" in bad.stderr


_WEIGHTS = st.floats(0, 1e6, allow_nan=False, allow_infinity=False)


@given(st.dictionaries(st.sampled_from(["male", "female"]), _WEIGHTS, min_size=1))
def test_mix_argument_reads_what_it_is_given(mix):
    from sass_tui.cli.fit import mix_argument

    text = ",".join(f"{g}={w!r}" for g, w in mix.items())
    assert mix_argument(text) == mix
    if len(mix) == 1 and max(mix.values()) > 1:  # one share alone is at most 1
        with pytest.raises(FitError, match="a share from 0 to 1"):
            check_mix(mix)
    elif sum(mix.values()) > 0 or len(mix) == 1:
        normalised = check_mix(mix)
        assert sum(normalised.values()) == pytest.approx(1.0)
    else:
        with pytest.raises(FitError):
            check_mix(mix)


@given(st.text(max_size=30))
def test_mix_argument_refuses_or_reads_any_text(text):
    import argparse

    from sass_tui.cli.fit import mix_argument

    try:
        mix = mix_argument(text)
    except argparse.ArgumentTypeError as exc:
        assert str(exc)
    else:
        assert set(mix) <= {"male", "female"}


@given(st.text(max_size=40))
def test_family_arguments_refuse_or_read_any_text(text):
    import argparse

    from sass_tui.cli.family import coverage_argument, measures_argument

    for parse in (coverage_argument, measures_argument):
        try:
            value = parse(text)
        except argparse.ArgumentTypeError as exc:
            assert str(exc)
        else:
            assert value is not None


def test_limit_lines_read_numeric_comparisons_in_canonical_units():
    from sass_tui.db.populations.fit import LimitLine, limit_lines

    lines = limit_lines(
        "gender = male AND stature > 63 in AND (mass > 50 kg AND mass < 200 lb) "
        "AND branch = 'Combat Arms' AND measure.sittingheight <= 95 cm"
    )
    assert [(x.field, x.op) for x in lines] == [
        ("stature", ">"),
        ("mass", ">"),
        ("mass", "<"),
        ("measure.sittingheight", "<="),
    ]
    assert lines[0].value == pytest.approx(160.02)
    assert lines[2].value == pytest.approx(90.718474)
    assert lines[3] == LimitLine("measure.sittingheight", "<=", 95.0)
    assert limit_lines("gender = female") == ()


def test_limit_histograms_count_every_person_of_the_population(engine_db):
    from sass_tui.db.populations.fit import limit_histograms

    (mass, stature) = limit_histograms(
        engine_db, "mass < 200 lb AND mass > 50 AND stature < 190 cm", "source = ansur2", bins=7
    )
    assert mass.field == "mass" and [x.op for x in mass.lines] == ["<", ">"]
    assert [x.value for x in mass.lines] == pytest.approx([90.718474, 50.0])
    mark = mark_of(engine_db)
    for hist, column in ((mass, "mass"), (stature, "stature")):
        assert len(hist.edges) == 8
        for line in hist.lines:
            assert hist.edges[0] <= line.value <= hist.edges[-1]
        for gender in ("male", "female"):
            values = [
                v
                for (v,) in engine_db.execute(
                    f"SELECT {column} FROM person WHERE source = 'ansur2' AND gender = {mark}",
                    (gender,),
                )
            ]
            expected = [
                sum(1 for v in values if lo <= v < hi or (k == 6 and v == hi))
                for k, (lo, hi) in enumerate(zip(hist.edges, hist.edges[1:]))
            ]
            assert hist.counts[gender].tolist() == expected
            assert sum(expected) == len(values)
