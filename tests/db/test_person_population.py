"""`sass person` (the headless Disp. Indv.) against the published CSV, and
`sass population` (populations from a selection) against medians computed
independently with plain SQL and the statistics module, on both engines
(tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json
import statistics

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.db.engine.dialect import ids_in
from sass_tui.db.engine.schema import QUERY_TABLES
from sass_tui.db.populations.population import (
    MIN_PEOPLE,
    PopulationError,
    parse_id_list,
    population_of,
)
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.measures import MEASURES
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, ROWS

FILES = ("ANSUR_II_MALE_Public.csv", "ANSUR_II_FEMALE_Public.csv")
KEYS = {
    "id",
    "name",
    "gender",
    "mass",
    "stature",
    "age",
    "source",
    "values",
    "measures",
    "unmeasured",
}


@pytest.fixture(scope="module")
def survey(ansur_dir) -> dict[str, dict[str, str]]:
    out = {}
    for name in FILES:
        with (ansur_dir / name).open(encoding="cp1252", newline="") as handle:
            for row in csv.DictReader(handle):
                row = {k.lower(): v for k, v in row.items()}
                letter = "M" if row["gender"] == "Male" else "F"
                out[f"ANSUR II {letter} {row['subjectid']}"] = row
    return out


def _json(capsys, *argv) -> dict:
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


def test_person_json_gives_the_survey_values(shared_target, survey, capsys):
    names = ["ANSUR II M 10027", "ANSUR II F 10037", "ANSUR II M 29452"]
    names = [n for n in names if n in survey][:2] + [next(n for n in survey if " F " in n)]
    out = _json(capsys, "person", "--db", shared_target, "--format", "json", *names)
    assert [p["name"] for p in out["persons"]] == names
    for person in out["persons"]:
        row = survey[person["name"]]
        assert set(person) == KEYS
        assert person["gender"] == row["gender"].lower()
        assert person["source"] == "ansur2"
        assert person["stature"] == pytest.approx(float(row["stature"]) / 10)
        assert person["mass"] == pytest.approx(float(row["weightkg"]) / 10)
        assert person["age"] == float(row["age"])
        assert set(person["measures"]) == set(MEASURES)
        for name in MEASURES:
            scale = 100 if name == "interpupillarybreadth" else 10
            assert person["measures"][name] == pytest.approx(float(row[name]) / scale)
        assert person["values"]["branch"] == row["branch"]
        assert person["values"]["component"] == row["component"]
        assert person["values"]["dodrace"] == int(row["dodrace"])
        unmeasured = set(person["unmeasured"])
        assert "joint_limit.right_shoulder_ul.x" in unmeasured
        assert "center_of_mass.neck.z" in unmeasured
        assert "strength.elbow_flexion.max" in unmeasured
        assert not any(u.startswith("measure.") for u in unmeasured)
        assert not unmeasured & set(person["values"])


def test_person_by_id_and_the_unmeasured(shared_target, capsys):
    out = _json(capsys, "person", "--db", shared_target, "--format", "json", "1")
    person = out["persons"][0]
    assert person["name"] == "SYNTH_M_001" and person["source"] == "synthetic"
    assert person["measures"] == {}
    assert {f"measure.{m}" for m in MEASURES} <= set(person["unmeasured"])
    assert person["values"]["girth.right_upper_arm.z"] > 20
    assert person["values"]["strength.elbow_flexion.max"] > 0


def test_person_table_and_errors(shared_target, capsys):
    assert main(["person", "--db", shared_target, "ansur ii m 10027", "2"]) == 0
    out = capsys.readouterr().out
    assert "ANSUR II M 10027" in out and "SYNTH_M_002" in out and "sittingheight" in out
    assert main(["person", "--db", shared_target, "nobody at all"]) == 2
    assert "no person with id or name 'nobody at all'" in capsys.readouterr().err


QUERY = "gender = female AND age < 25"


def _medians_by_sql(conn, table: str, axis: str) -> tuple[float, int]:
    values = [
        v
        for (v,) in conn.execute(
            f"SELECT q.{axis} FROM person p JOIN {table} q ON q.id_num = p.id_num "
            "WHERE p.gender = 'female' AND p.age < 25 AND q.{axis} IS NOT NULL "
            "AND p.source != 'synthetic' AND substr(p.source, 1, 8) != 'virtual:'".replace(
                "{axis}", axis
            )
        )
    ]
    return (statistics.median(values) if values else float("nan")), len(values)


def test_population_file_50th_are_the_medians(engine_db, shared_target, tmp_path, capsys):
    target = tmp_path / "young.dat"
    assert main(["population", "--db", shared_target, "--query", QUERY, "-o", str(target)]) == 0
    said = capsys.readouterr().out
    assert "young.dat" in said and "young-cmass.dat" in said
    women = engine_db.execute(
        "SELECT count(*) FROM person WHERE gender = 'female' AND age < 25 "
        "AND source != 'synthetic' AND substr(source, 1, 8) != 'virtual:'"  # real people only
    ).fetchone()[0]
    for group, path, table_group in (
        (GIRTH, target, "girth"),
        (CENTER_OF_MASS, tmp_path / "young-cmass.dat", "center_of_mass"),
    ):
        data = read_population_file(path, group)
        assert data.has("female") and not data.has("male")
        assert QUERY in data.title and f"{women} women" in data.title
        stats = data.stats("female")
        checked = 0
        for r, row in enumerate(ROWS[group]):
            table = QUERY_TABLES[table_group][row.name]
            for a, axis in enumerate("xyz"):
                median, n = _medians_by_sql(engine_db, table, axis)
                if n >= MIN_PEOPLE:
                    assert stats[r, a, 1] == pytest.approx(median, abs=1e-4), (row.name, axis)
                    checked += 1
                else:  # the report's, scaled by stature (test_population_complete.py)
                    assert stats[r, a, 1] == stats[r, a, 1]
        # no real person has a center of mass: that file is the model's (ANSUR II measured none)
        assert checked > 20 if group == GIRTH else checked == 0
    fig = tmp_path / "young.fig"
    assert main(["fig", "--girth", str(target), "--gender", "female", "-o", str(fig)]) == 0
    assert fig.is_file()


def test_population_5th_and_95th(engine_db):
    result = population_of(engine_db, "gender = male AND source = ansur2", date="2026-01-01")
    stats = result.groups[GIRTH].stats("male")
    arm = [
        v
        for (v,) in engine_db.execute(
            "SELECT q.z FROM person p JOIN q_girth_right_upper_arm q ON q.id_num = p.id_num "
            "WHERE p.gender = 'male' AND p.source = 'ansur2'"
        )
    ]
    cuts = statistics.quantiles(arm, n=20, method="inclusive")
    r = [row.name for row in ROWS[GIRTH]].index("right_upper_arm")
    assert stats[r, 2, 0] == pytest.approx(cuts[0])
    assert stats[r, 2, 2] == pytest.approx(cuts[-1])
    # ANSUR II has no centers of mass: every cell of that group is the stature model's
    assert result.modelled[CENTER_OF_MASS] == 3 * len(ROWS[CENTER_OF_MASS])
    assert "2026-01-01" in result.groups[GIRTH].title and "4082 men" in result.groups[GIRTH].title


def test_a_gender_with_too_few_people_is_refused(engine_db, shared_target, tmp_path, capsys):
    with pytest.raises(PopulationError, match=r"only 1 woman; .* at least 20"):
        population_of(engine_db, "gender = female AND age < 18")
    men = engine_db.execute(
        "SELECT count(*) FROM person WHERE gender = 'male' AND age < 19"
    ).fetchone()[0]
    assert men >= MIN_PEOPLE
    with pytest.raises(PopulationError, match=r"only 1 woman;"):  # the men alone would do
        population_of(engine_db, "age < 19 AND (gender = male OR age < 18)")
    argv = ["population", "--db", shared_target, "--query", "age < 18"]
    assert main([*argv, "-o", str(tmp_path / "x.dat")]) == 2
    assert "only 1 man and 1 woman" in capsys.readouterr().err
    target = tmp_path / "none.dat"
    with pytest.raises(PopulationError, match="selects nobody"):
        population_of(engine_db, "stature > 500 cm")
    assert not target.exists()


def test_population_of_a_list_of_ids_is_exactly_those_people(engine_db):
    """The selected list's path: every third young woman's id (not what any
    query selects); the 50th are the medians of exactly those people."""
    ids = [
        r[0]
        for r in engine_db.execute(
            "SELECT id_num FROM person WHERE gender = 'female' AND age < 25 ORDER BY id_num"
        )
    ][::3]
    assert len(ids) >= MIN_PEOPLE
    result = population_of(engine_db, ids=list(reversed(ids)), date="2026-01-01")
    assert result.counts == {"female": len(ids)}
    stats = result.groups[GIRTH].stats("female")
    listed, marks = ids_in(engine_db, "id_num", ids)
    r = [row.name for row in ROWS[GIRTH]].index("right_upper_arm")
    arm = [
        v
        for (v,) in engine_db.execute(
            f"SELECT z FROM q_girth_right_upper_arm WHERE {listed}", (marks,)
        )
    ]
    assert len(arm) == len(ids)
    assert stats[r, 2, 1] == pytest.approx(statistics.median(arm))
    assert f"selected list of {len(ids):,} people" in result.groups[GIRTH].title
    # a query narrows the list: only the people of the list it selects
    both = population_of(engine_db, "age < 22", ids=ids)
    (n,) = engine_db.execute(
        f"SELECT count(*) FROM person WHERE age < 22 AND {listed} "
        "AND source != 'synthetic' AND substr(source, 1, 8) != 'virtual:'",  # real people only
        (marks,),
    ).fetchone()
    assert both.counts == {"female": n}
    with pytest.raises(PopulationError, match=r"selected list of 5 people selects only 5 women"):
        population_of(engine_db, ids=ids[:5])
    with pytest.raises(PopulationError, match="selects nobody"):
        population_of(engine_db, ids=[])


# --- `sass population --ids`: the selected list's population, from the shell -----


def _young_women_ids(conn) -> list[int]:
    return [
        r[0]
        for r in conn.execute(
            "SELECT id_num FROM person WHERE gender = 'female' AND age < 25 ORDER BY id_num"
        )
    ][::3]


def test_population_from_a_file_of_ids(engine_db, shared_target, tmp_path, capsys):
    """Every third young woman, listed one id a line with a comment, a blank
    line, a repeat and two ids nobody has: the file's 50th are those people's
    medians, the title names the list, and the absent ids are reported."""
    ids = _young_women_ids(engine_db)
    listing = tmp_path / "chosen.txt"
    listing.write_text(
        "# chosen by hand\n" + "\n".join(map(str, ids)) + f"\n\n{ids[0]}\n999999991\n999999992\n"
    )
    target = tmp_path / "chosen.dat"
    argv = ["population", "--db", shared_target, "--ids", str(listing)]
    assert main([*argv, "-o", str(target)]) == 0
    said = capsys.readouterr()
    assert f"2 of the {len(ids) + 2} listed ids are not in the database: 999999991, 999999992" in (
        said.err
    )
    assert f"{len(ids)} women" in said.out
    data = read_population_file(target, GIRTH)
    assert f"the list {listing} of {len(ids) + 2:,} people" in data.title
    r = [row.name for row in ROWS[GIRTH]].index("right_upper_arm")
    listed, marks = ids_in(engine_db, "id_num", ids)
    arm = [
        v
        for (v,) in engine_db.execute(
            f"SELECT z FROM q_girth_right_upper_arm WHERE {listed}", (marks,)
        )
    ]
    assert data.stats("female")[r, 2, 1] == pytest.approx(statistics.median(arm), abs=1e-4)


def test_population_from_sass_query_csv_on_standard_input(
    shared_target, tmp_path, capsys, monkeypatch
):
    """`sass query --format csv ... | sass population --ids - --query ...`: the
    listing's first column is read (its header skipped), the query narrows it."""
    assert main(["query", "--db", shared_target, "--format", "csv", "gender = female"]) == 0
    listing = capsys.readouterr().out
    monkeypatch.setattr("sys.stdin", __import__("io").StringIO(listing))
    target = tmp_path / "young.dat"
    argv = ["population", "--db", shared_target, "--ids", "-", "--query", "age < 25"]
    assert main([*argv, "-o", str(target)]) == 0
    by_query = tmp_path / "by_query.dat"
    argv = ["population", "--db", shared_target, "--query", "gender = female AND age < 25"]
    assert main([*argv, "-o", str(by_query)]) == 0
    capsys.readouterr()
    listed = read_population_file(target, GIRTH).stats("female")
    queried = read_population_file(by_query, GIRTH).stats("female")
    np.testing.assert_allclose(listed, queried, equal_nan=True)
    assert "on standard input" in read_population_file(target, GIRTH).title


def test_population_ids_errors_say_where(shared_target, tmp_path, capsys):
    base = ["population", "--db", shared_target, "-o", str(tmp_path / "x.dat")]
    assert main(base) == 2
    assert "give --query QUERY, --ids FILE or both" in capsys.readouterr().err
    bad = tmp_path / "bad.txt"
    bad.write_text("id,name\n10027,A\n1.5,B\n")
    assert main([*base, "--ids", str(bad)]) == 2
    assert f"{bad}:3: '1.5' is not a person id" in capsys.readouterr().err
    for content, expected in (
        ("# nobody\n\n", "no person ids in it"),
        (b"\xff\xfe\x00", "not a text file"),
    ):
        bad.write_bytes(content.encode() if isinstance(content, str) else content)
        assert main([*base, "--ids", str(bad)]) == 2
        assert expected in capsys.readouterr().err
    assert main([*base, "--ids", str(tmp_path / "missing.txt")]) == 2
    assert "missing.txt" in capsys.readouterr().err
    assert not (tmp_path / "x.dat").exists()


@given(
    ids=st.lists(st.integers(min_value=0, max_value=2**63 - 1), min_size=1, max_size=30),
    header=st.booleans(),
    extra=st.lists(st.sampled_from(["", "# note", "   "]), max_size=3),
    columns=st.sampled_from(["", ",ANSUR II F 1,female", ", x"]),
)
def test_an_id_list_reads_back_the_ids_written(ids, header, extra, columns):
    lines = (["id,name"] if header else []) + [f"{i}{columns}" for i in ids] + extra
    assert parse_id_list("\n".join(lines), "ids.txt") == list(dict.fromkeys(ids))
