"""Paths the tests share (a module of its own: `conftest` is a name every test folder has)."""

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
REPORT = SHARED / "seeds" / "sass-report.txt"
ANSUR = SHARED / "data" / "ansur2"
DATASETS = ROOT / "datasets"
