"""Cost of the strength page: loading datasets/strength.dat at start-up (done
on the UI thread, before the first screen), recomputing the page after an
edit, and the page driven headless by Textual's Pilot.

    python benchmarks/strength_page.py [--runs 7]
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import subprocess
import sys
import time

COLD_LOAD = """
import time
from sass_tui.model.body.figure import Figure
from sass_tui.model.strength.strength import StrengthSheet, read_strength_file
figure = Figure.default()
start = time.perf_counter()
sheet = StrengthSheet(read_strength_file(), figure)
sheet.rows()
print(time.perf_counter() - start)
"""


def cold_load_ms(runs: int) -> list[float]:
    """Each in a fresh interpreter: the first least-squares fit pays numpy's
    linear-algebra start-up, as the app's first start does."""
    return [
        float(
            subprocess.run(
                [sys.executable, "-c", COLD_LOAD], capture_output=True, text=True, check=True
            ).stdout
        )
        * 1000
        for _ in range(runs)
    ]


def recompute_ms(runs: int) -> list[float]:
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.strength.strength import StrengthSheet, read_strength_file

    sheet = StrengthSheet(read_strength_file(), Figure.default())
    sheet.rows()
    times = []
    for i in range(runs * 100):
        start = time.perf_counter()
        sheet.set_angle(0, 0, 30 + i % 40)
        sheet.rows()
        times.append((time.perf_counter() - start) * 1000)
    return times


async def pilot_ms(runs: int) -> tuple[list[float], list[float], list[float]]:
    from sass_tui.ui.app import SassApp
    from sass_tui.ui.spreadsheet.strength_page import StrengthPage

    baseline, show, edit = [], [], []
    for _ in range(runs):
        app = SassApp()
        async with app.run_test(size=(100, 37)) as pilot:
            await pilot.pause()
            # Pilot's own waits per key, for comparison: another group's page.
            start = time.perf_counter()
            await pilot.press("j")
            await pilot.pause()
            baseline.append((time.perf_counter() - start) * 1000)
            start = time.perf_counter()
            await pilot.press("s")
            await pilot.pause()
            assert "Shoulder abduction" in str(app.query_one(StrengthPage).render())
            show.append((time.perf_counter() - start) * 1000)
            start = time.perf_counter()
            await pilot.press(*"45", "enter")
            await pilot.pause()
            assert "predicted" in str(app.query_one(StrengthPage).render())
            edit.append((time.perf_counter() - start) * 1000)
    return baseline, show, edit


def summary(times: list[float]) -> str:
    return f"median {statistics.median(times):.2f} ms ({min(times):.2f}-{max(times):.2f})"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7)
    args = parser.parse_args()
    print(
        f"start-up load + first page, fresh process ({args.runs} runs): "
        f"{summary(cold_load_ms(args.runs))}"
    )
    print(f"set_angle + rows() ({args.runs * 100} edits): {summary(recompute_ms(args.runs))}")
    baseline, show, edit = asyncio.run(pilot_ms(args.runs))
    print(
        f"Pilot: 'j' to the joint-limits page, for comparison ({args.runs} runs): "
        f"{summary(baseline)}"
    )
    print(f"Pilot: 's' to the page drawn ({args.runs} runs): {summary(show)}")
    print(
        f"Pilot: typed angle '45' + Enter to the row recomputed ({args.runs} runs): {summary(edit)}"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
