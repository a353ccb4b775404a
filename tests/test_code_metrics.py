"""The code stays in pieces a reader can hold: no module in sass_tui/ui/ over
500 lines, no class anywhere in sass_tui with over 30 methods of its own
(scripts/code_metrics.py, docs/architecture.md "Screens in pieces")."""

from __future__ import annotations

import inspect
import runpy
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
METRICS = runpy.run_path(str(ROOT / "scripts" / "code_metrics.py"))


def test_no_ui_module_is_over_the_limit():
    sizes = METRICS["module_sizes"]()
    assert sizes, "no UI module measured"
    over = [(name, lines) for name, lines in sizes if lines > METRICS["MAX_MODULE_LINES"]]
    assert over == []


def test_no_class_has_over_the_limit_of_methods():
    classes = METRICS["class_method_counts"]()
    # Every layer is measured, not the UI alone (the model's Figure and Session too).
    assert {c[0].split("/")[1] for c in classes} >= {"cli", "db", "model", "ui"}
    over = [c for c in classes if c[2] > METRICS["MAX_METHODS"]]
    assert over == []


def test_the_count_is_the_class_body_as_python_sees_it():
    # The script reads the source; the class object agrees: its own
    # functions and properties (a mixin's methods count where written).
    from sass_tui.ui.query_screen import QueryScreen
    from sass_tui.ui.spreadsheet import SpreadsheetScreen

    counted = {(c[0], c[1]): c[2] for c in METRICS["class_method_counts"]()}
    for cls in (SpreadsheetScreen, QueryScreen):
        own = [
            v
            for v in vars(cls).values()
            if inspect.isfunction(v) or isinstance(v, property) or hasattr(v, "__wrapped__")
        ]
        where = f"sass_tui/ui/{Path(inspect.getfile(cls)).name}"
        assert counted[(where, cls.__name__)] == len(own)
