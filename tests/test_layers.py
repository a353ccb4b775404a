"""Import hygiene: the model, database and command line never import Textual,
and the start-up keeps what it does not show for later.  What each start-up
path must not import is sass_tui/startup.py's table, run by tests/test_startup.py."""

from __future__ import annotations

import pkgutil
import subprocess
import sys

import sass_tui.db
import sass_tui.model

CLI_MODULES = [
    "sass_tui.cli",
    *(
        f"sass_tui.cli.{m}" if m not in {"options", "progress"} else f"sass_tui.cli.common.{m}"
        for m in (
            "db",
            "export",
            "family",
            "fig",
            "fit",
            "common.options",
            "person",
            "population",
            "predict",
            "common.progress",
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


def test_the_first_screen_is_drawn_before_numpy_is_imported():
    # The first screen's start-up target (<= 1.3x a bare Textual app): the default
    # figure is computed and drawn in plain floats; numpy (~31 ms) is first
    # imported by the figure panel and the strength sheet, one frame later.
    # The first screen's numbers are those the numpy code gives (snapshots,
    # tests/model/test_plain_floats.py).
    code = (
        "import asyncio, sys\n"
        "from sass_tui.ui.app import SassApp\n"
        "from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen\n"
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
        "app.run_app = lambda db, worksheet=None: print('tui', db) or 0\n"
        "from sass_tui.cli import VERBS, main\n"
        "status = main([])\n"
        "print(status, ','.join(v.name for v in VERBS if 'sass_tui.cli.' + v.module in sys.modules))\n"
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
        "app.run_app = lambda db, worksheet=None: seen.append(gc.isenabled()) or 0\n"
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
