"""tests/_built_once.py: what every test process of a run would build alike,
built once; a build that failed is started again, on an empty folder."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

import pytest
from _built_once import built_once


def _factory(base: Path) -> pytest.TempPathFactory:
    return SimpleNamespace(getbasetemp=lambda: base)  # type: ignore[return-value]


def test_a_build_that_failed_is_started_again_on_an_empty_folder(tmp_path, monkeypatch):
    monkeypatch.delenv("PYTEST_XDIST_WORKER", raising=False)  # the process's own folder

    def half_done(folder: Path) -> None:
        (folder / "data").mkdir()
        (folder / "data" / "half").write_text("copied so far")
        raise OSError(28, "No space left on device")

    with pytest.raises(OSError):
        built_once(_factory(tmp_path), "cluster", half_done)

    def whole(folder: Path) -> None:
        assert list(folder.iterdir()) == []  # nothing of the failed build
        (folder / "data").mkdir()
        (folder / "data" / "whole").write_text("all of it")

    folder = built_once(_factory(tmp_path), "cluster", whole)
    assert sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*")) == [
        "data",
        "data/whole",
    ]
    # built: the next process to ask takes it as it is
    assert built_once(_factory(tmp_path), "cluster", lambda _: pytest.fail("built twice")) == folder
