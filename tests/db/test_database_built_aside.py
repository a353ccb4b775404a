"""A new database is built beside its name and linked into place whole
(db/people/default.py `_build_aside`): `sass db init --db NEW.db` on a disk that
fills half-way leaves no NEW.db (it left a schema with nobody in it, which
then answered every query with "0"), and a killed build's temporary is
swept by the next build, as the atomic writer's are."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest
from _tmpfs import fill, mounted_tmpfs

from sass_tui.cli import main
from sass_tui.model.files.atomic import temporary_name

pytestmark = pytest.mark.sqlite_only("SQLite files built aside")


@pytest.mark.slow
def test_a_new_database_the_disk_cannot_hold_is_not_left_half_built(
    tmp_path, capsys, few_default_people
):
    with mounted_tmpfs(tmp_path / "mnt", 8 * 1024 * 1024) as mnt:
        fill(mnt, leave=1024 * 1024)  # room for the schema, not for the people
        new = mnt / "new.db"
        assert main(["db", "init", "--db", str(new)]) == 2
        err = capsys.readouterr().err
        assert f"cannot write {new}: the disk is full" in err and "Traceback" not in err, err
        assert sorted(p.name for p in mnt.iterdir()) == ["filler"]  # no new.db, no temporary
        assert main(["query", "--db", str(new), "--count", "gender = male"]) == 2
        assert "no database there" in capsys.readouterr().err  # not "0"


@pytest.mark.slow
def test_a_killed_build_leaves_no_database_and_its_temporary_is_swept(
    tmp_path, capsys, few_default_people
):
    new = tmp_path / "new.db"
    build = subprocess.Popen(
        [sys.executable, "-m", "sass_tui", "db", "init", "--db", str(new)],
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    try:
        # killed once its temporary database has grown past its schema
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            aside = [p for p in tmp_path.iterdir() if ".sass-tmp-" in p.name]
            if any(_size(p) > 1_000_000 for p in aside):
                break
            assert build.poll() is None, "the build ended before it could be killed"
            time.sleep(0.02)
        os.kill(build.pid, signal.SIGKILL)
    finally:
        build.wait(30)
    assert not new.exists()
    left = [p.name for p in tmp_path.iterdir()]
    assert left and all(name.startswith(".new.db.sass-tmp-") for name in left), left
    assert main(["db", "init", "--db", str(new)]) == 0  # the next build sweeps them
    assert [p.name for p in tmp_path.iterdir()] == ["new.db"]
    # the killed build read the shipped data, this one the sampled
    assert f"{few_default_people.ansur} ANSUR II people" in capsys.readouterr().out
    assert temporary_name(new).name.startswith(".new.db.sass-tmp-")


def _size(path) -> int:
    """A file's size, 0 once gone: SQLite removes its journal between a commit
    and the next, so a file listed a moment ago may be gone when measured."""
    try:
        return path.stat().st_size
    except FileNotFoundError:
        return 0
