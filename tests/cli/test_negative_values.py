"""An option's value that starts as a negative number does ("-30deg",
"-3kg", "-.5in") is read as the value (cli/__init__.py's parser): argparse
alone took it for an option and said "expected one argument"."""

from __future__ import annotations

import json

import pytest

from sass_tui.cli import main

LIFT = ["niosh", "--h", "40cm", "--v", "60cm", "--d", "80cm", "--f", "2", "--load", "12kg"]


def asymmetry(capsys, *angle: str) -> float:
    assert main([*LIFT, *angle, "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)["origin"]["multipliers"]["AM"]


def test_a_negative_angle_with_its_unit_is_the_options_value(capsys):
    # twisted 30 degrees to either side: AM 1 - 0.0032 x 30 (the manual's Table 6)
    assert asymmetry(capsys, "--a", "-30deg") == pytest.approx(0.904)
    assert asymmetry(capsys, "--a", "-30deg") == asymmetry(capsys, "--a=-30deg")
    assert asymmetry(capsys, "--a", "-30") == asymmetry(capsys, "--a", "30deg")


@pytest.mark.parametrize("load", ["-3kg", "-.5kg", "-3 kg"])
def test_a_negative_load_is_refused_for_what_it_is(capsys, load):
    argv = ["handling", "lift", "--h", "0.38", "--v", "1.03", "--d", "0.51", "--load", load]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert f"--load {load} is negative" in err and "expected one argument" not in err


def test_an_unknown_option_is_still_one(capsys):
    with pytest.raises(SystemExit) as stop:  # argparse's refusal: the usage, then the error
        main([*LIFT, "-x"])
    assert stop.value.code == 2
    assert "unrecognized arguments: -x" in capsys.readouterr().err
