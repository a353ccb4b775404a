"""The query commands start to end, this checkout against another one: the
before/after of a change to the query language's parser or its callers
(docs/performance.md, "The query parser").

Each command runs in a fresh process, interleaved (this checkout, the
other, `python -c pass`, ...) so all three see the same machine load; the
table gives the medians of wall time and of the process's CPU time, and
each command's ratio to `python -c pass` (cli_ratios.py's `sass query`
target: at most 5).  The database is the default one, built here.

    python benchmarks/query_parser.py --other-checkout DIR [--runs 21]

DIR is another checkout of this repository (e.g. `git archive COMMIT | tar
-x -C DIR`), run with PYTHONPATH=DIR from outside both trees.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PY = sys.executable
COMMANDS = (
    ("query", "--count", "gender = male"),
    ("query", "gender = male"),
    # no real person: the count, then the demonstration hint's
    ("query", "--count", "gender = male AND strength.elbow_flexion.max > 20 ft-lb"),
    ("fit", "stature <= 190 cm AND mass <= 110 kg"),
)


def timed(argv: list[str], env: dict[str, str], cwd: str) -> tuple[float, float]:
    """(wall, CPU) seconds of one run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(argv, env=env, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode:
        raise RuntimeError(f"{' '.join(argv)}: {done.stderr.decode()[-500:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--other-checkout", type=Path, required=True, metavar="DIR")
    parser.add_argument("--runs", type=int, default=21)
    args = parser.parse_args()
    here = Path(__file__).resolve().parents[1]
    other = args.other_checkout.resolve()
    with tempfile.TemporaryDirectory() as tmp:
        env = dict(os.environ, XDG_CACHE_HOME=str(Path(tmp) / "cache"))
        envs = {"this": dict(env, PYTHONPATH=str(here)), "other": dict(env, PYTHONPATH=str(other))}
        db = str(Path(tmp) / "sass.db")
        sass = [PY, "-m", "sass_tui", "--db", db]
        subprocess.run([*sass, "db", "init"], env=envs["this"], cwd=tmp, check=True)
        rows = []
        for command in COMMANDS:
            argv = [*sass, *command]
            for name in envs:  # the first run of each writes its caches (.pyc, parser tables)
                timed(argv, envs[name], tmp)
            times: dict[str, list[tuple[float, float]]] = {"this": [], "other": [], "pass": []}
            for _ in range(args.runs):
                times["this"].append(timed(argv, envs["this"], tmp))
                times["other"].append(timed(argv, envs["other"], tmp))
                times["pass"].append(timed([PY, "-c", "pass"], env, tmp))
            medians = {
                k: (statistics.median(w for w, _ in v), statistics.median(c for _, c in v))
                for k, v in times.items()
            }
            rows.append((" ".join(command), medians))
            print(f"  {' '.join(command)}: {medians}", file=sys.stderr)
    print(
        f"\n{time.strftime('%Y-%m-%d %H:%M')}, {os.cpu_count()} cores, Python "
        f"{sys.version.split()[0]}; medians of {args.runs} interleaved runs; other = {other}\n"
    )
    print(
        "| command | this: wall / CPU | other: wall / CPU | this / other (CPU) | this / `python -c pass` (wall) |"
    )
    print("| --- | --- | --- | --- | --- |")
    for what, m in rows:
        (tw, tc), (ow, oc), (pw, _pc) = m["this"], m["other"], m["pass"]
        print(
            f"| `sass {what}` | {tw * 1000:.0f} / {tc * 1000:.0f} ms | {ow * 1000:.0f} / "
            f"{oc * 1000:.0f} ms | {tc / oc:.2f} | {tw / pw:.2f} |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
