from __future__ import annotations

from pathlib import Path

import pytest
from _built_once import copy_database_file


@pytest.fixture(scope="session")
def default_people_db(shipped_db_file: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The default database for the browser tests: a copy of the session's build."""
    path = tmp_path_factory.mktemp("web") / "sass.db"
    copy_database_file(shipped_db_file, path)
    return path
