"""The start-up targets, each a ratio of two commands timed in one run.

Every pair is run interleaved (A, B, A, B, ...) in fresh processes so that
both sides see the same machine load; the table gives the medians and their
ratio against the target.  The databases are built here in a temporary
directory (ANSUR II from the shipped files, and 500,000 people for the
listing) and deleted afterwards.

    python benchmarks/cli_ratios.py [--runs 15] [--tui-runs 5]

Needs the `sass` console script (pip install -e .), the sqlite3 CLI for the
listing baseline and tmux for the TUI pair (each pair is skipped without).
"""

from __future__ import annotations

import argparse
import os
import shutil
import sqlite3
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

PY = sys.executable
SASS = shutil.which("sass", path=str(Path(PY).parent)) or shutil.which("sass")
LIST_PEOPLE = 500_000
TUI_READY = "Press left-mouse to select items."
BARE_APP = f"""
from textual.app import App
from textual.widgets import DataTable, Footer, Static

class Bare(App):
    def compose(self):
        yield DataTable()
        yield Static({TUI_READY!r})
        yield Footer()

    def on_mount(self):
        table = self.query_one(DataTable)
        table.add_columns("name", "x", "y", "z")
        for i in range(25):
            table.add_row(f"row {{i}}", 1.0, 2.0, 3.0)

Bare().run()
"""


def timed(command: list[str], env: dict[str, str]) -> float:
    start = time.perf_counter()
    done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    elapsed = time.perf_counter() - start
    if done.returncode:
        raise RuntimeError(f"{' '.join(command)}: {done.stderr.decode()[-500:]}")
    return elapsed


def pair(runs: int, a: Callable[[], float], b: Callable[[], float]) -> tuple[float, float]:
    a(), b()  # warm the page cache and any caches the commands keep
    times_a, times_b = [], []
    for _ in range(runs):
        times_a.append(a())
        times_b.append(b())
    return statistics.median(times_a), statistics.median(times_b)


def build_ansur_db(path: Path, env: dict[str, str]) -> None:
    """The default database (ANSUR II + synthetic) when `sass db init` builds it;
    else ANSUR II imported from the shipped or shared CSV files."""
    subprocess.run([SASS, "--db", str(path), "db", "init", "--force"], env=env, capture_output=True)
    conn = sqlite3.connect(path)
    try:
        ansur = conn.execute("SELECT count(*) FROM person WHERE source LIKE 'ansur%'").fetchone()[0]
    except sqlite3.Error:
        ansur = 0
    conn.close()
    if ansur:
        return
    shared = Path(__file__).resolve().parents[1].parent / "shared" / "data" / "ansur2"
    files = sorted(shared.glob("ANSUR_II_*_Public.csv"))
    if not files:
        raise SystemExit("no ANSUR II data: neither `sass db init` nor ../shared provides it")
    path.unlink(missing_ok=True)
    subprocess.run(
        [SASS, "--db", str(path), "db", "import-ansur", *map(str, files)],
        env=env,
        check=True,
        capture_output=True,
    )


def ansur_env(tmp: str) -> dict[str, str]:
    """The environment the benchmarks run `sass` in: SASS_DB an ANSUR II
    database built in `tmp`, and compiled modules kept as on a user's machine
    (some shells set PYTHONDONTWRITEBYTECODE, which makes every start compile
    sass anew)."""
    env = dict(os.environ, SASS_DB=str(Path(tmp) / "ansur.db"))
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    build_ansur_db(Path(env["SASS_DB"]), env)
    return env


def grow(source: Path, target: Path, people: int) -> None:
    """Copy `source` and repeat its people (person rows only: the listing reads
    person and strength_q) until there are `people`."""
    shutil.copy(source, target)
    conn = sqlite3.connect(target)
    with conn:
        base = conn.execute("SELECT count(*) FROM person").fetchone()[0]
        columns = [r[1] for r in conn.execute("PRAGMA table_info(person)")]
        others = [c for c in columns if c not in ("id_num", "source_key")]
        copy = 1
        while conn.execute("SELECT count(*) FROM person").fetchone()[0] < people:
            conn.execute(
                f"INSERT INTO person (id_num, {', '.join(others)}) "
                f"SELECT id_num + {copy} * 100000000, {', '.join(others)} FROM person "
                f"WHERE id_num < 100000000 LIMIT ?",
                (people - base * copy,),
            )
            copy += 1
    conn.close()


def tui_start(command: list[str], env: dict[str, str]) -> float:
    socket = f"sass-ratio-{os.getpid()}"
    tmux = ["tmux", "-L", socket]
    start = time.perf_counter()
    subprocess.run(
        [*tmux, "new-session", "-d", "-s", "r", "-x", "120", "-y", "40", *command],
        env=env,
        check=True,
    )
    try:
        while time.perf_counter() - start < 20:
            shown = subprocess.run(
                [*tmux, "capture-pane", "-p", "-t", "r"], capture_output=True, text=True
            ).stdout
            if TUI_READY in shown:
                return time.perf_counter() - start
            time.sleep(0.005)
        raise RuntimeError(f"{command}: {TUI_READY!r} never showed")
    finally:
        subprocess.run([*tmux, "kill-server"], capture_output=True)
        time.sleep(0.1)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    parser.add_argument("--tui-runs", type=int, default=5)
    args = parser.parse_args()
    if SASS is None:
        raise SystemExit("the `sass` console script is not installed (pip install -e .)")
    rows: list[tuple[str, float, float, str]] = []
    with tempfile.TemporaryDirectory() as tmp:
        env = ansur_env(tmp)

        def run(*command: str) -> Callable[[], float]:
            return lambda: timed(list(command), env)

        def add(
            what: str,
            target: str,
            a: Callable[[], float],
            b: Callable[[], float],
            runs: int = args.runs,
        ) -> None:
            ma, mb = pair(runs, a, b)
            rows.append((what, ma, mb, target))
            print(f"  {what}: {ma * 1000:.0f} ms vs {mb * 1000:.0f} ms", file=sys.stderr)

        add(
            '`sass query "gender = male"` / `python3 -c pass`',
            "≤ 5",
            run(SASS, "query", "gender = male"),
            run(PY, "-c", "pass"),
        )
        add(
            '`sass query "stature > 70 in"` / the same in cm',
            "≤ 1.2",
            run(SASS, "query", "stature > 70 in"),
            run(SASS, "query", "stature > 177.8 cm"),
        )
        fig = str(Path(tmp) / "X.fig")
        add(
            '`sass fig -o X.fig` / `python3 -c "import numpy"`',
            "≤ 1.6",
            run(SASS, "fig", "-o", fig),
            run(PY, "-c", "import numpy"),
        )

        big = Path(tmp) / "listing.db"
        grow(Path(env["SASS_DB"]), big, LIST_PEOPLE)
        count = sqlite3.connect(big).execute("SELECT count(*) FROM person").fetchone()[0]
        if shutil.which("sqlite3"):
            sql = (
                "SELECT p.id_num AS id, p.name, p.gender, p.mass, p.stature, p.handedness, "
                "p.age, p.source FROM person p WHERE p.stature > 0"
            )
            add(
                f"`sass query --format csv` listing {count:,} people / sqlite3 CLI",
                "≤ 1.5",
                run(SASS, "--db", str(big), "query", "--format", "csv", "stature > 0 cm"),
                run("sqlite3", "-csv", "-header", str(big), sql),
                runs=max(3, args.runs // 3),
            )
        else:
            print("  (sqlite3 CLI not installed: listing pair skipped)", file=sys.stderr)

        if shutil.which("tmux"):
            bare = Path(tmp) / "bare_app.py"
            bare.write_text(BARE_APP)
            add(
                "TUI first full screen, tmux 120×40 / bare Textual app + 25-row DataTable",
                "≤ 1.3",
                lambda: tui_start([SASS], env),
                lambda: tui_start([PY, str(bare)], env),
                runs=args.tui_runs,
            )
        else:
            print("  (tmux not installed: TUI pair skipped)", file=sys.stderr)

    print(
        f"\n{time.strftime('%Y-%m-%d')}, {os.cpu_count()} cores, Python "
        f"{sys.version.split()[0]}; medians of interleaved runs.\n"
    )
    print("| pair | first | second | ratio | target |")
    print("| --- | --- | --- | --- | --- |")
    for what, a, b, target in rows:
        print(f"| {what} | {a * 1000:.0f} ms | {b * 1000:.0f} ms | {a / b:.2f} | {target} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
