"""The verb table of sass_tui/cli/__init__.py: `sass --help` lists every verb
from it without importing one, each row agrees with its module, and every
option of every verb says what it does."""

from __future__ import annotations

import argparse
import pkgutil
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

import sass_tui.cli
from sass_tui.cli import VERBS, build_parser, main, verb_module

# The modules of sass_tui/cli that are not verbs: what the verbs share.
SHARED = {  # parts of a verb; what verbs share lives in cli/common/
    "prediction_figure",
    "query_weighted",
    "query_csv",  # sass query --format csv
    "query_json",  # sass query --format json
    "serving",  # sass serve, once its options are checked
    "strength_arm",  # sass strength arm_force
    "target_change",  # sass target NAME --sample, --drop
    "task_people",  # sass task --person, --target, --virtual
    "handling_people",  # sass handling from a posture, --person, --target, --virtual
    "niosh_job",  # sass niosh --tasks
    "reach_people",  # sass reach --target, --virtual
}


def _options(parser: argparse.ArgumentParser, words: str) -> Iterator[tuple[str, argparse.Action]]:
    """Every action of a parser and of its sub-parsers, with the command that reaches it."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from _options(sub, f"{words} {name}")
        elif not isinstance(action, argparse._HelpAction):
            yield words, action


def _listed(parser: argparse.ArgumentParser) -> dict[str, str | None]:
    (commands,) = (a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {choice.dest: choice.help for choice in commands._choices_actions}


def test_every_option_of_every_verb_says_what_it_does():
    parser = build_parser()  # every verb built
    silent = [
        f"{words} {'/'.join(action.option_strings) or action.dest}"
        for words, action in _options(parser, "sass")
        if not action.help or action.help == argparse.SUPPRESS
    ]
    assert silent == []
    assert sum(1 for _ in _options(parser, "sass")) > 100  # the walk reaches the verbs' options


def test_every_verb_module_has_a_row_and_every_row_a_module():
    modules = {m.name for m in pkgutil.iter_modules(sass_tui.cli.__path__) if not m.ispkg} - SHARED
    assert {verb.module for verb in VERBS} == modules
    assert len({verb.name for verb in VERBS}) == len(VERBS)


@pytest.mark.parametrize("verb", VERBS, ids=[verb.name for verb in VERBS])
def test_a_row_lists_the_help_its_module_gives(verb):
    # `sass --help` shows the row's line; `sass VERB --help` is built by the module.
    from_row = _listed(build_parser(["--help"]))[verb.name]
    from_module = _listed(build_parser([verb.name]))
    assert from_module == {verb.name: from_row}
    assert callable(verb_module(verb).register)


def test_sass_help_imports_no_verb_module():
    code = (
        "import sys\n"
        "from sass_tui.cli import VERBS, main\n"
        "try:\n"
        "    main(['--help'])\n"
        "except SystemExit:\n"
        "    pass\n"
        "print(sorted(v.module for v in VERBS if 'sass_tui.cli.' + v.module in sys.modules))\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == "[]"
    assert all(verb.name in done.stdout for verb in VERBS)


def test_every_verb_has_its_test_file_here():
    # tests/cli mirrors sass_tui/cli: where a newcomer looks for a verb's tests.
    here = Path(__file__).parent
    assert [verb.name for verb in VERBS if not (here / f"test_{verb.module}.py").is_file()] == []


@pytest.mark.parametrize(
    ("argv", "who"),
    [
        (["niosh", "--h", "40cm", "--f", "2", "--virtual", "nhanes-2017-2020"], "sass niosh"),
        (["fig", "--bogus"], "sass fig"),
        (["--bogus"], "sass"),
    ],
)
def test_an_unknown_option_is_refused_by_the_verb_it_was_given_to(capsys, argv, who):
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert err.startswith(f"usage: {who} ")
    assert f"\n{who}: error: unrecognized arguments: " in err


# An option's metavar says it takes a file or a folder: FILE, F, DIR, OUT.fig, ...
_NAMES_A_FILE = re.compile(r"FILE|^F$|^DIR$|\.(fig|x3d|glb|csv|dat|json)\b|^PATH")


def _file_options() -> list[tuple[list[str], str]]:
    """(the words that reach the option and the option with an empty name, its
    metavar) for every option and argument of every verb that names a file."""
    found = []
    for words, action in _options(build_parser(), "sass"):
        metavar = str(action.metavar or "")
        if _NAMES_A_FILE.search(metavar):
            given = [action.option_strings[0], ""] if action.option_strings else [""]
            found.append(([*words.split()[1:], *given], metavar))
    return found


def test_every_file_option_refuses_an_empty_name(capsys, tmp_path, monkeypatch):
    """`''` (or `"$OUT"` with OUT unset) was the current folder to each verb, and
    each said something else of it: `.: a directory`, `cannot write .`, `--input
    needs --output`; `sass fig -o ''` wrote MALE50.FIG and `--db ''` opened the
    default database."""
    found = _file_options()
    assert len(found) > 30  # the walk reaches every verb's file options
    parser = build_parser()
    for argv, metavar in found:
        with pytest.raises(SystemExit) as stopped:
            parser.parse_args(argv)
        assert stopped.value.code == 2, argv
        err = capsys.readouterr().err
        expected = "a database file or a postgresql://" if "PATH" in metavar else "a file's name"
        assert f"'': expected {expected}" in err, (argv, err)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stopped:
        main(["fig", "-o", ""])
    assert stopped.value.code == 2
    assert "argument -o/--output: '': expected a file's name" in capsys.readouterr().err
    assert list(tmp_path.iterdir()) == []  # no MALE50.FIG
