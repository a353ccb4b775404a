"""An import inside a function says why it is not at its module's top
(`# deferred: MODULE — REASON`, scripts/code_metrics.py), and a start-up path
a reason names is a row of sass_tui/startup.py's table."""

from __future__ import annotations

import runpy
from pathlib import Path

import pytest

from sass_tui.startup import PATHS

ROOT = Path(__file__).resolve().parent.parent
METRICS = runpy.run_path(str(ROOT / "scripts" / "code_metrics.py"))
TABLE = " (sass_tui/startup.py)"


@pytest.fixture(scope="module")
def found() -> list[tuple[str, int, str | None]]:
    """Every function-level import of sass_tui with its reason (one read of the tree)."""
    return METRICS["function_level_import_reasons"]()


def test_every_function_level_import_gives_its_reason(found):
    assert found, "no function-level import found: the script reads nothing"
    assert [f"{where}:{line}" for where, line, reason in found if reason is None] == []


def test_a_reason_names_only_paths_of_the_table(found):
    # "# deferred: numpy — off the first screen, sass query … (sass_tui/startup.py)"
    names = {path.name for path in PATHS}
    unknown = []
    for where, line, reason in found:
        why = METRICS["DEFERRED"].search(reason)["why"]
        if why.startswith("off ") and why.endswith(TABLE):
            for name in why.removeprefix("off ").removesuffix(TABLE).rstrip(" …").split(", "):
                if name not in names:
                    unknown.append(f"{where}:{line} {name}")
    assert unknown == []


def test_the_reason_is_found_where_it_is_written(tmp_path):
    # On the import's own line, or above the run of imports it begins; not
    # across a blank line or a statement.
    package = tmp_path / "sass_tui"
    package.mkdir()
    (package / "m.py").write_text(
        "def f():\n"
        "    # deferred: json — only f() needs it\n"
        "    import json\n"
        "    from os import path  # deferred: os — a trailing reason\n"
        "    import csv\n"
        "\n"
        "    import re\n"
        "    x = 1\n"
        "    import io  # a comment that gives no reason\n",
        encoding="utf-8",
    )
    scan = METRICS["function_level_import_reasons"]
    globals_ = scan.__globals__
    saved = globals_["PACKAGE"], globals_["ROOT"]
    globals_["PACKAGE"], globals_["ROOT"] = package, tmp_path
    try:
        found = {line: reason is not None for _, line, reason in scan()}
    finally:
        globals_["PACKAGE"], globals_["ROOT"] = saved
    assert found == {3: True, 4: True, 5: True, 7: False, 9: False}
