"""The generated databases the scale benchmarks measure on, and their timer.

benchmarks/db_scale.py (fetching one individual) and benchmarks/db_engines.py
(the sample query on each engine) share them: 1,000,000 people with
benchmarks/db_million.py's generator (~3-7 min), 5,000,000 by copying the 1M
file and replicating every person table four times in SQL with id offsets
(~9-15 min; the people repeat, the sizes are real).  Built once into a cache
directory (never committed) and reused by later runs.  Disk: 2.7 GB + 13.4 GB.
"""

from __future__ import annotations

import shutil
import sqlite3
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
from db_million import build

from sass_tui.db.engine.schema import PERSON_TABLES, connect

MILLION = 1_000_000


def _fast_writes(conn: sqlite3.Connection) -> None:
    conn.execute("PRAGMA journal_mode = OFF")
    conn.execute("PRAGMA synchronous = OFF")


def build_million(path: Path) -> None:
    tmp = path.with_suffix(".building")
    tmp.unlink(missing_ok=True)
    conn = connect(tmp, create=True)
    _fast_writes(conn)
    start = time.perf_counter()
    build(conn, MILLION, np.random.default_rng(1988))
    conn.close()
    tmp.rename(path)
    print(f"built {path} in {time.perf_counter() - start:.0f} s", file=sys.stderr)


def copied_columns(conn: sqlite3.Connection, table: str, new_id: str) -> tuple[str, str]:
    """The columns of `table`, and what to SELECT to copy a row under the id
    `new_id` (an SQL expression): a name of its own, no source key."""
    columns = [r[1] for r in conn.execute(f"PRAGMA table_info({table})")]
    select = [
        new_id
        if c == "id_num"
        else f"'GEN_' || ({new_id})"
        if (table, c) == ("person", "name")
        else "NULL"
        if (table, c) == ("person", "source_key")
        else c
        for c in columns
    ]
    return ", ".join(columns), ", ".join(select)


def build_replicated(source: Path, path: Path, copies: int) -> None:
    """`copies` x the people of `source` (ids 1..1M), each copy's ids offset by k x 1M."""
    tmp = path.with_suffix(".building")
    shutil.copyfile(source, tmp)
    conn = connect(tmp)
    _fast_writes(conn)
    start = time.perf_counter()
    conn.execute("BEGIN")
    for k in range(1, copies):
        offset = k * MILLION
        for table in ("person",) + PERSON_TABLES:
            columns, select = copied_columns(conn, table, f"id_num + {offset}")
            conn.execute(
                f"INSERT INTO {table} ({columns}) "
                f"SELECT {select} FROM {table} WHERE id_num <= {MILLION}"
            )
        print(f"\rreplicated {k + 1} x 1M", end="", file=sys.stderr, flush=True)
    conn.execute("COMMIT")
    conn.close()
    tmp.rename(path)
    print(f"\nbuilt {path} in {time.perf_counter() - start:.0f} s", file=sys.stderr)


def database(cache: Path, people: int) -> Path:
    cache.mkdir(parents=True, exist_ok=True)
    million = cache / "people_1000000.db"
    if not million.exists():
        build_million(million)
    if people == MILLION:
        return million
    path = cache / f"people_{people}.db"
    if not path.exists():
        build_replicated(million, path, people // MILLION)
    return path


def median_time(fn: Callable[[], object], runs: int = 5) -> tuple[float, object]:
    """(the median of `runs` runs in seconds, the last run's result)."""
    times, result = [], None
    for _ in range(runs):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), result
