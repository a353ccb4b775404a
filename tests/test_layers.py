"""Import hygiene: the model, database and command line never import Textual,
and the command line's start-up imports only what `sass fig` needs."""

from __future__ import annotations

import pkgutil
import subprocess
import sys

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
