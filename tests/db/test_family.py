"""`sass family` on the default database: files that read back, coverage that
equals an independent count over the ANSUR II CSV, on both engines
(tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json
import subprocess
import sys

import numpy as np
import pytest

from sass_tui.db.engine.dialect import mark_of
from sass_tui.db.populations.family import load_family
from sass_tui.db.populations.fit import FitError
from sass_tui.db.query.query import run_query
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.population.accommodation import AccommodationError, chi2_quantile


def _sass(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "sass_tui", *args], capture_output=True, text=True, timeout=300
    )


def _csv(ansur_dir, gender: str, columns: list[str]) -> np.ndarray:
    name = "MALE" if gender == "male" else "FEMALE"
    with open(ansur_dir / f"ANSUR_II_{name}_Public.csv", encoding="cp1252", newline="") as f:
        rows = [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(f)]
    return np.array([[float(r[c]) / 10 for c in columns] for r in rows])


@pytest.fixture()
def conn(shared_db):
    return shared_db


@pytest.fixture(scope="module")
def written(shared_target, tmp_path_factory):
    out = tmp_path_factory.mktemp("family") / "seat"
    done = _sass(
        "family", "--db", shared_target, "--gender", "male", "--measures",
        "stature,weightkg,hipbreadthsitting", "--coverage", "95", "--space", "measured",
        "-o", str(out),
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    return out, done.stdout


def test_family_files_exist_and_read_back(written):
    out, stdout = written
    data = json.loads((out / "family.json").read_text())
    assert data["gender"] == "male"
    assert data["measures"] == ["stature", "mass", "measure.hipbreadthsitting"]
    assert data["coverage_target"] == 95
    assert len(data["manikins"]) == 15
    for manikin in data["manikins"]:
        assert set(manikin) >= {"name", "values", "nearest", "files"}
        fig_name, x3d_name = manikin["files"]
        figure = read_fig(out / fig_name)
        assert figure.variables
        assert "<HAnimHumanoid" in (out / x3d_name).read_text()
    assert sorted(p.name for p in out.iterdir()) == sorted(
        ["family.json"] + [f for m in data["manikins"] for f in m["files"]]
    )
    assert "chi-square promise is 95 %" in stdout


def test_family_coverage_equals_an_independent_count(written, ansur_dir):
    out, _ = written
    data = json.loads((out / "family.json").read_text())
    people = _csv(ansur_dir, "male", ["stature", "weightkg", "hipbreadthsitting"])
    offsets = people - people.mean(axis=0)
    cov = np.cov(people, rowvar=False)
    d2 = np.einsum("ij,ij->i", offsets, np.linalg.solve(cov, offsets.T).T)
    inside = 100 * np.mean(d2 <= 7.814728)  # chi-square 95 %, 3 degrees (NIST table)
    assert data["coverage"]["inside_ellipsoid"] == pytest.approx(inside, abs=1e-3)
    assert data["coverage"]["people"] == len(people) == 4082
    low = np.array([data["ranges"][m][0] for m in data["measures"]])
    high = np.array([data["ranges"][m][1] for m in data["measures"]])
    within = np.all((people >= low - 1e-4) & (people <= high + 1e-4), axis=1)
    assert data["coverage"]["within_ranges_count"] == int(within.sum())


def test_nearest_people_are_in_the_population(written, conn):
    out, _ = written
    data = json.loads((out / "family.json").read_text())
    ansur_men = set(run_query(conn, "source = ansur2 AND gender = male").ids())
    for manikin in data["manikins"]:
        nearest = manikin["nearest"]
        assert nearest["id"] in ansur_men
        name = conn.execute(
            f"SELECT name FROM person WHERE id_num = {mark_of(conn)}", (nearest["id"],)
        )
        assert name.fetchone()[0] == nearest["name"]


def test_population_chooses_the_people(conn):
    family = load_family(
        conn,
        "female",
        ["stature", "mass"],
        0.9,
        population="source = ansur2 AND age < 30",
        space="as measured",
    )
    assert (
        family.coverage.n
        == run_query(conn, "source = ansur2 AND age < 30 AND gender = female").count()
    )
    assert len(family.manikins) == 9
    points = np.array([[m.values[f] for f in family.measures] for m in family.manikins[1:]])
    d2 = family.ellipsoid.distance2(points)
    np.testing.assert_allclose(d2, chi2_quantile(0.9, 2), rtol=1e-9)


def test_distributed_family(conn):
    family = load_family(conn, "male", ["stature", "mass", "sittingheight"], 0.9, "distributed")
    assert len(family.manikins) == 29
    assert family.kind == "distributed"


def test_bad_requests(conn, shared_target, tmp_path):
    with pytest.raises(AccommodationError, match="did you mean sittingheight"):
        load_family(conn, "male", ["stature", "sittinheight"], 0.9)
    with pytest.raises(FitError, match="no female people"):
        load_family(conn, "female", ["stature", "mass"], 0.9, population="gender = male")
    done = _sass("family", "--db", shared_target, "--gender", "male", "--measures",
                 "stature", "-o", str(tmp_path / "x"))  # fmt: skip
    assert done.returncode == 2 and "2 to 6" in done.stderr
    done = _sass("family", "--db", shared_target, "--gender", "male", "--measures",
                 "stature,massx", "-o", str(tmp_path / "x"))  # fmt: skip
    assert done.returncode == 2 and "sass family: error: unknown measurement" in done.stderr
    assert not (tmp_path / "x").exists()


def test_people_lacking_a_listed_measurement_are_left_out_and_counted(conn):
    # A source term: the synthetic people too, not the shipped virtual ones.
    everyone = 'stature > 0 AND source != "virtual:nhanes-2017-2020"'
    family = load_family(conn, "male", ["stature", "sittingheight"], 0.9, population=everyone)
    lacking = run_query(conn, "gender = male AND source = synthetic").count()
    assert lacking > 0
    assert family.coverage.missing == lacking
    assert family.coverage.n == 4082
    assert json_round_trip(family)["coverage"]["not_measured"] == lacking


def json_round_trip(family) -> dict:
    return json.loads(json.dumps(family.to_json(), allow_nan=False))
