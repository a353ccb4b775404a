"""The numbers a reader of the tree meets first: how big the UI modules and
classes are, how many imports hide inside functions, where the code reaches
into Textual's private API, and how the tests build their apps and wait.

    python scripts/code_metrics.py            # from the repository's root

Everything is read from the source with `ast` (nothing of sass is imported);
whether a private attribute is Textual's is decided by looking for its
definition in the installed Textual package's own source.
"""

from __future__ import annotations

import ast
import re
import sys
from collections import Counter
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "sass_tui"
UI = PACKAGE / "ui"
TESTS = ROOT / "tests"
MAX_METHODS = 30
MAX_MODULE_LINES = 500
# Import statements inside functions in sass_tui, at most: each is a module a
# start-up row of sass_tui/startup.py keeps off a path (or the path's verb
# module imports it only for an option).  A ceiling that only comes down as
# imports move to module tops (272 when first counted; 118 before the
# spreadsheet's commands, the database's engines and the verbs' options were
# split by topic; 42 with `sass handling`'s posture and population,
# cli/handling_people.py; 43 with `sass reach`'s --target/--virtual share,
# cli/reach_people.py; 44 with `sass niosh --tasks`'s file reader,
# cli/niosh_job.py).  With the generated parser's own 6 the package holds at
# most 60 (tests/test_code_metrics.py).
MAX_FUNCTION_LEVEL_IMPORTS = 44
# A ticket number in prose: "issue" or "issues", then a number (a "#" allowed).
ISSUE_REFERENCE = re.compile(r"\bissues?\s+#?\d+", re.IGNORECASE)
# Generated code is not read or written by hand.
GENERATED = {PACKAGE / "db" / "query" / "_query_parser.py"}


def python_files(folder: Path) -> list[Path]:
    return sorted(
        path
        for path in folder.rglob("*.py")
        if path not in GENERATED and "__snapshots__" not in path.parts and ".venv" not in path.parts
    )


def parse(path: Path) -> ast.Module:
    return ast.parse(path.read_text(encoding="utf-8"), filename=str(path))


def relative(path: Path) -> str:
    return str(path.relative_to(ROOT))


def module_sizes() -> list[tuple[str, int]]:
    sizes = [
        (relative(p), len(p.read_text(encoding="utf-8").splitlines())) for p in python_files(UI)
    ]
    return sorted(sizes, key=lambda item: -item[1])


def class_method_counts() -> list[tuple[str, str, int]]:
    """Every class of the package with the functions defined in its body."""
    found = []
    for path in python_files(PACKAGE):
        for node in ast.walk(parse(path)):
            if isinstance(node, ast.ClassDef):
                methods = sum(
                    isinstance(item, ast.FunctionDef | ast.AsyncFunctionDef) for item in node.body
                )
                found.append((relative(path), node.name, methods))
    return sorted(found, key=lambda item: -item[2])


# The reason a function-level import gives (sass_tui/startup.py): on the
# statement's own lines, or on a comment line directly above the run of imports
# it belongs to, "# deferred: MODULE — REASON".
DEFERRED = re.compile(r"#\s*deferred:\s*(?P<modules>[^—]*\S)\s+—\s+(?P<why>\S.*)$")


def function_level_import_reasons() -> list[tuple[str, int, str | None]]:
    """Every import statement inside a function body (nested functions too):
    where it is and the `# deferred:` comment that says why (None if none)."""
    found: list[tuple[str, int, str | None]] = []
    for path in python_files(PACKAGE):
        lines = path.read_text(encoding="utf-8").splitlines()
        tree = parse(path)
        import_lines = {
            line
            for node in ast.walk(tree)
            if isinstance(node, ast.Import | ast.ImportFrom)
            for line in range(node.lineno, (node.end_lineno or node.lineno) + 1)
        }
        inside: list[ast.Import | ast.ImportFrom] = []

        class Visitor(ast.NodeVisitor):
            depth = 0

            def visit_FunctionDef(self, node: ast.FunctionDef | ast.AsyncFunctionDef) -> None:
                self.depth += 1
                self.generic_visit(node)
                self.depth -= 1

            visit_AsyncFunctionDef = visit_FunctionDef

            def visit_Import(self, node: ast.Import | ast.ImportFrom) -> None:
                if self.depth:
                    inside.append(node)

            visit_ImportFrom = visit_Import

        Visitor().visit(tree)
        for node in inside:
            last = node.end_lineno or node.lineno
            reason = next(
                (m.group(0) for m in map(DEFERRED.search, lines[node.lineno - 1 : last]) if m),
                None,
            )
            line = node.lineno - 1  # 1-based number of the line above
            while reason is None and line >= 1:
                text = lines[line - 1].strip()
                if not (text.startswith("#") or line in import_lines):
                    break
                match = DEFERRED.search(text) if text.startswith("#") else None
                reason = match.group(0) if match else None
                line -= 1
            found.append((relative(path), node.lineno, reason))
    return found


def function_level_imports() -> Counter[str]:
    """Import statements inside a function body (nested functions too), by module."""
    return Counter(where for where, _, _ in function_level_import_reasons())


def textual_source() -> str:
    import textual  # only for where it is installed; its modules are read as text

    folder = Path(textual.__file__).parent
    return "\n".join(p.read_text(encoding="utf-8") for p in folder.rglob("*.py"))


def _defined_names(folder: Path) -> set[str]:
    """Every name the code in `folder` defines: functions, classes, assigned attributes and names."""
    names: set[str] = set()
    for path in python_files(folder):
        for node in ast.walk(parse(path)):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
                names.add(node.name)
            elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
                names.add(node.attr)
            elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
                names.add(node.id)
    return names


def private_textual_uses(folder: Path = PACKAGE) -> list[tuple[str, int, str]]:
    """`textual._x` imports, and `._name` attributes the package never defines
    but Textual's source does (`def _name`, `self._name =`, `_name:`)."""
    ours = _defined_names(PACKAGE) | _defined_names(folder)
    accesses: list[tuple[str, int, str]] = []
    imports: list[tuple[str, int, str]] = []
    for path in python_files(folder):
        for node in ast.walk(parse(path)):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("textual._"):
                imports.append((relative(path), node.lineno, f"from {node.module} import"))
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.startswith("textual._"):
                        imports.append((relative(path), node.lineno, f"import {alias.name}"))
            if (
                isinstance(node, ast.Attribute)
                and node.attr.startswith("_")
                and not node.attr.startswith("__")
            ):
                accesses.append((relative(path), node.lineno, node.attr))
    source = textual_source()
    theirs = [
        (where, line, f"._{name[1:]}")
        for where, line, name in accesses
        if name not in ours
        and re.search(rf"(def {name}\b|self\.{name}\s*[:=]|^\s*{name}\s*[:=])", source, re.M)
    ]
    return imports + theirs


def issue_references() -> Counter[str]:
    counts: Counter[str] = Counter()
    for folder in (PACKAGE, TESTS, ROOT / "scripts", ROOT / "benchmarks", ROOT / "docs"):
        for path in sorted(folder.rglob("*")):
            if (
                path.is_file()
                and path.suffix in {".py", ".md", ".tcss", ".txt", ".toml"}
                and path not in GENERATED
                and "__snapshots__" not in path.parts
            ):
                found = len(ISSUE_REFERENCE.findall(path.read_text(encoding="utf-8")))
                if found:
                    counts[folder.name] += found
    for path in (ROOT / "README.md", ROOT / "pyproject.toml", ROOT / ".ci" / "run"):
        if path.is_file():
            found = len(ISSUE_REFERENCE.findall(path.read_text(encoding="utf-8")))
            if found:
                counts[path.name] += found
    return counts


def _calls(name: str) -> list[tuple[str, int, ast.Call, bool]]:
    """Calls of `name` (a function or a method) in the tests, each with whether
    it sits inside a `while` loop."""
    found = []

    class Visitor(ast.NodeVisitor):
        def __init__(self, where: str) -> None:
            self.where = where
            self.loops = 0

        def visit_While(self, node: ast.While) -> None:
            self.loops += 1
            self.generic_visit(node)
            self.loops -= 1

        def visit_Call(self, node: ast.Call) -> None:
            func = node.func
            called = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
            if called == name:
                found.append((self.where, node.lineno, node, bool(self.loops)))
            self.generic_visit(node)

    for path in python_files(TESTS):
        Visitor(relative(path)).visit(parse(path))
    return found


def fixed_pauses() -> list[tuple[str, int, str]]:
    """`pause(delay)`, and `sleep(delay)` outside a polling loop, in the tests:
    a wait for time instead of for a condition.  (A `sleep` inside a `while`
    that tests a condition is the poll interval of a wait on that condition.)"""
    found = []
    for name in ("pause", "sleep"):
        for where, line, call, in_loop in _calls(name):
            if (call.args or call.keywords) and not (name == "sleep" and in_loop):
                delay = ast.unparse(call.args[0]) if call.args else "..."
                found.append((where, line, f"{name}({delay})"))
    return sorted(found)


def app_constructions() -> Counter[str]:
    return Counter(where for where, _, _, _ in _calls("SassApp"))


def main() -> int:
    print(f"UI modules (lines; over {MAX_MODULE_LINES} flagged):")
    sizes = module_sizes()
    for name, lines in sizes:
        print(f"  {lines:6d}  {name}{'  <-- over' if lines > MAX_MODULE_LINES else ''}")
    print(f"  {sum(n for _, n in sizes):6d}  total in {len(sizes)} modules")

    classes = class_method_counts()
    over = [c for c in classes if c[2] > MAX_METHODS]
    print(
        f"\nClasses by methods (the 12 largest; over {MAX_METHODS} flagged): {len(classes)} classes, {len(over)} over"
    )
    for where, name, methods in classes[:12]:
        print(f"  {methods:4d}  {name} ({where}){'  <-- over' if methods > MAX_METHODS else ''}")

    imports = function_level_imports()
    reasons = sum(reason is not None for _, _, reason in function_level_import_reasons())
    total = sum(imports.values())
    print(
        f"\nFunction-level imports: {total} ({reasons} with a reason; at most"
        f" {MAX_FUNCTION_LEVEL_IMPORTS}){'  <-- over' if total > MAX_FUNCTION_LEVEL_IMPORTS else ''}"
    )
    for where, count in imports.most_common(8):
        print(f"  {count:4d}  {where}")

    for folder in (PACKAGE, TESTS):
        private = private_textual_uses(folder)
        print(f"\nPrivate Textual API uses in {folder.name}/: {len(private)}")
        for where, line, what in private:
            print(f"  {where}:{line}  {what}")

    issues = issue_references()
    print(
        f"\n'issue N' references: {sum(issues.values())}  ({', '.join(f'{k} {v}' for k, v in issues.most_common())})"
    )

    pauses = fixed_pauses()
    print(f"\nFixed-delay pauses in tests: {len(pauses)}")
    for where, line, what in pauses:
        print(f"  {where}:{line}  {what}")

    apps = app_constructions()
    print(f"\nSassApp(...) constructions in tests: {sum(apps.values())} in {len(apps)} files")
    for where, count in apps.most_common(6):
        print(f"  {count:4d}  {where}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
