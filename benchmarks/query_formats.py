"""What `sass query --format json` costs against the table: the time to
write the same people both ways, in one process, rows fetched once.

    python benchmarks/query_formats.py [--runs 21] [--db PATH] [QUERY]

The database is `--db`, else the default one ($SASS_DB, else built on first
use); the query defaults to `gender = male` (4,082 ANSUR II men).  Prints the
medians and the ratio json / table (target: at most 1.5).
"""

from __future__ import annotations

import argparse
import io
import statistics
import time


def main() -> None:
    from sass_tui.cli.query import _write_table
    from sass_tui.cli.query_json import write_people as _write_json
    from sass_tui.db.people.default import open_database
    from sass_tui.db.query.query import run_query

    parser = argparse.ArgumentParser()
    parser.add_argument("query", nargs="?", default="gender = male")
    parser.add_argument("--runs", type=int, default=21)
    parser.add_argument("--db")
    args = parser.parse_args()
    conn = open_database(args.db)
    rows = run_query(conn, args.query).person_rows().fetchall()
    conn.close()

    def table() -> None:
        _write_table(io.StringIO(), rows)

    def json() -> None:
        _write_json(io.StringIO(), rows)

    times: dict[str, list[float]] = {"table": [], "json": []}
    for _ in range(args.runs):  # interleaved: both see the same load
        for name, write in (("table", table), ("json", json)):
            start = time.perf_counter()
            write()
            times[name].append(time.perf_counter() - start)
    median = {name: statistics.median(t) * 1000 for name, t in times.items()}
    print(f"{len(rows):,} people ({args.query}), median of {args.runs} runs")
    print(f"table {median['table']:.1f} ms, json {median['json']:.1f} ms")
    print(f"json / table = {median['json'] / median['table']:.2f} (target <= 1.5)")


if __name__ == "__main__":
    main()
