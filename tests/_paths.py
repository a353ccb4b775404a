"""Paths the tests share (a module of its own: `conftest` is a name every test folder has).

`SASS_TEST_SHARED` names another folder for ../shared: pointed at a folder that
does not exist, it shows what a clone without ../shared runs (every test that
needs it skips, saying which file is absent)."""

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED = Path(os.environ.get("SASS_TEST_SHARED") or ROOT.parent / "shared")
REPORT = SHARED / "seeds" / "sass-report.txt"
ANSUR = SHARED / "data" / "ansur2"
NHANES_CSV = SHARED / "data" / "nhanes" / "nhanes_p_demo_bmx_2020.csv"
DATASETS = ROOT / "datasets"


def shared_file(path: Path) -> Path:
    """`path` (a file of ../shared) when it is there; the test skips, naming it, when not."""
    if not path.is_file():
        pytest.skip(f"../shared/{path.relative_to(SHARED)} is absent")
    return path


def nhanes_lines() -> list[str]:
    """The published NHANES CSV's lines without its comment lines (the test skips without it)."""
    text = shared_file(NHANES_CSV).read_text(encoding="utf-8")
    return [line for line in text.splitlines() if not line.startswith("#")]
