from __future__ import annotations

from pathlib import Path

import pytest

from sass_tui.db.default import create_default_database
from sass_tui.db.schema import connect

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_FLAT = ROOT / "datasets" / "db"


@pytest.fixture(scope="session")
def default_db_file(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("db") / "default.db"
    create_default_database(path)
    return path


@pytest.fixture()
def default_db(default_db_file, tmp_path):
    """A private copy of the default database (tests may write to it)."""
    copy = tmp_path / "default.db"
    copy.write_bytes(default_db_file.read_bytes())
    conn = connect(copy)
    yield conn
    conn.close()
