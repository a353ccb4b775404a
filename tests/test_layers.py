"""Import hygiene: the model, database and command line never import Textual,
and the command line's start-up imports only what `sass fig` needs."""

from __future__ import annotations

import pkgutil
import shutil
import subprocess
import sys

import pytest

import sass_tui.db
import sass_tui.model

CLI_MODULES = [
    "sass_tui.cli",
    *(
        f"sass_tui.cli.{m}"
        for m in (
            "db",
            "export",
            "family",
            "fig",
            "fit",
            "options",
            "person",
            "population",
            "predict",
            "progress",
            "query",
            "strength",
        )
    ),
]


def _modules(package) -> list[str]:
    return [f"{package.__name__}.{m.name}" for m in pkgutil.walk_packages(package.__path__)]


def _run(code: str) -> str:
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


def test_model_db_and_cli_do_not_import_textual():
    modules = [*CLI_MODULES, *_modules(sass_tui.model), *_modules(sass_tui.db)]
    code = (
        "import sys\n"
        + "".join(f"import {m}\n" for m in modules)
        + "bad = sorted(m for m in sys.modules if m == 'textual' or m.startswith('textual.'))\n"
        "print(','.join(bad))\n"
    )
    assert _run(code) == ""


def test_the_command_line_starts_without_its_heavy_imports():
    # Every subcommand is registered, yet sqlite3, lark, pint and Textual wait
    # until a command needs them (`sass fig` < 0.5 s, docs/performance.md).
    code = (
        "import sys\nfrom sass_tui.cli import build_parser\nbuild_parser()\n"
        "heavy = ('sqlite3', 'lark', 'pint', 'textual')\n"
        "print(','.join(sorted(m for m in heavy if m in sys.modules)))\n"
    )
    assert _run(code) == ""


HEAVY = ("lark", "pint", "textual", "numpy")
# What `sass query` must not import either (start-up <= 5x a bare interpreter):
# the generated parser's logging, dataclasses/inspect and pickle, and shutil
# (argparse's help formatter imports it for the terminal's width); nor the
# drivers of the other engines on a SQLite file below the column copy's size.
QUERY_NEEDS_NONE_OF = (
    *HEAVY, "logging", "dataclasses", "inspect", "pickle", "shutil", "duckdb", "psycopg",
)  # fmt: skip


def _imported_while_running(argv: list[str], cwd, heavy: tuple[str, ...] = HEAVY) -> set[str]:
    code = (
        "import sys\nfrom sass_tui.cli import main\n"
        f"status = main({argv!r})\n"
        f"heavy = {heavy!r}\n"
        "print(status, ','.join(m for m in heavy if m in sys.modules), file=sys.stderr)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=cwd)
    last = done.stderr.strip().splitlines()[-1]
    status, _, modules = last.partition(" ")
    assert status == "0", done.stderr
    return set(filter(None, modules.split(",")))


@pytest.mark.slow
def test_a_query_in_inches_does_not_import_pint(shipped_db_file, tmp_path):
    # "70 in" is converted from the unit table, not by pint (slow to import).
    db = tmp_path / "sass.db"
    shutil.copy(shipped_db_file, db)
    imported = _imported_while_running(
        ["--db", str(db), "query", "--format", "csv", "stature > 70 in"], tmp_path
    )
    assert "pint" not in imported and "textual" not in imported
    # The table (the default format), a unit converted, parentheses, OR, a group row:
    # the parser, the compiler, the database and the table writer all ran.
    query = "(stature > 70 in OR mass < 60 kg) AND girth.right_upper_arm.z > 20 cm"
    argv = ["--db", str(db), "query", query]
    assert _imported_while_running(argv, tmp_path, QUERY_NEEDS_NONE_OF) == set()


def test_sass_fig_does_not_import_pint(tmp_path):
    # Nor numpy.ma (np.median and np.unique import it: 25 ms), nor secrets
    # (hashlib, hmac, random) for a temporary file's name.
    # What `import numpy` itself brings is numpy's (numpy 1.26, the floor, imports
    # numpy.ma and, through numpy.random, secrets): sass must not add them.
    by_numpy = set(
        subprocess.run(
            [sys.executable, "-c", "import sys, numpy; print(' '.join(sys.modules))"],
            capture_output=True,
            text=True,
            check=True,
        ).stdout.split()
    )
    heavy = tuple(
        m
        for m in (*HEAVY, "numpy.ma", "secrets", "logging", "shutil")
        if m == "numpy" or m not in by_numpy
    )
    imported = _imported_while_running(["fig", "-o", str(tmp_path / "X.fig")], tmp_path, heavy)
    assert imported == {"numpy"}  # no pint, no lark, no Textual
    assert (tmp_path / "X.fig").is_file()


def test_only_the_verb_being_run_is_built():
    # Each verb's parser costs start-up time: `sass query` builds only its own,
    # while `sass --help` (and an unknown verb's error) lists them all.
    import argparse

    from sass_tui.cli import VERBS, build_parser

    def verbs(argv: list[str]) -> set[str]:
        parser = build_parser(argv)
        (commands,) = (a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        return set(commands.choices)

    assert verbs(["query", "gender = male"]) == {"query"}
    assert verbs(["--db", "query", "fig", "-o", "X.fig"]) == {"fig"}
    for argv in ([], ["-h", "query"], ["--version", "fig"], ["nosuch"]):
        assert len(verbs(argv)) == len(VERBS), argv


def test_the_spreadsheet_starts_without_what_other_screens_use():
    # For a fast first screen: the database, the query language, pint, the
    # prediction model and the other screens load when first used.
    code = (
        "import sys\nimport sass_tui.ui.app\n"
        "later = ('sqlite3', 'lark', 'pint', 'sass_tui.model.prediction', 'sass_tui.db',\n"
        "         'sass_tui.ui.query_screen', 'sass_tui.ui.figure_screen', 'numpy')\n"
        "print(','.join(sorted(m for m in later if m in sys.modules)))\n"
    )
    assert _run(code) == ""


@pytest.mark.slow
def test_the_first_screen_is_drawn_without_what_it_does_not_show():
    # For a fast first screen: the spreadsheet with its figure panel at 120
    # columns, up and drawn, has not imported what only exports, other screens
    # or the first edit use.
    code = (
        "import asyncio, sys\n"
        "from sass_tui.ui.app import SassApp\n"
        "async def first_screen():\n"
        "    app = SassApp()\n"
        "    async with app.run_test(size=(120, 40)) as pilot:\n"
        "        await pilot.pause()\n"
        "        assert app.spreadsheet.figure_panel.outlines\n"
        "asyncio.run(first_screen())\n"
        "later = ('xml.etree.ElementTree', 'sqlite3', 'lark', 'pint',\n"
        "         'sass_tui.model.prediction', 'sass_tui.ui.query_screen')\n"
        "print(','.join(sorted(m for m in later if m in sys.modules)))\n"
    )
    assert _run(code) == ""


def test_the_first_screen_is_drawn_before_numpy_is_imported():
    # The first screen's start-up target (<= 1.3x a bare Textual app): the default
    # figure is computed and drawn in plain floats; numpy (~31 ms) is first
    # imported by the figure panel and the strength sheet, one frame later.
    # The first screen's numbers are those the numpy code gives (snapshots,
    # tests/model/test_plain_floats.py).
    code = (
        "import asyncio, sys\n"
        "from sass_tui.ui.app import SassApp\n"
        "from sass_tui.ui.spreadsheet import SpreadsheetScreen\n"
        "seen = {}\n"
        "drawn = SpreadsheetScreen._first_screen_drawn\n"
        "def first_screen_drawn(screen):\n"
        "    seen['numpy'] = 'numpy' in sys.modules\n"
        "    seen['strength'] = screen.session.strength_sheets.made() is not None\n"
        "    drawn(screen)\n"
        "SpreadsheetScreen._first_screen_drawn = first_screen_drawn\n"
        "async def first_screen():\n"
        "    app = SassApp()\n"
        "    async with app.run_test(size=(120, 40)) as pilot:\n"
        "        await pilot.pause()\n"
        "        assert app.spreadsheet.figure_panel.outlines\n"
        "        seen['strength after'] = app.session.strength_sheets.made() is not None\n"
        "asyncio.run(first_screen())\n"
        "print(sorted(seen.items()), 'numpy' in sys.modules)\n"
    )
    assert _run(code) == "[('numpy', False), ('strength', False), ('strength after', True)] True"


def test_plain_sass_opens_the_tui_without_building_the_parser():
    # For a fast first screen: with no arguments `sass` is the TUI, so no
    # verb's module is imported nor its parser built.
    code = (
        "import sys\nimport sass_tui.ui.app as app\n"
        "app.run_app = lambda db: print('tui', db) or 0\n"
        "from sass_tui.cli import VERBS, main\n"
        "status = main([])\n"
        "print(status, ','.join(v for v in VERBS if 'sass_tui.cli.' + v in sys.modules))\n"
    )
    assert _run(code) == "tui None\n0"


def test_the_tui_holds_the_collector_until_its_first_screen_is_drawn():
    # For a fast first screen: the start's long-lived objects are not walked
    # by the cyclic collector (~50 ms) before the first screen; once it is
    # drawn the collector runs again, with those objects frozen out of its walks.
    code = (
        "import asyncio, gc\n"
        "import sass_tui.ui.app as app\n"
        "seen = []\n"
        "app.run_app = lambda db: seen.append(gc.isenabled()) or 0\n"
        "from sass_tui.cli import main\n"
        "main([])\n"
        "seen.append(gc.isenabled())  # on again once the TUI has ended\n"
        "gc.disable()  # as run_tui holds it while the app starts\n"
        "async def first_screen():\n"
        "    tui = app.SassApp()\n"
        "    async with tui.run_test(size=(120, 40)) as pilot:\n"
        "        await pilot.pause()\n"
        "        seen.append(gc.isenabled())\n"
        "        seen.append(gc.get_freeze_count() > 1000)\n"
        "asyncio.run(first_screen())\n"
        "print(seen)\n"
    )
    assert _run(code) == "[False, True, True, True]"


def test_the_collector_runs_again_when_the_tui_ends_before_its_first_screen():
    # `sass --db '~nosuchuser/x.db'` refuses the path before any screen: the
    # process (or a caller of main) is left with the collector on.
    code = (
        "import gc\n"
        "from sass_tui.cli import main\n"
        "status = main(['--db', '~nosuchuser/x.db'])\n"
        "print(status, gc.isenabled())\n"
    )
    assert _run(code) == "2 True"


def test_a_command_does_not_run_the_collector_while_it_starts(tmp_path):
    # For a fast `sass fig`: at Python's default threshold the collector ran
    # ~50 times during `sass fig`; at sass's it does not run at all.
    code = (
        "import gc\n"
        "from sass_tui.cli import main\n"
        "runs = []\n"
        "gc.callbacks.append(lambda phase, info: phase == 'start' and runs.append(info))\n"
        f"status = main(['fig', '-o', {str(tmp_path / 'X.fig')!r}])\n"
        "print(status, len(runs))\n"
    )
    assert _run(code).splitlines()[-1] == "0 0"


def test_the_sass_command_leaves_what_it_made_out_of_the_last_collection(tmp_path):
    # `sass query`'s start-up target (<= 5x a bare interpreter): the interpreter's last
    # cyclic collection, as the process ends, walked every object the command
    # made (7-9 ms of `sass query`); the `sass` command freezes them first.
    code = (
        "import gc, sys\n"
        "from sass_tui.cli import command_line\n"
        f"sys.argv = ['sass', 'fig', '-o', {str(tmp_path / 'X.fig')!r}]\n"
        "status = command_line()\n"
        "print(status, gc.get_freeze_count() > 20_000, len(gc.get_objects()) < 1_000)\n"
    )
    assert _run(code).splitlines()[-1] == "0 True True"
    assert (tmp_path / "X.fig").is_file()
