from __future__ import annotations

import shutil
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def default_people_db(shipped_db_file: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The default database for the browser tests: a copy of the session's build."""
    path = tmp_path_factory.mktemp("web") / "sass.db"
    shutil.copy(shipped_db_file, path)
    return path
