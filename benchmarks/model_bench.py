"""Foundation benchmarks: rescale a whole figure, render and write a .fig, and
`sass fig` end to end (a fresh process, import time included).

    python benchmarks/model_bench.py
"""

from __future__ import annotations

import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.figfile import render_fig, write_fig
from sass_tui.model.names import GROUPS
from sass_tui.model.population.percentile_arrays import value_at


def best_of(func, repeat: int = 7, number: int = 200) -> float:
    """Best mean time of one call over `repeat` batches, in seconds."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        for _ in range(number):
            func()
        times.append((time.perf_counter() - start) / number)
    return min(times)


def main() -> None:
    figure = Figure.default()
    stats = {g: figure.groups[g].source.stats("male") for g in GROUPS}
    percentiles = iter([12.5, 87.5] * 10**6)

    def rescale_values():
        p = next(percentiles)
        for group in GROUPS:
            value_at(stats[group], p)

    def rescale_figure():
        p = next(percentiles)
        for group in GROUPS:
            figure.set_group_percentile(group, p)

    out = Path(tempfile.mkdtemp()) / "bench.fig"
    rows = [
        ("percentile interpolation, all 3 groups (86 rows x 3 axes)", best_of(rescale_values)),
        (
            "Figure.set_group_percentile for all 3 groups",
            best_of(rescale_figure),
        ),
        ("render a .fig (254 variables)", best_of(lambda: render_fig(figure), number=100)),
        (
            "write a .fig atomically (fsync included)",
            best_of(lambda: write_fig(figure, out), number=20),
        ),
    ]
    runs = []
    for _ in range(7):
        start = time.perf_counter()
        subprocess.run(
            [sys.executable, "-m", "sass_tui", "fig", "-o", str(out)],
            check=True,
            capture_output=True,
        )
        runs.append(time.perf_counter() - start)
    print(
        f"machine: {platform.machine()}, {platform.python_implementation()} {platform.python_version()}"
    )
    for label, seconds in rows:
        print(f"{label:66s} {seconds * 1e3:8.3f} ms")
    print(
        f"{'sass fig end to end (new process; median of 7, best)':66s} "
        f"{statistics.median(runs) * 1e3:8.1f} ms  {min(runs) * 1e3:6.1f} ms"
    )


if __name__ == "__main__":
    main()
