"""The TUI's first screen, measured closer than `cli_ratios.py`'s tmux pair.

Each start runs in a pseudo-terminal of 120x40 and is timed from the fork
until "Press left-mouse" appears in what it writes (no tmux server, no
polling of a pane), interleaved with the bare Textual app of `cli_ratios.py`
and that app importing numpy first (numpy's share of sass's start).  Then
one start of `sass` reports the cyclic collector's work before its first
screen, with the collector held off as `sass` does and without.

    python benchmarks/tui_first_screen.py [--runs 15] [--other-checkout DIR]

--other-checkout DIR also times `sass` with PYTHONPATH=DIR (another
checkout of this repository, e.g. a git worktree of an older commit), for a
before/after in one run.
"""

from __future__ import annotations

import argparse
import fcntl
import os
import pty
import select
import signal
import statistics
import struct
import sys
import tempfile
import termios
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cli_ratios import BARE_APP, SASS, TUI_READY

PY = sys.executable
# Runs `sass` (cli.main) until its first screen is drawn, then prints the
# collector's runs before it and exits; argv[1] "hold" or "default".
GC_PROBE = """
import gc, importlib.machinery, os, sys, time
runs = []
started = {}
def watch(phase, info):
    if phase == "start":
        started["t"] = time.perf_counter()
    else:
        runs.append(time.perf_counter() - started["t"])
gc.callbacks.append(watch)
if sys.argv[1] == "default":
    # sass's main() and run_tui() leave the collector as Python sets it.
    gc.disable = gc.set_threshold = lambda *args: None
def drawn(app):
    # Straight to the terminal: Textual captures print() while it runs.
    os.write(1, f"RESULT {len(runs)} {sum(runs) * 1000:.1f} END".encode())
    app.exit()
class PatchApp(importlib.machinery.PathFinder):
    # sass_tui.ui.app is imported by run_tui after it holds the collector:
    # patched as it loads, so that the probe imports nothing earlier.
    @classmethod
    def find_spec(cls, name, path=None, target=None):
        if name != "sass_tui.ui.app":
            return None
        spec = super().find_spec(name, path, target)
        run = spec.loader.exec_module
        def exec_module(module):
            run(module)
            module.SassApp.first_screen_drawn = drawn
        spec.loader.exec_module = exec_module
        return spec
sys.meta_path.insert(0, PatchApp)
from sass_tui.cli import main
main([])
"""


def first_screen(command: list[str], env: dict[str, str], ready: bytes) -> tuple[float, bytes]:
    """Seconds from the fork until `ready` is written, and what was written."""
    start = time.perf_counter()
    pid, fd = pty.fork()
    if pid == 0:  # the child: the terminal is 120x40 before the app asks
        fcntl.ioctl(0, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 120, 0, 0))
        os.execvpe(command[0], command, env)
    written = b""
    try:
        while ready not in written:
            if not select.select([fd], [], [], 20)[0]:
                raise RuntimeError(f"{command}: {ready!r} not written within 20 s")
            try:
                written += os.read(fd, 65536)
            except OSError:  # the child ended
                raise RuntimeError(f"{command} ended: {written[-400:]!r}") from None
        return time.perf_counter() - start, written
    finally:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        os.close(fd)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15)
    parser.add_argument("--other-checkout", type=Path)
    args = parser.parse_args()
    if SASS is None:
        raise SystemExit("the `sass` console script is not installed (pip install -e .)")
    env = dict(os.environ, TERM="xterm-256color")
    env.pop("PYTHONDONTWRITEBYTECODE", None)  # compiled modules kept, as for a user
    ready = TUI_READY.encode()
    with tempfile.TemporaryDirectory() as tmp:
        bare = Path(tmp) / "bare.py"
        bare.write_text(BARE_APP)
        bare_numpy = Path(tmp) / "bare_numpy.py"
        bare_numpy.write_text("import numpy\n" + BARE_APP)
        starts = {
            "sass": ([SASS], env),
            "bare Textual app": ([PY, str(bare)], env),
            "bare app importing numpy first": ([PY, str(bare_numpy)], env),
        }
        if args.other_checkout:
            other = dict(env, PYTHONPATH=str(args.other_checkout.resolve()))
            # Its own entry point: the installed `sass` script may name one
            # that the other checkout does not have (-P: not this directory first).
            starts[f"sass from {args.other_checkout}"] = (
                [PY, "-P", "-c", "import sys; from sass_tui.cli import main; sys.exit(main())"],
                other,
            )
        times: dict[str, list[float]] = {name: [] for name in starts}
        for command, command_env in starts.values():  # warm caches, compile modules
            first_screen(command, command_env, ready)
        for _ in range(args.runs):
            for name, (command, command_env) in starts.items():
                times[name].append(first_screen(command, command_env, ready)[0])
                time.sleep(0.05)
        probe = Path(tmp) / "gc_probe.py"
        probe.write_text(GC_PROBE)
        collector = {}
        for mode in ("hold", "default"):
            written = first_screen([PY, str(probe), mode], env, b" END")[1]
            tail = written[written.index(b"RESULT") :].split()
            collector[mode] = (int(tail[1]), float(tail[2]))

    bare_median = statistics.median(times["bare Textual app"])
    print(
        f"\n{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, {os.cpu_count()} cores, "
        f"Python {sys.version.split()[0]}, load average {os.getloadavg()[0]:.2f}; "
        f"{args.runs} interleaved starts each, pty 120x40.\n"
    )
    print("| start | median | quartiles | / bare app |")
    print("| --- | --- | --- | --- |")
    for name, values in times.items():
        q1, _, q3 = statistics.quantiles(values, n=4)
        median = statistics.median(values)
        print(
            f"| {name} | {median * 1000:.0f} ms | {q1 * 1000:.0f}–{q3 * 1000:.0f} ms "
            f"| {median / bare_median:.2f} |"
        )
    print("\n| collector before the first screen | runs | time |")
    print("| --- | --- | --- |")
    for mode, label in (("hold", "held off (as `sass` runs)"), ("default", "Python's default")):
        count, ms = collector[mode]
        print(f"| {label} | {count} | {ms:.1f} ms |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
