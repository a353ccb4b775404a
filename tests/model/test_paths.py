"""File names as typed: ~ expansion and non-regular files refused."""

from __future__ import annotations

import os

import pytest

from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import regular_file, user_path


def test_an_unknown_user_is_a_message_not_a_runtime_error():
    with pytest.raises(SassError, match="cannot expand ~nosuchuser"):
        user_path("~nosuchuser/x.db")


def test_home_is_expanded(monkeypatch, tmp_path):
    monkeypatch.setenv("HOME", str(tmp_path))
    assert user_path("~/a.fig") == tmp_path / "a.fig"


def test_a_fifo_or_a_directory_is_refused_before_it_is_opened(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(SassError, match="not a regular file"):
        regular_file(fifo)
    with pytest.raises(SassError, match="directory"):
        regular_file(tmp_path)
    with pytest.raises(SassError, match="no such file"):
        regular_file(tmp_path / "missing.dat")
    (tmp_path / "ok.dat").write_text("x")
    assert regular_file(tmp_path / "ok.dat") == tmp_path / "ok.dat"
