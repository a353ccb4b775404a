from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from sass_tui.db.schema import connect

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_FLAT = ROOT / "datasets" / "db"


@pytest.fixture(scope="session")
def default_db_file(shipped_db_file, tmp_path_factory) -> Path:
    """The default database the database tests share (their queries keep lists
    in it): a copy of the session's build, which other areas copy too."""
    path = tmp_path_factory.mktemp("db") / "default.db"
    shutil.copy(shipped_db_file, path)
    return path


@pytest.fixture()
def default_db(default_db_file, tmp_path):
    """A private copy of the default database (tests may write to it)."""
    copy = tmp_path / "default.db"
    copy.write_bytes(default_db_file.read_bytes())
    conn = connect(copy)
    yield conn
    conn.close()
