"""The database a script or benchmark measures on: the one named by `--db`,
or else the default database (the ANSUR II people) built now in a temporary
directory.  scripts/target_accuracy.py, benchmarks/fit.py and
benchmarks/target.py open theirs here."""

from __future__ import annotations

import argparse
import tempfile
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from sass_tui.db.people.default import create_default_database


def add_db_option(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--db", help="database (default: the default database, built now)")


@contextmanager
def default_database(db: str | None, *, say_build_time: bool = True) -> Iterator[tuple[Path, Path]]:
    """(the database's path, a temporary directory for the run's own files,
    removed after).  `say_build_time`: print how long the build took (a
    benchmark's baseline; a script printing a table alone says nothing)."""
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(db) if db else Path(tmp) / "default.db"
        if not db:
            start = time.perf_counter()
            create_default_database(path)
            if say_build_time:
                print(f"built the default database in {time.perf_counter() - start:.1f} s")
        yield path, Path(tmp)
