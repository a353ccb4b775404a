"""Target-population benchmark on ANSUR II (the default database).

    python benchmarks/target.py [--db PATH] [--runs N]

Without --db it builds the default database in a temporary directory.  In
process, median of N runs (docs/performance.md, "Target populations"):
- making a target from a 10,000-row sample (civilian-like women, stature in
  inches in the header, mass in kg): read and parse the CSV, load the 1,986
  ANSUR II women, calibrate, store the weights (replacing the last run's);
- a weighted fit test of the seat (docs/accommodation.md) on that target,
  beside the same fit test unweighted, measured in the same run.
The goal: each under 0.5 s.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from fit import median_ms  # benchmarks/fit.py: the one timing helper of both

from sass_tui.db.engine.schema import connect
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.targets import load_target, make_target, store_target
from sass_tui.model.files.sample_file import read_sample

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from scripts.default_database import add_db_option, default_database  # noqa: E402
from scripts.target_accuracy import civilian_women  # noqa: E402

SEAT = (
    "stature <= 190 cm AND measure.sittingheight <= 100 cm "
    "AND measure.hipbreadthsitting <= 45 cm AND mass <= 110 kg"
)
ROWS = 10_000


def sample_text(rows: int) -> str:
    """Heavier, shorter women than ANSUR II's (scripts/target_accuracy.py's)."""
    values = civilian_women(rows, seed=1)
    lines = ["id,stature[in],mass[kg]"]
    lines += [f"{i},{s / 2.54:.3f},{m:.2f}" for i, (s, m) in enumerate(values)]
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    parser.add_argument("--runs", type=int, default=10)
    args = parser.parse_args()
    with default_database(args.db) as (path, tmp):
        conn = connect(path)
        csv_path = tmp / "sample.csv"
        csv_path.write_text(sample_text(ROWS), encoding="utf-8")

        def make() -> None:
            text = csv_path.read_text(encoding="utf-8")
            sample = read_sample(text, ["stature", "mass"], str(csv_path))
            _target, weights, _w = make_target(conn, "bench", "female", sample, str(csv_path))
            store_target(conn, weights, replace=True)

        made, made_best = median_ms(make, args.runs)
        print(
            f"make a target from {ROWS:,} sample rows (read, calibrate 1,986 women, store): "
            f"{made:.1f} ms (best {made_best:.1f}); goal < 500 ms"
        )
        fit_test(conn, SEAT)  # the query grammar is built once per process
        plain, plain_best = median_ms(lambda: fit_test(conn, SEAT), args.runs)
        weighted, weighted_best = median_ms(
            lambda: fit_test(conn, SEAT, target=load_target(conn, "bench")), args.runs
        )
        print(f"fit test, seat, unweighted (6,068 people): {plain:.1f} ms (best {plain_best:.1f})")
        print(
            f"fit test, seat, weighted to the target (load its weights, 1,986 women): "
            f"{weighted:.1f} ms (best {weighted_best:.1f}); goal < 500 ms"
        )
        conn.close()


if __name__ == "__main__":
    main()
