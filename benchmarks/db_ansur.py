"""Database benchmark on ANSUR II: import time of both files, query latency,
time to fetch one individual.  Run:  python benchmarks/db_ansur.py
(needs ../shared/data/ansur2; prints the figures for docs/performance.md)."""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.ansur import import_ansur
from sass_tui.db.people.individual import fetch_individual
from sass_tui.db.query.query import run_query

ANSUR = Path(__file__).resolve().parents[1].parent / "shared" / "data" / "ansur2"
FILES = [ANSUR / "ANSUR_II_MALE_Public.csv", ANSUR / "ANSUR_II_FEMALE_Public.csv"]
QUERIES = [
    "gender = male AND girth.right_upper_arm.z > 28 cm",
    "stature >= 70 in AND mass < 80 kg",
    "(handedness = either OR handedness = left) AND gender = female",
    "gender = male AND (girth.right_upper_leg.x > 20 cm OR girth.neck.y < 12 cm) AND age >= 30",
]


def timed(func, repeat: int) -> list[float]:
    out = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        out.append(time.perf_counter() - start)
    return out


def main() -> None:
    if not all(f.is_file() for f in FILES):
        sys.exit("../shared/data/ansur2 is absent")
    with tempfile.TemporaryDirectory() as tmp:
        imports = []
        for k in range(3):
            conn = connect(Path(tmp) / f"a{k}.db", create=True)
            start = time.perf_counter()
            import_ansur(conn, FILES)
            imports.append(time.perf_counter() - start)
            if k < 2:
                conn.close()
        print(
            f"import both ANSUR II files (6,068 people): median {statistics.median(imports):.2f} s "
            f"(runs {', '.join(f'{t:.2f}' for t in imports)})"
        )
        for text in QUERIES:

            def run():
                q = run_query(conn, text)
                q.count()
                q.page(0, 25)

            times = timed(run, 20)
            print(
                f"query count + first page, {statistics.median(times) * 1000:.1f} ms median: {text}"
            )
        ids = [r[0] for r in conn.execute("SELECT id_num FROM person ORDER BY random() LIMIT 200")]
        times = []
        for pid in ids:
            start = time.perf_counter()
            fetch_individual(conn, pid)
            times.append(time.perf_counter() - start)
        print(
            f"fetch one individual: median {statistics.median(times) * 1000:.2f} ms, "
            f"max {max(times) * 1000:.2f} ms (200 people)"
        )
        conn.close()


if __name__ == "__main__":
    main()
