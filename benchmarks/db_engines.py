"""The report's sample query counted on 1,000,000 and 5,000,000 generated
people by each engine sass can use, side by side in one run:

- SQLite: `Query.count()` with the column copy off (what answers a database
  below 200,000 people, or without DuckDB installed);
- DuckDB: `Query.count()` answered from the DuckDB column copy
  (sass_tui/db/query/accelerator.py), warm, plus its build (`sass db copy`: the
  first count after any write waits for this in the background) and its
  first count in a new process (the copy opened from disk);
- PostgreSQL 15: the same query tree compiled in the "postgresql" dialect
  over the same people's three tables the query reads (person, the right
  upper arm's girth and the elbow flexion's strength, COPYed from SQLite into
  a throwaway cluster of tests/_postgres.py, primary keys, ANALYZE), its
  own parallel scans and hash joins; skipped without the server binaries.

    python benchmarks/db_engines.py [--cache DIR] [--sizes 1000000,5000000]

The databases are benchmarks/scale_databases.py's (built once into DIR and
reused), as benchmarks/db_scale.py's.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import sqlite3
import sys
import time
from pathlib import Path

from db_million import SAMPLE
from scale_databases import database, median_time

from sass_tui.db.engine.schema import connect
from sass_tui.db.query import accelerator, copy_file
from sass_tui.db.query.query import Query, compile_query

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from _postgres import running_cluster, why_not


def sqlite_count(conn: sqlite3.Connection) -> int:
    saved = accelerator.MIN_PEOPLE
    accelerator.MIN_PEOPLE = 1 << 62  # the copy off: SQLite answers
    try:
        return Query(conn, compile_query(SAMPLE)).count()
    finally:
        accelerator.MIN_PEOPLE = saved


def load_postgres(cluster, sqlite_conn: sqlite3.Connection, people: int) -> str:
    """The tables the sample query reads, copied into a new PostgreSQL database."""
    from sass_tui.db.engine.postgres import PostgresConnection

    url = cluster.create_database(f"people_{people}")
    pg = PostgresConnection(url)
    compiled = compile_query(SAMPLE)
    tables = {"person": ["id_num", "gender"]} | {
        table: ["id_num", compiled.tree.terms[k].column]  # type: ignore[union-attr]
        for k, (_alias, table) in enumerate(compiled.tables, 1)
    }
    for table, columns in tables.items():
        kind = ["BIGINT PRIMARY KEY"] + [
            "TEXT" if c == "gender" else "DOUBLE PRECISION" for c in columns[1:]
        ]
        pg.execute(f"CREATE TABLE {table} ({', '.join(f'{c} {k}' for c, k in zip(columns, kind))})")
        with pg.transaction():
            pg.copy_rows(
                table, columns, sqlite_conn.execute(f"SELECT {', '.join(columns)} FROM {table}")
            )
        pg.execute(f"VACUUM ANALYZE {table}")
    pg.close()
    return url


def postgres_count(url: str) -> tuple[float, int]:
    from sass_tui.db.engine.postgres import PostgresConnection

    pg = PostgresConnection(url)
    try:
        query = Query(pg, compile_query(SAMPLE))
        query.count()  # warm the buffers
        elapsed, count = median_time(query.count)
        return elapsed, int(count)  # type: ignore[call-overload]
    finally:
        pg.close()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cache", type=Path, default=Path("/tmp/sass_scale"))
    parser.add_argument("--sizes", default="1000000,5000000")
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    import duckdb

    reason = why_not()
    print(
        f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {platform.machine()}, "
        f"{os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}, Python "
        f"{platform.python_version()}, SQLite {sqlite3.sqlite_version}, DuckDB "
        f"{duckdb.__version__}, PostgreSQL {'absent: ' + reason if reason else 'present'}"
    )
    print(f"sample query: {SAMPLE}\n")
    results: dict[str, list[str]] = {}

    def note(what: str, value: str) -> None:
        results.setdefault(what, []).append(value)

    cluster_context = running_cluster() if reason is None else None
    cluster = cluster_context.__enter__() if cluster_context else None
    try:
        for people in sizes:
            path = database(args.cache, people)
            conn = connect(path)
            expected = sqlite_count(conn)  # also warms the page cache
            sqlite_time, _n = median_time(lambda: sqlite_count(conn), runs=3)
            copy_file.CACHE_DIR = args.cache / "columns"
            shutil.rmtree(copy_file.CACHE_DIR, ignore_errors=True)
            copy_file.OPEN_COPIES.clear()
            copy_file.BACKGROUND = False  # built in this thread, to time it
            t0 = time.perf_counter()
            first = Query(conn, compile_query(SAMPLE)).count()
            build_time = time.perf_counter() - t0
            assert accelerator.last_answer == "copy", accelerator.last_answer
            copy_file.OPEN_COPIES.clear()  # as the next process: the copy opened from disk
            t0 = time.perf_counter()
            Query(conn, compile_query(SAMPLE)).count()
            reload_time = time.perf_counter() - t0
            duck_time, got = median_time(lambda: Query(conn, compile_query(SAMPLE)).count())
            assert got == first == expected, (got, first, expected)
            copy_size = sum(f.stat().st_size for f in copy_file.CACHE_DIR.rglob("*"))
            note("people", f"{people:,}")
            note("people matching", f"{expected:,}")
            note("SQLite file", f"{path.stat().st_size / 1e9:.1f} GB")
            note("SQLite, median of 3", f"{sqlite_time * 1000:.0f} ms")
            note("**DuckDB column copy, warm, median of 5**", f"**{duck_time * 1000:.1f} ms**")
            note("DuckDB copy: first count of a new process", f"{reload_time * 1000:.0f} ms")
            note("DuckDB copy: built from SQLite (after any write)", f"{build_time:.1f} s")
            note("DuckDB copy: file size", f"{copy_size / 1e6:.0f} MB")
            if cluster is not None:
                t0 = time.perf_counter()
                url = load_postgres(cluster, conn, people)
                load_time = time.perf_counter() - t0
                pg_time, pg_count = postgres_count(url)
                assert pg_count == expected, (pg_count, expected)
                note("**PostgreSQL 15, warm, median of 5**", f"**{pg_time * 1000:.0f} ms**")
                note("PostgreSQL: the three tables loaded (COPY, ANALYZE)", f"{load_time:.0f} s")
            conn.close()
    finally:
        if cluster_context is not None:
            cluster_context.__exit__(None, None, None)
    header = results.pop("people")
    print(f"| sample query's count | {' | '.join(header)} |")
    print("|---|" + "---|" * len(header))
    for what, values in results.items():
        print(f"| {what} | {' | '.join(values)} |")


if __name__ == "__main__":
    main()
