"""The reader finds the report's suspected misprints by rule, and refuses
files of the wrong kind."""

from __future__ import annotations

import re

import pytest
from _paths import DATASETS

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.popfile import (
    PopulationFileError,
    check_center_of_mass_rules,
    parse_population_text,
    read_population_file,
)
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS

GIRTH_TEXT = (DATASETS / "girth.dat").read_text()
CMASS_TEXT = (DATASETS / "cmass.dat").read_text()


def _line(text: str, label: str, section: str) -> int:
    start = text.index(f"T {section}")
    before = text[: text.index(label, start)]
    return before.count("\n") + 1


def test_female_lower_torso_and_ball_of_foot_by_cross_gender_ratio():
    data = read_population_file(DATASETS / "girth.dat", GIRTH)
    torso = _line(GIRTH_TEXT, "/* Lower Torso */", "FEMALE")
    ball = _line(GIRTH_TEXT, "/* ball of right foot */", "FEMALE")
    found = [w for w in data.warnings if "times the male" in w]
    assert len(found) == 3, found
    assert any(w.startswith(f"{DATASETS / 'girth.dat'}:{torso}: Lower Torso z") for w in found)
    assert any(f":{ball}: Right Ball of Foot x" in w and "1.58 times" in w for w in found)


def test_the_cross_gender_rule_is_a_rule_not_a_list():
    """Double another female length: it is found; halve the lower torso back to
    a male-like ratio: it is no longer found."""
    section = GIRTH_TEXT.index("T FEMALE")
    head, female = GIRTH_TEXT[:section], GIRTH_TEXT[section:]
    female = female.replace(
        "35.1   37.4   39.7  /* r Upper Leg */", "70.2   74.8   79.4  /* r Upper Leg */"
    )
    female = female.replace(
        "24.9   26.1   27.3  /* Lower Torso */", "11.4   12.0   12.6  /* Lower Torso */"
    )
    data = parse_population_text(head + female, GIRTH, "g.dat")
    found = [w for w in data.warnings if "times the male" in w]
    leg = _line(head + female, "/* r Upper Leg */", "FEMALE")
    assert any(w.startswith(f"g.dat:{leg}: Right Upper Leg z") for w in found)
    assert not any("Lower Torso" in w for w in found)


def test_female_upper_leg_center_of_mass_and_foot_by_appendix_l1():
    girth = read_population_file(DATASETS / "girth.dat", GIRTH)
    cmass = read_population_file(DATASETS / "cmass.dat", CENTER_OF_MASS)
    found = check_center_of_mass_rules(cmass, girth)
    leg = _line(CMASS_TEXT, "/* r Upper Leg */", "FEMALE")
    assert any(
        w.startswith(f"{DATASETS / 'cmass.dat'}:{leg}: Right Upper Leg z: the 5th value 16.7")
        and "= 14.7" in w
        for w in found
    )
    ball = _line(GIRTH_TEXT, "/* ball of right foot */", "FEMALE")
    implied = [w for w in found if "foot rule" in w]
    assert len(implied) == 2 and f"girth.dat:{ball}: Right Ball of Foot x" in implied[0]
    assert re.search(r"gives 6\.2/6\.8/7\.4", implied[0])
    # the 50th and 95th percentiles follow the rule; the arms, off by the same
    # factor at every percentile, are not flagged
    assert len(found) == 4
    assert not any("Upper Arm" in w for w in found)


def test_the_scaling_rule_finds_a_changed_cell_anywhere():
    cmass_text = CMASS_TEXT.replace(
        "12.2   13.4  14.26  /* r Upper Arm */", "12.2   16.0  14.26  /* r Upper Arm */"
    )
    assert cmass_text != CMASS_TEXT
    cmass = parse_population_text(cmass_text, CENTER_OF_MASS, "c.dat")
    girth = read_population_file(DATASETS / "girth.dat", GIRTH)
    found = check_center_of_mass_rules(cmass, girth)
    arm = _line(cmass_text, "/* r Upper Arm */", "FEMALE")
    assert any(w.startswith(f"c.dat:{arm}: Right Upper Arm z: the 50th value 16") for w in found)


def test_loading_warns_with_the_file_just_loaded(capsys, tmp_path):
    assert (
        main(
            [
                "fig",
                "--gender",
                "female",
                "--cmass",
                str(DATASETS / "cmass.dat"),
                "-o",
                str(tmp_path / "f.fig"),
            ]
        )
        == 0
    )
    err = capsys.readouterr().err
    assert "Right Upper Leg z: the 5th value 16.7" in err
    # the foot rule's suspect cell is in girth.dat, a file not named: not said
    assert "Right Ball of Foot x" not in err
    both = ["--girth", str(DATASETS / "girth.dat"), "--cmass", str(DATASETS / "cmass.dat")]
    assert main(["fig", "--gender", "female", *both, "-o", str(tmp_path / "g.fig")]) == 0
    err = capsys.readouterr().err
    assert "Right Ball of Foot x" in err and "foot rule" in err


@pytest.mark.parametrize(
    "option,path,kind",
    [
        ("--girth", "jntlmt.dat", "a joint-limits file"),
        ("--cmass", "girth.dat", "a girth (segment dimensions) file"),
        ("--jntlmt", "cmass.dat", "a center-of-mass file"),
        ("--girth", "cmass.dat", "a center-of-mass file"),
    ],
)
def test_a_file_of_another_group_is_refused(capsys, tmp_path, option, path, kind):
    out = tmp_path / "x.fig"
    assert main(["fig", option, str(DATASETS / path), "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert re.search(
        rf"{re.escape(str(DATASETS / path))}:\d+: .*this looks like {re.escape(kind)}", err
    )
    assert not out.exists()


def test_a_refused_file_leaves_the_figure_as_it_was():
    figure = Figure.default("male")
    before = figure.groups[GIRTH].values.copy()
    with pytest.raises(PopulationFileError, match="looks like a joint-limits file"):
        figure.load_group(GIRTH, read_population_file(DATASETS / "jntlmt.dat", GIRTH))
    assert (figure.groups[GIRTH].values == before).all()
    # the right kind still loads
    figure.load_group(JOINT_LIMITS, read_population_file(DATASETS / "jntlmt.dat", JOINT_LIMITS))
