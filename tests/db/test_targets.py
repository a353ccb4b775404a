"""Target populations end to end: `sass target` weights the ANSUR II women to
a generated sample of heavier, shorter civilian-like women, and `fit`,
`population`, `query --count` and `family` answer for the weighted people.
Each weighted answer is checked against the sample's own figures, computed
here with numpy; the answers without --target are checked to stay as they were.
On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.db.engine.addresses import is_url
from sass_tui.db.engine.database import Database
from sass_tui.db.populations.targets import SHIPPED
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import GLOBAL, row_index

# U.S. civilian-like adult women: shorter and heavier than the soldiers of
# ANSUR II (women 162.8 cm, 67.8 kg); mass log-normal as adult masses are.
STATURE_MEAN, STATURE_SD = 160.5, 6.8
MASS_MEDIAN, LOG_MASS_SD, CORRELATION = 74.0, 0.19, 0.3


def civilian_women(rows: int, seed: int = 11) -> np.ndarray:
    rng = np.random.default_rng(seed)
    z1, z2 = rng.standard_normal((2, rows))
    stature = STATURE_MEAN + STATURE_SD * z1
    log_mass = np.log(MASS_MEDIAN) + LOG_MASS_SD * (
        CORRELATION * z1 + np.sqrt(1 - CORRELATION**2) * z2
    )
    return np.column_stack([stature, np.exp(log_mass)])


def write_sample(path: Path, values: np.ndarray) -> Path:
    """Stature in inches (the header's unit), mass in kg, a row in pounds on the values."""
    lines = ["id,stature[in],mass[kg],age"]
    for i, (stature, mass) in enumerate(values):
        cell = f"{mass / 0.45359237:.4f} lb" if i % 7 == 0 else f"{mass:.4f}"
        lines.append(f"{i},{stature / 2.54:.5f},{cell},40")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def sample() -> np.ndarray:
    return civilian_women(3000)


@pytest.fixture(scope="module")
def made(template_target, copy_database, sample, tmp_path_factory) -> str:
    """A copy of the default database holding the target `civ`, on each engine:
    its address (the tests that write copy it again)."""
    folder = tmp_path_factory.mktemp("target")
    db = copy_database(template_target)
    csv_path = write_sample(folder / "civilian.csv", sample)
    assert main(["target", "civ", "--db", db, "--gender", "female", "--sample", str(csv_path)]) == 0
    return db


def run_json(capsys, *argv: str) -> dict:
    capsys.readouterr()
    assert main([*argv]) == 0
    return json.loads(capsys.readouterr().out)


def stored_targets(db: str) -> list[tuple]:
    """The targets stored beside the shipped ones `sass db init` makes (their
    names in the target table, then in target_weight)."""
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            return [
                tuple(row)
                for sql in ("SELECT name FROM target", "SELECT DISTINCT target FROM target_weight")
                for row in conn.execute(sql).fetchall()
                if row[0] not in SHIPPED
            ]
    finally:
        opened.close()


@pytest.mark.parametrize(("q", "r"), [(50, 50), (90, 90), (70, 35), (30, 80)])
def test_the_weighted_share_is_the_samples(made, sample, capsys, q, r):
    """S, M at the sample's q-th and r-th percentiles (50/50 and 90/90 as asked;
    two pairs off the quartiles the weights are calibrated to)."""
    stature, mass = np.percentile(sample[:, 0], q), np.percentile(sample[:, 1], r)
    own = 100 * np.mean((sample[:, 0] <= stature) & (sample[:, 1] <= mass))
    limits = f"stature <= {stature:.4f} cm AND mass <= {mass:.4f} kg"
    result = run_json(capsys, "fit", "--db", made, "--target", "civ", "--format", "json", limits)
    assert result["target"]["name"] == "civ"
    assert abs(result["target"]["percent"] - own) <= 3.0
    assert 0 < result["target"]["effective_n"] < result["accommodated"]["female"]["n"]
    # Every share is weighted, the women's too (the target is women only), and
    # it is the headline; the unweighted soldiers fail the same check: the
    # weighting did it.
    assert result["accommodated"]["female"]["percent"] == pytest.approx(
        result["target"]["percent"], abs=1e-6
    )
    assert result["accommodated"]["weighted"]["percent"] == pytest.approx(
        result["target"]["percent"], abs=1e-6
    )
    if q == 50:
        plain = run_json(capsys, "fit", "--db", made, "--format", "json", limits)
        assert abs(plain["accommodated"]["female"]["percent"] - own) > 3.0


def test_the_weighted_population_has_the_samples_median(made, sample, tmp_path, capsys):
    out = tmp_path / "civ.dat"
    assert main(["population", "--db", made, "--target", "civ", "-o", str(out)]) == 0
    assert "target civ" in capsys.readouterr().out
    stats = read_population_file(tmp_path / "civ-global.dat", GLOBAL)
    assert "target civ" in stats.title
    p5, p50, p95 = stats.stats("female")[row_index(GLOBAL, "stature"), 0]
    assert abs(p50 - np.median(sample[:, 0])) <= 1.0
    assert abs(p5 - np.percentile(sample[:, 0], 5)) <= 1.5
    assert "target civ" in (tmp_path / "civ.dat").read_text(encoding="utf-8").splitlines()[0]
    # sass fig reads the file: the figure's 50th stature is the weighted one
    fig = tmp_path / "civ.fig"
    assert (
        main(
            [
                "fig",
                "--gender",
                "female",
                "--global",
                str(tmp_path / "civ-global.dat"),
                "-o",
                str(fig),
            ]
        )
        == 0
    )
    assert f"stature {p50:.1f} cm" in fig.read_text(encoding="utf-8")


def test_the_weighted_count(made, sample, capsys):
    stature = float(np.percentile(sample[:, 0], 25))
    capsys.readouterr()
    assert (
        main(["query", "--db", made, "--count", "--target", "civ", f"stature <= {stature} cm"]) == 0
    )
    raw, weighted = capsys.readouterr().out.splitlines()
    capsys.readouterr()
    assert main(["query", "--db", made, "--count", f"stature <= {stature} cm"]) == 0
    assert capsys.readouterr().out.strip() == raw
    share = float(weighted.split("(")[1].split(" %")[0])
    assert abs(share - 25.0) <= 1.5
    assert "target civ" in weighted


@pytest.mark.slow
def test_the_weighted_family(made, sample, tmp_path, capsys):
    capsys.readouterr()
    argv = [
        "family",
        "--db",
        made,
        "--gender",
        "female",
        "--measures",
        "stature,mass",
        "--space",
        "measured",
    ]
    assert main([*argv, "--target", "civ", "-o", str(tmp_path / "w")]) == 0
    assert "weighted: target civ" in capsys.readouterr().out
    weighted = json.loads((tmp_path / "w" / "family.json").read_text(encoding="utf-8"))
    assert main([*argv, "-o", str(tmp_path / "u")]) == 0
    plain = json.loads((tmp_path / "u" / "family.json").read_text(encoding="utf-8"))
    assert "target" not in plain and weighted["target"]["name"] == "civ"
    assert "weighted to target civ" in (tmp_path / "w" / "female_center.fig").read_text(
        encoding="utf-8"
    )
    center = next(m for m in weighted["manikins"] if m["name"] == "center")["values"]
    assert center["stature"] == pytest.approx(sample[:, 0].mean(), abs=0.05)
    assert center["mass"] == pytest.approx(sample[:, 1].mean(), abs=0.05)


def test_answers_without_target_are_unchanged(shared_target, made, tmp_path, capsys):
    """fit, population and query --count give the same answer on a database
    holding a target as on one without, and no weighted word."""
    limits = "stature <= 165 cm AND mass <= 80 kg"
    outputs = []
    for db in (shared_target, made):
        capsys.readouterr()
        out = tmp_path / f"answers-{len(outputs)}.dat"
        assert main(["fit", "--db", db, "--format", "json", limits]) == 0
        assert main(["query", "--db", db, "--count", "gender = female AND mass > 70 kg"]) == 0
        assert main(["population", "--db", db, "--query", "gender = female", "-o", str(out)]) == 0
        text = capsys.readouterr().out.replace(out.stem, "X")
        files = sorted(p.name.replace(out.stem, "X") for p in tmp_path.glob(f"{out.stem}*"))
        outputs.append((text, files, out.read_text(encoding="utf-8")))
    for before, after in zip(outputs[0], outputs[1]):
        assert before == after
    assert '"target"' not in outputs[0][0] and "weighted:" not in outputs[0][0]
    # the people's own stature and mass, unweighted, beside the girth file
    assert "X-global.dat" in outputs[0][1] and "weighted" not in outputs[0][2]


def test_list_replace_and_drop(made, copy_database, sample, tmp_path, capsys):
    db = copy_database(made)
    csv_path = write_sample(tmp_path / "other.csv", civilian_women(200, seed=3))
    argv = ["target", "civ", "--db", db, "--gender", "female", "--sample", str(csv_path)]
    capsys.readouterr()
    assert main(argv) == 2  # not a terminal: no question, a refusal
    assert "give --force" in capsys.readouterr().err
    assert main(["target", "--db", db, "--list"]) == 0
    assert "3000 rows" in capsys.readouterr().out
    assert main([*argv, "--force"]) == 0
    assert main(["target", "--db", db, "--list"]) == 0
    assert "200 rows of" in capsys.readouterr().out
    assert main(["target", "--db", db, "--drop", "civ"]) == 0
    assert stored_targets(db) == []
    assert main(["fit", "--db", db, "--target", "civ", "stature < 170 cm"]) == 2
    assert "no target named 'civ'" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("lines", "says"),
    [
        (["height,weight", "160,70"] * 20, "no column for stature, mass"),
        (["stature[cubits],mass", "160,70"], "unknown unit"),
        (["stature,mass", "160,70", "150 parsec,70"], ":3: column 1 'stature'"),
        (["stature,mass"] + [f"{160 + i % 7},{70 + i % 5}" for i in range(29)], "at least 30"),
        (
            ["stature,mass"] + [f"{195 + i % 9},{70 + i % 13}" for i in range(300)],
            "outside the people",
        ),
    ],
)
def test_bad_samples_store_nothing(engine_target, tmp_path, capsys, lines, says):
    db = engine_target
    csv_path = tmp_path / "bad.csv"
    csv_path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    before = _state(db)
    capsys.readouterr()
    assert main(["target", "t", "--db", db, "--gender", "female", "--sample", str(csv_path)]) == 2
    err = capsys.readouterr().err
    assert says in err and "Traceback" not in err
    assert str(csv_path) in err or "--by" in err
    assert stored_targets(db) == []
    assert _state(db) == before


def _state(db: str) -> object:
    """What a refusal must leave as it was: a SQLite file's bytes, a PostgreSQL
    database's row counts."""
    if not is_url(db):
        return Path(db).read_bytes()
    opened = Database.open(db)
    try:
        with opened.connection() as conn:
            tables = [t for (t,) in conn.execute(
                "SELECT table_name FROM information_schema.tables WHERE table_schema = 'public'"
            )]  # fmt: skip
            return {t: conn.execute(f"SELECT count(*) FROM {t}").fetchone()[0] for t in tables}
    finally:
        opened.close()


@pytest.mark.sqlite_only("people are deleted by SQLite's people_store.delete_people alone")
def test_people_deleted_since_drop_out_of_the_sums(made, tmp_path):
    from sass_tui.db.engine.schema import connect, transaction
    from sass_tui.db.people.people_store import delete_people
    from sass_tui.db.populations.targets import load_target, weighted_count

    db = tmp_path / "sass.db"
    shutil.copyfile(made, db)
    conn = connect(db)
    try:
        before = load_target(conn, "civ")
        gone = [int(i) for i in before.ids[:100]]
        with transaction(conn):
            delete_people(conn, gone)
        after = load_target(conn, "civ")
        assert len(after.ids) == len(before.ids) - 100
        assert not set(gone) & set(after.ids.tolist())
        assert after.of(np.array(gone, dtype=np.int64)).sum() == 0
        counted = weighted_count(conn, "gender = female", after)
        assert counted.weighted == pytest.approx(counted.total)
        assert counted.total == pytest.approx(before.weights[100:].sum())
    finally:
        conn.close()
