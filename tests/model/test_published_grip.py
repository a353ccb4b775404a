"""Hand and thumb-finger grip from FAA HFDS 2003 exhibit 14.5.2.1, as printed.

The page, typed here (not read from sass's data file): HFDS 2003, amended
October 2009, chapter 14, page 14-45, "Exhibit 14.5.2.1 (continued) Design
criteria for male muscle strength of the arm, hand, and thumb for control
forces (5th percentile values)", "Hand and thumb-finger strength N (lb)",
row "Momentary hold":

    (8) Hand grip L   (9) Hand grip R   (10) Thumb-finger grip (palmer)   Thumb-finger grip (tips)
    200 (44.8)        208 (47.2)        48 (10.4)                         48 (10.4)
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.model.errors import SassError
from sass_tui.model.strength.published_grip import (
    GRIP_MOTIONS,
    grip_strength,
    parse_hfds2003_text,
    read_hfds2003,
)
from sass_tui.model.strength.published_strength import PublishedStrengthError

# (motion, side) -> (newtons, pounds) as printed; None: the page prints no side.
PAGE = {
    ("hand_grip", "left"): (200.0, 44.8),
    ("hand_grip", "right"): (208.0, 47.2),
    ("thumb_finger_grip_palmar", None): (48.0, 10.4),
    ("thumb_finger_grip_tips", None): (48.0, 10.4),
}
SOURCE = "FAA HFDS 2003 exhibit 14.5.2.1 (MIL-STD-1472D), men, 5th percentile, momentary hold"
LBF = 4.4482216152605  # N per pound-force


def _asked(motion, side):
    return [side] if side else ["right", "left"]


@pytest.mark.parametrize(("motion", "side"), sorted(PAGE, key=str))
def test_each_value_is_the_page_as_printed(motion, side):
    newtons, pounds = PAGE[motion, side]
    for hand in _asked(motion, side):
        got = grip_strength(motion, hand)
        assert (got.force, got.printed_lb) == (newtons, pounds)
        assert (got.gender, got.percentile, got.condition) == ("male", 5.0, "momentary hold")
        assert got.sided == (side is not None)
        assert got.source == SOURCE


def test_the_shipped_file_holds_the_page_and_nothing_else():
    rows = read_hfds2003().rows
    got = {
        (r.motion, None if r.side == "either" else r.side): (r.newtons, r.printed_lb) for r in rows
    }
    assert got == PAGE
    assert {r.column for r in rows} == {
        "(8) Hand grip L",
        "(9) Hand grip R",
        "(10) Thumb-finger grip (palmer)",
        "Thumb-finger grip (tips)",
    }


def test_the_printed_pounds_are_not_exact_conversions():
    # Why sass gives the newtons: the page's pounds are rounded otherwise.
    for newtons, pounds in PAGE.values():
        assert abs(newtons / LBF - pounds) > 0.05


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"gender": "female"}, "gives only the 5th percentile of men for hand_grip; it has "
         "no values for women"),
        ({"percentile": 50.0}, "gives only the 5th percentile of men for hand_grip, not the "
         "50th percentile"),
        ({"percentile": 95.0}, "not the 95th percentile"),
        ({"percentile": 1.0}, "not the 1st percentile"),
        ({"percentile": 150.0}, "percentile 150 is outside 0.5-99.5"),
        ({"side": "middle"}, "side must be right or left, not 'middle'"),
        ({"gender": "robot"}, "gender must be male or female"),
    ],
)  # fmt: skip
def test_what_the_page_does_not_print_is_refused(kwargs, message):
    with pytest.raises(SassError) as info:
        grip_strength("hand_grip", **kwargs)
    assert message in str(info.value)


def test_an_arm_motion_is_refused_with_what_the_table_has():
    with pytest.raises(PublishedStrengthError, match="covers hand_grip, thumb_finger_grip_palmar"):
        grip_strength("elbow_flexion")


def test_the_5th_percentile_asked_by_name_is_given():
    assert grip_strength("thumb_finger_grip_tips", "left", "male", 5.0).force == 48.0


def test_cli_line_and_json_name_the_source(capsys):
    assert main(["strength", "hand_grip", "--side", "left"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].startswith("left hand grip: 200.00 N (FAA HFDS 2003 exhibit 14.5.2.1")
    assert "as printed 200 N (44.8 lb)" in out[0]
    assert out[1] == f"source: {SOURCE}"
    assert main(["strength", "thumb_finger_grip_palmar", "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    assert answer["source"] == SOURCE
    assert (answer["value"], answer["unit"], answer["printed"]) == (48.0, "N", "48 N (10.4 lb)")
    assert (answer["gender"], answer["percentile"], answer["sided"]) == ("male", 5.0, False)


def test_cli_gives_pounds_force_through_the_unit_table(capsys):
    assert main(["strength", "hand grip", "--unit", "lbf", "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    # 46.76, to the printed table's precision (0.1)
    assert answer["value"] == pytest.approx(208.0 / LBF, abs=0.05)
    assert answer["unit"] == "lbf" and answer["force_N"] == 208.0
    assert main(["strength", "thumb_finger_grip_tips", "--strength-data", "hfds2003"]) == 0
    assert "thumb-finger grip (tips), either hand: 48.00 N" in capsys.readouterr().out


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["hand_grip", "--gender", "female"], "gives only the 5th percentile of men"),
        (["hand_grip", "--percentile", "50"], "not the 50th percentile"),
        (["hand_grip", "--side", "middle"], "invalid choice: 'middle'"),
        (["hand_grip", "--unit", "N-m"], "a grip force is given in N or lbf"),
        (["knee_extension", "--unit", "lbf"], "a joint torque is given in ft-lb or N-m"),
        (["hand_grip", "--strength-data", "example"], "--strength-data hfds2003"),
        (["hand_grip", "--strength-data", "anderson2007"], "no hand or thumb-finger grip"),
        (["elbow_flexion", "--strength-data", "hfds2003"], "arm-strength table was not"),
        (["hand_grip", "--mass", "80", "--age", "30"], "--age, --mass: FAA HFDS 2003"),
        (["hand_grip", "wrist_x=10"], "JOINT_AXIS=ANGLE"),
        (["hand_grip", "--person", "17"], "--person"),
        (["hand_grip", "--strength-type", "isokinetic"], "--strength-type isokinetic"),
        (["hand_grip", "--plot"], "--plot"),
    ],
)
def test_cli_refusals_say_what_the_table_has(capsys, argv, message):
    try:
        status = main(["strength", *argv])
    except SystemExit as exc:  # argparse's own refusal of a choice
        status = exc.code
    assert status == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_the_example_data_are_still_reached_by_name(capsys):
    argv = ["strength", "shoulder_abduction", "shoulder_x=30", "shoulder_y=45", "elbow_y=90"]
    assert main([*argv, "--strength-data", "example"]) == 0
    named = capsys.readouterr().out
    assert main(argv) == 0
    assert capsys.readouterr().out == named
    assert "17.98 ft-lb" in named  # README's worked example, unchanged
    assert "source: example data (invented, for the report's worked examples)" in named


def _file(*rows: str) -> str:
    header = "motion,side,gender,percentile,condition,newtons,printed_lb,column"
    body = [
        "hand_grip,left,male,5,momentary hold,200,44.8,L",
        "hand_grip,right,male,5,momentary hold,208,47.2,R",
        "thumb_finger_grip_palmar,either,male,5,momentary hold,48,10.4,P",
        "thumb_finger_grip_tips,either,male,5,momentary hold,48,10.4,T",
    ]
    return "\n".join(["# a comment", header, *body, *rows]) + "\n"


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("motion,side\n", "g.csv:1: expected the header motion,side,gender"),
        (_file("hand_grip,left,male,5,momentary hold,200"), "g.csv:7: expected 8 fields"),
        (_file("wrist_grip,left,male,5,hold,1,1,W"), "g.csv:7: unknown motion 'wrist_grip'"),
        (_file("hand_grip,up,male,5,hold,1,1,W"), "g.csv:7: side 'up'"),
        (_file("hand_grip,left,male,nan,hold,1,1,W"), "g.csv:7: percentile 'nan'"),
        (_file("hand_grip,left,male,100,hold,1,1,W"), "g.csv:7: percentile '100' is not below"),
        (_file("hand_grip,left,female,5,momentary hold,-3,1,W"), "g.csv:7: newtons '-3'"),
        (_file("hand_grip,left,male,5,momentary hold,1,1,W"), "g.csv:7: a second hand_grip"),
        (_file("hand_grip,either,male,50,momentary hold,1,1,W"), "both one value for either"),
        (_file("hand_grip,left,male,50,sustained,1,1,W"), "expected one condition per motion"),
        ("\n".join(_file().splitlines()[:-1]), "g.csv: no values for thumb_finger_grip_tips"),
    ],
)
def test_a_broken_table_is_refused_with_file_and_line(text, message):
    with pytest.raises(PublishedStrengthError) as info:
        parse_hfds2003_text(text, "g.csv")
    assert message in str(info.value)


def test_a_table_of_several_percentiles_asks_for_one():
    table = parse_hfds2003_text(_file("hand_grip,left,male,50,momentary hold,400,90,L50"), "g.csv")
    with pytest.raises(PublishedStrengthError, match="5th percentile of men and the 50th"):
        grip_strength("hand_grip", "left", data=table)
    assert grip_strength("hand_grip", "left", percentile=50.0, data=table).force == 400.0
    assert grip_strength("hand_grip", "right", data=table).force == 208.0


def test_an_unreadable_file_is_refused(tmp_path):
    with pytest.raises(PublishedStrengthError, match="cannot read"):
        read_hfds2003(str(tmp_path / "absent.csv"))
    bad = tmp_path / "latin1.csv"
    bad.write_bytes(b"\xff\xfe")
    with pytest.raises(PublishedStrengthError, match="not UTF-8 text"):
        read_hfds2003(str(bad))


@settings(max_examples=40, deadline=None)
@given(st.lists(st.text(max_size=40), max_size=4), st.integers(0, 20))
def test_a_damaged_grip_table_is_refused_not_crashed(lines, at):
    good = Path(read_hfds2003().path).read_text(encoding="utf-8").splitlines()
    damaged = "\n".join(good[:at] + lines + good[at:]) + "\n"
    try:
        table = parse_hfds2003_text(damaged, "g.csv")
    except PublishedStrengthError as exc:
        assert str(exc).startswith("g.csv")
    else:
        for motion in GRIP_MOTIONS:
            try:
                grip_strength(motion, "left", data=table)
            except PublishedStrengthError as exc:
                assert motion in str(exc) or "percentile" in str(exc)
