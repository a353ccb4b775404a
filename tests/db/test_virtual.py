"""Virtual populations (db/populations/virtual.py, model/population/virtual.py): the shipped
`nhanes-2017-2020`, made by `sass db init` (and again by `sass target` in a database
that lacks it), holds NHANES's own weighted stature
and mass, a measure NHANES took that the prediction never saw agrees with
it, and its people never count among real people.  Expected numbers are
computed here from the published CSV (../shared/data/nhanes) by cumulative
weight, not through sass.  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import json

import pytest

from sass_tui.cli import main
from sass_tui.db.engine.database import Database
from sass_tui.db.engine.dialect import mark_of
from sass_tui.db.people.values import load_values
from sass_tui.db.populations.shipped import REMAKE
from sass_tui.db.populations.targets import SHIPPED, list_targets, load_target
from sass_tui.db.populations.virtual import drop_virtual
from tests._nhanes import by_cumulative_weight, nhanes

SOURCE = 'source = "virtual:nhanes-2017-2020"'


@pytest.fixture(scope="module")
def shipped(template_target, copy_database) -> str:
    """A copy of the default database, which `sass db init` built with the
    shipped target and virtual population in it."""
    return copy_database(template_target)


def shipped_state(db: str) -> dict[str, object]:
    """What a database holds of the shipped target and virtual population:
    each target's counts, the virtual people's key, gender, stature, mass and
    a predicted measure, and every weight by the weighted person's source key."""
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            targets = {
                t.name: (t.people, t.sample_rows, round(t.effective_n, 6))
                for t in list_targets(conn)
            }
            people = conn.execute(
                "SELECT p.source_key, p.gender, p.stature, p.mass, m.chestcircumference "
                "FROM person p JOIN measure m ON m.id_num = p.id_num "
                "WHERE p.source = 'virtual:nhanes-2017-2020' ORDER BY p.source_key"
            ).fetchall()
            weights = {
                name: sorted(
                    (str(key), round(float(w), 9))
                    for key, w in conn.execute(
                        "SELECT p.source_key, w.weight FROM target_weight w "
                        f"JOIN person p ON p.id_num = w.id_num WHERE w.target = {mark_of(conn)}",
                        (name,),
                    )
                )
                for name in targets
            }
    finally:
        opened.close()
    return {
        "targets": targets,
        "people": [(k, g, round(s, 6), round(m, 6), round(c, 6)) for k, g, s, m, c in people],
        "weights": weights,
    }


@pytest.mark.slow
def test_db_init_stores_the_shipped_target_and_virtual_people(engine_target, capsys):
    """Right after `sass db init` (the engine's template): both stored, listed
    as stored rather than as made on first use, and reading them stores nothing."""
    before = shipped_state(engine_target)
    assert list(before["targets"]) == list(SHIPPED)
    assert len(before["people"]) == before["targets"]["virtual:nhanes-2017-2020"][0] == 8381
    capsys.readouterr()
    assert main(["target", "--db", engine_target, "--list"]) == 0
    listed = capsys.readouterr().out
    assert [line.split()[0] for line in listed.splitlines()] == list(SHIPPED)
    assert "first use" not in listed
    argv = ["query", "--db", engine_target, "--count", "--virtual", "nhanes-2017-2020"]
    assert main([*argv, "mass > 0"]) == 0
    assert shipped_state(engine_target) == before


@pytest.mark.slow
def test_both_engines_test_databases_agree(default_db_file, cluster, postgres_template):
    """The SQLite database the tests share (create_default_database) and the
    PostgreSQL template (`sass db init`) hold the same shipped target and
    virtual people: the same people, measures and weights, by source key."""
    url = cluster.create_database("shipped_agree", postgres_template)
    try:
        sqlite, postgresql = shipped_state(str(default_db_file)), shipped_state(str(url))
    finally:
        cluster.drop_database("shipped_agree")
    assert sqlite["targets"] == postgresql["targets"]
    assert sqlite["people"] == postgresql["people"]
    assert sqlite["weights"] == postgresql["weights"]


@pytest.mark.slow
def test_a_database_without_them_says_so_and_the_target_verb_makes_them_again(
    engine_target, capsys
):
    """Both dropped: a verb that reads them reports them missing and stores
    nothing (a read never writes; it made 8,381 people); the `sass target`
    command the message gives makes them again, the same as `sass db init`
    made them, in one transaction."""
    made = shipped_state(engine_target)
    capsys.readouterr()
    assert main(["target", "--db", engine_target, "--drop", "nhanes-2017-2020"]) == 0
    opened = Database.open(engine_target)
    try:
        with opened.connection() as conn:
            assert drop_virtual(conn, "nhanes-2017-2020") == 8381
    finally:
        opened.close()
    dropped = shipped_state(engine_target)
    assert main(["target", "--db", engine_target, "--list"]) == 0
    assert capsys.readouterr().out.count(f"not stored: `sass db init` or `{REMAKE}`") == 2
    for argv in (
        ["query", "--db", engine_target, "--count", "--virtual", "nhanes-2017-2020", "mass > 0"],
        ["stats", "--db", engine_target, "--target", "nhanes-2017-2020"],
    ):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert "is not in this database" in err and "sass db init" in err
        assert len(err.splitlines()) == 1
    assert shipped_state(engine_target) == dropped
    assert main([*REMAKE.split()[1:], "--db", engine_target]) == 0
    again = shipped_state(engine_target)
    assert again["targets"] == made["targets"]
    assert again["people"] == made["people"]


def virtual_values(db: str, fields: list[str], gender: str):
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            values = load_values(conn, fields, f"{SOURCE} AND gender = {gender}")
            weights = load_target(conn, "virtual:nhanes-2017-2020").of(values.ids)
            return values.matrix, weights
    finally:
        opened.close()


@pytest.mark.slow
@pytest.mark.parametrize(("gender", "code"), [("female", "2"), ("male", "1")])
def test_the_virtual_people_are_nhanes_own_stature_and_mass(shipped, gender, code):
    matrix, weights = virtual_values(shipped, ["stature", "mass"], gender)
    expected, survey = nhanes(code, "BMXHT", "BMXWT")
    assert len(matrix) == len(expected)
    for j in range(2):
        for q in (0.05, 0.50, 0.95):
            own = by_cumulative_weight(expected[:, j], survey, q)
            assert by_cumulative_weight(matrix[:, j], weights, q) == pytest.approx(own, abs=0.6)


@pytest.mark.slow
@pytest.mark.parametrize(("gender", "code"), [("female", "2"), ("male", "1")])
def test_fit_virtual_gives_nhanes_weighted_shares(shipped, capsys, gender, code):
    """`sass fit --virtual`'s accommodated.<gender>.percent for stature and
    mass limits is NHANES's weighted share, computed from the file."""
    (stature, mass), survey = (lambda v, w: (v.T, w))(*nhanes(code, "BMXHT", "BMXWT"))
    for s_limit, m_limit in ((165.0, 80.0), (175.5, 101.3), (158.0, 120.8)):
        inside = (stature <= s_limit) & (mass <= m_limit)
        own = 100 * survey[inside].sum() / survey.sum()
        capsys.readouterr()
        limits = f"stature <= {s_limit} cm AND mass <= {m_limit} kg"
        argv = ["fit", "--db", shipped, "--virtual", "nhanes-2017-2020", "--format", "json"]
        assert main([*argv, limits]) == 0
        result = json.loads(capsys.readouterr().out)
        assert result["accommodated"][gender]["percent"] == pytest.approx(own, abs=0.3)
        assert result["target"]["name"] == "virtual:nhanes-2017-2020"
        assert result["target"]["virtual"] is True
        assert result["target"]["people"].startswith("VIRTUAL people, not measured")


@pytest.mark.slow
@pytest.mark.parametrize(("gender", "code"), [("female", "2"), ("male", "1")])
def test_the_measured_hip_is_kept(shipped, gender, code):
    """NHANES measured hip circumference (BMXHIP, at the buttocks' widest);
    the virtual people keep it as their buttock circumference (predicted for
    the few rows without one), on both engines: their weighted 5th/50th/95th
    agree within 0.6 cm (the predicted ones move the women's 95th by 0.5 cm;
    tests/db/test_virtual_measured.py holds the adults aged 20-59 to 0.3)."""
    matrix, weights = virtual_values(shipped, ["measure.buttockcircumference"], gender)
    hip, survey = nhanes(code, "BMXHIP")
    for q in (0.05, 0.50, 0.95):
        measured = by_cumulative_weight(hip[:, 0], survey, q)
        predicted = by_cumulative_weight(matrix[:, 0], weights, q)
        assert predicted == pytest.approx(measured, abs=0.6)


@pytest.mark.slow
def test_virtual_people_never_count_as_real(shipped, capsys):
    capsys.readouterr()
    assert main(["query", "--db", shipped, "--count", "mass > 0"]) == 0
    assert capsys.readouterr().out.strip() == "6068"
    assert main(["query", "--db", shipped, "--count", SOURCE]) == 0
    assert capsys.readouterr().out.strip() == "8381"
    assert main(["target", "--db", shipped, "--list"]) == 0
    listed = capsys.readouterr().out
    assert "virtual:nhanes-2017-2020  VIRTUAL population" in listed
    assert "nhanes-2017-2020  both, by stature, mass" in listed


@pytest.mark.slow
def test_predict_learns_from_the_virtual_people(shipped, capsys):
    """`predict --virtual`: the regression is fitted on the virtual women (as
    many as NHANES's with a stature and a mass), not on the soldiers."""
    argv = ["predict", "--db", shipped, "--gender", "female", "--format", "json"]
    known = ["--known", "stature=160cm", "--known", "mass=150kg"]
    capsys.readouterr()
    assert main([*argv, *known, "--virtual", "nhanes-2017-2020"]) == 0
    virtual = json.loads(capsys.readouterr().out)
    assert main([*argv, *known]) == 0
    real = json.loads(capsys.readouterr().out)
    assert "virtual:nhanes-2017-2020" in virtual["model"]["population"]
    assert virtual["model"]["n"] == len(nhanes("2", "BMXHT")[0]) and real["model"]["n"] == 1986
    # The fit is unweighted, and says so: in the JSON, and in the table.
    assert virtual["model"]["weighted"] is False
    assert virtual["model"]["virtual"] == "nhanes-2017-2020" and real["model"]["virtual"] is None
    table = ["predict", "--db", shipped, "--gender", "female", *known, "--nearest", "2"]
    assert main([*table, "--virtual", "nhanes-2017-2020"]) == 0
    said = capsys.readouterr().out
    assert "learnt from the VIRTUAL people of nhanes-2017-2020, unweighted: each virtual " in said
    assert "nearest VIRTUAL people of nhanes-2017-2020" in said
    assert "nearest real people" not in said
    assert main(table) == 0
    said = capsys.readouterr().out
    assert "unweighted" not in said and "nearest real people" in said
