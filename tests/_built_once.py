"""What every test process of a run would build alike, built once per run.

With `pytest -n 3` each worker is a process of its own, and each built the
shipped database (`sass db init`'s, ~3 s of CPU) and a PostgreSQL cluster
with `sass db init` in it (initdb, then ~5 s of CPU in the worker and the
server) for itself: three times a run what one build gives.  The first
worker to ask builds under a lock in the run's shared folder (the
controller's base temporary folder, `tmp_path_factory.getbasetemp().parent`
in a worker, as pytest-xdist's documentation shows for a session fixture run
once); the others wait on the lock and take what it made.  Without xdist the
process builds for itself, as before.
"""

from __future__ import annotations

import fcntl
import os
import shutil
from collections.abc import Callable
from pathlib import Path

import pytest

from sass_tui.db.populations.predict import file_cache_path


def run_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The folder every test process of this run shares (its own base folder
    when it runs alone)."""
    base = tmp_path_factory.getbasetemp()
    return base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base


def built_once(
    tmp_path_factory: pytest.TempPathFactory, name: str, build: Callable[[Path], None]
) -> Path:
    """The folder `name` of this run after `build(folder)` has filled it,
    called by one test process only; the others wait for it.  A build that
    failed is tried again by the next process that asks (its error is its
    own test's)."""
    shared = run_folder(tmp_path_factory)
    folder = shared / name
    done = shared / f"{name}.done"
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file closes
        if not done.exists():
            # a build that failed may have left part of its work: started again
            # on an empty folder (a cluster's data copied onto a half-copied
            # `data` would land inside it, as `data/data`)
            shutil.rmtree(folder, ignore_errors=True)
            folder.mkdir()
            build(folder)
            done.touch()
    return folder


def copy_database_file(source: Path, target: Path | str) -> Path:
    """A copy of the SQLite file `source` at `target`, with the prediction fit
    cached beside `source` (db/populations/predict.py's file_cache_path), if there
    is one, cached beside the copy: its people are the same, so the fit's key
    is, and a test that predicts on the copy loads the fit instead of making
    it again (0.2-0.4 s of CPU each; 60 fits a run made that way)."""
    target = Path(target)
    shutil.copyfile(source, target)
    fit = file_cache_path(source)
    if fit.is_file():
        shutil.copyfile(fit, file_cache_path(target))
    return target
