"""Only sass_tui/db knows a database engine: no module outside it imports
sqlite3, psycopg or duckdb, or reaches for a connection or a lock of the
database layer's objects (the import-linter contract "Only the database
layer imports a database engine" checks the imports too)."""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "sass_tui"
ENGINES = {"sqlite3", "psycopg", "duckdb"}
# The attributes that were the connection and the lock of QueryLists.
REACHES = {"conn", "lock", "_conn", "_lock"}


def outside_db() -> list[Path]:
    return [
        p for p in sorted(PACKAGE.rglob("*.py")) if "db" not in p.relative_to(PACKAGE).parts[:1]
    ]


def test_no_module_outside_the_database_layer_imports_an_engine():
    found = []
    for path in outside_db():
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            found += [f"{path}:{node.lineno}" for n in names if n.split(".")[0] in ENGINES]
    assert found == []


def test_no_module_outside_the_database_layer_touches_a_connection_or_lock():
    found = []
    for path in outside_db():
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.Attribute) and node.attr in REACHES:
                owner = ast.unparse(node.value)
                if "lists" in owner or "db" in owner.lower():
                    found.append(f"{path}:{node.lineno}: {ast.unparse(node)}")
    assert found == []


def test_the_checks_see_what_they_look_for(tmp_path):
    """The walks above find an engine import and a reach when there is one."""
    source = "import sqlite3\nfrom duckdb import connect\nwith self.lists.lock:\n    lists.conn.execute('')\n"
    tree = ast.parse(source)
    imports = [n for n in ast.walk(tree) if isinstance(n, ast.Import | ast.ImportFrom)]
    reaches = [n for n in ast.walk(tree) if isinstance(n, ast.Attribute) and n.attr in REACHES]
    assert len(imports) == 2 and len(reaches) == 2


def test_one_caller_decides_how_an_import_is_staged():
    # PostgreSQL stages an import in a SQLite file and copies it in one
    # transaction; whether to is decided once, in db/engine/staging.py's
    # store_people, for the command line (Database) and the screens
    # (QueryLists) alike, and PostgreSQL's `sass db init` (init_postgres).
    callers = set()
    for path in (Path(__file__).resolve().parent.parent / "sass_tui").rglob("*.py"):
        for function in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(function, ast.FunctionDef):
                for call in ast.walk(function):
                    if (
                        isinstance(call, ast.Call)
                        and getattr(call.func, "id", getattr(call.func, "attr", None))
                        == "import_staged"
                    ):
                        callers.add(f"{path.parent.name}/{path.name}:{function.name}")
    assert callers == {"engine/staging.py:store_people"}
