from __future__ import annotations

import asyncio
import shutil

import pytest

from sass_tui.db.default import create_default_database


@pytest.fixture
def drive():
    """Run an async Pilot scenario from a plain test (no asyncio plugin needed)."""
    return asyncio.run


@pytest.fixture(scope="session")
def default_db(tmp_path_factory):
    """The default database (synthetic people), built once per test process."""
    path = tmp_path_factory.mktemp("db") / "sass.db"
    create_default_database(path)
    return path


@pytest.fixture
def db(default_db, tmp_path):
    """A private copy: Input DB and the lists must not leak between tests."""
    path = tmp_path / "sass.db"
    shutil.copy(default_db, path)
    return path
