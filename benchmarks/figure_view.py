"""Figure view redraw after an edit, against the spreadsheet's own redraw.

In-process (Textual's headless driver): for each terminal size, an edit
(stature percentile) is made through the Session and then
- baseline: the spreadsheet redraws its sections (`refresh_screen`), its
  figure panel hidden,
- panel: the same with the live figure panel beside the data (from 120
  columns; `refresh_screen` redraws it), what a user waits for after an edit,
- figure: the figure screen rebuilds the outline and redraws the canvas,
- figure + overlay: the same with the population's 50th laid over it,
each followed by the screen's next paint (`pilot.pause`), so the times
include Textual's compositor and the pilot's wait for idle; `redraw()` is
the figure screen's own work (outline + canvas pixels) without the paint,
and "panel redraw()" the same for the spreadsheet's panel.  Median of --runs
edits; ratios are against the baseline measured in the same run.

    python benchmarks/figure_view.py [--runs 30]
"""

from __future__ import annotations

import argparse
import asyncio
import platform
import statistics
import time

from sass_tui.ui.app import SassApp
from sass_tui.ui.spreadsheet.figure_screen import FigureScreen

SIZES = ((80, 24), (120, 40), (200, 60))


async def measure(size: tuple[int, int], runs: int) -> dict[str, float]:
    app = SassApp()
    times: dict[str, list[float]] = {
        "baseline": [],
        "panel": [],
        "panel redraw": [],
        "figure": [],
        "figure + overlay": [],
        "redraw call": [],
    }
    async with app.run_test(size=size) as pilot:
        sheet = app.screen
        panel = sheet.figure_panel
        for name in ("baseline", "panel"):
            if panel is None and name == "panel":
                continue  # narrower than 120 columns: no panel
            if panel is not None:
                panel.display = name == "panel"
                await pilot.pause()
            for i in range(runs):
                app.session.set_stature_percentile(40 + i % 20)
                start = time.perf_counter()
                if name == "panel":
                    sheet.redraw_figure_panel()  # what refresh_screen calls last
                    times["panel redraw"].append(time.perf_counter() - start)
                sheet.refresh_screen()
                await pilot.pause()
                times[name].append(time.perf_counter() - start)
        await pilot.press("b")
        await pilot.pause()
        figure_screen = app.screen
        assert isinstance(figure_screen, FigureScreen)
        for name, overlay_presses in (("figure", 0), ("figure + overlay", 1)):
            for _ in range(overlay_presses):
                await pilot.press("o")
                await pilot.pause()
            for i in range(runs):
                app.session.set_stature_percentile(40 + i % 20)
                start = time.perf_counter()
                figure_screen.redraw()
                if name == "figure":
                    times["redraw call"].append(time.perf_counter() - start)
                await pilot.pause()
                times[name].append(time.perf_counter() - start)
    return {
        name: statistics.median(values) * 1000 if values else float("nan")
        for name, values in times.items()
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=30)
    args = parser.parse_args()
    print(f"{platform.node()} {platform.machine()} Python {platform.python_version()}")
    print(
        f"{'size':>8} {'baseline ms':>12} {'panel ms':>9} {'ratio':>6} {'figure ms':>10} "
        f"{'ratio':>6} {'+overlay ms':>12} {'ratio':>6} {'redraw() ms':>12} "
        f"{'panel redraw() ms':>18}"
    )
    for size in SIZES:
        result = asyncio.run(measure(size, args.runs))
        base = result["baseline"]
        print(
            f"{size[0]:>4}x{size[1]:<3} {base:12.1f} {result['panel']:9.1f} "
            f"{result['panel'] / base:6.2f} {result['figure']:10.1f} "
            f"{result['figure'] / base:6.2f} {result['figure + overlay']:12.1f} "
            f"{result['figure + overlay'] / base:6.2f} {result['redraw call']:12.1f} "
            f"{result['panel redraw']:18.1f}"
        )


if __name__ == "__main__":
    main()
