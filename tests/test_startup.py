"""Every start-up path in sass_tui/startup.py imports none of its forbidden
modules: each row is run as the user would start it (the verb's argv, or the
TUI up to its first screen) in a fresh interpreter, and `sys.modules` read."""

from __future__ import annotations

import subprocess
import sys

import pytest
from _built_once import copy_database_file

from sass_tui.startup import PATHS, StartupPath

VERB = """
import sys
from sass_tui.cli import main
try:
    status = main({argv!r})
except SystemExit as stop:  # --help
    status = stop.code
print("STATUS", status, file=sys.stderr)
print("MODULES", " ".join(sys.modules), file=sys.stderr)
"""

# The first screen at 120x40, with its figure panel: "drawn" reads sys.modules
# when the spreadsheet reports its first screen on the terminal, "settled" once
# the figure panel has drawn its outlines (the frame after).
TUI = """
import asyncio, sys
from sass_tui.ui.app import SassApp
from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen
seen = []
drawn = SpreadsheetScreen._first_screen_drawn
def first_screen_drawn(screen):
    seen.append(list(sys.modules))
    drawn(screen)
SpreadsheetScreen._first_screen_drawn = first_screen_drawn
async def first_screen():
    app = SassApp()
    async with app.run_test(size=(120, 40)) as pilot:
        await pilot.pause()
        assert app.spreadsheet.figure_panel.outlines
asyncio.run(first_screen())
modules = seen[0] if {moment!r} == "drawn" else list(sys.modules)
print("STATUS", 0, file=sys.stderr)
print("MODULES", " ".join(modules), file=sys.stderr)
"""

# Rows measured at 2-4 s on 2 loaded cores: the TUI's two, the database
# built from the shipped files, the regressions of predict and family, the
# population files.
SLOW = {
    "the first screen",
    "the first screen's next frame",
    "sass db init",
    "sass family",
    "sass predict",
    "sass population",
}


def _imported(code: str, cwd) -> tuple[int | None, set[str], str]:
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=cwd)
    lines = done.stderr.splitlines()
    status = next((line.split()[1] for line in lines if line.startswith("STATUS ")), None)
    modules = next((line.split()[1:] for line in lines if line.startswith("MODULES ")), [])
    return (None if status is None else int(status)), set(modules), done.stderr[-2000:]


@pytest.fixture(scope="module")
def brought_by_numpy() -> set[str]:
    """What `import numpy` itself imports (numpy 1.26, the floor, brings
    numpy.ma and, through numpy.random, secrets): not sass's doing."""
    done = subprocess.run(
        [sys.executable, "-c", "import sys, numpy; print(' '.join(sys.modules))"],
        capture_output=True,
        text=True,
        check=True,
    )
    return set(done.stdout.split())


def test_every_row_is_well_formed():
    names = [path.name for path in PATHS]
    assert len(names) == len(set(names))
    for path in PATHS:
        assert path.forbidden and path.why, path.name
        assert path.moment in (("drawn", "settled") if path.argv == () else ("end",)), path.name


@pytest.mark.parametrize(
    "path",
    [pytest.param(p, id=p.name, marks=[pytest.mark.slow] if p.name in SLOW else []) for p in PATHS],
)
def test_the_path_imports_nothing_it_must_not(
    path: StartupPath, tmp_path, shipped_db_file, brought_by_numpy
):
    argv = list(path.argv)
    if path.needs_db:
        copy_database_file(shipped_db_file, tmp_path / "sass.db")
        argv = ["--db", str(tmp_path / "sass.db"), *argv]
    if path.argv == ():
        code = TUI.format(moment=path.moment)
    else:
        code = VERB.format(argv=argv)
    status, modules, stderr = _imported(code, tmp_path)
    assert status == path.status, stderr
    assert modules, stderr
    forbidden = set(path.forbidden)
    if "numpy" not in forbidden:
        forbidden -= brought_by_numpy
    imported = {
        name for name in forbidden if any(m == name or m.startswith(f"{name}.") for m in modules)
    }
    assert imported == set(), f"{path.name}: {path.why}"
