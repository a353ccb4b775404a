"""`sass strength`: one answer in text and JSON alike, and invented data
labelled wherever it appears."""

from __future__ import annotations

import json

import pytest

from sass_tui.cli import main


def test_text_and_json_give_the_same_answer(capsys):
    assert main(["strength", "elbow_flexion", "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    assert main(["strength", "elbow_flexion"]) == 0
    text = capsys.readouterr().out
    assert (answer["motion"], answer["side"], answer["unit"]) == ("elbow_flexion", "right", "ft-lb")
    assert f"{answer['value']:.2f} {answer['unit']}" in text


def test_the_shipped_strength_file_is_labelled_as_test_data(capsys):
    # datasets/strength.dat is made by scripts/make_strength_dat.py, not measured.
    assert main(["strength", "elbow_flexion"]) == 0
    text = capsys.readouterr().out
    assert "invented" in text and "TEST DATA" in text


def test_an_unknown_motion_is_refused(capsys):
    assert main(["strength", "elbow_wiggle"]) == 2
    assert "elbow_wiggle" in capsys.readouterr().err


def test_joint_angles_may_follow_the_options(capsys):
    """argparse hands a verb its positionals at their first word: angles typed
    after an option were "unrecognized arguments: elbow_y=90"."""
    first = ["strength", "knee_extension", "knee_y=45", "--side", "left", "--format", "json"]
    assert main(first) == 0
    before = json.loads(capsys.readouterr().out)
    after = ["strength", "knee_extension", "--side", "left", "knee_y=45", "--format", "json"]
    assert main(after) == 0
    assert json.loads(capsys.readouterr().out) == before
    with pytest.raises(SystemExit):  # a word that is no angle is still refused, alone
        main([*after, "--bogus"])
    assert capsys.readouterr().err.endswith("error: unrecognized arguments: --bogus\n")


def test_an_axis_given_twice_is_refused(capsys):
    # the last was kept silently
    assert main(["strength", "knee_extension", "knee_y=45", "knee_y=50"]) == 2
    assert "'knee_y=50': knee_y is given twice (also 'knee_y=45')" in capsys.readouterr().err
