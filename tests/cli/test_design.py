"""`sass design`: one unknown is NHANES adults' weighted percentile computed
here from the published CSV (../shared/data/nhanes) by cumulative weight;
several unknowns give, through `sass fit` itself, the share asked for, for
real (ANSUR II), target (NHANES-weighted) and virtual people."""

from __future__ import annotations

import json

import numpy as np
import pytest

from sass_tui.cli import main
from tests._paths import SHARED
from tests.db.test_virtual import by_cumulative_weight, nhanes

NHANES_CSV = SHARED / "data" / "nhanes" / "nhanes_p_demo_bmx_2020.csv"
VIRTUAL = "nhanes-2017-2020"
SEAT = (
    "measure.poplitealheight BETWEEN ? AND ? AND measure.buttockpopliteallength >= ? "
    "AND measure.hipbreadthsitting <= ?"
)


def nhanes_adults() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Adults 20+ with a height and a weight (the virtual population's people,
    tests/db/test_virtual.py's reading of the CSV): stature (cm), gender code
    (1 male, 2 female) and WTMECPRP."""
    if not NHANES_CSV.is_file():
        pytest.skip("../shared/data/nhanes is absent")
    (men, men_w), (women, women_w) = nhanes("1", "BMXHT", "BMXWT"), nhanes("2", "BMXHT", "BMXWT")
    stature = np.concatenate([men[:, 0], women[:, 0]])
    code = np.concatenate([np.ones(len(men), int), np.full(len(women), 2)])
    return stature, code, np.concatenate([men_w, women_w])


def nhanes_mass() -> np.ndarray:
    """BMXWT of the same adults as nhanes_adults(), in its order."""
    return np.concatenate([nhanes(code, "BMXWT")[0][:, 0] for code in ("1", "2")])


def run_json(capsys, *argv: str) -> dict:
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


def test_one_unknown_is_the_weighted_95th_percentile_of_nhanes_adults(people_db, capsys):
    stature, _gender, weight = nhanes_adults()
    expected = by_cumulative_weight(stature, weight, 0.95)
    answer = run_json(
        capsys,
        *("--db", str(people_db), "design", "--virtual", VIRTUAL),
        *("--accommodate", "95", "--format", "json", "stature <= ?"),
    )
    (limit,) = answer["limits"]
    assert limit["measure"] == "stature" and limit["low"] is None
    assert limit["high"]["unit"] == "cm"
    assert limit["high"]["value"] == pytest.approx(expected, abs=0.3)
    assert limit["text"] == f"stature <= {limit['high']['value']:.1f} cm"
    assert answer["accommodate"] == 95
    assert answer["accommodated"]["percent"] == pytest.approx(95, abs=0.3)
    assert limit["excluded_above"] == pytest.approx(5, abs=0.3)


def test_women_at_least_their_weighted_5th_percentile(people_db, capsys):
    stature, gender, weight = nhanes_adults()
    women = gender == 2
    expected = by_cumulative_weight(stature[women], weight[women], 0.05)
    answer = run_json(
        capsys,
        *("--db", str(people_db), "design", "--virtual", VIRTUAL, "--gender", "female"),
        *("--accommodate", "95", "--format", "json", "stature >= ?"),
    )
    (limit,) = answer["limits"]
    assert limit["low"]["value"] == pytest.approx(expected, abs=0.3)
    assert set(answer["accommodated"]) == {"percent", "female"}


@pytest.mark.parametrize("percent", [90, 95])
@pytest.mark.parametrize(
    "people", [(), ("--target", "nhanes-2017-2020"), ("--virtual", VIRTUAL)], ids=str
)
def test_three_unknowns_give_the_share_in_sass_fit(people_db, capsys, percent, people):
    db = ("--db", str(people_db))
    answer = run_json(
        capsys,
        *db,
        "design",
        *people,
        *("--accommodate", str(percent), "--format", "json", SEAT),
    )
    texts = [limit["text"] for limit in answer["limits"]]
    assert len(texts) == 3
    assert all("?" not in text for text in texts)
    # Equal split: each limit with ? excludes the same share on its own, as
    # nearly as the weights allow (the NHANES-weighted soldiers' weights come in
    # steps of several percent: there a limit excludes at most its share).
    own = [limit["excluded_below"] + limit["excluded_above"] for limit in answer["limits"]]
    if "--target" not in people:
        assert max(own) - min(own) < 0.5
    fit = run_json(capsys, *db, "fit", *people, "--format", "json", " AND ".join(texts))
    headline = fit["accommodated"]["weighted"]["percent"]
    assert headline == pytest.approx(percent, abs=0.3)
    assert answer["accommodated"]["percent"] == pytest.approx(headline, abs=1e-9)


def test_fixed_limits_count_and_the_table_says_how(people_db, capsys):
    argv = ["--db", str(people_db), "design", "--accommodate", "90"]
    assert main([*argv, "stature <= 185 cm AND mass <= ?"]) == 0
    out = capsys.readouterr().out
    assert "stature <= 185 cm" in out and "(fixed)" in out
    assert "Accommodated (checked with sass fit): 90." in out


@pytest.mark.parametrize(
    ("split", "says"),
    [(None, "split equally"), ("1,1", "split equally"), ("1,0", "as --split gives"),
     ("3,1", "as --split gives")],
)  # fmt: skip
def test_the_table_says_how_the_exclusion_was_split(people_db, capsys, split, says):
    argv = ["--db", str(people_db), "design", "--accommodate", "95"]
    argv += [] if split is None else ["--split", split]
    assert main([*argv, "stature <= ? AND mass <= ?"]) == 0
    solved = [line for line in capsys.readouterr().out.splitlines() if line.startswith("Solved")]
    assert len(solved) == 1 and says in solved[0]


@pytest.mark.parametrize(
    ("limits", "says"),
    [
        ("gender = ?", "? is solved only"),
        ("stature = ?", "? is solved only"),
        ("(stature <= ? OR mass <= ?)", "a limit with ? is one field's"),
        ("stature <= 180 cm", "no limit has an unknown"),
        # one value asked twice would take two shares of the exclusion
        (
            "stature <= ? AND mass <= ? AND mass<=?",
            "mass<=?: the upper limit of mass is asked for twice (also by mass <= ?); ask for it once",
        ),
        ("stature <= ? AND stature BETWEEN 150 cm AND ?", "the upper limit of stature is asked"),
    ],
)
def test_bad_designs_are_one_line(people_db, capsys, limits, says):
    argv = ["--db", str(people_db), "design", "--accommodate", "95", limits]
    assert main(argv) != 0
    err = capsys.readouterr().err
    assert says in err and "Traceback" not in err


@pytest.mark.parametrize(
    ("split", "limits", "says"),
    [
        ("1,1", "stature <= ?", "--split gives 2 shares for 1 limit with a ?"),
        ("1", "stature <= ? AND mass <= ?", "--split gives 1 share for 2 limits with a ?"),
    ],
)
def test_a_split_of_the_wrong_length_is_counted_in_words(people_db, capsys, split, limits, says):
    argv = ["--db", str(people_db), "design", "--accommodate", "95", "--split", split, limits]
    assert main(argv) != 0
    assert says in capsys.readouterr().err


def test_sass_fit_refuses_an_unknown(people_db, capsys):
    assert main(["--db", str(people_db), "fit", "stature <= ?"]) != 0
    assert "sass design" in capsys.readouterr().err


@pytest.mark.slow
def test_a_civilian_figure_in_one_step(people_db, tmp_path, capsys):
    """`sass fig --virtual --gender female --percentile 5`: the women's
    weighted 5th percentile of stature, from the published CSV."""
    stature, gender, weight = nhanes_adults()
    women = gender == 2
    expected = by_cumulative_weight(stature[women], weight[women], 0.05)
    out = tmp_path / "f5.fig"
    argv = ["--db", str(people_db), "fig", "--virtual", VIRTUAL, "--gender", "female"]
    assert main([*argv, "--percentile", "5", "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    written = float(text.split(" cm (mass percentile")[0].rsplit("stature ", 1)[1])
    assert written == pytest.approx(expected, abs=0.3)
    assert "VIRTUAL people" in text and "; female;" in text
    assert main([*argv, "--girth", "x.dat", "-o", str(out)]) != 0
    assert "leave out --girth" in capsys.readouterr().err


@pytest.mark.slow
@pytest.mark.parametrize("gender", ["female", "male"])
def test_family_manikins_lie_inside_the_peoples_mass_and_bmi(people_db, tmp_path, gender):
    """Boundary manikins of NHANES adults (the virtual people's stature and
    mass are NHANES's own) at 99 %: no mass or BMI beyond the CSV's adults'."""
    stature, code, _weight = nhanes_adults()
    mass = nhanes_mass()
    mine = code == (2 if gender == "female" else 1)
    bmi = mass[mine] / (stature[mine] / 100) ** 2
    out = tmp_path / gender
    argv = ["--db", str(people_db), "family", "--virtual", VIRTUAL, "--gender", gender]
    assert main([*argv, "--measures", "stature,mass", "--coverage", "99", "-o", str(out)]) == 0
    family = json.loads((out / "family.json").read_text(encoding="utf-8"))
    assert family["space"] == "log mass"
    for manikin in family["manikins"]:
        m, s = manikin["values"]["mass"], manikin["values"]["stature"]
        assert mass[mine].min() - 0.05 <= m <= mass[mine].max() + 0.05
        assert bmi.min() - 0.05 <= m / (s / 100) ** 2 <= bmi.max() + 0.05


@pytest.mark.slow
def test_a_family_of_both_genders_counts_with_survey_weights(people_db, tmp_path):
    stature, _code, weight = nhanes_adults()
    mass = nhanes_mass()
    out = tmp_path / "both"
    argv = ["--db", str(people_db), "family", "--virtual", VIRTUAL, "--measures", "stature,mass"]
    assert main([*argv, "--coverage", "95", "--gltf", "-o", str(out)]) == 0
    family = json.loads((out / "family.json").read_text(encoding="utf-8"))
    assert family["gender"] == "both"
    for manikin in family["manikins"]:  # --gltf: each body as .glb too
        glb = next(f for f in manikin["files"] if f.endswith(".glb"))
        assert (out / glb).read_bytes()[:4] == b"glTF"
    (s_low, s_high), (m_low, m_high) = family["ranges"]["stature"], family["ranges"]["mass"]
    within = (stature >= s_low) & (stature <= s_high) & (mass >= m_low) & (mass <= m_high)
    own = 100 * weight[within].sum() / weight.sum()
    # the family's ranges are rounded to 1e-4 in family.json: a person on an edge may differ
    assert family["coverage"]["within_ranges"] == pytest.approx(own, abs=0.05)
    genders = {m["name"]: m["nearest"]["name"].split()[-2] for m in family["manikins"]}
    assert set(genders.values()) == {"M", "F"}
