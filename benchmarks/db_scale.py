"""Database at scale: the report's sample query counted on 1,000,000 and
5,000,000 generated people, several ways side by side in one run, and
fetching one individual at 1,000,000, cold and warm.  Run:
    python benchmarks/db_scale.py [--cache DIR] [--sizes 1000000,5000000] [--fetch-only]
    python benchmarks/db_scale.py --log-cost

The count:
- SQLite as before: `Query.count()` on a connection with the file mapped
  (PRAGMA mmap_size, as connect() did before this benchmark's change);
- SQLite now: the same on a connection as connect() gives now (read()),
  which is what answers whenever the column copy cannot;
- column copy: `Query.count()` answered by sass_tui/db/accelerator.py, warm
  (the copy built), plus its one-off build and its first load in a new process;
- DuckDB (if installed: `pip install -e '.[bench]'`) over Parquet files of
  the same data: the same three-table join, and the three columns pre-joined.

The databases are built once into DIR (default /tmp/sass_scale; never
committed) and reused by later runs: 1M with benchmarks/db_million.py's
generator (~3-5 min), 5M by copying the 1M file and replicating every person
table four times in SQL with id offsets (~9 min; the people repeat, the
sizes are real).  Disk: 2.7 GB + 13.4 GB.
"""

from __future__ import annotations

import argparse
import gc
import os
import platform
import resource
import shutil
import sqlite3
import statistics
import sys
import time
from pathlib import Path

import numpy as np
from db_million import SAMPLE, build

from sass_tui.db import accelerator
from sass_tui.db.individual import _fetch_individual, fetch_individual
from sass_tui.db.lists import QueryLists
from sass_tui.db.query import run_query
from sass_tui.db.schema import PERSON_TABLES, connect, delete_people

MILLION = 1_000_000
MAPPED = 17179869184  # connect()'s memory map before this change (PRAGMA mmap_size)


def _fast_writes(conn: sqlite3.Connection) -> None:
    conn.execute("PRAGMA journal_mode = OFF")
    conn.execute("PRAGMA synchronous = OFF")


def build_million(path: Path) -> None:
    tmp = path.with_suffix(".building")
    tmp.unlink(missing_ok=True)
    conn = connect(tmp, create=True)
    _fast_writes(conn)
    start = time.perf_counter()
    build(conn, MILLION, np.random.default_rng(1988))
    conn.close()
    tmp.rename(path)
    print(f"built {path} in {time.perf_counter() - start:.0f} s", file=sys.stderr)


def copied_columns(conn: sqlite3.Connection, table: str, new_id: str) -> tuple[str, str]:
    """The columns of `table`, and what to SELECT to copy a row under the id
    `new_id` (an SQL expression): a name of its own, no source key."""
    columns = [r[1] for r in conn.execute(f"PRAGMA table_info({table})")]
    select = [
        new_id
        if c == "id_num"
        else f"'GEN_' || ({new_id})"
        if (table, c) == ("person", "name")
        else "NULL"
        if (table, c) == ("person", "source_key")
        else c
        for c in columns
    ]
    return ", ".join(columns), ", ".join(select)


def build_replicated(source: Path, path: Path, copies: int) -> None:
    """`copies` x the people of `source` (ids 1..1M), each copy's ids offset by k x 1M."""
    tmp = path.with_suffix(".building")
    shutil.copyfile(source, tmp)
    conn = connect(tmp)
    _fast_writes(conn)
    start = time.perf_counter()
    conn.execute("BEGIN")
    for k in range(1, copies):
        offset = k * MILLION
        for table in ("person",) + PERSON_TABLES:
            columns, select = copied_columns(conn, table, f"id_num + {offset}")
            conn.execute(
                f"INSERT INTO {table} ({columns}) "
                f"SELECT {select} FROM {table} WHERE id_num <= {MILLION}"
            )
        print(f"\rreplicated {k + 1} x 1M", end="", file=sys.stderr, flush=True)
    conn.execute("COMMIT")
    conn.close()
    tmp.rename(path)
    print(f"\nbuilt {path} in {time.perf_counter() - start:.0f} s", file=sys.stderr)


def database(cache: Path, people: int) -> Path:
    cache.mkdir(parents=True, exist_ok=True)
    million = cache / "people_1000000.db"
    if not million.exists():
        build_million(million)
    if people == MILLION:
        return million
    path = cache / f"people_{people}.db"
    if not path.exists():
        build_replicated(million, path, people // MILLION)
    return path


def median_time(fn, runs: int = 5) -> tuple[float, object]:
    times, result = [], None
    for _ in range(runs):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times), result


def sqlite_count(conn: sqlite3.Connection) -> int:
    saved = accelerator.MIN_PEOPLE
    accelerator.MIN_PEOPLE = 1 << 62  # the accelerator off: SQLite answers
    try:
        return run_query(conn, SAMPLE).count()
    finally:
        accelerator.MIN_PEOPLE = saved


def parquet_files(conn: sqlite3.Connection, cache: Path, people: int, store) -> dict[str, Path]:
    """The sample query's three tables as Parquet (each table's own rows), and
    the three columns pre-joined in one file, written by DuckDB from the data
    read out of SQLite (DuckDB cannot read the SQLite file here)."""
    import duckdb

    folder = cache / f"parquet_{people}"
    files = {
        name: folder / f"{name}.parquet"
        for name in ("person", "q_girth_right_upper_arm", "q_strength_elbow_flexion", "joined")
    }
    shutil.rmtree(folder, ignore_errors=True)  # the database changes at every run
    folder.mkdir(parents=True, exist_ok=True)
    ids = np.asarray(store.ids)
    gender = store.columns[("person", "gender")]
    gender_text = np.asarray(gender.words, dtype=object)[np.asarray(gender.codes)]
    z = np.asarray(store.columns[("q_girth_right_upper_arm", "z")])
    elbow = np.asarray(store.columns[("q_strength_elbow_flexion", "max")])
    duck = duckdb.connect()
    tables = {
        "person": {"id_num": ids, "gender": gender_text},
        "q_girth_right_upper_arm": {"id_num": ids[~np.isnan(z)], "z": z[~np.isnan(z)]},
        "q_strength_elbow_flexion": {
            "id_num": ids[~np.isnan(elbow)],
            "max": elbow[~np.isnan(elbow)],
        },
        "joined": {"id_num": ids, "gender": gender_text, "z": z, "max": elbow},
    }
    for name, frame in tables.items():
        duck.register("frame", frame)
        # NaN is "no value" in the arrays; in DuckDB NaN sorts above every number, NULL does not.
        columns = ", ".join(
            f"CASE WHEN isnan({c}) THEN NULL ELSE {c} END AS {c}"
            if frame[c].dtype == np.float64
            else c
            for c in frame
        )
        tmp = files[name].with_suffix(".tmp")
        duck.execute(f"COPY (SELECT {columns} FROM frame) TO '{tmp}' (FORMAT parquet)")
        duck.unregister("frame")
        os.replace(tmp, files[name])
    duck.close()
    return files


def duckdb_counts(files: dict[str, Path], compiled) -> dict[str, tuple[float, int]]:
    import duckdb

    duck = duckdb.connect()
    for name, path in files.items():
        duck.execute(f"CREATE VIEW {name} AS SELECT * FROM read_parquet('{path}')")
    same_sql = f"SELECT count(*) FROM {compiled.from_clause()} WHERE {compiled.where}"
    joined_sql = "SELECT count(*) FROM joined WHERE gender = ? AND z > ? AND max > ?"
    out = {}
    for label, sql in (("join", same_sql), ("joined", joined_sql)):
        duck.execute(sql, list(compiled.params)).fetchone()  # warm
        out[label] = median_time(lambda: duck.execute(sql, list(compiled.params)).fetchone()[0])
    duck.close()
    return out


def fetch_before(conn: sqlite3.Connection, id_num: int) -> None:
    """fetch_individual as it was before this benchmark's change (the baseline):
    one query per relation and one per strength query table, 22 in all."""
    from sass_tui.db.schema import QUERY_TABLES, STRENGTH_PARAMETERS

    conn.execute(
        "SELECT id_num, name, gender, stature, mass, handedness, age, source "
        "FROM person WHERE id_num = ?",
        (id_num,),
    ).fetchone()
    for sql in (
        "SELECT seg_name, thickness, width, length, mass FROM girth WHERE id_num = ?",
        "SELECT seg_name, jlimit_x, jlimit_y, jlimit_z FROM joint_limits WHERE id_num = ?",
        "SELECT seg_name, cmass_x, cmass_y, cmass_z FROM center_of_mass WHERE id_num = ?",
        f"SELECT {', '.join(STRENGTH_PARAMETERS)} FROM strength_q WHERE id_num = ?",
        *(f"SELECT max FROM {t} WHERE id_num = ?" for t in QUERY_TABLES["strength"].values()),
        "SELECT * FROM strength_par WHERE id_num = ? ORDER BY exp_num",
        "SELECT * FROM shoulder_strgh WHERE id_num = ? ORDER BY exp_num, axis",
        "SELECT * FROM elbow_strgh WHERE id_num = ? ORDER BY exp_num",
        "SELECT * FROM wrist_strgh WHERE id_num = ? ORDER BY exp_num, axis",
    ):
        conn.execute(sql, (id_num,)).fetchall()


def _queue_wait() -> float:
    """Seconds this thread has waited for a core, runnable (Linux schedstat; 0 elsewhere)."""
    try:
        with open("/proc/thread-self/schedstat") as f:
            return int(f.read().split()[1]) / 1e9
    except (OSError, IndexError, ValueError):
        return 0.0


def fetch_times(conn: sqlite3.Connection, fetch, stored: np.ndarray, seed: int):
    """Wall time, this thread's CPU time and its time waiting for a core of
    each fetch, and the blocks read from disk (the rest of the wall time is
    blocked on the disk)."""
    walls, cpus, queued, faults = [], [], [], 0
    for pid in np.random.default_rng(seed).choice(stored, 200, replace=False).tolist():
        before = resource.getrusage(resource.RUSAGE_SELF).ru_inblock
        q0, c0, t0 = _queue_wait(), time.thread_time(), time.perf_counter()
        fetch(conn, pid)
        walls.append(time.perf_counter() - t0)
        cpus.append(time.thread_time() - c0)
        queued.append(_queue_wait() - q0)
        faults += resource.getrusage(resource.RUSAGE_SELF).ru_inblock - before
    return walls, cpus, queued, faults


def small_write(conn: sqlite3.Connection, people: int, seed: int) -> None:
    """Import 10 people (copies of 10 others under new ids, every table, in
    SQL as an import writes them) and delete 10 others through sass, in one
    transaction."""
    rng = np.random.default_rng(seed)
    picked = rng.choice(np.arange(1, people + 1), 20, replace=False).tolist()
    copied, deleted = picked[:10], picked[10:]
    top = conn.execute("SELECT max(id_num) FROM person").fetchone()[0]
    conn.execute("BEGIN IMMEDIATE")
    for k, id_num in enumerate(copied, 1):
        for table in ("person",) + PERSON_TABLES:
            columns, select = copied_columns(conn, table, str(top + k))
            conn.execute(
                f"INSERT INTO {table} ({columns}) SELECT {select} FROM {table} WHERE id_num = ?",
                (id_num,),
            )
    delete_people(conn, deleted)
    conn.execute("COMMIT")


def after_write_times(conn: sqlite3.Connection, people: int) -> dict:
    """The first count after a small write: followed through the change log
    (now), in this process and in a new one (the disk copy older than the
    write), against building the copy anew (before: every write did that)."""
    out = {}
    accelerator.BACKGROUND = True
    small_write(conn, people, seed=1)
    t0 = time.perf_counter()
    out["now"] = run_query(conn, SAMPLE).count()
    out["now_s"] = time.perf_counter() - t0
    assert out["now"] == sqlite_count(conn), out
    accelerator.wait()  # the background save of the patched copy, outside the timing
    small_write(conn, people, seed=2)
    accelerator._STORES.clear()  # a new process: the copy on disk is one write old
    t0 = time.perf_counter()
    out["new_process"] = run_query(conn, SAMPLE).count()
    out["new_process_s"] = time.perf_counter() - t0
    assert out["new_process"] == sqlite_count(conn), out
    accelerator.wait()
    small_write(conn, people, seed=3)
    accelerator.BACKGROUND = False
    accelerator._STORES.clear()
    shutil.rmtree(accelerator.CACHE_DIR, ignore_errors=True)  # as before: build it all
    t0 = time.perf_counter()
    out["rebuild"] = run_query(conn, SAMPLE).count()
    out["rebuild_s"] = time.perf_counter() - t0
    assert out["rebuild"] == sqlite_count(conn), out
    return out


def list_times(path: Path) -> tuple[float, float, int]:
    """Query DB's list (QueryLists.run) of the sample query: SQLite's INSERT ...
    SELECT against the copy's ids inserted through json_each (copy warm)."""
    lists = QueryLists.open(path)
    saved = accelerator.MIN_PEOPLE
    try:
        accelerator.MIN_PEOPLE = 1 << 62
        sql_time, sql_n = median_time(lambda: lists.run(SAMPLE), runs=3)
        accelerator.MIN_PEOPLE = saved
        lists.run(SAMPLE)
        copy_time, copy_n = median_time(lambda: lists.run(SAMPLE), runs=3)
    finally:
        accelerator.MIN_PEOPLE = saved
        lists.close()
    assert sql_n == copy_n, (sql_n, copy_n)
    return sql_time, copy_time, int(copy_n)  # type: ignore[call-overload]


LOG_VARIANTS = (
    "schema 3: every row logged by its trigger",
    "the quiet flag only (triggers fire, stop at the WHEN)",
    "now: the flag, triggers dropped from 2,000 people",
    "no change log (triggers dropped)",
)


def _log_variant(conn: sqlite3.Connection, label: str) -> None:
    """Make a new file's triggers those of the variant (schema 4's are there)."""
    from sass_tui.db.schema import QUIET_WHEN, change_log_triggers

    for name, sql in change_log_triggers().items():
        conn.execute(f"DROP TRIGGER {name}")
        if label.startswith("schema 3"):  # as schema 3 wrote it: never quiet
            conn.execute(sql.replace(f"{QUIET_WHEN}AND ", ""))
        elif label.startswith(("now", "the quiet")):
            conn.execute(sql)


def log_cost(people: int = 50_000, runs: int = 3) -> None:
    """What the change log costs an import: storing `people` generated people
    (db_million's generator, ~45 logged rows each) and importing both ANSUR II
    files (6,068 people, every measurement), with schema 3's triggers (every
    row logged), with schema 4's bulk path (triggers quiet, each person
    logged once) and with no triggers; plus opening a connection.  The
    variants interleaved in each run, median of `runs`."""
    import tempfile

    from db_ansur import FILES

    from sass_tui.db import schema
    from sass_tui.db.ansur import import_ansur

    ansur = all(f.is_file() for f in FILES)
    builds: dict[str, list[float]] = {label: [] for label in LOG_VARIANTS}
    imports: dict[str, list[float]] = {label: [] for label in LOG_VARIANTS}
    opens: dict[str, list[float]] = {label: [] for label in LOG_VARIANTS}
    quiet = schema.logged_once.__enter__
    threshold = schema.DROP_TRIGGERS_FROM
    with tempfile.TemporaryDirectory() as tmp:
        for run in range(runs):
            for label in LOG_VARIANTS:
                # schema 3's path had no bulk flag: its store_people let the triggers log
                schema.logged_once.__enter__ = (  # type: ignore[method-assign]
                    quiet if label.startswith(("now", "the quiet")) else lambda self: None
                )
                schema.DROP_TRIGGERS_FROM = 10**9 if label.startswith("the quiet") else threshold
                for kind, times in (("generated", builds), ("ansur", imports)):
                    if kind == "ansur" and not ansur:
                        continue
                    path = Path(tmp) / f"{run}-{label[:4]}-{kind}.db"
                    conn = connect(path, create=True)
                    if kind == "generated":
                        _fast_writes(conn)
                    _log_variant(conn, label)
                    t0 = time.perf_counter()
                    if kind == "generated":
                        build(conn, people, np.random.default_rng(run))
                    else:
                        import_ansur(conn, FILES)
                    times[label].append(time.perf_counter() - t0)
                    conn.close()
                    if kind == "generated":
                        t0 = time.perf_counter()
                        for _ in range(20):
                            c = sqlite3.connect(path)
                            c.execute("SELECT count(*) FROM meta").fetchone()
                            c.close()
                        opens[label].append((time.perf_counter() - t0) / 20)
                    path.unlink()
    # The default build (`sass db init`): the bulk path against every row
    # logged by the triggers (its file is made with schema 4's triggers, whose
    # logging stops at the WHEN only when a bulk write asks it to).
    from sass_tui.db.default import create_default_database

    default: dict[str, list[float]] = {"every row logged": [], "now": []}
    with tempfile.TemporaryDirectory() as tmp:
        for run in range(2 * runs - 1):
            for label in default:
                schema.logged_once.__enter__ = (  # type: ignore[method-assign]
                    quiet if label == "now" else lambda self: None
                )
                t0 = time.perf_counter()
                create_default_database(Path(tmp) / f"{run}-{label[:3]}.db")
                default[label].append(time.perf_counter() - t0)
    schema.logged_once.__enter__ = quiet  # type: ignore[method-assign]
    schema.DROP_TRIGGERS_FROM = threshold
    base = LOG_VARIANTS[0]
    print(
        f"| median of {runs}, interleaved | {people:,} generated people stored | ratio to "
        "schema 3 | ANSUR II imported (both files) | ratio | opening a connection |"
    )
    print("|---|---|---|---|---|---|")
    for label in LOG_VARIANTS:
        gen = statistics.median(builds[label])
        row = f"| {label} | {gen:.2f} s | {gen / statistics.median(builds[base]):.2f} |"
        if ansur:
            imp = statistics.median(imports[label])
            row += f" {imp:.2f} s | {imp / statistics.median(imports[base]):.2f} |"
        else:
            row += " - | - |"
        print(row + f" {statistics.median(opens[label]) * 1000:.2f} ms |")
    every, now = (statistics.median(default[k]) for k in ("every row logged", "now"))
    print(
        f"\nthe default database build (sass db init), median of {2 * runs - 1} interleaved: "
        f"every row logged {every:.3f} s, now {now:.3f} s ({now / every:.2f}x)"
    )


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cache", type=Path, default=Path("/tmp/sass_scale"))
    parser.add_argument("--sizes", default="1000000,5000000")
    parser.add_argument("--fetch-only", action="store_true", help="only the fetch table")
    parser.add_argument("--log-cost", action="store_true", help="only the change log's cost")
    args = parser.parse_args()
    if args.log_cost:
        log_cost()
        return
    if args.fetch_only:
        fetch_table(database(args.cache, MILLION))
        return
    sizes = [int(s) for s in args.sizes.split(",")]
    try:
        import duckdb

        duck_version = duckdb.__version__
    except ImportError:
        duck_version = None
    print(
        f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {platform.machine()}, "
        f"{os.cpu_count()} cores, Python {platform.python_version()}, SQLite "
        f"{sqlite3.sqlite_version}, numpy {np.__version__}, DuckDB {duck_version or 'absent'}"
    )
    print(f"sample query: {SAMPLE}\n")
    results: dict[str, list[str]] = {}

    def note(what: str, value: str) -> None:
        results.setdefault(what, []).append(value)

    for people in sizes:
        path = database(args.cache, people)
        conn = connect(path)
        mapped = connect(path)
        mapped.execute(f"PRAGMA mmap_size = {MAPPED}")
        compiled = run_query(conn, SAMPLE).compiled
        expected = sqlite_count(conn)  # also warms the page cache
        sqlite_count(mapped)
        old_times, now_times = [], []
        for _ in range(5):  # interleaved: the machine's load falls on both alike
            old_times.append(median_time(lambda: sqlite_count(mapped), runs=1)[0])
            now_times.append(median_time(lambda: sqlite_count(conn), runs=1)[0])
        old, now = statistics.median(old_times), statistics.median(now_times)
        accelerator.CACHE_DIR = args.cache / "columns"
        shutil.rmtree(accelerator.CACHE_DIR, ignore_errors=True)
        accelerator._STORES.clear()
        accelerator.BACKGROUND = False  # built in this thread, to time it
        t0 = time.perf_counter()
        first = run_query(conn, SAMPLE).count()
        build_time = time.perf_counter() - t0
        accelerator._STORES.clear()  # as the next process: the copy is read from disk
        t0 = time.perf_counter()
        run_query(conn, SAMPLE).count()
        reload_time = time.perf_counter() - t0
        new, got = median_time(lambda: run_query(conn, SAMPLE).count())
        assert got == first == expected, (got, first, expected)
        note("people", f"{people:,}")
        note("SQLite file", f"{path.stat().st_size / 1e9:.1f} GB")
        note("people matching", f"{expected:,}")
        note("SQLite, file mapped (before), median of 5", f"{old * 1000:.0f} ms")
        note("SQLite, read() (now, where the copy cannot answer)", f"{now * 1000:.0f} ms")
        note("**column copy, warm, median of 5 (now)**", f"**{new * 1000:.1f} ms**")
        note("SQLite before / column copy", f"{old / new:.0f}x")
        note("column copy built from SQLite (first count after a write)", f"{build_time:.1f} s")
        note(
            "column copy read from disk (first count of a new process)",
            f"{reload_time * 1000:.0f} ms",
        )
        if duck_version:
            store = next(iter(accelerator._STORES.values()))
            duck = duckdb_counts(parquet_files(conn, args.cache, people, store), compiled)
            assert all(n == expected for _t, n in duck.values()), duck
            note(
                "DuckDB over Parquet, the same three-table join, median of 5",
                f"{duck['join'][0] * 1000:.1f} ms",
            )
            note(
                "DuckDB over Parquet, the three columns pre-joined, median of 5",
                f"{duck['joined'][0] * 1000:.1f} ms",
            )
        sql_list, copy_list, listed = list_times(path)
        note("Query DB's list (QueryLists.run), SQLite, median of 3", f"{sql_list * 1000:.0f} ms")
        note(
            "**Query DB's list from the column copy, median of 3**",
            f"**{copy_list * 1000:.0f} ms**",
        )
        after = after_write_times(conn, people)
        note(
            "**first count after importing 10 people and deleting 10 (now: patched)**",
            f"**{after['now_s'] * 1000:.0f} ms**",
        )
        note(
            "the same, a new process, the disk copy one write old (patched)",
            f"{after['new_process_s'] * 1000:.0f} ms",
        )
        note(
            "the same, the copy built anew (before: every write)",
            f"{after['rebuild_s']:.1f} s",
        )
        conn.close()
        mapped.close()
    header = results.pop("people")
    print(f"| sample query's count | {' | '.join(header)} |")
    print("|---|" + "---|" * len(header))
    for what, values in results.items():
        print(f"| {what} | {' | '.join(values)} |")
    if MILLION in sizes:
        fetch_table(database(args.cache, MILLION))


def page_cache(path: Path, warm: bool) -> None:
    """Drop the file's pages from the OS page cache (posix_fadvise: this file
    only), or read it all into it."""
    with open(path, "rb") as f:
        if warm:
            while f.read(1 << 24):
                pass
        else:
            os.posix_fadvise(f.fileno(), 0, 0, os.POSIX_FADV_DONTNEED)


def fetch_table(path: Path) -> None:
    print(
        "\nfetch one individual, 200 random people at 1,000,000, a new connection "
        "and fresh random ids for each line; cold: the file dropped from the page "
        "cache first, warm: the whole file read into it first.  CPU is this thread's "
        "CPU time; the rest of the wall time is waiting for a core or the disk.\n"
    )
    print(
        "| pages | how | median | max | CPU median | CPU max | read from disk | "
        "slowest: CPU / waiting for a core / blocked on disk | over 5 ms |"
    )
    print("|---|---|---|---|---|---|---|---|---|")
    cases = [
        (state, label, fetch, mmap)
        for state in ("cold", "warm")
        for _ in range(2)  # each case twice, interleaved: the wall maxima swing with load
        for label, fetch, mmap in (
            ("22 queries, file mapped (two rounds ago)", fetch_before, MAPPED),
            ("before: 8 queries, each its own read transaction", _fetch_individual, None),
            ("now: 8 queries in one read transaction", fetch_individual, None),
        )
    ]
    # The people stored now (each run of the count table imports and deletes a
    # few), read before any page cache is dropped.
    conn = connect(path)
    stored = np.asarray([r[0] for r in conn.execute("SELECT id_num FROM person")])
    conn.close()
    for seed, (state, label, fetch, mmap) in enumerate(cases):
        page_cache(path, warm=state == "warm")
        conn = connect(path)
        if mmap is not None:
            conn.execute(f"PRAGMA mmap_size = {mmap}")
        gc.collect()
        walls, cpus, queued, faults = fetch_times(conn, fetch, stored, seed)
        conn.close()
        k = int(np.argmax(walls))
        print(
            f"| {state} | {label} | {statistics.median(walls) * 1000:.2f} ms | "
            f"{max(walls) * 1000:.2f} ms | {statistics.median(cpus) * 1000:.2f} ms | "
            f"{max(cpus) * 1000:.2f} ms | {faults * 512 // 1024:,} KB | "
            f"{cpus[k] * 1000:.2f} / {queued[k] * 1000:.2f} / "
            f"{max(walls[k] - cpus[k] - queued[k], 0) * 1000:.2f} ms | "
            f"{sum(w > 0.005 for w in walls)} |"
        )
    # The CPU of a warm fetch, before and now, alternating on one connection.
    conn = connect(path)
    picked = np.random.default_rng(99).choice(stored, 2000, replace=False).tolist()
    for pid in picked:
        fetch_individual(conn, pid)
    per_fetch: dict[str, list[float]] = {"before": [], "now": []}
    for _ in range(5):
        for label, fetch in (("before", _fetch_individual), ("now", fetch_individual)):
            c0 = time.thread_time()
            for pid in picked:
                fetch(conn, pid)
            per_fetch[label].append((time.thread_time() - c0) / len(picked))
    conn.close()
    before, now = (statistics.median(per_fetch[k]) * 1e6 for k in ("before", "now"))
    print(
        f"\nwarm, 2,000 people on one connection, CPU per fetch, median of 5 alternating: "
        f"before {before:.0f} us, now {now:.0f} us ({now / before:.2f}x)"
    )
    print(
        "\nthe sample query counted by SQLite on a cold file (dropped from the page "
        "cache first), file mapped as before against read() as now, alternating:\n"
    )
    print("| how | time | read from disk |")
    print("|---|---|---|")
    for label, mmap in (("mapped", MAPPED), ("read()", None)) * 2:
        page_cache(path, warm=False)
        conn = connect(path)
        if mmap is not None:
            conn.execute(f"PRAGMA mmap_size = {mmap}")
        before = resource.getrusage(resource.RUSAGE_SELF).ru_inblock
        elapsed, _n = median_time(lambda: sqlite_count(conn), runs=1)
        read = (resource.getrusage(resource.RUSAGE_SELF).ru_inblock - before) * 512 // 2**20
        conn.close()
        print(f"| {label} | {elapsed:.2f} s | {read:,} MB |")


if __name__ == "__main__":
    main()
