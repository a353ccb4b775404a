from __future__ import annotations

import asyncio
import shutil

import pytest
from textual.widgets import Input

from sass_tui.db.default import create_default_database


@pytest.fixture(autouse=True)
def no_cursor_blink(monkeypatch):
    """A steady cursor: snapshots must not depend on when the blink timer fired."""
    monkeypatch.setattr(Input.__dict__["cursor_blink"], "_default", False)


@pytest.fixture(autouse=True)
def own_config_dir(tmp_path_factory, monkeypatch):
    """Never the user's remembered theme (snapshots), nor write to it."""
    monkeypatch.setenv("XDG_CONFIG_HOME", str(tmp_path_factory.mktemp("config")))


@pytest.fixture
def drive():
    """Run an async Pilot scenario from a plain test (no asyncio plugin needed)."""
    return asyncio.run


@pytest.fixture(scope="session")
def shipped_db_file(tmp_path_factory):
    """The database `sass` builds from the shipped data (synthetic people),
    built once per test process."""
    path = tmp_path_factory.mktemp("db") / "sass.db"
    create_default_database(path)
    return path


@pytest.fixture
def db(shipped_db_file, tmp_path):
    """A private copy: Input DB and the lists must not leak between tests."""
    path = tmp_path / "sass.db"
    shutil.copy(shipped_db_file, path)
    return path
