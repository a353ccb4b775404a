"""Every path, module, class attribute and function the docs (README.md,
docs/*.md) name exists in the repository: a doc that names a file, a module
or a method that was renamed or removed fails here, not in a newcomer's hands."""

from __future__ import annotations

import ast
import builtins
import re
from functools import cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
CODE = ("sass_tui", "tests", "scripts", "benchmarks")

# A path the docs write from the repository's top (sass_tui/db/query/lists.py) or,
# inside sass_tui, from its layer (db/query/lists.py).
PATH = re.compile(
    r"(?<![\w/.~$-])((?:\.ci|sass_tui|tests|docs|benchmarks|scripts|datasets|node|LICENSES"
    r"|model|db|ui|cli)/[\w./-]*[\w/])"
)
# A file named alone, in backticks: `startup.py`, `pyproject.toml`, `sass.tcss`.
FILE = re.compile(r"`([\w/.-]+\.(?:py|md|toml|tcss))`")
MODULE = re.compile(r"\bsass_tui(?:\.\w+)+")
# `Session.undo`, `model/session.py's Session.undo()`: a class of sass_tui's and its attribute.
ATTRIBUTE = re.compile(r"`(?:[\w/]+\.py's )?([A-Z]\w+)\.(\w+)(?:\(\))?`")
CALL = re.compile(r"`(\w+)\(\)`")


def _trees() -> dict[Path, ast.Module]:
    return {
        path: ast.parse(path.read_text(encoding="utf-8"))
        for top in CODE
        for path in (ROOT / top).rglob("*.py")
        if "__snapshots__" not in path.parts
    }


@cache
def _code() -> tuple[dict[str, set[str]], set[str], set[str]]:
    """sass_tui's classes (their attributes, bases as "base:NAME"), every
    function and class name of the repository's code, the repository's files."""
    classes: dict[str, set[str]] = {}
    names: set[str] = set(dir(builtins))
    for path, tree in _trees().items():
        for node in ast.walk(tree):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
                names.add(node.name)
            if isinstance(node, ast.ClassDef) and path.is_relative_to(ROOT / "sass_tui"):
                attributes = classes.setdefault(node.name, set())
                attributes.update(f"base:{ast.unparse(base)}" for base in node.bases)
                for inner in ast.walk(node):
                    if isinstance(inner, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
                        attributes.add(inner.name)
                    elif isinstance(inner, ast.Name | ast.Attribute) and isinstance(
                        inner.ctx, ast.Store
                    ):
                        attributes.add(inner.id if isinstance(inner, ast.Name) else inner.attr)
    files = {path.name for top in CODE for path in (ROOT / top).rglob("*")}
    files |= {path.name for path in ROOT.glob("*")} | {p.name for p in (ROOT / "docs").glob("*")}
    return classes, names, files


def _has(classes: dict[str, set[str]], name: str, attribute: str) -> bool:
    """The class or one of sass_tui's classes it derives from has the
    attribute (a base from elsewhere, Textual's Screen, may too)."""
    if attribute in classes[name]:
        return True
    bases = [b.removeprefix("base:").split(".")[-1] for b in classes[name] if b.startswith("base:")]
    return any(base not in classes or _has(classes, base, attribute) for base in bases)


@cache
def _parsed(module: Path) -> ast.Module:
    return ast.parse(module.read_text(encoding="utf-8"))


def _module_has(dotted: str) -> bool:
    """sass_tui.db.query.lists (a module) or sass_tui.db.query.lists.QueryLists (a name it defines)."""
    parts = dotted.split(".")
    for end in range(len(parts), 0, -1):
        base = ROOT.joinpath(*parts[:end])
        module = base / "__init__.py" if base.is_dir() else base.with_suffix(".py")
        if module.is_file():
            rest = parts[end:]
            if not rest:
                return True
            tree = _parsed(module)
            defined = {
                getattr(node, "name", None) or getattr(node, "id", None)
                for node in ast.walk(tree)
                if isinstance(node, ast.FunctionDef | ast.ClassDef | ast.Name | ast.alias)
            } | {
                alias.asname or alias.name
                for node in ast.walk(tree)
                for alias in getattr(node, "names", ())
                if isinstance(alias, ast.alias)
            }
            return rest[0] in defined or (base / rest[0]).exists()
    return False


def missing(text: str) -> list[str]:
    """What a document's text names that the repository does not have."""
    classes, names, files = _code()
    absent = []
    for found in PATH.finditer(text):
        path = found.group(1).rstrip("/.")
        if not any((top / path).exists() for top in (ROOT, ROOT / "sass_tui")):
            absent.append(path)
    for found in FILE.finditer(text):
        path = found.group(1)
        if "/" not in path and path not in files:
            absent.append(path)
    absent += [m.group(0) for m in MODULE.finditer(text) if not _module_has(m.group(0))]
    for found in ATTRIBUTE.finditer(text):
        name, attribute = found.groups()
        if name in classes and not _has(classes, name, attribute):
            absent.append(f"{name}.{attribute}")
    absent += [f"{m.group(1)}()" for m in CALL.finditer(text) if m.group(1) not in names]
    return absent


@pytest.mark.slow
def test_every_path_module_and_function_the_docs_name_exists():
    assert DOCS[1:], "no docs/*.md found"
    absent = {
        doc.relative_to(ROOT).as_posix(): found
        for doc in DOCS
        if (found := missing(doc.read_text(encoding="utf-8")))
    }
    assert absent == {}


def test_the_check_finds_what_does_not_exist():
    text = (
        "`sass_tui/db/query/lists.py`, db/query/lists.py, `QueryLists.open`, `sass_tui.db.query.lists`, "
        "`compile_query()`, `pyproject.toml`"
    )
    assert missing(text) == []
    text = (
        "sass_tui/db/nosuch.py, model/gone.py, `nosuch.py`, `sass_tui.db.nosuch`, "
        "`QueryLists.nosuch`, `nosuch_function()`"
    )
    assert missing(text) == [
        "sass_tui/db/nosuch.py",
        "model/gone.py",
        "nosuch.py",
        "sass_tui.db.nosuch",
        "QueryLists.nosuch",
        "nosuch_function()",
    ]
