"""The verbs that compute over many people give the same answers on SQLite
and PostgreSQL after `sass db init`: `fit` (table and JSON), `target` (the
stored weights, through every verb that reads them), `population` (the files,
byte for byte but the title's date), `predict` (numbers within floating-point
noise), `family` (manikins and coverage), the query screen's lists, and a
person by `--person` (`fig`, `export`, `strength`).  The fixtures `cluster`
and `initialised` are tests/conftest.py's (a throwaway PostgreSQL cluster)."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from test_targets import civilian_women, write_sample

from sass_tui.cli import main


def both(capsys, initialised, *argv: str) -> dict[str, str]:
    """What `sass ARGV --db <engine>` prints on each engine (it must succeed)."""
    printed = {}
    for engine, target in initialised.items():
        assert main([*argv, "--db", target]) == 0, capsys.readouterr().err
        printed[engine] = capsys.readouterr().out
    return printed


@pytest.fixture(scope="module")
def with_target(initialised, tmp_path_factory) -> dict[str, str]:
    """The target `civ` (women weighted to a civilian-like sample) made on both
    engines; what `sass target` printed on each."""
    sample = write_sample(tmp_path_factory.mktemp("sample") / "civ.csv", civilian_women(3000))
    made = {}
    for engine, target in initialised.items():
        argv = ["target", "civ", "--force", "--gender", "female", "--sample", str(sample)]
        assert main([*argv, "--db", target]) == 0
        made[engine] = target
    return made


LIMITS = (
    "stature <= 190 cm AND measure.sittingheight <= 100 cm AND mass <= 110 kg "
    "AND branch != 'Combat Arms'"
)


@pytest.mark.parametrize(
    "argv",
    [
        ["fit", LIMITS],
        ["fit", "--format", "json", "--failing", "--mix", "male=0.8", LIMITS],
        ["fit", "--population", "gender = female AND age < 30", "stature <= 165 cm"],
        ["fit", "--strength", "knee_extension >= 150 N-m at knee_y=60", "stature <= 190 cm"],
        [
            "fit",
            "--format",
            "json",
            "--population",
            "source = synthetic",
            "strength.elbow_flexion.max > 20 ft-lb AND girth.right_upper_arm.z > 28 cm",
        ],
        [
            "design",
            "--accommodate",
            "90",
            "stature <= 190 cm AND mass <= ? AND measure.hipbreadthsitting BETWEEN ? AND ?",
        ],
    ],  # fmt: skip
)
def test_fit_prints_the_same_on_both_engines(initialised, capsys, argv):
    printed = both(capsys, initialised, *argv)
    assert printed["postgresql"] == printed["sqlite"]
    if "json" in argv:
        result = json.loads(printed["sqlite"])
        shares = [g["percent"] for k, g in result["accommodated"].items() if k != "weighted"]
        assert any(0 < s < 100 for s in shares), shares  # not a vacuous agreement
        if "--failing" in argv:
            assert len(result["failing"]) > 10


def test_a_target_is_the_same_on_both_engines(with_target, initialised, capsys):
    listed = both(capsys, initialised, "target", "--list")
    created = re.compile(r"; \d{4}-\d\d-\d\dT[0-9:+]+$", re.M)
    assert created.sub("", listed["postgresql"]) == created.sub("", listed["sqlite"])
    assert "effective n" in listed["sqlite"]
    # the weights, read back by each verb that takes --target
    limits = "stature <= 165 cm AND mass <= 80 kg"
    fitted = both(capsys, initialised, "fit", "--format", "json", "--target", "civ", limits)
    assert fitted["postgresql"] == fitted["sqlite"]
    assert json.loads(fitted["sqlite"])["target"]["percent"] > 0
    counted = both(capsys, initialised, "query", "--count", "--target", "civ", "stature <= 165 cm")
    assert counted["postgresql"] == counted["sqlite"] and "weighted:" in counted["sqlite"]


@pytest.mark.slow
def test_a_target_is_dropped_on_postgresql(cluster, postgres_template, tmp_path, capsys):
    url = cluster.create_database("targets", postgres_template)  # after `sass db init`
    sample = write_sample(tmp_path / "civ.csv", civilian_women(500))
    argv = ["target", "t1", "--gender", "female", "--sample", str(sample), "--db", url]
    assert main(argv) == 0
    assert main(argv) == 2  # stored already, no --force
    assert "exists" in capsys.readouterr().err
    assert main(["target", "--drop", "t1", "--db", url]) == 0
    capsys.readouterr()
    assert main(["target", "--list", "--db", url]) == 0
    listed = capsys.readouterr().out.splitlines()  # the shipped ones db init made stay
    assert [line.split()[0] for line in listed] == ["nhanes-2017-2020", "virtual:nhanes-2017-2020"]


DATE = re.compile(rb"\d{4}-\d\d-\d\d\)$", re.M)


def files_of(folder: Path) -> dict[str, bytes]:
    """Every file under `folder` by its relative name, the title's date blanked."""
    return {
        str(p.relative_to(folder)): DATE.sub(b"DATE)", p.read_bytes())
        for p in sorted(folder.rglob("*"))
        if p.is_file()
    }


def run_in(engine_dirs: dict[str, Path], initialised, capsys, *argv: str) -> dict[str, str]:
    """`sass ARGV --db <engine>` with its output written under a folder per engine
    (`{out}` in ARGV); what it printed, the folder's name replaced by OUT."""
    printed = {}
    for engine, target in initialised.items():
        out = engine_dirs[engine]
        args = [a.replace("{out}", str(out)) for a in argv]
        assert main([*args, "--db", target]) == 0, capsys.readouterr().err
        captured = capsys.readouterr()
        printed[engine] = (captured.out + captured.err).replace(str(out), "OUT")
    return printed


@pytest.fixture()
def engine_dirs(tmp_path) -> dict[str, Path]:
    dirs = {"sqlite": tmp_path / "sqlite", "postgresql": tmp_path / "postgresql"}
    for folder in dirs.values():
        folder.mkdir()
    return dirs


@pytest.mark.slow
def test_population_files_are_the_same_on_both_engines(
    initialised, with_target, engine_dirs, capsys, tmp_path
):
    ids = tmp_path / "ids.csv"
    assert main(["query", "--format", "csv", "--db", initialised["sqlite"], "stature > 160 cm"
                 " AND source = synthetic"]) == 0  # fmt: skip
    ids.write_text(capsys.readouterr().out + "999999\n", encoding="utf-8")
    for argv in (
        ["population", "--query", "gender = female AND age < 25", "-o", "{out}/young.dat"],
        ["population", "--ids", str(ids), "-o", "{out}/listed.dat"],
        [
            "population",
            "--ids",
            str(ids),
            "--query",
            "gender = male AND source = synthetic",
            "-o",
            "{out}/men.dat",
        ],
        ["population", "--target", "civ", "-o", "{out}/civ.dat"],
    ):
        printed = run_in(engine_dirs, initialised, capsys, *argv)
        assert printed["postgresql"] == printed["sqlite"]
    made = {engine: files_of(folder) for engine, folder in engine_dirs.items()}
    assert made["postgresql"] == made["sqlite"]
    assert len(made["sqlite"]) == 4 * 3  # girth, center of mass, stature and mass each


def close(a: object, b: object) -> bool:
    """Equal, numbers within floating-point noise (relative 1e-9)."""
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(close(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(close(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, (int, float)):
        return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-9)
    return a == b


@pytest.mark.slow
@pytest.mark.parametrize(
    "argv",
    [
        [
            "--gender",
            "male",
            "--known",
            "stature=175.5cm",
            "--known",
            "mass=82.2kg",
            "--nearest",
            "5",
        ],
        [
            "--gender",
            "female",
            "--population",
            "branch = 'Combat Arms'",
            "--known",
            "stature=165cm",
        ],
    ],  # fmt: skip
)
def test_predict_gives_the_same_numbers_on_both_engines(initialised, capsys, argv):
    printed = both(capsys, initialised, "predict", "--format", "json", *argv)
    sqlite, postgresql = (json.loads(printed[e]) for e in ("sqlite", "postgresql"))
    assert close(postgresql, sqlite)
    assert sqlite["model"]["n"] > 20 and len(sqlite["predicted"]) > 50


@pytest.mark.slow
def test_predict_csv_batch_on_both_engines(initialised, engine_dirs, capsys, tmp_path):
    known = tmp_path / "known.csv"
    known.write_text("stature,mass\n175 cm,80 kg\n190 cm,95 kg\n", encoding="utf-8")
    run_in(engine_dirs, initialised, capsys, "predict", "--gender", "male", "--input", str(known),
           "--output", "{out}/predicted.csv")  # fmt: skip
    rows = {}
    for engine, folder in engine_dirs.items():
        lines = (folder / "predicted.csv").read_text(encoding="utf-8").splitlines()
        rows[engine] = [line.split(",") for line in lines]
    assert rows["sqlite"][0] == rows["postgresql"][0] and len(rows["sqlite"]) == 3
    for a, b in zip(rows["sqlite"][1:], rows["postgresql"][1:]):
        assert close([number(x) for x in a], [number(x) for x in b])


def number(cell: str) -> float | str:
    try:
        return float(cell)
    except ValueError:
        return cell  # an input column as given, e.g. '175 cm'


@pytest.mark.slow
@pytest.mark.parametrize(
    "argv",
    [
        ["--gender", "female", "--measures", "stature,mass,sittingheight", "--coverage", "90"],
        [
            "--gender",
            "male",
            "--measures",
            "stature,mass",
            "--kind",
            "distributed",
            "--coverage",
            "95",
            "--population",
            "branch = 'Combat Arms'",
        ],
        ["--gender", "female", "--measures", "stature,mass", "--coverage", "90", "--target", "civ"],
    ],  # fmt: skip
)
def test_family_is_the_same_on_both_engines(initialised, with_target, engine_dirs, capsys, argv):
    printed = run_in(engine_dirs, initialised, capsys, "family", *argv, "-o", "{out}/family")
    assert printed["postgresql"] == printed["sqlite"]
    assert "inside the ellipsoid" in printed["sqlite"]
    made = {engine: files_of(folder) for engine, folder in engine_dirs.items()}
    assert made["postgresql"] == made["sqlite"] and len(made["sqlite"]) > 3


# --- the query screen's lists (the TUI's database work) ------------------------


def lists_work(target: str) -> dict[str, object]:
    """Everything the query screen asks of its lists, on one engine."""
    from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists

    lists = QueryLists.open(target)
    try:
        seen: dict[str, object] = {}
        seen["run"] = lists.run("gender = female AND stature > 175 cm")
        first = lists.page(QUERY_LIST, 0, 10)
        seen["page"] = first
        assert lists.select_one(first[3]["id"]) and not lists.select_one(first[3]["id"])
        assert lists.select_one(first[1]["id"])
        seen["after select"] = (lists.count(QUERY_LIST), lists.count(SELECTED_LIST))
        seen["selected"] = lists.selected_ids()  # in the order selected
        seen["rerun"] = lists.run("gender = female AND stature > 175 cm")  # the selected stay out
        seen["ranges"] = lists.run("stature > 170 cm", progress=lambda done, total: None)
        seen["select all"] = lists.select_all()
        assert lists.delete_one(SELECTED_LIST, seen["selected"][0])  # type: ignore[index]
        seen["selected page"] = lists.page(SELECTED_LIST, 0, 5)
        seen["person"] = lists.fetch_selected(0).name
        fit, histograms = lists.fit_test("stature <= 190 cm AND mass <= 100 kg", "source = ansur2")
        seen["fit"] = fit.to_json()
        seen["histograms"] = [(h.field, h.edges.tolist(), h.missing) for h in histograms]
        population = lists.population_of(tuple(lists.selected_ids()), "the selected people")
        seen["population"] = (population.counts, population.modelled)
        seen["hint"] = lists.demonstration_hint("strength.elbow_flexion.max > 20 ft-lb")
        return seen
    finally:
        lists.close()


@pytest.mark.slow
def test_the_query_screens_lists_work_the_same_on_both_engines(initialised):
    sqlite, postgresql = (lists_work(initialised[e]) for e in ("sqlite", "postgresql"))
    assert close(postgresql, sqlite), [k for k in sqlite if not close(postgresql[k], sqlite[k])]
    assert sqlite["run"] > 10 and sqlite["select all"] > 100 and sqlite["hint"]


# --- a person of the database as a figure, a humanoid, strength (--person) ---------


@pytest.mark.parametrize(
    "argv",
    [
        ["fig", "--person", "17", "-o", "{out}/person.fig"],
        ["fig", "--person", "ANSUR II M 10032", "--percentile", "5", "-o", "{out}/person.fig"],
        ["export", "hanim", "--person", "ansur ii f 10037", "-o", "{out}/person.x3d"],
        ["strength", "--person", "17", "--format", "json", "knee_extension", "knee_y=60"],
    ],
)
def test_a_person_is_the_same_on_both_engines(initialised, engine_dirs, capsys, argv):
    printed = run_in(engine_dirs, initialised, capsys, *argv)
    assert printed["postgresql"] == printed["sqlite"]
    made = {engine: files_of(folder) for engine, folder in engine_dirs.items()}
    assert made["postgresql"] == made["sqlite"]
    assert made["sqlite"] or '"person"' in printed["sqlite"] or "17" in printed["sqlite"]


@pytest.mark.slow
def test_the_lists_on_postgresql_import_and_outlive_a_restart(
    cluster, postgres_template, ansur_dir
):
    """The query screen's Input DB imports into PostgreSQL (staged, one
    transaction); after a server restart the lists start again, empty, and work."""
    from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST, QueryLists

    url = cluster.create_database("lists", postgres_template)  # after `sass db init`
    lists = QueryLists.open(url)
    try:
        female = ansur_dir / "ANSUR_II_FEMALE_Public.csv"
        women = lists.import_ansur(female, "desk")
        assert women > 1000 and lists.run("source = desk") == women
        lists.select_one(lists.page(QUERY_LIST, 0, 1)[0]["id"])
        assert lists.count(SELECTED_LIST) == 1
        cluster.restart()
        assert lists.page(SELECTED_LIST, 0, 5) == []
        assert (lists.count(QUERY_LIST), lists.count(SELECTED_LIST)) == (0, 0)
        assert lists.run("source = desk AND stature > 170 cm") > 0
    finally:
        lists.close()


def test_a_long_statement_on_postgresql_is_cancelled(initialised):
    """Escape on a screen sets the cancel: a PostgreSQL statement running then
    is cancelled by the server at once, as SQLite's is interrupted."""
    import threading
    import time

    from sass_tui.db.engine.database import Database
    from sass_tui.db.progress import Cancelled, interruptible

    db = Database.open(initialised["postgresql"])
    try:
        with db.connection() as conn:
            cancel = threading.Event()
            threading.Timer(0.3, cancel.set).start()
            started = time.monotonic()
            with pytest.raises(Cancelled):
                with interruptible(conn, cancel, "the sleep"):
                    conn.execute("SELECT pg_sleep(30)")
            assert time.monotonic() - started < 10
            assert conn.execute("SELECT 1").fetchone()[0] == 1  # the connection goes on
    finally:
        db.close()
