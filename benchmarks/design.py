"""`sass design` benchmark on the shipped virtual population (docs/performance.md,
"Design limits").

    python benchmarks/design.py [--db PATH] [--runs N]

Without --db it builds the default database in a temporary directory.  In
process, median of N runs, over the 8,381 virtual people of nhanes-2017-2020
weighted by their survey's weights:
- the seat of docs/accommodation.md with three limits and four unknowns
  (popliteal height range, buttock-popliteal length, hip breadth sitting)
  solved for 95 % and checked by the fit test -- goal under 1 s;
- against a baseline measured in the same run: `sass fit` of the solved
  limits (the check alone), so the ratio says what solving costs beyond it.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from fit import median_ms  # benchmarks/fit.py: the one timing helper

from sass_tui.db.engine.schema import connect
from sass_tui.db.populations.design import design
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.shipped import load_weights

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from scripts.default_database import add_db_option, default_database

SEAT = (
    "measure.poplitealheight BETWEEN ? AND ? AND measure.buttockpopliteallength >= ? "
    "AND measure.hipbreadthsitting <= ?"
)
VIRTUAL = "virtual:nhanes-2017-2020"


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    parser.add_argument("--runs", type=int, default=10)
    args = parser.parse_args()
    with default_database(args.db) as (path, _out):
        conn = connect(path)
        target = load_weights(conn, VIRTUAL)
        people = target.target.population
        solved = design(conn, SEAT, 95.0, people, None, target)  # warm: grammar, caches
        limits = " AND ".join(solved.texts)
        base, base_best = median_ms(
            lambda: fit_test(conn, limits, people, target=target), args.runs
        )
        whole, whole_best = median_ms(
            lambda: design(conn, SEAT, 95.0, people, None, target), args.runs
        )
        print(f"solved: {limits}: {solved.fit.weighted_percent:.2f} %")
        print(f"baseline: sass fit of the solved limits: {base:.1f} ms (best {base_best:.1f})")
        print(
            f"sass design, 3 limits, 4 unknowns, 8,381 virtual people: {whole:.1f} ms "
            f"(best {whole_best:.1f}), {whole / base:.1f} x the baseline; goal < 1000 ms"
        )
        conn.close()


if __name__ == "__main__":
    main()
