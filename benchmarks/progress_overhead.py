"""What progress reports and the cancel cost: each long db
function run with a progress callback and a cancel (a threading.Event that is
never set, as in the TUI) against the same call without, in the same run.

    python benchmarks/progress_overhead.py [--db PATH] [--runs N] [--people N] [--scale N]

Without --db it builds the default database in a temporary directory.
Measured, median of N runs each, interleaved:
- the query `gender = male` into the query list (QueryLists.run; with
  progress it searches in id ranges of 5,000 and the SQLite progress handler
  is installed);
- Input DB of N generated people (person + 25 girth rows each), into a copy
  of the database each time;
- Make Population of the ANSUR II women (population_of);
- the seat's fit test (docs/accommodation.md).
With --scale N it also builds a database of N generated people
(benchmarks/db_million.py's generator) and times the report's sample query
on it, where the query takes long enough to need a bar.
Prints the ratio with/without (1.00 = free).
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import sys
import tempfile
import threading
import time
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from big_flat_files import write_big_flat_files

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.default import create_default_database
from sass_tui.db.people.flatfile import import_flat_files
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.population import population_of
from sass_tui.db.query.lists import QueryLists

SEAT = (
    "stature <= 190 cm AND measure.sittingheight <= 100 cm "
    "AND measure.hipbreadthsitting <= 45 cm AND mass <= 110 kg"
)


def timed(func: Callable[[], object]) -> float:
    start = time.perf_counter()
    func()
    return (time.perf_counter() - start) * 1000


def compare(name: str, plain: Callable[[], object], tracked: Callable[[], object], runs: int):
    a, b = [], []
    for _ in range(runs):
        a.append(timed(plain))
        b.append(timed(tracked))
    pa, pb = statistics.median(a), statistics.median(b)
    print(f"| {name} | {pa:.1f} ms | {pb:.1f} ms | {pb / pa:.2f} × |")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--db")
    parser.add_argument("--runs", type=int, default=7)
    parser.add_argument("--people", type=int, default=3000)
    parser.add_argument("--scale", type=int, default=0, help="also a query on N generated people")
    args = parser.parse_args()
    reports = []

    def progress(done: int, total: int) -> None:
        reports.append(done)

    cancel = threading.Event()
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(args.db) if args.db else Path(tmp) / "default.db"
        if not args.db:
            create_default_database(path)
        files = write_big_flat_files(Path(tmp) / "flat", people=args.people)
        print("| what | without | with progress + cancel | ratio |")
        print("|---|---|---|---|")
        lists = QueryLists.open(path)
        compare(
            "query `gender = male` into the query list",
            lambda: lists.run("gender = male"),
            lambda: lists.run("gender = male", progress, cancel),
            args.runs,
        )
        lists.close()

        def import_into(tracked: bool) -> Callable[[], object]:
            def run() -> object:
                copy = Path(tmp) / "copy.db"
                shutil.copy(path, copy)
                conn = connect(copy)
                try:
                    if tracked:
                        return import_flat_files(conn, files, progress, cancel)
                    return import_flat_files(conn, files)
                finally:
                    conn.close()

            return run

        compare(
            f"Input DB of {args.people:,} people ({args.people * 26:,} lines; incl. copying the db)",
            import_into(False),
            import_into(True),
            args.runs,
        )
        conn = connect(path)
        women = "gender = female AND source = ansur2"
        compare(
            "Make Population of the ANSUR II women",
            lambda: population_of(conn, women),
            lambda: population_of(conn, women, progress=progress, cancel=cancel),
            args.runs,
        )
        compare(
            "fit test, the seat",
            lambda: fit_test(conn, SEAT),
            lambda: fit_test(conn, SEAT, progress=progress, cancel=cancel),
            args.runs * 3,
        )
        conn.close()
        if args.scale:
            import numpy as np
            from db_million import build

            big = Path(tmp) / "scale.db"
            conn = connect(big, create=True)
            build(conn, args.scale, np.random.default_rng(1988))
            conn.close()
            lists = QueryLists.open(big)
            sample = (
                "gender = male AND girth.right_upper_arm.z > 28 cm "
                "AND strength.elbow_flexion.max > 20 ft-lb"
            )
            compare(
                f"the report's sample query on {args.scale:,} generated people",
                lambda: lists.run(sample),
                lambda: lists.run(sample, progress, cancel),
                args.runs,
            )
            lists.close()


if __name__ == "__main__":
    main()
