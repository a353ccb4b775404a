"""`sass niosh` and `sass handling` start to end, each against `python -c pass`
and against the command line's own floor, `python -c "import sass_tui.cli"`
(argparse and the verb table every verb pays), against argparse alone
(imported, one empty command line parsed: the least any argparse command
does), and against argparse and json (that, and the module that reads the
verbs' tables from datasets/), in fresh processes, interleaved so both sides
see the same load.

The target (under 2x `python -c pass`) is read as: what a verb adds to the
least a Python command that parses its arguments with argparse and reads
JSON tables pays is under one `python -c pass`.  Literally, 2x is below
that least on Python 3.11 (argparse alone ~2.1x, re alone, which json and
argparse import, ~1.5x; docs/performance.md); the last lines print the
margin of each verb.
Wall and CPU time (user + system of the child): on a loaded machine the CPU
time is the steadier of the two.  Run as a user runs sass: with bytecode
caching (PYTHONDONTWRITEBYTECODE, set in some shells and CI, is dropped for
the children, and the warm-up run writes the .pyc files): without it every
sass module is compiled from source on every run, ~25 ms of each verb.

    python benchmarks/handling_verbs.py [--runs 15] [--against TREE]

--against TREE (another checkout, e.g. `git worktree add --detach /tmp/main
main`) adds each verb run from that tree and from this one the same way
(`python -c "...command_line()"` with the tree first on sys.path), so a
change's effect is measured interleaved, under the same load.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import time
from pathlib import Path

PY = sys.executable
# the console script a user runs (pip install -e .), beside this Python
SASS = str(Path(PY).parent / "sass")
VERBS = {
    "sass niosh": [SASS, "niosh", "--h", "40cm", "--v", "60cm", "--d", "80cm",
                   "--f", "2", "--load", "12kg"],
    "sass handling": [SASS, "handling", "lift", "--h", "0.38", "--v", "1.03",
                      "--d", "0.51", "--load", "10kg"],
}  # fmt: skip
FLOOR = "python -c 'import sass_tui.cli'"
# The least any command that reads its arguments with argparse does: import it
# and parse an empty command line (the parser's own messages are looked up in
# gettext's catalogues as it is made).  No sass code; its ratio to `python -c
# pass` is the lowest a verb can reach while it parses with argparse.
ARGPARSE_ALONE = "import argparse; argparse.ArgumentParser().parse_args([])"
# ... and json, which reads the verbs' tables (datasets/*.json, model/shipped.py)
ARGPARSE_AND_JSON = "import argparse, json; argparse.ArgumentParser().parse_args([])"
LEAST = f"python -c '{ARGPARSE_AND_JSON}'"
BASELINES = {
    "python -c pass": [PY, "-c", "pass"],
    f"python -c '{ARGPARSE_ALONE}'": [PY, "-c", ARGPARSE_ALONE],
    LEAST: [PY, "-c", ARGPARSE_AND_JSON],
    FLOOR: [PY, "-c", "import sass_tui.cli"],
}


def from_tree(tree: str, argv: list[str]) -> list[str]:
    """`sass ARGV` run with `tree`'s sass_tui (first on sys.path)."""
    code = (
        f"import sys; sys.path.insert(0, {tree!r}); sys.argv = {['sass', *argv]!r}; "
        "from sass_tui.cli import command_line; sys.exit(command_line())"
    )
    return [PY, "-c", code]


ENV = {name: value for name, value in os.environ.items() if name != "PYTHONDONTWRITEBYTECODE"}


def timed(command: list[str]) -> tuple[float, float]:
    """The wall time and the CPU time (user + system) of one run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, env=ENV)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    parser.add_argument("--against", metavar="TREE", help="another checkout to compare with")
    args = parser.parse_args()
    commands = {**VERBS, **BASELINES}
    if args.against:
        here = str(Path(__file__).resolve().parent.parent)
        for side, tree in (("against", args.against), ("this tree", here)):
            for name, command in VERBS.items():
                commands[f"{name} ({side})"] = from_tree(tree, command[1:])
    for command in commands.values():  # warm the page cache
        timed(command)
    times: dict[str, list[float]] = {name: [] for name in commands}
    cpu: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(args.runs):
        for name, command in commands.items():
            wall, used = timed(command)
            times[name].append(wall)
            cpu[name].append(used)
    median = {name: statistics.median(found) for name, found in times.items()}
    median_cpu = {name: statistics.median(found) for name, found in cpu.items()}
    print(
        f"{time.strftime('%Y-%m-%d')}, {os.cpu_count()} cores, Python "
        f"{sys.version.split()[0]}, load average {os.getloadavg()[0]:.1f}; "
        f"medians of {args.runs} interleaved runs.\n"
    )
    print("| command | wall | / python -c pass | CPU | / python -c pass | / import sass_tui.cli |")
    print("| --- | --- | --- | --- | --- | --- |")
    for name in commands:
        print(
            f"| `{name}` | {median[name] * 1000:.0f} ms "
            f"| {median[name] / median['python -c pass']:.2f} "
            f"| {median_cpu[name] * 1000:.0f} ms "
            f"| {median_cpu[name] / median_cpu['python -c pass']:.2f} "
            f"| {median[name] / median[FLOOR]:.2f} |"
        )
    print()
    bare, bare_cpu = median["python -c pass"], median_cpu["python -c pass"]
    for name in VERBS:
        added, added_cpu = median[name] - median[LEAST], median_cpu[name] - median_cpu[LEAST]
        print(
            f"{name} adds {added * 1000:.1f} ms wall ({added / bare:.2f}x `python -c pass`), "
            f"{added_cpu * 1000:.1f} ms CPU ({added_cpu / bare_cpu:.2f}x) to argparse and json: "
            + ("under 1x" if max(added / bare, added_cpu / bare_cpu) < 1 else "NOT under 1x")
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
