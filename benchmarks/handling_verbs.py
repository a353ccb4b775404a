"""`sass niosh` and `sass handling` start to end, each against `python -c pass`
(the issue's target: under 2x) and against the command line's own floor,
`python -c "import sass_tui.cli"` (argparse and the verb table every verb
pays), in fresh processes, interleaved so both sides see the same load.

    python benchmarks/handling_verbs.py [--runs 15]
"""

from __future__ import annotations

import argparse
import os
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
BASELINES = {
    "python -c pass": [PY, "-c", "pass"],
    FLOOR: [PY, "-c", "import sass_tui.cli"],
}


def timed(command: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    args = parser.parse_args()
    commands = {**VERBS, **BASELINES}
    for command in commands.values():  # warm the page cache
        timed(command)
    times: dict[str, list[float]] = {name: [] for name in commands}
    for _ in range(args.runs):
        for name, command in commands.items():
            times[name].append(timed(command))
    median = {name: statistics.median(found) for name, found in times.items()}
    print(
        f"{time.strftime('%Y-%m-%d')}, {os.cpu_count()} cores, Python "
        f"{sys.version.split()[0]}; medians of {args.runs} interleaved runs.\n"
    )
    print("| command | median | / python -c pass | / import sass_tui.cli |")
    print("| --- | --- | --- | --- |")
    for name in commands:
        print(
            f"| `{name}` | {median[name] * 1000:.0f} ms "
            f"| {median[name] / median['python -c pass']:.2f} "
            f"| {median[name] / median[FLOOR]:.2f} |"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
