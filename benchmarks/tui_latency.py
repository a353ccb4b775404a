"""Cold start and key-to-screen latency of the `sass` spreadsheet in a real terminal.

Starts `sass` in a detached tmux session (its own server socket) the way a
new user would, and polls the pane until the full layout is on the screen;
then sends keys one at a time and times how long until the screen shows
their effect.  The times include tmux's own work and the polling interval
(printed), so they are upper bounds on what the application adds.

    python benchmarks/tui_latency.py [--runs 5] [--keys 20] [--size 80x24]
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import time

SOCKET = "sass-bench"
SESSION = "bench"
POLL_S = 0.005


def tmux(*args: str) -> str:
    done = subprocess.run(["tmux", "-L", SOCKET, *args], capture_output=True, text=True)
    if done.returncode:
        raise RuntimeError(f"tmux {' '.join(args)}: {done.stderr.strip()}")
    return done.stdout


def screen() -> str:
    return tmux("capture-pane", "-p", "-t", SESSION)


def wait_for(predicate, timeout: float = 10.0) -> float:
    start = time.perf_counter()
    while time.perf_counter() - start < timeout:
        if predicate(screen()):
            return time.perf_counter() - start
        time.sleep(POLL_S)
    raise TimeoutError(f"screen did not reach the expected state:\n{screen()}")


def full_layout(text: str) -> bool:
    """Every section of report figure 4 is drawn: group line, global data,
    command menu, data rows, message line and footer."""
    return all(
        part in text
        for part in (
            "Strength (s)",
            "Population",
            "Fatigue",
            "Create Figure",
            "Bottom Head",
            "Press left-mouse to select items.",
            "q Quit",
        )
    )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--keys", type=int, default=20)
    parser.add_argument("--size", default="80x24")
    args = parser.parse_args()
    if shutil.which("tmux") is None:
        print("tmux is not installed (apt-get install tmux)", file=sys.stderr)
        return 1
    sass = shutil.which("sass")
    command = [sass] if sass else [sys.executable, "-m", "sass_tui"]

    starts, page_keys, unit_keys = [], [], []
    for _ in range(args.runs):
        try:
            begin = time.perf_counter()
            width, height = args.size.split("x")
            tmux("new-session", "-d", "-s", SESSION, "-x", width, "-y", height, *command)
            wait_for(full_layout)
            starts.append(time.perf_counter() - begin)
            # Joint limits: 40 rows, two pages even on a tall terminal.
            tmux("send-keys", "-t", SESSION, "j")
            wait_for(lambda text: "deg" in text and "Neck ul" in text)
            for i in range(args.keys):
                # n / p: page forward and back; c: unit conversion.
                key, expected = ("n", "page 2/") if i % 2 == 0 else ("p", "page 1/")
                tmux("send-keys", "-t", SESSION, key)
                page_keys.append(wait_for(lambda text: expected in text))
                unit = " rad " if i % 2 == 0 else " deg "
                tmux("send-keys", "-t", SESSION, "c")
                unit_keys.append(
                    wait_for(
                        lambda text: (
                            unit in next(line for line in text.splitlines() if "page " in line)
                        )
                    )
                )
        finally:
            subprocess.run(["tmux", "-L", SOCKET, "kill-server"], capture_output=True)
            time.sleep(0.2)  # let the server go before the next run starts one

    def line(name, values):
        ms = [v * 1000 for v in values]
        return (
            f"{name:<34} n={len(ms):<3} min {min(ms):7.1f} ms  median "
            f"{statistics.median(ms):7.1f} ms  max {max(ms):7.1f} ms"
        )

    print(
        f"sass in tmux {args.size}; command {' '.join(command)}; poll every {POLL_S * 1000:.0f} ms"
    )
    print(line("cold start to full layout", starts))
    print(line("key n/p to new page on screen", page_keys))
    print(line("key c to converted unit on screen", unit_keys))
    return 0


if __name__ == "__main__":
    sys.exit(main())
