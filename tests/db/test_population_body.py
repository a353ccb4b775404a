"""A population's figure is that population's body: `sass population` writes
the people's own stature and mass beside its girth and center-of-mass files
(NAME-global.dat), `sass fig --girth NAME.dat` and the exports read it, the
figure's header says whose they are, and the files sass wrote read back
without a warning.  The README's example, with the expected numbers computed
here from the published ANSUR II CSV.  On both engines (tests/db/conftest.py)."""

from __future__ import annotations

import csv
import json
import re
import statistics
from pathlib import Path

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, row_index

TALL_WOMEN = "gender = female AND stature > 175 cm"


@pytest.fixture(scope="module")
def tall_women(ansur_dir) -> list[dict[str, str]]:
    """The women of the README's example, straight from the CSV (stature in mm)."""
    with (ansur_dir / "ANSUR_II_FEMALE_Public.csv").open(encoding="utf-8-sig") as handle:
        return [r for r in csv.DictReader(handle) if int(r["stature"]) > 1750]


def _population(db: str, target: Path, query: str, capsys) -> Path:
    assert main(["population", "--db", db, "--query", query, "-o", str(target)]) == 0
    assert "warning" not in capsys.readouterr().err
    return target


def test_the_readme_example_is_the_tall_womens_body(
    shared_target, tmp_path, tall_women, capsys, monkeypatch
):
    monkeypatch.chdir(tmp_path)
    assert len(tall_women) == 67
    _population(shared_target, Path("tall.dat"), TALL_WOMEN, capsys)
    assert Path("tall-global.dat").is_file()
    # the README's own command line
    assert main(["fig", "--girth", "tall.dat", "--cmass", "tall-cmass.dat", "-o", "TALL.fig"]) == 0
    said = capsys.readouterr()
    assert said.err == "", said.err  # no warning at all
    stature = statistics.median(int(r["stature"]) / 10 for r in tall_women)  # mm -> cm
    mass = statistics.median(int(r["weightkg"]) / 10 for r in tall_women)  # 0.1 kg -> kg
    header = Path("TALL.fig").read_text(encoding="utf-8").splitlines()[2]
    assert f"mass {mass:.2f} kg, stature {stature:.1f} cm" in header, header
    assert "of Population of gender = female AND stature > 175 cm (67 women" in header
    # 5th/50th/95th of each, as numpy computes them over the CSV
    own = read_population_file("tall-global.dat", GLOBAL).stats("female")
    for row, column, scale in (("stature", "stature", 10), ("mass", "weightkg", 10)):
        values = [int(r[column]) / scale for r in tall_women]
        expected = np.percentile(values, [5, 50, 95])
        assert own[row_index(GLOBAL, row), 0] == pytest.approx(expected, abs=0.01)


@pytest.mark.slow
def test_the_exports_stand_as_tall_as_the_people(shared_target, tmp_path, tall_women, capsys):
    girth = _population(shared_target, tmp_path / "tall.dat", TALL_WOMEN, capsys)
    stature = statistics.median(int(r["stature"]) / 1000 for r in tall_women)  # mm -> m
    x3d = tmp_path / "TALL.x3d"
    assert main(["export", "hanim", "--girth", str(girth), "-o", str(x3d)]) == 0
    assert capsys.readouterr().err == ""
    vertex = re.search(r'name="skull_vertex_pt" translation="0 ([\d.]+) 0"', x3d.read_text())
    assert vertex is not None and float(vertex.group(1)) == pytest.approx(stature, abs=0.005)
    gltf = tmp_path / "TALL.gltf"
    assert main(["export", "gltf", "--girth", str(girth), "-o", str(gltf)]) == 0
    assert capsys.readouterr().err == ""
    nodes = json.loads(gltf.read_text())["nodes"]
    parent = {child: i for i, node in enumerate(nodes) for child in node.get("children", ())}
    here = next(i for i, node in enumerate(nodes) if node.get("name") == "skull_vertex_pt")
    height = 0.0  # the joints of a standing body translate without rotating
    while here is not None:
        assert "rotation" not in nodes[here]
        height += nodes[here].get("translation", (0, 0, 0))[1]
        here = parent.get(here)
    assert height == pytest.approx(stature, abs=0.005)


@pytest.mark.slow
@pytest.mark.parametrize(
    "query",
    [
        "source = ansur2",  # both genders: the cross-gender check applies
        "gender = male AND stature > 185 cm",
        "gender = female AND age < 25",
        TALL_WOMEN,
    ],
)
def test_the_files_sass_writes_read_back_without_a_warning(shared_target, tmp_path, query, capsys):
    girth = _population(shared_target, tmp_path / "p.dat", query, capsys)
    cmass = tmp_path / "p-cmass.dat"
    for path, group in (
        (girth, GIRTH),
        (cmass, CENTER_OF_MASS),
        (tmp_path / "p-global.dat", GLOBAL),
    ):
        assert read_population_file(path, group).warnings == []
    genders = read_population_file(girth, GIRTH).sections
    for gender in genders:
        out = tmp_path / f"{gender}.fig"
        options = ["--gender", gender, "--girth", str(girth), "--cmass", str(cmass)]
        assert main(["fig", *options, "-o", str(out)]) == 0
        assert capsys.readouterr().err == ""


def test_a_girth_file_alone_names_no_file_the_user_did_not_pass(shared_target, tmp_path, capsys):
    """The shipped center of mass goes with the report's girth, not with the tall
    women's: appendix L.1's rules tie a pair of one population only."""
    girth = _population(shared_target, tmp_path / "tall.dat", TALL_WOMEN, capsys)
    assert main(["fig", "--girth", str(girth), "-o", str(tmp_path / "T.fig")]) == 0
    assert capsys.readouterr().err == ""
    assert main(["fig", "--cmass", str(tmp_path / "tall-cmass.dat"), "--gender", "female",
                 "-o", str(tmp_path / "C.fig")]) == 0  # fmt: skip
    assert "datasets" not in capsys.readouterr().err
