"""Import hygiene: the model, database and command line never import Textual."""

from __future__ import annotations

import pkgutil
import subprocess
import sys

import sass_tui.db
import sass_tui.model


def _modules(package) -> list[str]:
    return [f"{package.__name__}.{m.name}" for m in pkgutil.walk_packages(package.__path__)]


def test_model_db_and_cli_do_not_import_textual():
    modules = ["sass_tui.cli", *_modules(sass_tui.model), *_modules(sass_tui.db)]
    code = ("import sys\n" + "".join(f"import {m}\n" for m in modules) +
            "bad = sorted(m for m in sys.modules if m == 'textual' or m.startswith('textual.'))\n"
            "print(','.join(bad))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == ""
