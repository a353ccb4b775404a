"""The default database (ANSUR II + the synthetic people): build time, a
`measure.*` query and load_values, each with a baseline measured in the same
run.  Run:  python benchmarks/db_default.py   (prints the lines for
docs/performance.md, "Default database")."""

from __future__ import annotations

import gzip
import os
import platform
import statistics
import tempfile
import time
from pathlib import Path

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.default import create_default_database
from sass_tui.db.people.default_people import shipped_ansur_files
from sass_tui.db.people.values import load_values
from sass_tui.db.query.query import run_query
from sass_tui.model.measures import MEASURES

QUERIES = [
    "measure.sittingheight > 95 cm",
    "gender = female AND measure.weightkg < 60 kg AND branch = 'Combat Arms'",
    "measure.span > 190 cm OR measure.footlength > 30 cm",
]


def timed(func, repeat: int) -> list[float]:
    out = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        out.append(time.perf_counter() - start)
    return out


def ms(values: list[float]) -> str:
    return f"{statistics.median(values) * 1000:.1f} ms"


def main() -> None:
    print(
        f"machine: {platform.machine()}, {os.cpu_count()} cores, Python {platform.python_version()}"
    )
    with tempfile.TemporaryDirectory() as tmp:
        fresh = []
        for k in range(3):
            path = Path(tmp) / f"d{k}.db"
            start = time.perf_counter()
            create_default_database(path)
            fresh.append(time.perf_counter() - start)
        rebuild = timed(lambda: create_default_database(path, replace=True), 3)
        # Baseline: reading and decompressing the two shipped files alone.
        read = timed(lambda: [gzip.decompress(f.read_bytes()) for f in shipped_ansur_files()], 3)
        print(
            f"build the default database (6,068 ANSUR II + 200 synthetic people), new file: "
            f"median {statistics.median(fresh):.2f} s (runs {', '.join(f'{t:.2f}' for t in fresh)})"
        )
        print(
            f"rebuild in place over an existing one (db init --force): "
            f"median {statistics.median(rebuild):.2f} s"
        )
        print(f"  baseline, reading the two .gz files: {ms(read)}")
        conn = connect(path)
        for text in QUERIES:

            def query(text: str = text) -> None:
                q = run_query(conn, text)
                q.count()
                q.page(0, 25)

            times = timed(query, 20)
            print(f"count + first page, {ms(times)} median of 20: {text}")
        baseline = timed(lambda: conn.execute("SELECT count(*) FROM person").fetchone(), 20)
        print(f"  baseline, SELECT count(*) FROM person: {ms(baseline)}")
        fields = [f"measure.{m}" for m in MEASURES]
        load = timed(lambda: load_values(conn, fields, "source = ansur2"), 10)
        columns = ", ".join(f"m.{name}" for name in MEASURES)
        plain = timed(
            lambda: conn.execute(
                f"SELECT p.id_num, p.name, p.gender, {columns} FROM person p "
                "JOIN measure m ON m.id_num = p.id_num WHERE p.source = 'ansur2'"
            ).fetchall(),
            10,
        )
        print(
            f"load_values, all 93 measures of the 6,068 ANSUR II people: {ms(load)} median of 10; "
            f"baseline, fetching the same cells as rows: {ms(plain)} "
            f"(ratio {statistics.median(load) / statistics.median(plain):.2f})"
        )
        conn.close()


if __name__ == "__main__":
    main()
