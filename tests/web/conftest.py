from __future__ import annotations

from pathlib import Path

import pytest

from sass_tui.db.default import create_default_database


@pytest.fixture(scope="session")
def default_people_db(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The default database, built once for the browser tests."""
    path = tmp_path_factory.mktemp("web") / "sass.db"
    create_default_database(path)
    return path
