"""`sass handling` (cli/handling.py): the JSON the issue asks for (push and
pull: initial and sustained), the refused ranges, a load typed as a force,
the hands' H and V from a posture file and from a figure, and a virtual
population's share: the survey-weighted mix of the women's and men's percent
capable, the weights read here from the stored virtual people."""

from __future__ import annotations

import json
import math

import pytest

from sass_tui.cli import main
from sass_tui.cli.handling_people import figure_at
from sass_tui.model.body.posture import parse_angles, pose_figure
from tests._virtual_task import virtual_people

# The shared README's reference case (Liberty Mutual, women, lift)
LIFT = ["--h", "0.38", "--v", "1.03m", "--d", "51cm", "--f", "1"]


def handling(capsys, *argv):
    assert main(["handling", *argv, "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_the_json_shape_for_lift(capsys):
    answer = handling(capsys, "lift", *LIFT, "--load", "10kg")
    women = answer["female"]
    assert answer["task"] == "lift" and "Potvin" in answer["source"]
    assert women["mal"] == {"value": pytest.approx(15.556, abs=5e-3), "unit": "kg"}
    assert women["cv"] == 0.26 and women["percent_capable"] == pytest.approx(91.5, abs=0.05)
    assert women["load_for"]["75"] == pytest.approx(12.83, abs=0.01)
    assert women["load_for"]["90"] == pytest.approx(10.37, abs=0.01)
    assert set(answer["male"]["factors"]) == {"RL", "H", "VRM", "DV", "F"}


def test_push_and_pull_are_initial_and_sustained_and_take_a_force(capsys):
    answer = handling(capsys, "pull", "--v", "1.2", "--d", "20", "--load", "100N")
    men = answer["male"]
    assert set(men) >= {"initial", "sustained"} and men["initial"]["mal"]["unit"] == "kgf"
    assert men["initial"]["mal"]["value"] == pytest.approx(22.91, abs=0.01)
    assert men["sustained"]["mal"]["value"] == pytest.approx(13.77, abs=0.01)
    kgf = 100 / 9.80665
    z = (1 - kgf / men["initial"]["mal"]["value"]) / 0.238
    share = 50 * (1 + math.erf(z / math.sqrt(2)))
    assert men["initial"]["percent_capable"] == pytest.approx(share, abs=0.05)


@pytest.mark.parametrize("typed", ["10.197162kgf", "10.197162 kp", "22.480894lbf"])
def test_a_push_load_in_the_papers_own_kgf_or_in_lbf_is_the_same_force(capsys, typed):
    # 100 N = 100 / 9.80665 kgf = 22.480894 lbf: the same share accept it
    in_newtons = handling(capsys, "push", "--v", "1.2", "--d", "20", "--load", "100N")
    typed_so = handling(capsys, "push", "--v", "1.2", "--d", "20", "--load", typed)
    assert typed_so["load"]["unit"] == "kgf"
    assert typed_so["load"]["value"] == pytest.approx(100 / 9.80665, abs=1e-4)
    for sex in ("female", "male"):
        for phase in ("initial", "sustained"):
            assert typed_so[sex][phase]["percent_capable"] == pytest.approx(
                in_newtons[sex][phase]["percent_capable"], abs=1e-3
            )


def test_outside_the_papers_ranges_is_refused_for_that_sex(capsys):
    answer = handling(capsys, "lift", "--h", "0.22", "--v", "1", "--d", "0.5")
    assert "mal" in answer["female"]
    assert answer["male"]["refused"] == ["H 0.22 m outside 0.25-0.73 m"]


def test_a_posture_file_gives_h_and_v(capsys, tmp_path):
    # the hands' third knuckles 0.45 m ahead of L5 and 0.95 m above the floor
    points = {
        "l_metacarpophalangeal_3": [0.15, 0.95, 0.45],
        "r_metacarpophalangeal_3": [-0.15, 0.95, 0.45],
        "l_radiocarpal": [0.15, 1.0, 0.4],
        "r_radiocarpal": [-0.15, 1.0, 0.4],
        "l_elbow": [0.17, 1.05, 0.2],
        "r_elbow": [-0.17, 1.05, 0.2],
        "l_shoulder": [0.18, 1.4, 0.0],
        "r_shoulder": [-0.18, 1.4, 0.0],
        "vl5": [0.0, 1.0, 0.0],
        "vc7": [0.0, 1.45, 0.0],
    }
    posture = tmp_path / "posture.json"
    posture.write_text(json.dumps(points), encoding="utf-8")
    answer = handling(capsys, "lift", "--posture", str(posture), "--d", "0.5", "--gender", "female")
    assert answer["female"]["inputs"]["h"] == pytest.approx(0.45)
    assert answer["female"]["inputs"]["v"] == pytest.approx(0.95)


def test_one_posture_for_the_5th_percentile_woman_and_the_95th_percentile_man(capsys):
    posture = ["shoulder_y=60", "elbow_y=30"]
    small = handling(capsys, "lift", *posture, "--d", "0.5", "--gender", "female",
                     "--percentile", "5")["female"]  # fmt: skip
    large = handling(capsys, "lift", *posture, "--d", "0.5", "--gender", "male",
                     "--percentile", "95")["male"]  # fmt: skip
    assert (
        large["inputs"]["h"] > small["inputs"]["h"] and large["inputs"]["v"] > small["inputs"]["v"]
    )
    # the hands where the posed figure puts them: the knuckles' midpoint from the ankles'
    body = pose_figure(figure_at("female", 5.0), parse_angles(posture))
    grasp = (body.points["l_metacarpophalangeal_3"] + body.points["r_metacarpophalangeal_3"]) / 2
    ankles = (body.centers["l_talocrural"] + body.centers["r_talocrural"]) / 2
    assert small["inputs"]["v"] == pytest.approx(grasp[1])
    assert small["inputs"]["h"] == pytest.approx(math.hypot(*(grasp - ankles)[[0, 2]]))


def test_virtual_population_is_the_weighted_mix_of_women_and_men(capsys, people_db):
    answer = handling(capsys, "carry", "--v", "0.9", "--d", "5", "--f", "0.5", "--load", "15kg",
                      "--virtual", "nhanes-2017-2020", "--db", str(people_db))  # fmt: skip
    weights = {
        sex: float(virtual_people(str(people_db), sex)[1].sum()) for sex in ("female", "male")
    }
    mix = sum(answer[sex]["percent_capable"] * weights[sex] for sex in weights) / sum(
        weights.values()
    )
    assert answer["population"]["percent_capable"] == pytest.approx(mix, abs=0.01)
    assert answer["population"]["weights"] == pytest.approx(weights)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["lift", "--v", "1", "--d", "0.5"], "lift needs --h"),
        (["carry", "--v", "1"], "give --d"),
        (["lift", *LIFT, "--load", "100N"], "takes a mass"),
        (["carry", "--v", "1", "--d", "5", "--load", "10kgf"], "takes a mass"),
        (["lift", *LIFT, "--virtual", "nhanes-2017-2020"], "give it"),
        (["lift", "shoulder_y=45", "--h", "0.3", "--d", "0.5"], "leave out --h"),
        (["lift", "shoulder_y=45", "kg", "--h", "0.3", "--d", "0.5"], "'kg' is a unit"),
        (["lift", "--h", "-0.3", "--v", "1", "--d", "0.5"], "--h -0.3 is negative"),
        (["lift", "--h", "0.3", "--v", "1", "--d", "0.5", "--f=nan"], "--f: 'nan' is not a usable"),
        (["lift", "--h", "0.3", "--v", "1", "--d", "0.5", "--f=-1"], "--f: '-1' is negative"),
        (["lift", "--h", "0.3", "--v", "1", "--d", "0.5", "--f", "2/day"], "no time unit"),
    ],
)
def test_bad_input_is_one_line(capsys, argv, message):
    assert main(["handling", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_a_frequency_may_be_counted_per_hour(capsys):
    """Potvin et al.'s F is per minute: `--f 60/h` is `--f 1`."""
    per_minute = handling(capsys, "lift", *LIFT, "--load", "10kg")
    rest = [a for a in LIFT if a not in ("--f", "1")]
    per_hour = handling(capsys, "lift", *rest, "--f", "60/h", "--load", "10kg")
    assert per_hour["female"] == per_minute["female"] and per_hour["male"] == per_minute["male"]
