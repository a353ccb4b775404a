"""`sass reach` (model/body/reach.py), checked from outside: the
survey's measured reach of ANSUR II people (their CSV rows), the model's
reach from their other measurements against it, the envelope's glTF through
the Khronos validator and read back with pygltflib (its joints and
measurements, not sass's), and the envelope closed (each edge in two
triangles, opposite ways)."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np
import pytest
from _built_once import copy_database_file
from _gltf_files import accessor as glb_accessor
from _gltf_files import khronos_validator

from sass_tui.cli import main
from sass_tui.model.body.body_measures import figure_measures
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.body.reach import (
    REACH_MEASURES,
    TRAVEL,
)

pygltflib = pytest.importorskip("pygltflib")

# The brief's tolerance for a person's measured thumb-tip reach.
MEASURED_REACH = 1.5  # cm


def _json(capsys, *argv: str) -> dict:
    capsys.readouterr()
    assert main(["reach", *argv, "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


# --- real people ------------------------------------------------------------------


@pytest.mark.slow
def test_a_person_s_measured_reach_is_reported_within_1_5_cm(
    ansur_dir, shipped_db_file, capsys, tmp_path
):
    """Three men and three women across sizes (the shortest, the median and
    the tallest by stature): their thumb-tip reach, overhead reach sitting and
    span as the CSV has them (mm), said to be measured, with the model's own
    value from their other measurements beside it; the median man's and
    woman's seated envelope (read back from its .glb) as high as their
    measured overhead reach."""
    for gender, letter in (("male", "M"), ("female", "F")):
        rows = sorted(_rows(ansur_dir, gender), key=lambda row: float(row["stature"]))
        for share in (0.0, 0.5, 1.0):
            row = rows[int(share * (len(rows) - 1))]
            name = f"ANSUR II {letter} {row['subjectid']}"
            answer = _json(capsys, "--db", str(shipped_db_file), "--person", name)
            for measure in REACH_MEASURES:
                entry = answer[measure]
                assert entry["unit"] == "cm" and entry["source"] == "measured"
                assert abs(entry["value"] - float(row[measure]) / 10) <= MEASURED_REACH, (
                    name,
                    measure,
                )
                assert abs(entry["model"] - float(row[measure]) / 10) < 15, (name, measure)
            if share == 0.5:
                # seated, the fingertip's envelope tops out at their overhead reach
                glb = tmp_path / f"{letter}.glb"
                argv = ["reach", "--db", str(shipped_db_file), "--person", name, "--seated"]
                assert main([*argv, "-o", str(glb)]) == 0
                positions, _ = _meshes(glb)["right_fingertip_reach"]
                overhead = float(row["overheadfingertipreachsitting"]) / 1000
                assert positions[:, 1].max() == pytest.approx(overhead, abs=0.01), name


# --- the envelope as glTF ------------------------------------------------------------


@pytest.fixture(scope="module")
def validator():
    return khronos_validator()


def _meshes(path: Path) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    gltf = pygltflib.GLTF2().load(str(path))
    blob = gltf.binary_blob()

    def accessor(index: int) -> np.ndarray:
        return glb_accessor(gltf, blob, index)

    out = {}
    for mesh in gltf.meshes:
        primitive = mesh.primitives[0]
        out[mesh.name] = (
            accessor(primitive.attributes.POSITION).astype(float),
            accessor(primitive.indices).astype(np.int64).reshape(-1, 3),
        )
    return out


def _watertight(triangles: np.ndarray) -> bool:
    edges = np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    directed = {tuple(e) for e in edges.tolist()}
    return len(directed) == len(edges) and all((b, a) in directed for a, b in directed)


def _joints(path: Path) -> dict[str, np.ndarray]:
    """World positions of the joint nodes (standing: translations add up)."""
    gltf = pygltflib.GLTF2().load(str(path))
    parent = {c: i for i, node in enumerate(gltf.nodes) for c in node.children or []}

    def world(i: int) -> np.ndarray:
        here = np.array(gltf.nodes[i].translation or [0, 0, 0], dtype=float)
        return here + (world(parent[i]) if i in parent else 0)

    return {node.name: world(i) for i, node in enumerate(gltf.nodes) if node.mesh is None}


@pytest.mark.slow
def test_the_envelope_is_a_valid_closed_gltf_mesh(tmp_path, validator, capsys):
    """Alone (standing, seated with the trunk free) and with the body (both
    hands): 0 errors, 0 warnings; each envelope closed and outward (positive
    volume); straight ahead of the right shoulder it reaches as far as the
    body's own arm (its joints in the file), hand (its measured-or-predicted
    hand length in the file's extras) and the forward shoulder travel."""
    alone = tmp_path / "alone.glb"
    seated = tmp_path / "seated.glb"
    left = tmp_path / "left.gltf"
    body = tmp_path / "body.glb"
    assert main(["reach", "--gender", "female", "-o", str(alone)]) == 0
    assert main(["reach", "--seated", "--trunk", "--hand-point", "grip", "-o", str(seated)]) == 0
    assert main(["reach", "--hand", "both", "--with-body", "-o", str(body)]) == 0
    assert main(["reach", "--hand", "left", "-o", str(left)]) == 0
    assert (tmp_path / "left.bin").is_file()
    for report in validator([alone, seated, body, left]):
        assert (report["numErrors"], report["numWarnings"]) == (0, 0), report
    meshes = {**_meshes(alone), **_meshes(seated)}
    both = _meshes(body)
    assert sorted(both) == ["left_fingertip_reach", "male_50_body", "right_fingertip_reach"]
    for name, (positions, triangles) in [*meshes.items(), *both.items()]:
        if name.endswith("_reach"):
            assert _watertight(triangles), name
            a, b, c = (positions[triangles[:, i]] for i in range(3))
            assert np.einsum("ij,ij->i", a, np.cross(b, c)).sum() > 0, name
    joints = _joints(body)
    shoulder, elbow, wrist = (joints[f"r_{j}"] for j in ("shoulder", "elbow", "radiocarpal"))
    extras = pygltflib.GLTF2().load(str(body)).scenes[0].extras
    hand = extras["bodyMeasures"]["handlength"]["cm"] / 100
    arm = np.linalg.norm(elbow - shoulder) + np.linalg.norm(wrist - elbow) + hand
    positions, _ = both["right_fingertip_reach"]
    level = np.abs(positions[:, 1] - shoulder[1]) < 0.05
    level &= np.abs(positions[:, 0] - shoulder[0]) < 0.05
    ahead = positions[level, 2].max() - shoulder[2]
    assert ahead == pytest.approx(arm + TRAVEL["male"][0], abs=0.01)


def test_a_point_is_reached_or_missed_by_how_much(capsys):
    """The male 50th figure's right fingertip, straight ahead of its shoulder:
    2 cm short of its forward reach is reached, 6 cm beyond it missed by
    about 6 cm; with --hand both a point half a metre out from the left
    shoulder is the left hand's alone."""
    humanoid = build_humanoid(Figure.default("male"))
    s = humanoid.centers["r_shoulder"] * 100
    e, w = humanoid.centers["r_elbow"] * 100, humanoid.centers["r_radiocarpal"] * 100
    env = _json(capsys, "--gender", "male", f"--point={s[0]:.2f},{s[1]:.2f},60")
    assert env["point"]["reached"] and env["point"]["hands"] == ["right"]
    assert env["point"]["miss"] == {"value": 0.0, "unit": "cm"}
    hand = figure_measures(Figure.default("male"), 175.5).values["handlength"]
    arm = np.linalg.norm(e - s) + np.linalg.norm(w - e) + hand + TRAVEL["male"][0] * 100
    near = _json(capsys, f"--point={s[0]:.2f},{s[1]:.2f},{arm - 2:.2f}")
    assert near["point"]["reached"]
    far = _json(capsys, f"--point={s[0]:.2f},{s[1]:.2f},{arm + 6:.2f}")
    assert not far["point"]["reached"]
    assert far["point"]["miss"]["value"] == pytest.approx(6, abs=1.5)
    left = _json(capsys, "--hand", "both", f"--point={-s[0] + 50:.2f},{s[1]:.2f},0")
    assert left["point"]["hands"] == ["left"]


@pytest.mark.slow
def test_a_population_s_share_reaching_a_point(shipped_db_file, tmp_path, capsys):
    """The virtual civilians, each with their own shoulder and arm: nobody
    reaches 3 m ahead, everyone a point by the shoulder; farther ahead
    fewer; men before women."""
    db = tmp_path / "sass.db"
    copy_database_file(shipped_db_file, db)
    shares = []
    for ahead in (20, 66, 300):
        answer = _json(
            capsys, "--db", str(db), "--virtual", "nhanes-2017-2020", f"--point=-18,125,{ahead}"
        )
        assert answer["point"]["leftOut"] == 0
        shares.append(answer["point"]["shares"])
    assert all(share == 100.0 for share in shares[0].values())
    assert all(share == 0.0 for share in shares[-1].values())
    everyone = [share["VIRTUAL everyone"] for share in shares]
    assert everyone == sorted(everyone, reverse=True)
    assert any(share["VIRTUAL men"] > share["VIRTUAL women"] for share in shares[1:-1]), shares


# --- a predicted person ------------------------------------------------------------

# Half the residual RMSE (about 3 cm) of ANSUR II's reach measures on stature
# and mass: a predicted person's reach sits on the population's regression.
ON_THE_REGRESSION = 1.5  # cm


@pytest.fixture(scope="module")
def predict_db(shipped_db_file, tmp_path_factory) -> Path:
    """A copy of the shipped database: sass predict caches its fit beside it."""
    db = tmp_path_factory.mktemp("reach_predict") / "sass.db"
    copy_database_file(shipped_db_file, db)
    return db


def _ols(ansur_dir: Path, gender: str, stature: float, mass: float) -> dict[str, float]:
    """Each reach measure at (stature cm, mass kg) by least squares on the
    published ANSUR II rows (stature in mm, weightkg in tenths of a kg)."""
    rows = _rows(ansur_dir, gender)
    x = np.array([[1.0, float(r["stature"]) / 10, float(r["weightkg"]) / 10] for r in rows])
    out = {}
    for name in REACH_MEASURES:
        y = np.array([float(r[name]) / 10 for r in rows])
        coefficients = np.linalg.lstsq(x, y, rcond=None)[0]
        out[name] = float(coefficients @ [1.0, stature, mass])
    return out


@pytest.mark.parametrize("gender, stature, mass", [("male", 175, 80), ("female", 160, 62)])
def test_a_predicted_person_s_reach_is_on_the_population_s_regression(
    ansur_dir, predict_db, capsys, gender, stature, mass
):
    """`--known stature= --known mass=`: each reach measure the model's from the
    predicted arm (said so), within 1.5 cm of a least-squares fit of that
    measure on stature and mass over the published CSV, and sass predict's
    own estimate beside it with its interval."""
    known = ["--known", f"stature={stature}cm", "--known", f"mass={mass}kg"]
    answer = _json(capsys, "--db", str(predict_db), "--gender", gender, *known)
    assert "sass predict" in answer["basis"] and "model" in answer["basis"]
    oracle = _ols(ansur_dir, gender, stature, mass)
    for name in REACH_MEASURES:
        entry = answer[name]
        assert entry["source"] == "model" and "model" not in entry, entry
        assert abs(entry["value"] - oracle[name]) <= ON_THE_REGRESSION, (name, entry, oracle)
        band = entry["predicted"]
        assert band["low"] < oracle[name] < band["high"], (name, band)


def test_a_predicted_person_s_known_values_move_the_reach(predict_db, capsys):
    """Taller, a longer thumb-tip reach and span; a longer known upper arm
    (acromion-radiale length) than the prediction's, a longer reach; a known
    thumb-tip reach reported as given, the others still the model's."""
    db = ["--db", str(predict_db), "--gender", "male", "--known", "mass=80kg"]
    short, tall = (_json(capsys, *db, "--known", f"stature={s}cm") for s in (165, 185))
    for name in REACH_MEASURES:
        assert tall[name]["value"] > short[name]["value"] + 5, name
    arm = _json(
        capsys, *db, "--known", "stature=165cm", "--known", "measure.acromionradialelength=40cm"
    )
    assert arm["thumbtipreach"]["value"] > short["thumbtipreach"]["value"] + 2
    given = _json(capsys, *db, "--known", "stature=175cm", "--known", "measure.thumbtipreach=90cm")
    assert given["thumbtipreach"] == {"value": 90.0, "unit": "cm", "source": "known"}
    assert given["span"]["source"] == "model"


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--known", "stature"], "expected NAME=VALUE"),
        (["--known", "stature=3kg"], "not a unit of length"),
        (["--known", "stature=abc"], "expected a number"),
        (["--known", "elbowlength=30cm"], "unknown name 'elbowlength'"),
        (["--known", "stature=170", "--stature", "170"], "leave out --stature"),
        (["--known", "stature=170", "--percentile", "5"], "leave out --percentile"),
        (["--known", "stature=170", "--person", "ANSUR II M 10037"], "leave out --person"),
    ],
)
def test_a_bad_known_is_a_one_line_error(argv, words, predict_db, capsys):
    capsys.readouterr()
    assert main(["reach", "--db", str(predict_db), "--gender", "male", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err, err


def test_known_needs_a_gender(capsys):
    assert main(["reach", "--known", "stature=170cm"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--known needs --gender" in err, err


# --- what is refused ------------------------------------------------------------------


@pytest.mark.parametrize(
    "argv, words",
    [
        (["--point", "1,2"], "--point '1,2': expected X,Y,Z"),
        (["--point", "1,2,3 kg"], "not a unit of length"),
        (["--seated", "--with-body", "-o", "x.glb"], "the body is written standing"),
        (["--with-body"], "goes with -o"),
        (["-o", "x.obj"], "ends in .glb"),
    ],
)
def test_bad_options_are_one_line_errors(argv, words, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["reach", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err, err
    assert list(tmp_path.iterdir()) == []


def _rows(ansur_dir: Path, gender: str) -> list[dict[str, str]]:
    with open(ansur_dir / f"ANSUR_II_{gender.upper()}_Public.csv", encoding="latin-1") as handle:
        return [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(handle)]


@pytest.mark.parametrize(
    ("typed", "noted"),
    [
        ("0.5,1.4,0.3", True),  # metres meant: half a centimetre ahead, 1.4 cm up
        ("0.5,1.4,0.3 m", False),
        ("40,140,60", False),
        ("-20,130,60", False),  # a negative X as its own word, no `=` needed
    ],
)
def test_a_point_that_reads_as_metres_without_its_unit_gets_a_note(capsys, typed, noted):
    assert main(["reach", "--point", typed, "--format", "json"]) == 0
    captured = capsys.readouterr()
    answer, err = json.loads(captured.out), captured.err
    assert ("is read in cm (no unit typed)" in err) is noted
    if noted:
        assert f"metres are written '{typed} m'" in err
    assert answer["point"]["value"][0] == pytest.approx(
        float(typed.split(",")[0]) * (100 if typed.endswith("m") else 1)
    )
