"""Fit test and manikin-family benchmark on ANSUR II (the default database).

    python benchmarks/fit.py [--db PATH] [--runs N]

Without --db it builds the default database in a temporary directory.  In
process, median of N runs:
- the seat's fit test (docs/accommodation.md) over the 6,068 ANSUR II people,
  against a baseline measured in the same run: `sass query`'s count of the
  same limits (one plain SELECT count(*));
- a boundary family of k = 3 (stature, mass, sitting height; 15 manikins,
  each completed by the prediction model, .fig + .x3d each, family.json),
  against a baseline measured in the same run: one figure written the way
  `sass fig` + `sass export hanim` write it (Figure.default, .fig, .x3d).
The targets: fit test <= 50 ms, family with its 15 figures <= 2 s.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

from sass_tui.db.engine.schema import connect
from sass_tui.db.populations.family import load_family
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.predict import open_predictor
from sass_tui.db.query.query import run_query
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.family_files import write_family
from sass_tui.model.files.figfile import write_fig
from sass_tui.model.files.hanim_x3d import export_hanim

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from scripts.default_database import add_db_option, default_database

SEAT = (
    "stature <= 190 cm AND measure.sittingheight <= 100 cm "
    "AND measure.hipbreadthsitting <= 45 cm AND mass <= 110 kg"
)
FAMILY = ["stature", "mass", "sittingheight"]


def median_ms(func: Callable[[], object], runs: int) -> tuple[float, float]:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        func()
        times.append((time.perf_counter() - start) * 1000)
    return statistics.median(times), min(times)


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    parser.add_argument("--runs", type=int, default=20)
    args = parser.parse_args()
    with default_database(args.db) as (path, out):
        conn = connect(path)
        fit_test(conn, SEAT)  # the query grammar is built once per process
        base, base_best = median_ms(lambda: run_query(conn, SEAT).count(), args.runs)
        fit, fit_best = median_ms(lambda: fit_test(conn, SEAT), args.runs)
        print(
            f"baseline: count of the seat's limits (one SELECT): {base:.2f} ms (best {base_best:.2f})"
        )
        print(
            f"fit test, seat, 6,068 ANSUR II people: {fit:.2f} ms (best {fit_best:.2f}), "
            f"{fit / base:.1f} x the baseline; target <= 50 ms"
        )
        start = time.perf_counter()
        open_predictor(conn)
        print(
            f"prediction model, first use (fit and cache beside the database): "
            f"{(time.perf_counter() - start) * 1000:.0f} ms"
        )
        family_runs = max(3, args.runs // 4)

        def one_figure() -> None:
            figure = Figure.default("female")
            write_fig(figure, out / "one.fig")
            export_hanim(figure, out / "one.x3d")

        def family() -> None:
            built = load_family(conn, "female", FAMILY, 0.9)
            write_family(built, out / "family", Figure.default("female"))

        single, single_best = median_ms(one_figure, family_runs)
        whole, whole_best = median_ms(family, family_runs)
        files = len(list((out / "family").iterdir()))
        print(f"baseline: one figure, .fig + .x3d: {single:.1f} ms (best {single_best:.1f})")
        print(
            f"family k = 3, 15 manikins ({files} files), cached model: {whole:.0f} ms "
            f"(best {whole_best:.0f}), {whole / single:.1f} x one figure; target <= 2000 ms"
        )
        conn.close()


if __name__ == "__main__":
    main()
