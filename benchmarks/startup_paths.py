"""Every start-up path of sass_tui/startup.py timed in this checkout and in
another one (before a change), interleaved in one run: is any path slower?

    python benchmarks/startup_paths.py --other-checkout DIR [--runs 11]

DIR is a checkout of sass (e.g. `git worktree add DIR main`, or `git archive
main | tar -x -C DIR`); both sides run `sass_tui.cli.command_line()` from
their own tree (PYTHONPATH) in this interpreter, in fresh processes, A, B,
A, B, ... so that both see the same machine load.  The rows that read a
database get a copy of the one `sass db init` builds here; the TUI's rows
are benchmarks/tui_first_screen.py's.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from sass_tui.startup import PATHS  # noqa: E402  (this checkout's table)

RUN = "import sys; from sass_tui.cli import command_line; sys.exit(command_line())"


def timed(tree: Path, argv: list[str], cwd: Path, status: int) -> float:
    env = dict(os.environ, PYTHONPATH=str(tree))
    env.pop("PYTHONDONTWRITEBYTECODE", None)  # compiled modules kept, as on a user's machine
    (cwd / "new.db").unlink(missing_ok=True)  # `sass db init` builds it anew each run
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", RUN, *argv], cwd=cwd, env=env, capture_output=True)
    elapsed = time.perf_counter() - start
    if done.returncode != status:
        raise RuntimeError(f"{tree}: sass {' '.join(argv)}: {done.stderr.decode()[-400:]}")
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--other-checkout", type=Path, required=True, help="the tree before")
    parser.add_argument("--runs", type=int, default=11, help="runs of each side (default 11)")
    args = parser.parse_args()
    trees = (args.other_checkout.resolve(), ROOT)
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        db = work / "sass.db"
        subprocess.run(
            [sys.executable, "-c", RUN, "--db", str(db), "db", "init"],
            env=dict(os.environ, PYTHONPATH=str(ROOT)),
            check=True,
            capture_output=True,
        )
        print(
            f"{time.strftime('%Y-%m-%d %H:%M', time.gmtime())} UTC, load {os.getloadavg()[0]:.1f}"
        )
        print("| path | before | after | after / before |")
        print("| --- | --- | --- | --- |")
        for path in PATHS:
            if not path.argv:
                continue  # the TUI: benchmarks/tui_first_screen.py
            argv = list(path.argv)
            if path.needs_db:
                shutil.copy(db, work / "copy.db")
                argv = ["--db", str(work / "copy.db"), *argv]
            times: tuple[list[float], list[float]] = ([], [])
            for tree in trees:  # warm the page cache and the compiled modules
                timed(tree, argv, work, path.status)
            for _ in range(args.runs):
                for side, tree in enumerate(trees):
                    times[side].append(timed(tree, argv, work, path.status))
            before, after = (statistics.median(t) * 1000 for t in times)
            print(f"| {path.name} | {before:.0f} ms | {after:.0f} ms | {after / before:.2f} |")


if __name__ == "__main__":
    main()
