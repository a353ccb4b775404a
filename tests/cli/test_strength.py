"""`sass strength`: one answer in text and JSON alike, and invented data
labelled wherever it appears."""

from __future__ import annotations

import json

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
