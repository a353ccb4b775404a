"""Small file systems the fault tests can fill or make read-only.

`mounted_tmpfs(folder, size)` mounts a tmpfs of `size` bytes on `folder` and
always unmounts it on the way out; where this process may not mount (not
root, no CAP_SYS_ADMIN, no `mount`), the test is skipped with the reason.
As root, chmod does not stop a write: a tmpfs mounted read-only or filled to
the last byte does.
"""

from __future__ import annotations

import errno
import os
import shutil
import subprocess
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

CHUNK = 64 * 1024


def _run(*command: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(command, capture_output=True, text=True, timeout=60)


@contextmanager
def mounted_tmpfs(folder: Path, size: int) -> Iterator[Path]:
    if shutil.which("mount") is None or shutil.which("umount") is None:
        pytest.skip("no mount/umount command here: cannot make a small file system")
    folder.mkdir(parents=True, exist_ok=True)
    kib = max(64, -(-size // 1024))
    result = _run("mount", "-t", "tmpfs", "-o", f"size={kib}k,mode=0755", "tmpfs", str(folder))
    if result.returncode != 0:
        reason = result.stderr.strip() or f"exit status {result.returncode}"
        pytest.skip(f"mounting a tmpfs is not permitted here (needs root): {reason}")
    try:
        yield folder
    finally:
        if _run("umount", str(folder)).returncode != 0:
            _run("umount", "-l", str(folder))  # something still holds it: detach


def remount_read_only(folder: Path) -> None:
    result = _run("mount", "-o", "remount,ro", str(folder))
    assert result.returncode == 0, result.stderr


def fill(folder: Path, leave: int = 0) -> Path:
    """Write a filler file until `leave` bytes (rounded down to whole chunks)
    are free, or, with leave=0, until the file system refuses a single byte."""
    filler = folder / "filler"
    with filler.open("wb", buffering=0) as handle:
        try:
            while True:
                stats = os.statvfs(folder)
                free = stats.f_bavail * stats.f_frsize
                if leave and free - CHUNK < leave:
                    break
                handle.write(b"\0" * (CHUNK if free >= CHUNK or leave else 4096))
        except OSError as exc:
            assert exc.errno == errno.ENOSPC, exc
    if not leave:  # not even one byte more
        try:
            with filler.open("ab", buffering=0) as handle:
                handle.write(b"\0")
        except OSError as exc:
            assert exc.errno == errno.ENOSPC, exc
        else:
            raise AssertionError(f"{folder} still takes writes")
    return filler


def build_small_db(path: Path) -> Path:
    """A sass database of the 200 shipped synthetic people (~1.8 MB: small
    enough for a tmpfs of a few MB)."""
    from sass_tui.db.engine.schema import connect
    from sass_tui.db.people.flatfile import FlatFiles, import_flat_files
    from sass_tui.model import datasets

    conn = connect(path, create=True)
    try:
        import_flat_files(conn, FlatFiles.in_directory(datasets.directory() / "db"))
    finally:
        conn.close()
    return path
