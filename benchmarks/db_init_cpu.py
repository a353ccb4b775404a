"""CPU time of building the default database as `sass db init` does, and of
making the shipped virtual population alone in it, the latter's share of the
former measured in the same run (docs/performance.md, "Virtual civilians
that keep what NHANES measured").  CPU time, not wall time: on 2 shared
cores the wall time of the same build varied 5-15 s within minutes.

    python benchmarks/db_init_cpu.py [--runs N]

Compare two checkouts by running it with PYTHONPATH=CHECKOUT, alternately.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.default import create_default_database
from sass_tui.db.populations.virtual import make_virtual, shipped_sample
from sass_tui.model.datasets import NHANES_NAME


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--runs", type=int, default=3)
    args = parser.parse_args()
    builds, virtuals = [], []
    for _ in range(args.runs):
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "sass.db"
            start = time.process_time()
            create_default_database(path)
            builds.append(time.process_time() - start)
            conn = connect(path)
            sample = shipped_sample()
            start = time.process_time()
            make_virtual(conn, NHANES_NAME, sample, NHANES_NAME)
            virtuals.append(time.process_time() - start)
            conn.close()
    build, virtual = statistics.median(builds), statistics.median(virtuals)
    print(f"build the default database (CPU): {build:.2f} s median of {args.runs}")
    print(f"make the shipped virtual population in it (CPU, not stored): {virtual:.2f} s")
    print(f"virtual / build = {virtual / build:.3f}")


if __name__ == "__main__":
    main()
