"""The default database: where it lives and how it is first built.

Nothing here parses arguments or prints; the CLI and the TUI call these.
"""

from __future__ import annotations

import os
import sqlite3
import tempfile
from collections.abc import Callable
from pathlib import Path

from sass_tui.db.schema import connect, default_db_path

Progress = Callable[[int, int], None]


def open_database(path: str | Path | None = None, *, create: bool = False) -> sqlite3.Connection:
    """Open `path`, or the default database (built from the shipped data on first use)."""
    if path is not None:
        return connect(path, create=create)
    return default_database()


def default_database() -> sqlite3.Connection:
    """Open the default database, creating it from the shipped data set on first use."""
    path = default_db_path()
    if not path.exists():
        create_default_database(path)
    return connect(path)


def create_default_database(path: str | Path, progress: Progress | None = None) -> int:
    """Build a fresh database from datasets/db beside `path`, then rename it into place."""
    from sass_tui.db.flatfile import FlatFiles, import_flat_files
    from sass_tui.model import datasets

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    os.close(fd)
    os.unlink(tmp)
    try:
        conn = connect(tmp, create=True)
        try:
            count = import_flat_files(conn, FlatFiles.in_directory(datasets.directory() / "db"))
        finally:
            conn.close()
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return count
