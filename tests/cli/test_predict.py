"""`sass predict` on a database imported from the ANSUR II files, and the
cached fit beside it (sass_tui/db/populations/predict.py)."""

from __future__ import annotations

import csv
import json
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from _built_once import built_once

from sass_tui.cli import main
from sass_tui.db.engine.schema import connect, transaction
from sass_tui.db.people.ansur import import_ansur
from sass_tui.db.people.people_store import delete_people
from sass_tui.db.populations.predict import cache_path, data_key, open_predictor
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.population.prediction import Predictor

# SQLite only: the fit is cached beside the SQLite file; predict on both
# engines is tests/db/test_engines_verbs.py's.

KNOWN = ["--known", "stature=175.5cm", "--known", "mass=82.2kg"]


@pytest.fixture(scope="session")
def ansur_db_file(ansur_dir, tmp_path_factory) -> Path:
    """A database holding ANSUR II, imported from the published files once a
    run (tests/_built_once.py), with its fit cached beside it; never written."""

    def build(folder: Path) -> None:
        conn = connect(folder / "ansur.db", create=True)
        try:
            import_ansur(
                conn,
                [ansur_dir / "ANSUR_II_MALE_Public.csv", ansur_dir / "ANSUR_II_FEMALE_Public.csv"],
            )
            open_predictor(conn)  # the fit, cached beside the file
        finally:
            conn.close()

    return built_once(tmp_path_factory, "predict-ansur", build) / "ansur.db"


@pytest.fixture()
def db(ansur_db_file, tmp_path) -> Path:
    """A private copy of the ANSUR II database and its cached fit (tests may write to it)."""
    copy = tmp_path / "ansur.db"
    shutil.copyfile(ansur_db_file, copy)
    shutil.copyfile(f"{ansur_db_file}.predict.npz", f"{copy}.predict.npz")
    return copy


@pytest.fixture(scope="session")
def predictor(ansur_db_file) -> Predictor:
    conn = connect(ansur_db_file)
    try:
        return open_predictor(conn, cache=False)
    finally:
        conn.close()


def _json(capsys, *argv: str) -> dict:
    assert main(["predict", *argv]) == 0
    return json.loads(capsys.readouterr().out)


def test_json_has_the_issues_shape(db, capsys):
    doc = _json(
        capsys, "--db", str(db), "--gender", "male", *KNOWN, "--format", "json", "--nearest", "3"
    )
    assert set(doc) == {"gender", "known", "predicted", "nearest", "model"}
    assert doc["gender"] == "male"
    assert doc["known"] == {"stature": 175.5, "mass": 82.2}
    assert "stature" not in doc["predicted"]
    arm = doc["predicted"]["girth.right_upper_arm.z"]
    assert set(arm) == {"value", "unit", "low", "high"} and arm["unit"] == "cm"
    assert arm["low"] < arm["value"] < arm["high"]
    assert doc["predicted"]["measure.sittingheight"]["unit"] == "cm"
    conn = connect(db)
    has_com = conn.execute("SELECT count(cmass_x) FROM center_of_mass").fetchone()[0] > 0
    conn.close()
    # centers of mass are predicted when the import derives them
    assert any(name.startswith("center_of_mass.") for name in doc["predicted"]) == has_com
    assert len(doc["nearest"]) == 3
    assert all(set(n) == {"id", "name", "distance"} for n in doc["nearest"])
    assert [n["distance"] for n in doc["nearest"]] == sorted(n["distance"] for n in doc["nearest"])
    assert doc["model"]["n"] == 4082
    assert set(doc["model"]["cv_rmse"]) == set(doc["predicted"])
    # the leave-one-out error is a little above the model's own residual SD
    sd = (arm["high"] - arm["value"]) / 1.6448536
    assert 0.9 * sd < doc["model"]["cv_rmse"]["girth.right_upper_arm.z"] < 1.1 * sd


def test_the_predicted_fig_file_reads_back(db, tmp_path, capsys, predictor):
    out = tmp_path / "P.fig"
    assert main(["predict", "--db", str(db), "--gender", "male", *KNOWN, "-o", str(out)]) == 0
    assert f"wrote {out}" in capsys.readouterr().out
    fig = read_fig(out)
    prediction = predictor.predict("male", {"stature": 175.5, "mass": 82.2})
    assert fig.variables["ruparmz"][0] == pytest.approx(
        prediction.values["girth.right_upper_arm.z"].value, abs=0.005
    )
    assert fig.variables["ruparmmass"][0] == pytest.approx(0.028 * 82.2, abs=0.005)
    assert "predicted from stature 175.5 cm, mass 82.2 kg" in out.read_text()


def test_the_predicted_hanim_humanoid_is_x3d(db, tmp_path, capsys):
    out = tmp_path / "P.x3d"
    assert (
        main(
            [
                "predict",
                "--db",
                str(db),
                "--gender",
                "female",
                "--known",
                "stature=64in",
                "-o",
                str(out),
            ]
        )
        == 0
    )
    root = ET.parse(out).getroot()
    assert root.tag == "X3D"
    assert "predicted from stature 162.56 cm" in out.read_text()


def test_table_and_csv_formats(db, capsys):
    assert main(["predict", "--db", str(db), "--gender", "male", *KNOWN, "--nearest", "2"]) == 0
    table = capsys.readouterr().out
    assert table.startswith("male, predicted from stature 175.5 cm, mass 82.2 kg")
    assert "nearest real people" in table
    assert main(["predict", "--db", str(db), "--gender", "male", *KNOWN, "--format", "csv"]) == 0
    rows = list(csv.DictReader(capsys.readouterr().out.splitlines()))
    by_field = {r["field"]: r for r in rows}
    assert by_field["stature"]["known"] == "1" and float(by_field["stature"]["value"]) == 175.5
    assert by_field["measure.sittingheight"]["known"] == "0"


def test_batch_csv(db, tmp_path, capsys, predictor):
    source = tmp_path / "known.csv"
    source.write_text(
        "id,stature,mass,note\na,175.5,82.2,first\nb,70 in,,no mass\nc,160cm,176 lb,\n"
    )
    target = tmp_path / "predicted.csv"
    argv = ["predict", "--db", str(db), "--gender", "male", "--input", str(source)]
    assert main([*argv, "--output", str(target)]) == 0
    assert "(3 people)" in capsys.readouterr().out
    rows = list(csv.DictReader(target.open()))
    header = list(rows[0])
    assert header[:4] == ["id", "stature", "mass", "note"]
    assert "stature.low" in header and "measure.sittingheight.high" in header
    assert header.count("stature") == 1
    assert [r["id"] for r in rows] == ["a", "b", "c"] and rows[0]["note"] == "first"
    assert rows[1]["stature"] == "70 in"  # input cells are kept as written
    expected = [
        {"stature": 175.5, "mass": 82.2},
        {"stature": 177.8},
        {"stature": 160.0, "mass": 176 * 0.45359237},
    ]
    for row, known in zip(rows, expected):
        prediction = predictor.predict("male", known)
        for field in ("measure.sittingheight", "girth.right_upper_arm.z", "stature", "mass"):
            e = prediction.values[field]
            if not e.known:
                assert float(row[field]) == pytest.approx(e.value, abs=0.0006)
            assert float(row[f"{field}.low"]) == pytest.approx(e.low, abs=0.0006)
            assert float(row[f"{field}.high"]) == pytest.approx(e.high, abs=0.0006)
    assert rows[1]["mass"] != "" and float(rows[1]["mass.low"]) < float(rows[1]["mass.high"])


def test_a_file_predict_wrote_runs_again_with_every_value_known(db, tmp_path, capsys):
    """Every field of the second run is known: the residual spread's terms
    are then dependent (numpy raised "Singular matrix" through the verb), and
    the first run's F.low and F.high are replaced, not written twice."""
    source = tmp_path / "known.csv"
    source.write_text("id,stature,mass\na,165,60\n")
    first, second = tmp_path / "first.csv", tmp_path / "second.csv"
    argv = ["predict", "--db", str(db), "--gender", "female"]
    assert main([*argv, "--input", str(source), "--output", str(first)]) == 0
    assert main([*argv, "--input", str(first), "--output", str(second)]) == 0
    assert "(1 person)" in capsys.readouterr().out
    header = next(csv.reader(second.open()))
    assert len(header) == len(set(header)) and set(header) == set(next(csv.reader(first.open())))
    before, after = next(csv.DictReader(first.open())), next(csv.DictReader(second.open()))
    fields = [name for name in header if f"{name}.low" in after]
    assert len(fields) > 100 and {"stature", "measure.chestcircumference"} <= set(fields)
    for field in fields:  # known now: the interval is the value itself
        assert float(after[field]) == float(before[field])
        assert float(after[f"{field}.low"]) == float(after[f"{field}.high"]) == float(before[field])


def test_batch_errors_name_file_and_line(db, tmp_path, capsys):
    source = tmp_path / "known.csv"
    source.write_text("id,stature,mass\n1,175,80\n2,175,80 cm\n")
    target = tmp_path / "predicted.csv"
    argv = ["predict", "--db", str(db), "--gender", "male", "--input", str(source)]
    assert main([*argv, "--output", str(target)]) == 2
    err = capsys.readouterr().err
    assert f"{source}:3: column mass: cm is not a unit of mass" in err
    source.write_text("id,stature\n1,175\n2,1750\n")
    assert main([*argv, "--output", str(target)]) == 2
    assert f"{source}:3: stature = 1750 cm is" in capsys.readouterr().err
    source.write_text("id,height\n1,175\n")
    assert main([*argv, "--output", str(target)]) == 2
    assert "no column names a known value" in capsys.readouterr().err
    source.write_text("id;stature\n1;175\n")  # a spreadsheet set for a decimal comma
    assert main([*argv, "--output", str(target)]) == 2
    assert f"{source}:1: the cells are separated by ';', not commas" in capsys.readouterr().err
    assert not target.exists()


@pytest.mark.parametrize(
    ("known", "message"),
    [
        (
            "measure.sitingheight=90",
            "unknown name 'measure.sitingheight'; did you mean measure.sittingheight",
        ),
        ("mass=80cm", "mass=80cm: cm is not a unit of mass"),
        ("stature=1755", "stature = 1755 cm is"),
        ("stature", "expected NAME=VALUE"),
    ],
)
def test_errors_are_one_clear_line(db, capsys, known, message):
    assert main(["predict", "--db", str(db), "--gender", "male", "--known", known]) == 2
    err = capsys.readouterr().err
    assert err.startswith("sass predict: error: ") and message in err
    assert "Traceback" not in err


@pytest.mark.slow
def test_a_gender_without_people_says_so(db, capsys):
    conn = connect(db)
    females = [r[0] for r in conn.execute("SELECT id_num FROM person WHERE gender = 'female'")]
    with transaction(conn):
        delete_people(conn, females)
    conn.close()
    assert main(["predict", "--db", str(db), "--gender", "female", "--known", "stature=160"]) == 2
    assert "no female people" in capsys.readouterr().err


@pytest.mark.slow
def test_the_fit_is_cached_beside_the_database_and_rebuilt_when_data_change(db):
    conn = connect(db)
    path = cache_path(conn)
    assert path == db.with_name("ansur.db.predict.npz")
    path.unlink()
    first = open_predictor(conn)
    assert path.exists()
    stamp = path.stat().st_mtime_ns
    key = data_key(conn)
    again = open_predictor(conn)
    assert path.stat().st_mtime_ns == stamp and again.key == first.key == key
    # editing one value changes the key and the fit
    person = conn.execute("SELECT id_num FROM person WHERE gender = 'male' LIMIT 1").fetchone()[0]
    with transaction(conn):
        conn.execute(
            "UPDATE measure SET sittingheight = sittingheight + 5 WHERE id_num = ?", (person,)
        )
    assert data_key(conn) != key
    edited = open_predictor(conn)
    assert edited.key == data_key(conn)
    assert not np.array_equal(edited.model("male").mean, first.model("male").mean)
    # removing a person changes it too
    with transaction(conn):
        delete_people(conn, [person])
    assert data_key(conn) != edited.key
    assert open_predictor(conn).model("male").n == 4081
    conn.close()
