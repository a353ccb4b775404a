from __future__ import annotations

from pathlib import Path

import pytest
from _paths import ANSUR, REPORT


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
