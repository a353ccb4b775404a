"""Where the start-up of `sass query`, `sass fig` and the TUI's first screen goes
(each has a start-up target): `python -X importtime` and py-spy.

For each path: the modules imported (self time, the minimum over --runs runs
of -X importtime, so machine load counts less), grouped by top-level package,
and a py-spy profile (sampling at 1 kHz) summarised as the functions with the
most samples of their own and the sass functions with the most samples in
all.  The TUI path starts `sass`'s app in a detached tmux session at 120x40
and exits it once the first screen is drawn.

    python benchmarks/startup_profiles.py [--runs 7]

Needs py-spy (pip install --group bench; it reads another process's memory,
so a container may need SYS_PTRACE) and tmux for the TUI path; a path whose
tool is missing is skipped.  --speedscope DIR also writes each profile as a
speedscope file (https://www.speedscope.app).
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cli_ratios import SASS, ansur_env

PY = sys.executable
PY_SPY = shutil.which("py-spy", path=str(Path(PY).parent)) or shutil.which("py-spy")
# The TUI as `sass` starts it (cli.run_tui), until its first screen is
# drawn, then out (run inside tmux).
FIRST_SCREEN = """
import sys

from sass_tui.cli import run_tui
from sass_tui.ui.spreadsheet.spreadsheet import SpreadsheetScreen


def first_screen_drawn(screen):
    screen.app.exit()


SpreadsheetScreen._first_screen_drawn = first_screen_drawn
sys.exit(run_tui(None))
"""


def importtime(command: list[str], env: dict[str, str], runs: int) -> dict[str, int]:
    """Module -> its own import time in µs, the minimum over `runs` runs."""
    best: dict[str, int] = {}
    for _ in range(runs):
        done = subprocess.run(
            [PY, "-X", "importtime", *command], env=env, capture_output=True, text=True
        )
        for line in done.stderr.splitlines():
            if not line.startswith("import time:") or "self [us]" in line:
                continue
            own, _cumulative, name = line[len("import time:") :].split("|")
            module = name.strip()
            best[module] = min(best.get(module, 1 << 62), int(own))
    return best


def show_imports(best: dict[str, int], top: int = 12) -> None:
    groups: Counter[str] = Counter()
    for module, own in best.items():
        head = module.split(".")[0]
        groups[head if head != "sass_tui" else ".".join(module.split(".")[:3])] += own
    total = sum(best.values())
    print(f"  -X importtime: {len(best)} modules, {total / 1000:.1f} ms of own time (min of runs)")
    for group, own in groups.most_common(top):
        print(f"    {own / 1000:6.1f} ms  {group}")


def py_spy(
    command: list[str], env: dict[str, str], out: Path, tmux: bool = False
) -> Counter[tuple[str, ...]]:
    """Stacks sampled by py-spy (raw format), each a tuple of frames, outermost first."""
    record = [PY_SPY, "record", "-r", "1000", "--nolineno", "--format", "raw", "-o", str(out)]
    record += ["--", *command]
    if not tmux:
        subprocess.run(record, env=env, capture_output=True, check=True)
    else:
        socket = f"sass-prof-{os.getpid()}"
        line = " ".join(f"'{w}'" for w in record)
        subprocess.run(
            ["tmux", "-L", socket, "new-session", "-d", "-s", "p", "-x", "120", "-y", "40", line],
            env=env,
            check=True,
        )
        start = time.perf_counter()
        while time.perf_counter() - start < 60:
            alive = subprocess.run(
                ["tmux", "-L", socket, "has-session", "-t", "p"], capture_output=True
            )
            if alive.returncode:
                break
            time.sleep(0.1)
        subprocess.run(["tmux", "-L", socket, "kill-server"], capture_output=True)
    stacks: Counter[tuple[str, ...]] = Counter()
    for row in out.read_text().splitlines():
        frames, _, count = row.rpartition(" ")
        if frames.startswith("_bootstrap (threading.py"):
            continue  # another thread (Textual's input thread): the main one only
        stacks[tuple(frames.split(";"))] += int(count)
    return stacks


def show_profile(stacks: Counter[tuple[str, ...]], top: int = 10) -> None:
    total = sum(stacks.values())
    own: Counter[str] = Counter()
    inclusive: Counter[str] = Counter()
    for frames, count in stacks.items():
        own[_short(frames[-1])] += count
        for frame in {_short(f) for f in frames if "sass_tui" in f}:
            inclusive[frame] += count
    # py-spy stops the process for each sample, so a profiled start takes longer
    # than a plain one: the shares are what to read, not the sample count.
    print(f"  py-spy: {total} samples of the main thread at 1 kHz")
    print("    own samples:")
    for frame, count in own.most_common(top):
        print(f"      {100 * count / total:5.1f} %  {frame}")
    print("    sass functions, samples in all (themselves and what they call):")
    for frame, count in inclusive.most_common(top):
        print(f"      {100 * count / total:5.1f} %  {frame}")


def _short(frame: str) -> str:
    """'f (/long/path/site-packages/pkg/mod.py)' -> 'f (pkg/mod.py)'."""
    name, _, where = frame.partition(" (")
    if not name.strip():
        return "(no Python frame: the interpreter starting or native code)"
    for marker in ("site-packages/", "python3.11/", "sass_tui/"):
        if marker in where:
            where = where.split(marker, 1)[1]
            break
    return f"{name} ({where}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    if SASS is None:
        raise SystemExit("the `sass` console script is not installed (pip install -e .)")
    with tempfile.TemporaryDirectory() as tmp:
        env = ansur_env(tmp)
        first_screen = Path(tmp) / "first_screen.py"
        first_screen.write_text(FIRST_SCREEN)
        # (what, its imports measured by, its profile's command, in tmux)
        fig = [SASS, "fig", "-o", str(Path(tmp) / "X.fig")]
        paths = [
            ('sass query "gender = male"', [SASS, "query", "gender = male"], None, False),
            ("sass fig -o X.fig", fig, None, False),
            (
                "TUI first screen (tmux 120x40)",
                ["-c", "from sass_tui.cli import main; import sass_tui.ui.app"],
                [str(first_screen)],
                True,
            ),
        ]
        print(f"{time.strftime('%Y-%m-%d %H:%M')}, Python {sys.version.split()[0]}")
        for what, command, profiled, needs_tmux in paths:
            print(f"\n{what}")
            show_imports(importtime(command, env, args.runs))
            if PY_SPY is None or (needs_tmux and not shutil.which("tmux")):
                print("  (py-spy or tmux not installed: no profile)")
                continue
            out = Path(tmp) / "profile.txt"
            show_profile(py_spy([PY, *(profiled or command)], env, out, tmux=needs_tmux))
    return 0


if __name__ == "__main__":
    sys.exit(main())
