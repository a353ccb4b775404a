"""A real person's HAnim humanoid and .fig are that person: every site their
ANSUR II measurements place stands where they put it, the acromions as far
apart as the biacromial breadth, and the joints follow (docs/hanim.md, "A
real person").  Expected values come straight from the CSV in ../shared."""

from __future__ import annotations

import csv
import re
import statistics

import pytest
from _built_once import copy_database_file

from sass_tui.cli import main
from sass_tui.db.engine.schema import connect
from sass_tui.db.people.individual import fetch_individual, find_person, person_figure
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid, landmark_heights
from sass_tui.model.body.landmarks import BIACROMIAL_FRACTION
from sass_tui.model.files.fig_reader import read_fig

FILES = {"male": "ANSUR_II_MALE_Public.csv", "female": "ANSUR_II_FEMALE_Public.csv"}
PEOPLE = 20  # of each gender, evenly spread through the file, and F 29390
# site -> the CSV column of its height (mm); radiale: see _expected_height
SITE_COLUMNS = {
    "skull_vertex_pt": "stature",
    "cervicale_pt": "cervicaleheight",
    "suprasternale_pt": "suprasternaleheight",
    "l_acromion_pt": "acromialheight",
    "r_acromion_pt": "acromialheight",
    "l_radiale_pt": None,
    "r_radiale_pt": None,
    "l_iliocristale_pt": "iliocristaleheight",
    "r_iliocristale_pt": "iliocristaleheight",
    "l_trochanterion_pt": "trochanterionheight",
    "r_trochanterion_pt": "trochanterionheight",
    "l_tibiale_pt": "tibialheight",
    "r_tibiale_pt": "tibialheight",
    "l_lateral_malleolus_pt": "lateralmalleolusheight",
    "r_lateral_malleolus_pt": "lateralmalleolusheight",
}


def _expected_height(site: str, row: dict[str, str]) -> float:
    """m; ANSUR II has no radiale height: the acromial height less the
    acromion-radiale length, both measured standing with the arm hanging."""
    column = SITE_COLUMNS[site]
    if column is None:
        return (float(row["acromialheight"]) - float(row["acromionradialelength"])) / 1000
    return float(row[column]) / 1000


def _rows(ansur_dir, gender):
    with (ansur_dir / FILES[gender]).open(encoding="latin-1", newline="") as handle:
        rows = [{k.lower(): v for k, v in r.items()} for r in csv.DictReader(handle)]
    picked = [rows[int(k * len(rows) / PEOPLE)] for k in range(PEOPLE)]
    if gender == "female":
        picked += [r for r in rows if r["subjectid"] == "29390"]
    return picked


@pytest.fixture(scope="module")
def people(tmp_path_factory, ansur_dir, shipped_db_file):
    """A database of the sampled people (imported with `sass db import-ansur`
    from CSV files holding just their rows), and their CSV rows."""
    folder = tmp_path_factory.mktemp("hanim_people")
    db = folder / "people.db"
    copy_database_file(shipped_db_file, db)  # what `sass db init` builds
    chosen = {}
    for gender, file in FILES.items():
        header = (ansur_dir / file).read_text(encoding="latin-1").splitlines()[0]
        rows = _rows(ansur_dir, gender)
        chosen[gender] = rows
        lines = [header] + [",".join(r.values()) for r in rows]
        (folder / file).write_text("\n".join(lines) + "\n", encoding="latin-1")
        assert main(["--db", str(db), "db", "import-ansur", str(folder / file)]) == 0
    return db, chosen


def _humanoids(people):
    db, chosen = people
    conn = connect(db)
    try:
        for gender, rows in chosen.items():
            population = Figure.default(gender)
            letter = "M" if gender == "male" else "F"
            for row in rows:
                person = fetch_individual(
                    conn, find_person(conn, f"ANSUR II {letter} {row['subjectid']}")
                )
                yield row, person_figure(person, population)
    finally:
        conn.close()


def test_every_named_site_stands_at_the_persons_own_height(people):
    """Each of the 15 sites, over 41 people: within 10 mm of the person's
    measured height on average (they sit on it: the humanoid is placed from
    those very measurements)."""
    errors: dict[str, list[float]] = {site: [] for site in SITE_COLUMNS}
    for row, figure in _humanoids(people):
        sites = {s.name: s for s in build_humanoid(figure).sites}
        for site in SITE_COLUMNS:
            errors[site].append(abs(sites[site].translation[1] - _expected_height(site, row)))
    for site, values in errors.items():
        assert len(values) == 2 * PEOPLE + 1
        assert statistics.mean(values) < 0.010, site


def test_acromions_are_as_far_apart_as_the_biacromial_breadth(people):
    errors = []
    for row, figure in _humanoids(people):
        sites = {s.name: s.translation for s in build_humanoid(figure).sites}
        spacing = sites["l_acromion_pt"][0] - sites["r_acromion_pt"][0]
        errors.append(abs(spacing - float(row["biacromialbreadth"]) / 1000))
        # the shoulder centres below and inside the acromia
        humanoid = build_humanoid(figure)
        for side in "lr":
            centre, acromion = humanoid.centers[f"{side}_shoulder"], sites[f"{side}_acromion_pt"]
            assert centre[1] < acromion[1]
            assert abs(centre[0]) < abs(acromion[0])
    assert statistics.mean(errors) < 0.010


def test_f_29390_has_her_own_shoulders_and_wrists(people):
    """She was 497 mm across the acromia when the humanoid took them from
    stature ratios; her biacromial breadth is 353 mm."""
    found = [(row, figure) for row, figure in _humanoids(people) if row["subjectid"] == "29390"]
    assert len(found) == 1, "ANSUR II F 29390 not in the sample"
    row, figure = found[0]
    humanoid = build_humanoid(figure)
    sites = {s.name: s.translation for s in humanoid.sites}
    assert sites["l_acromion_pt"][0] - sites["r_acromion_pt"][0] == pytest.approx(0.353)
    for side in "lr":
        assert humanoid.centers[f"{side}_radiocarpal"][1] == pytest.approx(
            float(row["wristheight"]) / 1000
        )
        assert humanoid.centers[f"{side}_knee"][1] == pytest.approx(
            float(row["lateralfemoralepicondyleheight"]) / 1000
        )
    # the shoulder centre: 17 % of the biacromial breadth below the acromion
    assert humanoid.centers["r_shoulder"][1] == pytest.approx((1367 - 0.17 * 353) / 1000)


def test_whole_body_center_of_mass_varies_with_the_person(people):
    """With joints from stature ratios it moved by 0.14 % of the stature over
    30 people; from their own landmarks it follows their proportions."""
    shares = []
    for row, figure in _humanoids(people):
        segments = build_humanoid(figure).segments.values()
        mass = sum(s.mass for s in segments)
        com = sum(s.mass * s.center_of_mass[1] for s in segments) / mass
        shares.append(com / (float(row["stature"]) / 1000))
    assert all(0.53 <= share <= 0.59 for share in shares), (min(shares), max(shares))
    assert max(shares) - min(shares) > 0.015
    assert statistics.stdev(shares) > 0.004


def test_a_percentile_figure_is_placed_from_its_stature_alone():
    """No measured landmarks: the stature's shares, and none of a person's sites."""
    figure = Figure.default("female")
    assert figure.landmarks == {}
    humanoid = build_humanoid(figure)
    names = {s.name for s in humanoid.sites}
    assert "cervicale_pt" not in names and "l_radiale_pt" not in names
    heights = landmark_heights("female", figure.stature / 100)
    assert humanoid.centers["l_hip"][1] == pytest.approx(heights["trochanterion"])


def test_the_persons_fig_has_the_humanoids_limb_lengths(people, tmp_path):
    """`sass fig --person`: the limb z are the humanoid's joint-to-joint
    lengths, flooroffset the hip centre's height (the trochanterion)."""
    db, chosen = people
    row = chosen["male"][3]
    name = f"ANSUR II M {row['subjectid']}"
    out = tmp_path / "P.fig"
    assert main(["--db", str(db), "fig", "--person", name, "-o", str(out)]) == 0
    fig = read_fig(out)

    def mm(column):
        return float(row[column]) / 10  # cm

    def cm(variable):
        return fig.variables[variable][0]

    hip, knee = mm("trochanterionheight"), mm("lateralfemoralepicondyleheight")
    ankle = mm("lateralmalleolusheight")
    shoulder = mm("acromialheight") - 0.17 * mm("biacromialbreadth")
    elbow = mm("acromialheight") - mm("acromionradialelength")
    for side in "rl":
        assert cm(f"{side}uplegz") == pytest.approx(hip - knee, abs=0.006)
        assert cm(f"{side}lowlegz") == pytest.approx(knee - ankle, abs=0.006)
        assert cm(f"{side}uparmz") == pytest.approx(shoulder - elbow, abs=0.006)
        assert cm(f"{side}lowarmz") == pytest.approx(elbow - mm("wristheight"), abs=0.006)
    assert cm("flooroffset") == pytest.approx(hip, abs=0.02)
    assert re.search(r"limb lengths from joint centre to joint centre", out.read_text())


def test_sass_export_hanim_person_writes_the_sites(people, tmp_path):
    import xml.etree.ElementTree as ET

    db, chosen = people
    row = chosen["female"][-1]
    out = tmp_path / "P.x3d"
    name = f"ANSUR II F {row['subjectid']}"
    assert main(["--db", str(db), "export", "hanim", "--person", name, "-o", str(out)]) == 0
    sites = {
        s.get("name"): [float(v) for v in s.get("translation", "").split()]
        for s in ET.parse(out).getroot().iter("HAnimSite")
        if s.get("name")
    }
    for site in SITE_COLUMNS:
        assert sites[site][1] == pytest.approx(_expected_height(site, row), abs=1e-5), site


def test_a_length_set_by_hand_reaches_the_fig_as_set(people):
    """A person's .fig takes the joints' limb lengths, except one typed on
    the spreadsheet: that one is written as set (and undo brings the joints'
    back, since the record of it is part of the figure's snapshot)."""
    from sass_tui.model.files.figfile import girth_variables
    from sass_tui.model.names import ROWS, row_index

    row, figure = next(iter(_humanoids(people)))
    written = {name: value for name, value, _ in girth_variables(figure)}
    joints = written["ruplegz"]
    hip = float(row["trochanterionheight"]) / 10
    assert joints == pytest.approx(hip - float(row["lateralfemoralepicondyleheight"]) / 10)
    snapshot = figure.snapshot()
    figure.set_value("girth", row_index("girth", "right_upper_leg"), 2, 47.5)
    written = {name: value for name, value, _ in girth_variables(figure)}
    assert written["ruplegz"] == pytest.approx(47.5)
    assert written["luplegz"] == pytest.approx(joints)  # the other leg untouched
    assert ROWS["girth"][row_index("girth", "right_upper_leg")].name in figure.hand_set_lengths
    figure.restore(snapshot)
    assert {name: value for name, value, _ in girth_variables(figure)}["ruplegz"] == joints


def test_one_glenohumeral_rule_for_people_and_percentile_figures(ansur_dir):
    """A person whose biacromial breadth is that of a percentile figure's
    stature share has the percentile figure's shoulder height: one rule (Rab
    et al. 2002, 17 % of the acromia's distance below the acromion) for both,
    and with no breadth measured a person takes the stature's share too."""
    import runpy

    from _paths import ROOT

    script = runpy.run_path(str(ROOT / "scripts" / "hanim_landmarks.py"))
    share = script["biacromial_fractions"](ansur_dir)
    assert share == BIACROMIAL_FRACTION  # the model's constant is the CSV's mean
    for gender in ("male", "female"):
        stature = 1.70
        figure = landmark_heights(gender, stature)
        acromion_cm = figure["acromion"] * 100
        own = {"acromialheight": acromion_cm, "biacromialbreadth": share[gender] * stature * 100}
        person = landmark_heights(gender, stature, own)
        assert person["shoulder"] == pytest.approx(figure["shoulder"], abs=1e-9)
        assert figure["acromion"] - figure["shoulder"] == pytest.approx(
            0.17 * share[gender] * stature, abs=1e-9
        )
        unmeasured = landmark_heights(gender, stature, {"acromialheight": acromion_cm + 2})
        assert unmeasured["acromion"] - unmeasured["shoulder"] == pytest.approx(
            0.17 * share[gender] * stature, abs=1e-9
        )
