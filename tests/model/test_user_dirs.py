"""sass's own directories come from platformdirs (model/files/paths.py), which
follows the XDG base directory variables on Linux; the database's default
place is the data directory's sass.db."""

from __future__ import annotations

import sys

import pytest

from sass_tui.db.engine.schema import default_db_path
from sass_tui.model.files.paths import cache_dir, config_dir, data_dir


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="XDG directories are Linux's")
def test_the_directories_follow_xdg(tmp_path, monkeypatch):
    for kind in ("DATA", "CACHE", "CONFIG"):
        monkeypatch.setenv(f"XDG_{kind}_HOME", str(tmp_path / kind.lower()))
    monkeypatch.delenv("SASS_DB", raising=False)
    assert data_dir() == tmp_path / "data" / "sass"
    assert cache_dir() == tmp_path / "cache" / "sass"
    assert config_dir() == tmp_path / "config" / "sass"
    assert default_db_path() == tmp_path / "data" / "sass" / "sass.db"
    for kind in ("DATA", "CACHE", "CONFIG"):
        monkeypatch.delenv(f"XDG_{kind}_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert data_dir() == tmp_path / "home" / ".local" / "share" / "sass"
    assert cache_dir() == tmp_path / "home" / ".cache" / "sass"
    assert config_dir() == tmp_path / "home" / ".config" / "sass"


def test_sass_db_comes_first(tmp_path, monkeypatch):
    monkeypatch.setenv("SASS_DB", str(tmp_path / "mine.db"))
    assert default_db_path() == tmp_path / "mine.db"
