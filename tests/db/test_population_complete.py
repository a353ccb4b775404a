"""Every population of real people makes a figure: `sass population` fills
every girth and center-of-mass cell (the people's own values where they have
them, else the report's scaled by their stature), says which in comments,
always writes the center-of-mass file, and `sass fig` reads both.  Expected
values come from the published CSV in ../shared.  On both engines
(tests/db/conftest.py)."""

from __future__ import annotations

import csv
import math
import statistics
from pathlib import Path

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.db.populations.population import MIN_PEOPLE
from sass_tui.model import datasets
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, ROWS, row_index


@pytest.fixture(scope="module")
def women(ansur_dir) -> list[dict[str, str]]:
    with (ansur_dir / "ANSUR_II_FEMALE_Public.csv").open(encoding="utf-8-sig") as handle:
        return list(csv.DictReader(handle))


def _make(db: str, target: Path, *options: str) -> tuple[Path, Path]:
    assert main(["population", "--db", db, *options, "-o", str(target)]) == 0
    cmass = target.with_name(f"{target.stem}-cmass.dat")
    assert target.is_file() and cmass.is_file()  # the center-of-mass file, always
    return target, cmass


def _complete(path: Path, group: str, genders: set[str]) -> None:
    """No 999 and no NaN anywhere; a provenance comment before every row."""
    text = path.read_text()
    assert " 999 " not in f" {text} ".replace("\n", " ") and "nan" not in text.lower()
    data = read_population_file(path, group)
    assert set(data.sections) == genders
    for gender in genders:
        assert np.isfinite(data.stats(gender)).all()
    comments = [line for line in text.splitlines() if line.startswith("C ")]
    assert any("Where each value comes from" in c for c in comments)
    for row in ROWS[group]:
        assert any(c.startswith(f"C {row.label}: x ") for c in comments), row.label


def _figure(tmp_path: Path, girth: Path, cmass: Path, *gender: str) -> None:
    fig = tmp_path / f"out{'-'.join(gender)}.fig"
    options = ["--gender", *gender] if gender else []
    assert (
        main(["fig", *options, "--girth", str(girth), "--cmass", str(cmass), "-o", str(fig)]) == 0
    )
    text = fig.read_text()
    assert "nan" not in text.lower() and "999" not in text


def test_a_query_over_real_women_makes_a_complete_figure(shared_target, tmp_path, women):
    girth, cmass = _make(
        shared_target, tmp_path / "young.dat", "--query", "gender = female AND age < 25"
    )
    _complete(girth, GIRTH, {"female"})
    _complete(cmass, CENTER_OF_MASS, {"female"})
    _figure(tmp_path, girth, cmass)  # the file's only gender, without --gender
    young = [r for r in women if int(r["Age"]) < 25]
    data = read_population_file(girth, GIRTH)
    head = row_index(GIRTH, "bottom_head")
    # a cell the women have: the median of their own head length (mm -> cm)
    assert data.stats("female")[head, 0, 1] == pytest.approx(
        statistics.median(float(r["headlength"]) for r in young) / 10
    )
    text = girth.read_text()
    assert f"C Bottom Head: x people ({len(young)}), y people ({len(young)}), z model" in text
    # a cell they lack (head length, menton to vertex): appendix C scaled by their stature
    report = read_population_file(datasets.path("girth.dat"), GIRTH).stats("female")
    stature = read_population_file(datasets.path("global.dat"), GLOBAL).stats("female")[0, 0]
    own = np.percentile([float(r["stature"]) / 10 for r in young], [5, 50, 95])
    assert data.stats("female")[head, 2] == pytest.approx(report[head, 2] * own / stature, rel=1e-4)
    cm = read_population_file(cmass, CENTER_OF_MASS).stats("female")
    cm_report = read_population_file(datasets.path("cmass.dat"), CENTER_OF_MASS).stats("female")
    torso = row_index(CENTER_OF_MASS, "center_torso")
    assert cm[torso, 2] == pytest.approx(cm_report[torso, 2] * own / stature, rel=1e-4)
    # a segment appendix L.1 scales from the men's by length: the report's men's
    # center of mass x the women's own upper arm length / the report's men's
    arm, arm_length = (
        row_index(CENTER_OF_MASS, "right_upper_arm"),
        row_index(GIRTH, "right_upper_arm"),
    )
    men = read_population_file(datasets.path("cmass.dat"), CENTER_OF_MASS).stats("male")
    men_length = read_population_file(datasets.path("girth.dat"), GIRTH).stats("male")
    assert cm[arm, 2] == pytest.approx(
        men[arm, 2] * data.stats("female")[arm_length, 2] / men_length[arm_length, 2], rel=1e-4
    )


def test_a_list_of_25_ids_makes_a_complete_figure(engine_db, shared_target, tmp_path):
    ids = [
        i
        for (i,) in engine_db.execute(
            "SELECT id_num FROM person WHERE source = 'ansur2' AND gender = 'male' "
            "ORDER BY id_num LIMIT 25"
        )
    ]
    assert len(ids) == 25 >= MIN_PEOPLE
    listed = tmp_path / "chosen.csv"
    # as Excel's "CSV UTF-8" saves it: a byte-order mark before the header
    # (the header read '\ufeffid', "not a person id")
    listed.write_text("id\n" + "".join(f"{i}\n" for i in ids), encoding="utf-8-sig")
    girth, cmass = _make(shared_target, tmp_path / "chosen.dat", "--ids", str(listed))
    _complete(girth, GIRTH, {"male"})
    _complete(cmass, CENTER_OF_MASS, {"male"})
    assert "C Right Hand: x model, y people (25), z people (25)" in girth.read_text()
    _figure(tmp_path, girth, cmass)


def test_the_whole_survey_makes_a_complete_figure_of_each_gender(shared_target, tmp_path):
    girth, cmass = _make(shared_target, tmp_path / "all.dat", "--query", "source = ansur2")
    _complete(girth, GIRTH, {"male", "female"})
    _complete(cmass, CENTER_OF_MASS, {"male", "female"})
    for gender in ("male", "female"):
        _figure(tmp_path, girth, cmass, gender)
    assert "(4082 men and 1986 women" in girth.read_text()


def test_the_model_keeps_each_cells_order(shared_target, tmp_path):
    """Report cells whose values barely differ (the eyes) are not reordered by
    the scaling: no 5th-above-50th warning is added by the model."""
    girth, _cmass = _make(
        shared_target, tmp_path / "tall.dat", "--query", "gender = male AND stature > 185 cm"
    )
    data = read_population_file(girth, GIRTH)
    assert not [w for w in data.warnings if "Eye" in w]
    stats = data.stats("male")
    assert math.isfinite(float(stats.sum()))
