"""Speed of `sass predict` (target: a prediction ≤ 5 ms once the fit is cached).

    python benchmarks/predict.py [--db PATH]     (default: the default database, ANSUR II)

Times, on the database's people:
- the fit (load every value from SQLite, fit both genders), the cache key
  (computed: SQL totals; and again, the file unchanged since: its header read),
  loading the cached fit, and `open_predictor` with a current cache, both ways;
- one prediction from stature + mass (male), with and without 5 nearest people,
  and the first one from those names (the residual spread model fitted);
- a batch of 10,000 rows (stature + mass, 5 % of the masses missing) with
  `Predictor.predict_matrix`, and through `sass predict --input/--output`.
Baselines measured in the same run: numpy least squares of every field on
[1, stature, mass] over the same people (`np.linalg.lstsq`, what a model
without the conditional-normal trick would solve per set of known names),
and applying those coefficients to 10,000 rows.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np

from sass_tui.cli.predict import predict_csv
from sass_tui.db.people.default import open_database
from sass_tui.db.populations import predict
from sass_tui.db.populations.predict import cache_path, data_key, fit_predictor, open_predictor
from sass_tui.model.population.prediction import Predictor


def best_of(fn, number: int, repeat: int = 5) -> tuple[float, float]:
    times = [t / number for t in timeit.repeat(fn, number=number, repeat=repeat)]
    return min(times), statistics.median(times)


def row(what: str, timing: tuple[float, float], baseline: tuple[float, float] | None = None):
    best, median = timing
    ratio = f"{best / baseline[0]:.2f}" if baseline else ""
    print(f"| {what} | {best * 1e3:.3f} ms | {median * 1e3:.3f} ms | {ratio} |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--db", metavar="PATH")
    args = parser.parse_args()
    conn = open_database(args.db)
    key = data_key(conn)
    predictor = fit_predictor(conn, key)
    male = predictor.model("male")
    index = male.index()
    columns = [index["stature"], index["mass"]]
    people = male.scores.astype(np.float64) * male.sd + male.mean
    x = np.column_stack([np.ones(male.n), people[:, columns]])

    def lstsq() -> np.ndarray:
        return np.linalg.lstsq(x, people, rcond=None)[0]

    coefficients = lstsq()
    rng = np.random.default_rng(1)
    rows = 10_000
    known = np.column_stack([rng.normal(175.5, 7.0, rows), rng.normal(85.0, 12.0, rows)])
    known[rng.random(rows) < 0.05, 1] = np.nan
    complete = np.column_stack([np.ones(rows), np.nan_to_num(known, nan=85.0)])

    print(f"database: {conn.execute('PRAGMA database_list').fetchone()[2]}")
    print(f"people: male {male.n}, female {predictor.model('female').n}; fields {len(male.fields)}")
    print("| what | best | median | ratio to baseline |")
    print("| --- | ---: | ---: | ---: |")
    base_fit = best_of(lstsq, 20)
    row("baseline: `np.linalg.lstsq`, every field on [1, stature, mass], male", base_fit)
    row(
        "fit: load every value from SQLite and fit both genders",
        best_of(lambda: fit_predictor(conn, key), 1, 3),
        base_fit,
    )

    def key_computed() -> str:
        predict._KEYS.clear()  # what this process remembered: a first open
        return data_key(conn)

    row("cache key, computed (SQL totals)", best_of(key_computed, 5), base_fit)
    row(
        "cache key, the file unchanged since (its header read)",
        best_of(lambda: data_key(conn), 5),
        base_fit,
    )
    path = cache_path(conn)
    with tempfile.TemporaryDirectory() as tmp:
        saved = predictor.save(Path(tmp) / "bench.predict.npz")
        row("load the cached fit (.npz)", best_of(lambda: Predictor.load(saved, key), 10), base_fit)
        save_time = best_of(lambda: predictor.save(Path(tmp) / "bench.predict.npz"), 3, 3)
        row("save the fit (.npz, fsync)", save_time, base_fit)
    if path is not None:
        open_predictor(conn)  # make the cache current
        row(
            "`open_predictor` with a current cache, the key computed (key + load)",
            best_of(lambda: (predict._KEYS.clear(), open_predictor(conn)), 5),
            base_fit,
        )
        row(
            "`open_predictor` with a current cache, the file unchanged since",
            best_of(lambda: open_predictor(conn), 5),
            base_fit,
        )
    one = {"stature": 175.5, "mass": 82.2}
    base_one = best_of(lambda: np.array([1.0, 175.5, 82.2]) @ lstsq(), 50)
    row("baseline: lstsq fit + one row", base_one)
    row(
        "one prediction (stature + mass, male)",
        best_of(lambda: predictor.predict("male", one), 500),
        base_one,
    )
    row(
        "first prediction from new known names (fits their spread model, kept for the next)",
        best_of(lambda: Predictor(predictor.models).predict("male", one), 10),
        base_one,
    )
    row(
        "one prediction + 5 nearest people",
        best_of(lambda: predictor.predict("male", one, nearest=5), 200),
        base_one,
    )
    row(
        "leave-one-out RMSE of every field (`cv_rmse`, JSON output)",
        best_of(lambda: predictor.cv_rmse("male", one), 20),
        base_one,
    )
    base_batch = best_of(lambda: complete @ coefficients, 20)
    row(f"baseline: {rows:,} rows × fitted coefficients (matmul)", base_batch)
    row(
        f"batch of {rows:,} rows (`predict_matrix`)",
        best_of(lambda: predictor.predict_matrix("male", ["stature", "mass"], known), 3),
        base_batch,
    )
    with tempfile.TemporaryDirectory() as tmp:
        source = Path(tmp) / "known.csv"
        text = "id,stature,mass\n" + "".join(
            f"{i},{s:.1f},{'' if np.isnan(m) else f'{m:.1f}'}\n" for i, (s, m) in enumerate(known)
        )
        source.write_text(text)
        target = str(Path(tmp) / "predicted.csv")
        start = time.perf_counter()
        predict_csv(predictor, "male", str(source), target)
        elapsed = time.perf_counter() - start
        row(f"batch CSV of {rows:,} rows (read, predict, write)", (elapsed, elapsed), base_batch)
    conn.close()


if __name__ == "__main__":
    main()
