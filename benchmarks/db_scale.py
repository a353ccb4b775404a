"""Database at scale: the generated databases of 1,000,000 and 5,000,000
people (built once, reused), and fetching one individual at 1,000,000, cold
and warm.  Run:
    python benchmarks/db_scale.py [--cache DIR]

The sample query's count on SQLite, DuckDB and PostgreSQL side by side is
benchmarks/db_engines.py, over the same databases.

The databases are built once into DIR (default /tmp/sass_scale; never
committed) and reused by later runs (benchmarks/scale_databases.py).
"""

from __future__ import annotations

import argparse
import gc
import os
import resource
import sqlite3
import statistics
import time
from pathlib import Path

import numpy as np
from db_million import SAMPLE
from scale_databases import MILLION, database, median_time

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.individual import _fetch_individual, fetch_individual
from sass_tui.db.query.query import compile_query

MAPPED = 17179869184  # connect()'s memory map before this change (PRAGMA mmap_size)


def sqlite_count(conn: sqlite3.Connection) -> int:
    """The sample query counted by SQLite itself (no column copy)."""
    compiled = compile_query(SAMPLE)
    sql = f"SELECT count(*) FROM {compiled.from_clause()} WHERE {compiled.where}"
    return int(conn.execute(sql, compiled.params).fetchone()[0])


def fetch_before(conn: sqlite3.Connection, id_num: int) -> None:
    """fetch_individual as it was before this benchmark's change (the baseline):
    one query per relation and one per strength query table, 22 in all."""
    from sass_tui.db.engine.schema import QUERY_TABLES, STRENGTH_PARAMETERS

    conn.execute(
        "SELECT id_num, name, gender, stature, mass, handedness, age, source "
        "FROM person WHERE id_num = ?",
        (id_num,),
    ).fetchone()
    for sql in (
        "SELECT seg_name, thickness, width, length, mass FROM girth WHERE id_num = ?",
        "SELECT seg_name, jlimit_x, jlimit_y, jlimit_z FROM joint_limits WHERE id_num = ?",
        "SELECT seg_name, cmass_x, cmass_y, cmass_z FROM center_of_mass WHERE id_num = ?",
        f"SELECT {', '.join(STRENGTH_PARAMETERS)} FROM strength_q WHERE id_num = ?",
        *(f"SELECT max FROM {t} WHERE id_num = ?" for t in QUERY_TABLES["strength"].values()),
        "SELECT * FROM strength_par WHERE id_num = ? ORDER BY exp_num",
        "SELECT * FROM shoulder_strgh WHERE id_num = ? ORDER BY exp_num, axis",
        "SELECT * FROM elbow_strgh WHERE id_num = ? ORDER BY exp_num",
        "SELECT * FROM wrist_strgh WHERE id_num = ? ORDER BY exp_num, axis",
    ):
        conn.execute(sql, (id_num,)).fetchall()


def _queue_wait() -> float:
    """Seconds this thread has waited for a core, runnable (Linux schedstat; 0 elsewhere)."""
    try:
        with open("/proc/thread-self/schedstat") as f:
            return int(f.read().split()[1]) / 1e9
    except (OSError, IndexError, ValueError):
        return 0.0


def fetch_times(conn: sqlite3.Connection, fetch, stored: np.ndarray, seed: int):
    """Wall time, this thread's CPU time and its time waiting for a core of
    each fetch, and the blocks read from disk (the rest of the wall time is
    blocked on the disk)."""
    walls, cpus, queued, faults = [], [], [], 0
    for pid in np.random.default_rng(seed).choice(stored, 200, replace=False).tolist():
        before = resource.getrusage(resource.RUSAGE_SELF).ru_inblock
        q0, c0, t0 = _queue_wait(), time.thread_time(), time.perf_counter()
        fetch(conn, pid)
        walls.append(time.perf_counter() - t0)
        cpus.append(time.thread_time() - c0)
        queued.append(_queue_wait() - q0)
        faults += resource.getrusage(resource.RUSAGE_SELF).ru_inblock - before
    return walls, cpus, queued, faults


def page_cache(path: Path, warm: bool) -> None:
    """Drop the file's pages from the OS page cache (posix_fadvise: this file
    only), or read it all into it."""
    with open(path, "rb") as f:
        if warm:
            while f.read(1 << 24):
                pass
        else:
            os.posix_fadvise(f.fileno(), 0, 0, os.POSIX_FADV_DONTNEED)


def fetch_table(path: Path) -> None:
    print(
        "\nfetch one individual, 200 random people at 1,000,000, a new connection "
        "and fresh random ids for each line; cold: the file dropped from the page "
        "cache first, warm: the whole file read into it first.  CPU is this thread's "
        "CPU time; the rest of the wall time is waiting for a core or the disk.\n"
    )
    print(
        "| pages | how | median | max | CPU median | CPU max | read from disk | "
        "slowest: CPU / waiting for a core / blocked on disk | over 5 ms |"
    )
    print("|---|---|---|---|---|---|---|---|---|")
    cases = [
        (state, label, fetch, mmap)
        for state in ("cold", "warm")
        for _ in range(2)  # each case twice, interleaved: the wall maxima swing with load
        for label, fetch, mmap in (
            ("22 queries, file mapped (two rounds ago)", fetch_before, MAPPED),
            ("before: 8 queries, each its own read transaction", _fetch_individual, None),
            ("now: 8 queries in one read transaction", fetch_individual, None),
        )
    ]
    # The people stored now (each run of the count table imports and deletes a
    # few), read before any page cache is dropped.
    conn = connect(path)
    stored = np.asarray([r[0] for r in conn.execute("SELECT id_num FROM person")])
    conn.close()
    for seed, (state, label, fetch, mmap) in enumerate(cases):
        page_cache(path, warm=state == "warm")
        conn = connect(path)
        if mmap is not None:
            conn.execute(f"PRAGMA mmap_size = {mmap}")
        gc.collect()
        walls, cpus, queued, faults = fetch_times(conn, fetch, stored, seed)
        conn.close()
        k = int(np.argmax(walls))
        print(
            f"| {state} | {label} | {statistics.median(walls) * 1000:.2f} ms | "
            f"{max(walls) * 1000:.2f} ms | {statistics.median(cpus) * 1000:.2f} ms | "
            f"{max(cpus) * 1000:.2f} ms | {faults * 512 // 1024:,} KB | "
            f"{cpus[k] * 1000:.2f} / {queued[k] * 1000:.2f} / "
            f"{max(walls[k] - cpus[k] - queued[k], 0) * 1000:.2f} ms | "
            f"{sum(w > 0.005 for w in walls)} |"
        )
    # The CPU of a warm fetch, before and now, alternating on one connection.
    conn = connect(path)
    picked = np.random.default_rng(99).choice(stored, 2000, replace=False).tolist()
    for pid in picked:
        fetch_individual(conn, pid)
    per_fetch: dict[str, list[float]] = {"before": [], "now": []}
    for _ in range(5):
        for label, fetch in (("before", _fetch_individual), ("now", fetch_individual)):
            c0 = time.thread_time()
            for pid in picked:
                fetch(conn, pid)
            per_fetch[label].append((time.thread_time() - c0) / len(picked))
    conn.close()
    before, now = (statistics.median(per_fetch[k]) * 1e6 for k in ("before", "now"))
    print(
        f"\nwarm, 2,000 people on one connection, CPU per fetch, median of 5 alternating: "
        f"before {before:.0f} us, now {now:.0f} us ({now / before:.2f}x)"
    )
    print(
        "\nthe sample query counted by SQLite on a cold file (dropped from the page "
        "cache first), file mapped as before against read() as now, alternating:\n"
    )
    print("| how | time | read from disk |")
    print("|---|---|---|")
    for label, mmap in (("mapped", MAPPED), ("read()", None)) * 2:
        page_cache(path, warm=False)
        conn = connect(path)
        if mmap is not None:
            conn.execute(f"PRAGMA mmap_size = {mmap}")
        before = resource.getrusage(resource.RUSAGE_SELF).ru_inblock
        elapsed, _n = median_time(lambda: sqlite_count(conn), runs=1)
        read = (resource.getrusage(resource.RUSAGE_SELF).ru_inblock - before) * 512 // 2**20
        conn.close()
        print(f"| {label} | {elapsed:.2f} s | {read:,} MB |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cache", type=Path, default=Path("/tmp/sass_scale"))
    args = parser.parse_args()
    fetch_table(database(args.cache, MILLION))


if __name__ == "__main__":
    main()
