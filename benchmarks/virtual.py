"""Virtual-population benchmark on the default database (docs/performance.md,
"Virtual populations and sass stats").

    python benchmarks/virtual.py [--db PATH] [--runs N]

Without --db it builds the default database in a temporary directory.  In
process, median of N runs:
- building the shipped virtual population nhanes-2017-2020 (8,381 virtual
  people): read the shipped NHANES file, load and fit the regression on the
  6,068 real people, draw, store the people and their weights, in a copy of
  the database from which `sass db init`'s own were dropped first (untimed)
  -- goal under 3 s; beside it, building the default database as `sass db
  init` does (6,068 ANSUR II people, 200 synthetic ones, the shipped target
  and the same virtual population) and the calibration target of the same
  sample, measured in the same run: the ratio says what the machine's load
  does not;
- `sass stats` over it (every measure, 93 columns, weighted) beside the same
  table over the 6,068 real people unweighted -- goal under 0.3 s.
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import sys
from pathlib import Path

from fit import median_ms  # benchmarks/fit.py: the one timing helper

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.default import create_default_database
from sass_tui.db.populations.shipped import load_weights
from sass_tui.db.populations.stats import EVERY_MEASURE, stats_table
from sass_tui.db.populations.targets import BOTH, drop_target, make_target, store_target
from sass_tui.db.populations.virtual import (
    drop_virtual,
    make_virtual,
    shipped_sample,
    store_virtual,
)
from sass_tui.model.datasets import NHANES_NAME

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from scripts.default_database import add_db_option, default_database  # noqa: E402


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    with default_database(args.db) as (path, tmp):
        conn = connect(path)
        rebuilt = tmp / "baseline.db"
        baseline, baseline_best = median_ms(
            lambda: create_default_database(rebuilt, replace=True), args.runs
        )

        def build_virtual() -> None:
            sample = shipped_sample()
            store_virtual(fresh[0], make_virtual(fresh[0], NHANES_NAME, sample, NHANES_NAME))

        # Each run builds it in a fresh copy of the database without it, as its
        # first use in a database that lacks it does (replacing a stored one
        # would also time deleting the people stored before).
        copies = []
        for k in range(args.runs):
            copy = tmp / f"fresh{k}.db"
            shutil.copy(path, copy)
            lacking = connect(copy)
            drop_virtual(lacking, NHANES_NAME)
            drop_target(lacking, NHANES_NAME)
            lacking.close()
            copies.append(copy)
        fresh = [connect(copies[0])]

        def next_copy() -> None:
            fresh[0].close()
            fresh[0] = connect(copies.pop(0))

        def build_target() -> None:
            sample = shipped_sample()
            _t, weights, _w = make_target(
                conn, NHANES_NAME, BOTH, sample, NHANES_NAME, within_range=True
            )
            store_target(conn, weights, replace=True)

        times = []
        for _ in range(args.runs):
            next_copy()
            times.append(median_ms(build_virtual, 1)[0])
        fresh[0].close()
        virtual, virtual_best = statistics.median(times), min(times)
        target, target_best = median_ms(build_target, args.runs)
        print(
            f"build the virtual population {NHANES_NAME} (8,381 people: read, fit, draw, "
            f"store): {virtual:.0f} ms (best {virtual_best:.0f}); goal < 3000 ms"
        )
        print(
            f"build the default database as sass db init does (6,268 people and the "
            f"shipped target and virtual population, the baseline): {baseline:.0f} ms "
            f"(best {baseline_best:.0f}); virtual / baseline = {virtual / baseline:.2f}"
        )
        print(
            f"make the target {NHANES_NAME} (the 6,068 real people weighted): "
            f"{target:.0f} ms (best {target_best:.0f})"
        )
        weights = load_weights(conn, f"virtual:{NHANES_NAME}")  # made by the build
        fields = list(EVERY_MEASURE)
        stats_table(conn, fields)  # the query grammar is built once per process
        real, real_best = median_ms(lambda: stats_table(conn, fields), args.runs * 4)
        weighted, weighted_best = median_ms(
            lambda: stats_table(conn, fields, weights=weights), args.runs * 4
        )
        print(f"stats, every measure, 6,068 real people: {real:.0f} ms (best {real_best:.0f})")
        print(
            f"stats, every measure, the 8,381 virtual people weighted: {weighted:.0f} ms "
            f"(best {weighted_best:.0f}); goal < 300 ms"
        )
        conn.close()


if __name__ == "__main__":
    main()
