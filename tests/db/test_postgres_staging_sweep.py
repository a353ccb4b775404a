"""A PostgreSQL import stages its people in a SQLite file of its own
(db/engine/postgres.py `import_staged`); one killed half-way left that copy (23 MB
for ANSUR II) in the temporary directory for good.  The staging folder is
named for its process, and the next import removes those of processes that
are gone, as model/files/atomic.py sweeps its temporaries."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import tempfile
import time

import pytest

from sass_tui.cli import main
from sass_tui.db.engine.postgres import STAGING_PREFIX, sweep_staging


def _dead_pid() -> int:
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_only_folders_of_ended_processes_are_swept(tmp_path):
    dead = tmp_path / f"{STAGING_PREFIX}{_dead_pid()}-abc"
    live = tmp_path / f"{STAGING_PREFIX}{os.getpid()}-def"
    other = tmp_path / f"{STAGING_PREFIX}oldstyle"
    for folder in (dead, live, other):
        folder.mkdir()
        (folder / "staging.db").write_bytes(b"x" * 1000)
    assert sweep_staging(tmp_path) == [dead]
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([live.name, other.name])


@pytest.mark.slow
def test_a_killed_postgres_import_leaves_a_copy_the_next_import_removes(
    cluster, tmp_path, monkeypatch, few_default_people
):
    url = cluster.create_database("staging_sweep")
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    # a real import, killed while its staging copy grows
    importing = subprocess.Popen(
        [sys.executable, "-m", "sass_tui", "db", "init", "--force", "--db", url],
        env={**os.environ, "TMPDIR": str(scratch)},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            staged = list(scratch.glob(f"{STAGING_PREFIX}*/staging.db"))
            if staged and staged[0].stat().st_size > 1_000_000:
                break
            assert importing.poll() is None, "the import ended before it could be killed"
            time.sleep(0.02)
        os.kill(importing.pid, signal.SIGKILL)
    finally:
        importing.wait(30)
    left = list(scratch.iterdir())
    assert [p.name.startswith(f"{STAGING_PREFIX}{importing.pid}-") for p in left] == [True]
    monkeypatch.setattr(tempfile, "tempdir", str(scratch))
    # (the killed import read the shipped data, this one the sampled: it sweeps the same)
    assert main(["db", "init", "--force", "--db", url]) == 0
    assert list(scratch.iterdir()) == []  # swept, and this import's own removed
