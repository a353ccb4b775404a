"""`.fig` files: appendix F reproduced, hand-computed figures, round trip, `sass fig`."""

from __future__ import annotations

import re
import subprocess
import sys

import pytest
from _paths import DATASETS

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.fig_reader import parse_fig, read_fig
from sass_tui.model.files.figfile import FigParseError, default_fig_name, render_fig

# Appendix F misspells three names that BODY.FIG (appendix D) reads otherwise.
APPENDIX_F_SPELLING = {
    "boheadx": "botheadx",
    "boheady": "botheady",
    "boheadz": "botheadz",
    "rlolegmass": "rlowlegmass",
    "llolegmass": "llowlegmass",
    "rloarmmass": "rlowarmmass",
    "lloarmmass": "llowarmmass",
}
# Appendix F's arm lengths are not appendix B's 50th percentile (docs/model.md).
ARM_LENGTHS = {"ruparmz", "luparmz", "rlowarmz", "llowarmz"}


@pytest.fixture(scope="module")
def appendix_f(report_lines) -> dict[str, tuple[float, str]]:
    start = report_lines.index("F Sample Figure Description File, MALE50.FIG")
    stop = report_lines.index("G Joint motion variable list")
    out = {}
    for line in report_lines[start:stop]:
        match = re.match(r"^\s*(\w+) = (-?[\d.]+)(cm|kg|deg);", line)
        if match:
            name = APPENDIX_F_SPELLING.get(match.group(1), match.group(1))
            out[name] = (float(match.group(2)), match.group(3))
    return out


@pytest.fixture
def male50(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["fig", "-o", "MALE50.FIG"]) == 0
    return read_fig(tmp_path / "MALE50.FIG")


def test_male50_reproduces_appendix_f_girths(appendix_f, male50):
    girth = {k: v for k, v in appendix_f.items() if v[1] == "cm"}
    assert len(girth) == 76
    for name, (value, unit) in girth.items():
        if name in ARM_LENGTHS:
            assert male50.variables[name][0] != value
            continue
        assert male50.variables[name] == (value, unit), name
    assert male50.variables["flooroffset"] == (94.10, "cm")


def test_male50_reproduces_appendix_f_masses(appendix_f, male50):
    masses = {k: v for k, v in appendix_f.items() if v[1] == "kg"}
    assert len(masses) == 31
    for name, (value, unit) in masses.items():
        assert male50.variables[name] == (value, unit), name
    total = sum(v for v, u in male50.variables.values() if u == "kg")
    assert total == pytest.approx(82.2, abs=0.05)


def test_male50_joint_limit_names_are_appendix_f_names(appendix_f, male50):
    joints = {k for k, v in appendix_f.items() if v[1] == "deg"}
    written = {k for k, v in male50.variables.items() if v[1] == "deg"}
    assert joints <= written
    assert male50.variables["right_elbow_y_ulimit"] == (149.75, "deg")  # 50th, appendix H
    assert "right_elbow_x_ulimit" not in written  # 999: no motion
    assert male50.archive == "skinny.a" and male50.body == "body.fig"


def test_female_5th_by_hand(tmp_path):
    out = tmp_path / "f.fig"
    assert main(["fig", "--gender", "female", "--percentile", "5", "-o", str(out)]) == 0
    fig = read_fig(out).variables
    by_hand = {  # appendix C (5th column) with the psurf rules; appendix I; global.dat
        "ruparmx": 7.48 / 2,
        "ruparmy": 6.36 / 2,
        "ruparmz": 27.2,
        "rfootx": 16.0 * 0.75,
        "rfooty": 8.6 / 2,
        "flooroffset": 9.2 + 30.7 + 35.1,
        "eyelocx": 16.3 / 2,
        "eyelocy": 2.7,
        "reyey": 2.75,
        "rtoesx": 10.4,
        "rtoesy": 8.0 / 2,
        "rfingersz": 8.4,
        "right_elbow_y_ulimit": 144.9,
        "neck_y_llimit": -64.9,
        "right_shoulder_z_llimit": -95.8,
        "ruplegcmz": 16.7,
        "botheadcmx": 0.0,
        "ruplegmass": 0.1 * 51.3,
        "ctorsomass": 0.138 * 51.3,
    }
    for name, value in by_hand.items():
        assert fig[name][0] == pytest.approx(value, abs=0.0051), name


def test_male_95th_by_hand(tmp_path):
    out = tmp_path / "m.fig"
    assert main(["fig", "--percentile", "95", "-o", str(out), "--figure-type", "polybody"]) == 0
    fig = read_fig(out)
    by_hand = {
        "ruplegz": 47.0,
        "flooroffset": 15.8 + 38.3 + 47.0,
        "rfootx": 21.1 * 0.75,
        "ctorsoy": 45.4 / 2,
        "botheadx": 21.1 / 2,
        "eyelocx": 20.8 / 2,
        "right_shoulder_x_ulimit": 188.7,
        "neck_y_llimit": -103.0,  # appendices J and F; H misprints +103.0
        "right_shoulder_z_llimit": -126.6,  # appendix F; H and J misprint +126.6
        "right_knee_y_ulimit": 145.6,
        "ctorsocmx": -2.6,
        "rfootcmx": 7.41,
        "ruplegmass": 0.1 * 107.6,
    }
    for name, value in by_hand.items():
        assert fig.variables[name][0] == pytest.approx(value, abs=0.0051), name
    assert fig.archive == "polybody.a"


def test_round_trip_every_variable(tmp_path):
    figure = Figure.default("female")
    figure.set_group_percentile("girth", 37.5)
    text = render_fig(figure)
    parsed = parse_fig(text)
    assigned = re.findall(r"^(\w+) = (-?[\d.]+)(\w+);$", text, re.M)
    assert len(parsed.variables) == len(assigned) > 200
    for name, value, unit in assigned:
        assert parsed.variables[name] == (float(value), unit)


@pytest.mark.parametrize(
    "text,message",
    [
        ("a = 1cm\nb = 2cm;\n", "x.fig:2:1: found 'b'; expected ';'"),
        ("a = cm;\n", "x.fig:1:5: found 'cm'; expected a number"),
        ("a = 1cm;\n", "no closing line"),
        ('a = 1cm;\na = 2cm;\nfigure ["body.fig"] ("skinny.a");', "x.fig:2:1: a assigned twice"),
        ("a = 1cm; $", "x.fig:1:10: unexpected character '$'"),
    ],
)
def test_fig_parse_errors_say_where(text, message):
    with pytest.raises(FigParseError) as info:
        parse_fig(text, "x.fig")
    assert message in str(info.value)


@pytest.mark.parametrize(
    "args,name",
    [
        ([], "MALE50.FIG"),
        (["--gender", "female", "--percentile", "5"], "FEMALE05.FIG"),
        (["--figure-type", "polybody", "--percentile", "95"], "PBMALE95.FIG"),
    ],
)
def test_default_file_names(tmp_path, monkeypatch, args, name):
    monkeypatch.chdir(tmp_path)
    assert main(["fig", *args]) == 0
    assert (tmp_path / name).is_file()
    assert default_fig_name("female", 97.5) == "FEMALE97_5.FIG"


def test_refused_without_a_group_for_the_gender(tmp_path, capsys):
    male_only = (DATASETS / "girth.dat").read_text().split("T FEMALE")[0]
    (tmp_path / "male_only.dat").write_text(male_only)
    out = tmp_path / "f.fig"
    status = main(
        ["fig", "--gender", "female", "--girth", str(tmp_path / "male_only.dat"), "-o", str(out)]
    )
    assert status != 0
    assert "Girth not loaded for female" in capsys.readouterr().err
    assert not out.exists()


@pytest.mark.parametrize(
    "args,message",
    [
        (["--mass", "12 cm"], "cm is not a unit of mass"),
        (["--stature", "12 kg"], "kg is not a unit of length"),
        (["--girth", "nope.dat"], "cannot read"),
    ],
)
def test_cli_errors_leave_no_file(tmp_path, monkeypatch, capsys, args, message):
    monkeypatch.chdir(tmp_path)
    assert main(["fig", *args]) == 2
    assert message in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []


def test_cli_percentile_120_is_refused(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as info:
        main(["fig", "--percentile", "120"])
    assert info.value.code == 2
    assert "percentile 120 is outside 0.5-99.5" in capsys.readouterr().err


def test_overwrite_is_atomic_and_complete(tmp_path):
    out = tmp_path / "x.fig"
    out.write_text("old")
    assert main(["fig", "-o", str(out)]) == 0
    assert out.read_text().rstrip().endswith('figure ["body.fig"] ("skinny.a");')
    assert [p.name for p in tmp_path.iterdir()] == ["x.fig"]


def test_cli_end_to_end_as_a_process(tmp_path):
    done = subprocess.run(
        [sys.executable, "-m", "sass_tui", "fig", "-o", str(tmp_path / "a.fig")],
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    assert "flooroffset = 94.10cm;" in (tmp_path / "a.fig").read_text()
