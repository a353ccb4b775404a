from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"
REPORT = SHARED / "seeds" / "sass-report.txt"
ANSUR = SHARED / "data" / "ansur2"
DATASETS = ROOT / "datasets"


@pytest.fixture(scope="session")
def report_lines() -> list[str]:
    if not REPORT.is_file():
        pytest.skip("../shared/seeds/sass-report.txt is absent")
    return REPORT.read_text(encoding="utf-8").splitlines()


@pytest.fixture(scope="session")
def ansur_dir() -> Path:
    if not (ANSUR / "ANSUR_II_MALE_Public.csv").is_file():
        pytest.skip("../shared/data/ansur2 is absent")
    return ANSUR
