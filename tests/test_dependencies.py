"""What a user installs carries no developer tool and no exact pin: those are
pyproject.toml's [dependency-groups] (PEP 735), which the README's test command
and .ci/run install beside the extras."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _name(requirement: str) -> str:
    """The distribution a requirement names, normalised (PEP 503)."""
    name = re.match(r"[A-Za-z0-9._-]+", requirement)
    assert name, requirement
    return re.sub(r"[-_.]+", "-", name.group(0)).lower()


def _group(name: str) -> list[str]:
    """A dependency group's requirements, its included groups' too."""
    found: list[str] = []
    for entry in PYPROJECT["dependency-groups"][name]:
        found += _group(entry["include-group"]) if isinstance(entry, dict) else [entry]
    return found


def test_the_extras_hold_no_exact_pin_and_no_developer_tool():
    extras = PYPROJECT["project"]["optional-dependencies"]
    tools = {_name(r) for r in _group("dev") + _group("bench")} - {"textual", "rich"}
    requirements = [r for listed in extras.values() for r in listed]
    assert requirements, "no extras read"
    assert [r for r in requirements if "==" in r or "===" in r] == []
    assert [r for r in requirements if _name(r) in tools] == []


def test_the_dev_group_holds_the_tools_ci_runs():
    dev = {_name(r) for r in _group("dev")}
    assert {"pytest", "pytest-xdist", "ruff", "mypy", "import-linter", "vulture"} <= dev
    # The snapshots' exact pins are a group of their own: the floor run leaves it out.
    assert all("==" in r for r in _group("snapshots"))
    assert not any("==" in r for r in _group("test") + _group("lint"))


def test_the_readme_test_command_is_one_line_that_installs_the_dev_group():
    # .ci/run runs the second ```sh block as written.
    blocks = re.findall(r"```sh\n(.*?)```", README, flags=re.S)
    (command,) = blocks[1].strip().splitlines()
    assert "--group dev" in command and "pip>=25.1" in command and "pytest" in command
    # pip learnt --group in 25.1; the command upgrades pip before it asks for it.
    assert command.index("pip>=25.1") < command.index("--group")
