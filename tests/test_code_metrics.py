"""The UI stays in pieces a reader can hold: no module in sass_tui/ui/ over
500 lines, no class there with over 30 methods of its own
(scripts/code_metrics.py, docs/architecture.md "Screens")."""

from __future__ import annotations

import runpy
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
METRICS = runpy.run_path(str(ROOT / "scripts" / "code_metrics.py"))


def test_no_ui_module_or_class_is_too_big():
    assert METRICS["too_big"](METRICS["measure_tree"]()) == []


def test_the_limits_catch_a_big_module_and_a_big_class(tmp_path):
    # The check itself can fail: a module of 501 lines with a class of 31
    # methods, measured as the UI's are.
    body = "".join(f"    def m{i}(self):\n        return {i}\n" for i in range(31))
    source = "class Big:\n" + body + "\n" * (501 - 1 - 2 * 31)
    module = tmp_path / "big.py"
    module.write_text(source)
    measured = METRICS["measure"](module)
    assert measured.lines == 501
    assert measured.classes == {"Big": 31}
    ui = METRICS["UI"]
    moved = type(measured)(ui / "big.py", measured.lines, measured.classes, 0, 0)
    problems = METRICS["too_big"]([moved])
    assert problems == [
        "sass_tui/ui/big.py: 501 lines (at most 500)",
        "sass_tui/ui/big.py: class Big has 31 methods (at most 30)",
    ]


def test_imports_inside_functions_and_private_reads_are_counted(tmp_path):
    module = tmp_path / "m.py"
    module.write_text(
        "import os\n\ndef f(node):\n    import json\n    from math import pi\n"
        "    return node._bindings, self_._x\n\nclass C:\n    def g(self):\n"
        "        return self._own\n"
    )
    measured = METRICS["measure"](module)
    assert (measured.function_imports, measured.private_reads) == (2, 2)
