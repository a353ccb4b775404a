"""Sizes a reader of the code meets: module lines, methods per class, imports
inside functions, and private attributes read from another object.

    python scripts/code_metrics.py            # the table for sass_tui/
    python scripts/code_metrics.py --check    # exit 1 if a UI module or class is too big

The limits are the UI's (docs/architecture.md, "Screens"): no module in
sass_tui/ui/ over MAX_MODULE_LINES lines and no class there with more than
MAX_CLASS_METHODS methods of its own (methods a class inherits from its
mixins count where they are written).  tests/test_code_metrics.py checks them.
"""

from __future__ import annotations

import argparse
import ast
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "sass_tui"
UI = PACKAGE / "ui"
MAX_MODULE_LINES = 500
MAX_CLASS_METHODS = 30


@dataclass(frozen=True)
class ModuleMetrics:
    path: Path
    lines: int
    classes: dict[str, int]  # class name -> methods written in its body
    function_imports: int  # import statements inside a function
    private_reads: int  # `other._name`: a private attribute of another object


def _methods(node: ast.ClassDef) -> int:
    return sum(isinstance(n, ast.FunctionDef | ast.AsyncFunctionDef) for n in node.body)


def _function_imports(tree: ast.Module) -> int:
    count = 0
    for function in ast.walk(tree):
        if isinstance(function, ast.FunctionDef | ast.AsyncFunctionDef):
            count += sum(
                isinstance(n, ast.Import | ast.ImportFrom)
                for statement in function.body
                for n in ast.walk(statement)
            )
    return count


def _private_reads(tree: ast.Module) -> int:
    return sum(
        isinstance(node, ast.Attribute)
        and node.attr.startswith("_")
        and not node.attr.startswith("__")
        and not (isinstance(node.value, ast.Name) and node.value.id in ("self", "cls"))
        for node in ast.walk(tree)
    )


def measure(path: Path) -> ModuleMetrics:
    text = path.read_text(encoding="utf-8")
    tree = ast.parse(text, str(path))
    classes = {n.name: _methods(n) for n in ast.walk(tree) if isinstance(n, ast.ClassDef)}
    return ModuleMetrics(
        path, len(text.splitlines()), classes, _function_imports(tree), _private_reads(tree)
    )


def measure_tree(root: Path = PACKAGE) -> list[ModuleMetrics]:
    # Generated code (the lark parser) is nobody's to read.
    return [measure(p) for p in sorted(root.rglob("*.py")) if not p.name.startswith("_query_")]


def too_big(metrics: list[ModuleMetrics]) -> list[str]:
    """What breaks the UI's limits, one line each; empty: none."""
    problems = []
    for m in metrics:
        if not m.path.is_relative_to(UI):
            continue
        where = m.path.relative_to(ROOT)
        if m.lines > MAX_MODULE_LINES:
            problems.append(f"{where}: {m.lines} lines (at most {MAX_MODULE_LINES})")
        for name, methods in m.classes.items():
            if methods > MAX_CLASS_METHODS:
                problems.append(
                    f"{where}: class {name} has {methods} methods (at most {MAX_CLASS_METHODS})"
                )
    return problems


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="exit 1 if the UI's limits break")
    parser.add_argument("--top", type=int, default=10, help="rows of each table (default 10)")
    args = parser.parse_args(argv)
    metrics = measure_tree()
    ui = [m for m in metrics if m.path.is_relative_to(UI)]
    print(f"{'module':<44} {'lines':>6}")
    for m in sorted(ui, key=lambda m: -m.lines)[: args.top]:
        print(f"{str(m.path.relative_to(ROOT)):<44} {m.lines:>6}")
    print(f"\n{'class (sass_tui/ui)':<44} {'methods':>7}")
    classes = sorted(((c, n, m) for m in ui for c, n in m.classes.items()), key=lambda t: -t[1])
    for name, methods, m in classes[: args.top]:
        print(f"{name + ' (' + m.path.name + ')':<44} {methods:>7}")
    print(
        f"\nsass_tui: {len(metrics)} modules, {sum(m.lines for m in metrics):,} lines, "
        f"{sum(m.function_imports for m in metrics)} imports inside functions, "
        f"{sum(m.private_reads for m in metrics)} private attributes read from another object"
    )
    problems = too_big(metrics)
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if args.check and problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
