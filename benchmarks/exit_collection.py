"""What the `sass` command's freeze before exit saves (`sass query`'s start-up).

As Python ends it runs one last cyclic collection over every object still
alive; `cli.command_line` freezes them first.  This times, interleaved in
fresh processes, `sass query "gender = male"` on ANSUR II as the `sass`
command runs it, the same `main()` without the freeze, and `python3 -c pass`.

    python benchmarks/exit_collection.py [--runs 41]
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cli_ratios import PY, SASS, ansur_env, timed

QUERY = "gender = male"
# main() as the `sass` command runs it, without command_line's freeze.
WITHOUT_FREEZE = "import sys; from sass_tui.cli import main; sys.exit(main(sys.argv[1:]))"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=41)
    args = parser.parse_args()
    if SASS is None:
        raise SystemExit("the `sass` console script is not installed (pip install -e .)")
    with tempfile.TemporaryDirectory() as tmp:
        env = ansur_env(tmp)
        commands = {
            "`sass query` (the sass command: frozen before exit)": [SASS, "query", QUERY],
            "the same main() without the freeze": [PY, "-P", "-c", WITHOUT_FREEZE, "query", QUERY],
            "`python3 -c pass`": [PY, "-c", "pass"],
        }
        for command in commands.values():  # warm the page cache, compile modules
            timed(command, env)
        times: dict[str, list[float]] = {name: [] for name in commands}
        for _ in range(args.runs):
            for name, command in commands.items():
                times[name].append(timed(command, env))
    bare = statistics.median(times["`python3 -c pass`"])
    print(
        f"\n{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {os.cpu_count()} cores, "
        f"Python {sys.version.split()[0]}, load average {os.getloadavg()[0]:.2f}; "
        f"{args.runs} interleaved runs each.\n"
    )
    print("| command | median | quartiles | / python3 -c pass |")
    print("| --- | --- | --- | --- |")
    for name, values in times.items():
        q1, median, q3 = statistics.quantiles(values, n=4)
        print(
            f"| {name} | {median * 1000:.1f} ms | {q1 * 1000:.1f}–{q3 * 1000:.1f} ms "
            f"| {median / bare:.2f} |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
