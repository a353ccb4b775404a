"""`sass niosh` (cli/niosh.py): the JSON the issue asks for, the two forms
chosen by the units typed, the limits named, the special frequency
adjustment, a job file's composite index, and bad input said in one line."""

from __future__ import annotations

import json

import pytest

from sass_tui.cli import main


def niosh(capsys, *argv):
    assert main(["niosh", *argv, "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_the_json_shape_and_the_metric_form(capsys):
    answer = niosh(capsys, "--h", "40cm", "--v", "60cm", "--d", "80cm", "--a", "30",
                   "--f", "2", "--duration", "moderate", "--load", "12kg")  # fmt: skip
    origin = answer["origin"]
    assert set(origin["multipliers"]) == {"LC", "HM", "VM", "DM", "AM", "FM", "CM"}
    assert origin["rwl"]["unit"] == "kg" and origin["multipliers"]["LC"] == 23
    # the manual's formulas, by hand: 25/40, 1 - .003 x 15, .82 + 4.5/80, 1 - .0032 x 30,
    # Table 5 (2/min, <= 2 h, V < 75 cm) .84, Table 7 (fair, V < 75 cm) .95
    rwl = 23 * (25 / 40) * (1 - 0.003 * 15) * (0.82 + 4.5 / 80) * (1 - 0.0032 * 30) * 0.84 * 0.95
    assert origin["rwl"]["value"] == pytest.approx(rwl, abs=1e-3)
    assert origin["lifting_index"] == pytest.approx(12 / rwl, abs=1e-3)
    assert answer["destination"] is None and "NIOSH" in answer["source"]


def test_inches_use_the_us_form_and_the_destination_is_rated(capsys):
    # the manual's Example 4: 26 lb, H 10 -> 20 in, V 22 -> 59 in, F 3/min, <= 1 h
    answer = niosh(capsys, "--h", "10in", "--v", "22in", "--dest-h", "20in", "--dest-v",
                   "59in", "--f", "3", "--duration", "short", "--load", "26lb")  # fmt: skip
    assert answer["form"] == "us" and answer["origin"]["rwl"]["unit"] == "lb"
    assert answer["origin"]["multipliers"]["LC"] == 51
    assert answer["destination"]["rwl"]["value"] == pytest.approx(15.2, rel=0.01)
    assert answer["lifting_index"] == pytest.approx(1.7, abs=0.05)


def test_limits_are_named_and_no_load_is_null(capsys):
    answer = niosh(capsys, "--h", "70cm", "--v", "30cm", "--d", "10cm", "--f", "0.1",
                   "--load", "5kg")  # fmt: skip
    limits = " ".join(answer["origin"]["limits"])
    assert "beyond 63 cm" in limits and "taken as 25 cm" in limits and "taken as 0.2" in limits
    assert answer["rwl"]["value"] == 0 and answer["lifting_index"] is None


def test_the_special_frequency_adjustment(capsys):
    # 10 lifts a minute for 8 of the 15 minutes: F = 5.33, between the rows for 5 and 6
    answer = niosh(capsys, "--h", "25cm", "--v", "75cm", "--d", "25cm", "--f", "10",
                   "--lifting-minutes", "8", "--duration", "short", "--coupling", "good")  # fmt: skip
    fm = 0.80 + (80 / 15 - 5) * (0.75 - 0.80)
    assert answer["origin"]["multipliers"]["FM"] == pytest.approx(fm, abs=1e-4)


def test_a_job_file_gives_the_composite_index(capsys, tmp_path):
    job = tmp_path / "job.csv"
    job.write_text(
        "name,load,h,v,d,f,coupling\na,10,25cm,75cm,25cm,1,good\nb,10,25cm,75cm,25cm,2,good\n",
        encoding="utf-8-sig",  # as Excel's "CSV UTF-8" writes it: the first column was '\ufeffname'
    )
    answer = niosh(capsys, "--tasks", str(job), "--duration", "long")
    # FIRWL 23 each; STLI 10/(23 x .75) and 10/(23 x .65): b first; CLI = STLI_b
    # + FILI_a (1/FM(3/min) - 1/FM(2/min))
    expected = 10 / (23 * 0.65) + 10 / 23 * (1 / 0.55 - 1 / 0.65)
    assert [t["name"] for t in answer["tasks"]] == ["b", "a"]
    assert answer["composite_lifting_index"] == pytest.approx(expected, abs=1e-3)
    assert main(["niosh", "--tasks", str(job)]) == 0
    assert "Composite lifting index: " in capsys.readouterr().out


def test_a_posture_file_gives_the_origin(capsys, tmp_path):
    points = {
        "l_metacarpophalangeal_3": [0.15, 0.80, 0.40],
        "r_metacarpophalangeal_3": [-0.15, 0.80, 0.40],
        "l_radiocarpal": [0.15, 0.85, 0.35],
        "r_radiocarpal": [-0.15, 0.85, 0.35],
        "l_elbow": [0.17, 1.0, 0.2],
        "r_elbow": [-0.17, 1.0, 0.2],
        "l_shoulder": [0.18, 1.4, 0.0],
        "r_shoulder": [-0.18, 1.4, 0.0],
        "vl5": [0.0, 1.0, 0.05],
        "vc7": [0.0, 1.45, 0.0],
    }
    posture = tmp_path / "posture.json"
    # with the byte-order mark a Windows editor writes first (it was no JSON then)
    posture.write_text(json.dumps(points), encoding="utf-8-sig")
    answer = niosh(capsys, "--posture", str(posture), "--d", "50cm", "--f", "1")
    # H from below L5: 0.35 m; V 0.80 m
    assert answer["inputs"]["h"] == pytest.approx(35.0)
    assert answer["inputs"]["v"] == pytest.approx(80.0)
    assert answer["origin"]["multipliers"]["HM"] == pytest.approx(25 / 35, abs=1e-4)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--v", "60cm", "--f", "1"], "a lift needs --h"),
        (["shoulder_y=60", "--v", "60cm", "--d", "20", "--f", "1"], "leave out --v"),
        (["--h", "40cm", "--v", "60cm", "--f", "1"], "give the vertical travel distance"),
        (["--h", "40cm", "--v", "60cm", "--d", "1kg", "--f", "1"], "not a unit of length"),
        (["--h", "40cm", "--v", "60cm", "--d", "20", "--f", "x"], "lifts per minute: expected a number"),
        (["--h", "40cm", "--v", "60cm", "--dest-v", "90cm", "--f", "1"], "both --dest-h"),
        (["--h", "40cm", "--v", "60cm", "--d", "20", "--f", "20", "--lifting-minutes", "5"],
         "at most 15 lifts"),
        (["--tasks", "/nonexistent/job.csv"], "no such file"),
        (["--tasks", "job.csv", "--h", "40cm"], "leave out --h"),
        # the posture was passed over without a word
        (["--tasks", "job.csv", "shoulder_y=90"], "leave out JOINT=ANGLE"),
        (["--tasks", "job.csv", "--posture", "p.json"], "leave out --posture"),
        # `--load 10 kg`: the shell leaves `kg` a posture word, which is named
        # (not "leave out --h, --v", which the typed --h and --v would give)
        (["--h", "40cm", "--v", "60cm", "--d", "20", "--f", "1", "--load", "10", "kg"],
         "'kg': expected JOINT=ANGLE, e.g. shoulder_y=90 ('kg' is a unit: write it against "
         "its number, as in 12kg)"),
    ],
)  # fmt: skip
def test_bad_input_is_one_line(capsys, argv, message):
    assert main(["niosh", *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_a_place_no_load_is_acceptable_at_says_so(capsys):
    # H 70 cm is past the manual's 63 cm: HM 0, the RWL 0, the index of any
    # load infinite; said as such, never as a number or "above 1"
    args = ["--h", "70cm", "--v", "60cm", "--d", "30cm", "--f", "1", "--load", "5kg"]
    assert main(["niosh", *args]) == 0
    text = capsys.readouterr().out
    table = {line.split()[0]: line.split()[1:] for line in text.splitlines() if line.strip()}
    assert table["HM"] == ["0.000"] and table["LI"] == ["infinite"]
    said = next(line for line in text.splitlines() if line.startswith("Lifting index of 5 kg"))
    assert said == (
        "Lifting index of 5 kg: infinite (the RWL is 0: a limit below leaves no load "
        "acceptable at this place)"
    )
    assert "H 70 cm beyond 63 cm: HM 0" in text
    answer = niosh(capsys, *args)
    assert answer["rwl"]["value"] == 0 and answer["lifting_index"] is None


def test_a_job_names_the_limit_that_left_a_task_no_load(capsys, tmp_path):
    job = tmp_path / "job.csv"
    job.write_text(
        "name,load,h,v,d,f,coupling\nfar,10,70cm,75cm,25cm,1,good\nnear,10,25cm,75cm,25cm,2,good\n",
        encoding="utf-8",
    )
    assert main(["niosh", "--tasks", str(job)]) == 0
    lines = capsys.readouterr().out.splitlines()
    header = next(line for line in lines if line.lstrip().startswith("#"))
    far = next(line for line in lines if " far " in line)
    assert far.split()[-2:] == ["infinite", "infinite"]
    assert len(far) == len(header)  # the words fit their columns
    assert "Limit (task far): H 70 cm beyond 63 cm: HM 0" in lines
    assert not [line for line in lines if line.startswith("Limit (task near)")]
    answer = niosh(capsys, "--tasks", str(job))
    limits = {task["name"]: task["limits"] for task in answer["tasks"]}
    assert limits == {"far": ["H 70 cm beyond 63 cm: HM 0"], "near": []}
    assert answer["composite_lifting_index"] is None


def test_a_frequency_may_be_counted_per_hour_or_timed_in_seconds(capsys):
    """F is per minute (Table 5); `--f 120/h` and `--f 2/min` are the same lift."""
    args = ["--h", "40cm", "--v", "60cm", "--d", "80cm", "--load", "12kg", "--format", "json"]
    answers = []
    for rate in ("2", "2/min", "120/h", "120 per hour", "0.0333333333333333/s"):
        assert main(["niosh", *args, "--f", rate]) == 0
        answers.append(json.loads(capsys.readouterr().out)["origin"]["multipliers"]["FM"])
    assert answers == [answers[0]] * len(answers) and answers[0] < 1
