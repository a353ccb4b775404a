"""The column copy's file and what both of its modules need: where the copy
lives (CACHE_DIR), the SQLite state it follows (its data version), the
copies open in this process and the Unsupported that sends a query back to
SQLite.

Separate from db/query/accelerator.py (the light front that `sass query --count`
imports to ask whether a copy can answer) and db/query/column_copy.py (which reads
SQLite's columns with numpy and writes and reads the copy with DuckDB): both
import this, and neither imports the other's module back.  No numpy, duckdb,
uuid or shutil here: off the `sass query --count` row of sass_tui/startup.py.
"""

from __future__ import annotations

import hashlib
import os
import sqlite3
import struct
import threading
from pathlib import Path
from typing import Any

# Where the copies live; None: $XDG_CACHE_HOME/sass/columns (~/.cache/sass/columns).
CACHE_DIR: Path | None = None
# Build a missing copy in a background thread while SQLite answers (True), or
# in the caller (False: tests and benchmarks).
BACKGROUND = True
COPY_FILE = "copy.duckdb"

# The copies open in this process (db/query/column_copy.py's CopyHeld, by database
# file) and the lock over them and the background builds.
LOCK = threading.RLock()
OPEN_COPIES: dict[Path, Any] = {}


class Unsupported(Exception):
    """The copy cannot answer this query or database provably alike: SQLite answers."""


def data_version(conn: sqlite3.Connection) -> tuple[int, ...]:
    """The key of the copy: header change counter, page count and schema cookie,
    with the file's size, mtime and inode.  Call inside a read transaction."""
    path = database_path(conn)
    with open(path, "rb") as f:
        header = f.read(100)
        stat = os.fstat(f.fileno())
    if len(header) < 100 or not header.startswith(b"SQLite format 3\0"):
        raise Unsupported("no SQLite header")
    if header[18] != 1 or header[19] != 1:
        raise Unsupported("not in rollback-journal mode (WAL): the change counter may not move")
    counter, pages = struct.unpack(">II", header[24:32])
    (cookie,) = struct.unpack(">I", header[40:44])
    return (counter, pages, cookie, stat.st_size, stat.st_mtime_ns, stat.st_ino, stat.st_dev)


def database_path(conn: sqlite3.Connection) -> Path:
    for _seq, name, file in conn.execute("PRAGMA database_list"):
        if name == "main":
            if not file:
                raise Unsupported("an in-memory or temporary database")
            return Path(file)
    raise Unsupported("no main database")  # pragma: no cover - SQLite always has one


def cache_folder(path: Path) -> Path:
    """The folder of the copy of the database file at `path`."""
    base = CACHE_DIR
    if base is None:
        xdg = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
        base = Path(xdg) / "sass" / "columns"
    digest = hashlib.sha256(str(path.resolve()).encode()).hexdigest()[:16]
    return base / digest
