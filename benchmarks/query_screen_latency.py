"""The query screen on 1,000,000 people, in a real terminal (tmux): build the
report's sample query through the pop-up menus, run it, and time keys sent
while it runs (the interface must answer them) and paging the result.

The database is generated with benchmarks/db_million.py's generator in a
temporary directory and deleted afterwards (about two minutes); `--db PATH`
reuses one already built.

    python benchmarks/query_screen_latency.py [--runs 3] [--db PATH] [--people N]
"""

from __future__ import annotations

import argparse
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import tui_latency
from db_million import build
from tui_latency import SESSION, screen, tmux, wait_for

from sass_tui.db.engine.schema import connect

# (expected pop-up title, how many Down presses to the item) of figure 13's sequence;
# None = type the constraint value instead.
SEQUENCE = (
    ("Query Menu", 0, None),
    ("Global Information", 0, None),
    ("Gender", 0, None),
    ("Conjunction Menu", 0, None),
    ("Query Menu", 1, None),
    ("Anthropometric Group", 0, None),
    ("Girth Menu", 4, None),
    ("Axis Menu", 2, None),
    ("Relational Operation Menu", 1, None),
    ("Type in the constraint value:", None, "28 cm"),
    ("Conjunction Menu", 0, None),
    ("Query Menu", 1, None),
    ("Anthropometric Group", 3, None),
    ("Strength Menu", 6, None),
    ("Relational Operation Menu", 1, None),
    ("Type in the constraint value:", None, "20 ft-lb"),
    ("Conjunction Menu", 2, None),  # Done
)
SIZE = ("100", "37")
# A tmux server of its own: tui_latency.py may run at the same time and kills its server.
SOCKET = tui_latency.SOCKET = "sass-query-bench"


def send(*keys: str) -> None:
    tmux("send-keys", "-t", SESSION, *keys)


def one_run(command: list[str]) -> dict[str, object]:
    tmux("new-session", "-d", "-s", SESSION, "-x", SIZE[0], "-y", SIZE[1], *command)
    wait_for(lambda text: "Press left-mouse to select items." in text, timeout=20)
    send("d")
    wait_for(lambda text: "Query DB (d) to query it" in text, timeout=30)
    send("d", "b")
    for title, downs, typed in SEQUENCE:
        # The pop-up's border title (a title can also be an item of the menu before).
        wait_for(lambda text: (title in text) if typed else (f"─ {title} ─" in text))
        if typed is not None:
            send("-l", typed)
            send("Enter")
            continue
        send(*(["Down"] * downs), "Enter")
    start = time.perf_counter()
    wait_for(lambda text: "Query on database, please wait..." in text)
    answered = []
    # Keys while the query runs: `b` (no builder open) says so on the message line,
    # Enter / Down move nothing visible; alternate two messages to see each answer.
    while "Query execution is complete." not in screen():
        send("b")
        t0 = time.perf_counter()
        try:
            wait_for(
                lambda text: "Query DB (d) first" in text or "Query execution is complete." in text,
                timeout=5,
            )
        except TimeoutError:
            break
        if "Query execution is complete." in screen():
            break
        answered.append(time.perf_counter() - t0)
        send("n")
        wait_for(
            lambda text: (
                "Query on database, please wait..." in text
                or "Query execution is complete." in text
            ),
            timeout=5,
        )
    wait_for(lambda text: "Query execution is complete." in text, timeout=120)
    run_time = time.perf_counter() - start
    pages = []
    for i in range(10):
        send("n")
        t0 = time.perf_counter()
        wait_for(lambda text: f"page {i + 2}/" in text)
        pages.append(time.perf_counter() - t0)
    final = screen()
    return {"run": run_time, "answered": answered, "pages": pages, "screen": final}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--db", type=Path, help="an already built database")
    parser.add_argument("--people", type=int, default=1_000_000)
    args = parser.parse_args()
    if shutil.which("tmux") is None:
        print("tmux is not installed (apt-get install tmux)", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        path = args.db
        if path is None:
            path = Path(tmp) / "million.db"
            conn = connect(path, create=True)
            conn.execute("PRAGMA journal_mode = OFF")
            conn.execute("PRAGMA synchronous = OFF")
            build(conn, args.people, np.random.default_rng(1988))
            conn.close()
        sass = shutil.which("sass")
        command = ([sass] if sass else [sys.executable, "-m", "sass_tui"]) + ["--db", str(path)]
        results = []
        for _ in range(args.runs):
            try:
                results.append(one_run(command))
            finally:
                subprocess.run(["tmux", "-L", SOCKET, "kill-server"], capture_output=True)
                time.sleep(0.3)
    runs = [r["run"] for r in results]
    answered = [t for r in results for t in r["answered"]]
    pages = [t for r in results for t in r["pages"]]
    print(
        f"Done to 'Query execution is complete.': median {statistics.median(runs):.2f} s "
        f"(runs {', '.join(f'{t:.2f}' for t in runs)})"
    )
    if answered:
        print(
            f"keys answered while the query ran: {len(answered)}, median "
            f"{statistics.median(answered) * 1000:.0f} ms, max {max(answered) * 1000:.0f} ms"
        )
    else:
        print("no key answered while the query ran (it finished first)")
    print(
        f"Next Page on the result: median {statistics.median(pages) * 1000:.0f} ms, "
        f"max {max(pages) * 1000:.0f} ms ({len(pages)} pages)"
    )
    print(results[-1]["screen"])
    return 0


if __name__ == "__main__":
    sys.exit(main())
