"""A database with real people for the model tests that need one."""

from __future__ import annotations

import csv
import shutil

import pytest

from sass_tui.cli import main


@pytest.fixture(scope="session")
def person_db(shipped_db_file, tmp_path_factory, ansur_dir):
    """The default database and three ANSUR II women (the first rows of the CSV)."""
    folder = tmp_path_factory.mktemp("persondb")
    db = folder / "people.db"
    lines = (ansur_dir / "ANSUR_II_FEMALE_Public.csv").read_text(encoding="latin-1").splitlines()
    small = folder / "ANSUR_II_FEMALE_Public.csv"
    small.write_text("\n".join(lines[:4]) + "\n", encoding="latin-1")
    shutil.copy(shipped_db_file, db)  # what `sass db init` builds
    assert main(["--db", str(db), "db", "import-ansur", str(small)]) == 0
    rows = list(csv.DictReader(lines[:4]))
    return db, rows
