"""docs/architecture.md names every package of sass_tui, and no package holds
more than 30 modules: the rooms a newcomer is told of are the rooms there are."""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MOST_MODULES = 30


def packages() -> list[Path]:
    return sorted(init.parent for init in (ROOT / "sass_tui").rglob("__init__.py"))


def named_in_rooms_table() -> set[str]:
    text = (ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")
    section = text.split("## Rooms", 1)[1].split("\n## ", 1)[0]
    return set(re.findall(r"^\| `(sass_tui/[\w/]*)` \|", section, flags=re.M))


def test_the_rooms_table_names_every_package_and_no_other():
    existing = {p.relative_to(ROOT).as_posix() + "/" for p in packages()}
    assert named_in_rooms_table() == existing


def test_no_package_holds_more_than_30_modules():
    crowded = {
        p.relative_to(ROOT).as_posix(): n
        for p in packages()
        if (n := len(list(p.glob("*.py")))) > MOST_MODULES
    }
    assert crowded == {}


def test_every_package_says_what_lives_there():
    silent = [
        p.relative_to(ROOT).as_posix()
        for p in packages()
        if not ast.get_docstring(ast.parse((p / "__init__.py").read_text(encoding="utf-8")))
    ]
    assert silent == []
