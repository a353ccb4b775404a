"""The command-line tests' fixtures: a private copy of the database `sass db
init` builds, and the ANSUR II CSV files read directly (the oracle the verbs'
answers are checked against)."""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import pytest
from _built_once import copy_database_file


@pytest.fixture()
def people_db(shipped_db_file, tmp_path) -> Path:
    """A copy of the shipped database (ANSUR II and the demonstration people) to write to."""
    path = tmp_path / "sass.db"
    copy_database_file(shipped_db_file, path)
    return path


@pytest.fixture(scope="session")
def ansur_stature_cm(ansur_dir) -> dict[str, np.ndarray]:
    """Every ANSUR II soldier's stature in cm (the CSVs give mm), by gender."""
    return {
        gender: np.array(
            [
                float(row["stature"]) / 10
                for row in csv.DictReader(
                    (ansur_dir / f"ANSUR_II_{gender.upper()}_Public.csv").open(encoding="latin-1")
                )
            ]
        )
        for gender in ("male", "female")
    }
