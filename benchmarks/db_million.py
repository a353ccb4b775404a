"""Database benchmark on 1,000,000 generated people: the report's sample query
and fetching one individual.  The database is generated here, in a temporary
directory, and deleted afterwards (never committed).  Run:
    python benchmarks/db_million.py [PEOPLE]

Each person has global data, every girth row (relation and query table) and
one isometric strength experiment with its elbow row; joint limits, centers
of mass and the shoulder / wrist rows are left out to keep the build to
about two minutes (the query does not read them).
"""

from __future__ import annotations

import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from sass_tui.db.engine.schema import connect, transaction
from sass_tui.db.people.individual import fetch_individual
from sass_tui.db.people.people_store import PeopleBatch, girth_mass_fractions, store_people
from sass_tui.db.query.query import run_query
from sass_tui.model import datasets
from sass_tui.model.files.popfile import read_population_file
from sass_tui.model.names import GIRTH, GLOBAL
from sass_tui.model.population.percentile import Z95

SAMPLE = (
    "gender = male AND girth.right_upper_arm.z > 28 cm AND strength.elbow_flexion.max > 20 ft-lb"
)
CHUNK = 50_000


def at_z(stats: np.ndarray, z: np.ndarray) -> np.ndarray:
    """percentile_arrays.value_at, but from the normal score directly: value_at's
    quantile function runs per element in Python, too slow for 75 million cells."""
    z = np.clip(z, -2.576, 2.576)  # the 0.5-99.5 percentile range
    v5, v50, v95 = stats[..., 0], stats[..., 1], stats[..., 2]
    return v50 + z * np.where(z < 0, v50 - v5, v95 - v50) / Z95


def build(conn, people: int, rng: np.random.Generator) -> None:
    girth_stats = read_population_file(datasets.path("girth.dat"), GIRTH)
    glob = read_population_file(datasets.path("global.dat"), GLOBAL)
    with transaction(conn):
        for start in range(0, people, CHUNK):
            n = min(CHUNK, people - start)
            male = rng.random(n) < 0.5
            gender = np.where(male, "male", "female")
            size = rng.standard_normal(n)
            stature = np.empty(n)
            mass = np.empty(n)
            girth = np.empty((n, 25, 4))
            for g, mask in (("male", male), ("female", ~male)):
                k = int(mask.sum())
                st = glob.stats(g)[:, 0, :]
                stature[mask] = at_z(st[0], size[mask])
                mass[mask] = at_z(st[1], 0.6 * size[mask] + 0.8 * rng.standard_normal(k))
                s = girth_stats.stats(g)
                z = 0.6 * size[mask][:, None, None] + 0.8 * rng.standard_normal((k, 25, 3))
                girth[mask, :, :3] = at_z(s, z)
            girth[:, :, 3] = mass[:, None] * girth_mass_fractions()
            elbow = np.where(male, 65.0, 39.0) * np.exp(0.25 * rng.standard_normal(n))
            ids = np.arange(start + 1, start + n + 1)
            batch = PeopleBatch(
                id_num=ids,
                name=[f"GEN_{i}" for i in ids.tolist()],
                gender=gender.tolist(),
                stature=stature,
                mass=mass,
                handedness=["right"] * n,
                age=rng.integers(19, 60, n).astype(float),
                source=["generated benchmark"] * n,
                source_key=[None] * n,
                girth=girth,
                strength_par=[(i, 1, "right", "isometric", 0.0, 0.0, 0.0) for i in range(n)],
                elbow=[
                    (i, 1, 90.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, float(v), float(v) * 0.7)
                    for i, v in enumerate(elbow.tolist())
                ],
            )
            store_people(conn, batch, replace=False)
            print(f"\rbuilt {start + n:,} people", end="", file=sys.stderr, flush=True)
    print(file=sys.stderr)


def main() -> None:
    people = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "million.db"
        conn = connect(path, create=True)
        conn.execute("PRAGMA journal_mode = OFF")
        conn.execute("PRAGMA synchronous = OFF")
        start = time.perf_counter()
        build(conn, people, np.random.default_rng(1988))
        print(
            f"build {people:,} people: {time.perf_counter() - start:.1f} s, "
            f"{path.stat().st_size / 1e9:.2f} GB"
        )
        conn.close()
        conn = connect(path)
        counts, pages, firsts = [], [], []
        for _ in range(5):
            t0 = time.perf_counter()
            query = run_query(conn, SAMPLE)
            n = query.count()
            t1 = time.perf_counter()
            query.page(0, 25)
            t2 = time.perf_counter()
            query.page_after(500_000, 25)
            t3 = time.perf_counter()
            counts.append(t1 - t0)
            firsts.append(t2 - t1)
            pages.append(t3 - t2)
        print(
            f"sample query on {people:,}: {n:,} people; count median {statistics.median(counts):.3f} s "
            f"(runs {', '.join(f'{t:.3f}' for t in counts)}); first page "
            f"{statistics.median(firsts) * 1000:.1f} ms; keyset page deep in the list "
            f"{statistics.median(pages) * 1000:.1f} ms"
        )
        times = []
        for pid in np.random.default_rng(1).integers(1, people + 1, 200).tolist():
            t0 = time.perf_counter()
            fetch_individual(conn, pid)
            times.append(time.perf_counter() - t0)
        print(
            f"fetch one individual: median {statistics.median(times) * 1000:.2f} ms, "
            f"max {max(times) * 1000:.2f} ms (200 people)"
        )
        conn.close()


if __name__ == "__main__":
    main()
