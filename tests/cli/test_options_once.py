"""An option that takes one value, given twice on one command line, is refused
naming both values (cli/__init__.py's parser): argparse kept the last one
and said nothing, so `--load 10kg ... --load 20kg` answered for 20 kg."""

from __future__ import annotations

import argparse
import json

import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.cli import build_parser, main

LIFT = ["niosh", "--h", "40cm", "--v", "60cm", "--d", "80cm", "--f", "2"]


def refused(capsys, argv: list[str]) -> str:
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    return captured.err.strip().splitlines()[-1]


def test_an_option_given_twice_is_refused_naming_both_values(capsys):
    error = refused(capsys, [*LIFT, "--load", "12kg", "--load", "20kg"])
    assert error == "sass niosh: error: --load given twice ('20kg' after '12kg'); give it once"
    # the same value twice too: one of them was meant to be another option
    error = refused(capsys, ["query", "--format", "json", "--format", "json", "stature > 1 m"])
    assert error == "sass query: error: --format given twice ('json' after 'json'); give it once"
    # an option's = form counts as the option
    assert "--d given twice ('90cm' after '80cm')" in refused(capsys, [*LIFT, "--d=90cm"])


def test_given_once_each_is_answered_and_a_list_option_takes_many(capsys):
    assert main([*LIFT, "--load", "12kg", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["origin"]["lifting_index"] == pytest.approx(
        1.62, abs=0.005
    )
    # --known is a list (argparse's append): each is another known value
    known = ["--known", "stature=175.5cm", "--known", "mass=82.2kg"]
    args, unknown = build_parser(["predict"]).parse_known_args(
        ["predict", "--gender", "male", *known]
    )
    assert (args.known, unknown) == (["stature=175.5cm", "mass=82.2kg"], [])


def test_one_parser_reads_command_lines_one_after_another():
    # what an option remembers is the command line it is reading: a second
    # command line may give it again
    parser = build_parser(None)
    for load in ("12kg", "20kg"):
        args, unknown = parser.parse_known_args([*LIFT, "--load", load])
        assert (args.load, unknown) == (load, [])


def _verbs(parser: argparse.ArgumentParser):
    for action in parser._actions:  # argparse's own list of what a parser takes
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield name, sub
                yield from ((f"{name} {n}", p) for n, p in _verbs(sub))


def test_every_option_of_every_verb_that_takes_one_value_refuses_a_second(capsys):
    parser = build_parser(None)  # every verb built
    checked = 0
    for verb, sub in [("sass", parser), *_verbs(parser)]:
        for action in sub._actions:
            if type(action).__name__ not in ("_StoreAction", "_StoreOnce"):
                continue
            if not action.option_strings:
                continue  # a positional is given once by its place
            option = action.option_strings[-1]
            namespace = argparse.Namespace()
            action(sub, namespace, "first", option)
            with pytest.raises(SystemExit):
                action(sub, namespace, "second", option)
            err = capsys.readouterr().err
            assert f"{option} given twice ('second' after 'first')" in err, (verb, option)
            checked += 1
    assert checked > 150  # every verb's options, not a few


@given(st.lists(st.sampled_from(["--h", "--v", "--d", "--f"]), min_size=1, max_size=6))
def test_any_option_repeated_in_a_lift_is_refused(options):
    # LIFT gives each of these once: any of them again is a second value
    argv = [*LIFT, "--load", "12kg"]
    for option in options:
        argv += [option, "70"]
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
