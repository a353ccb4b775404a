"""Strength for every row of the strength page (14 rows, spec: under 1 ms in total).

Times StrengthSheet.values() (lookup, prediction equation, percentile and every
modifier for all 14 rows) with every row off the stored configurations, so
each is predicted, and with the default (stored) rows.  Also times the batch
prediction alone, and prints the fit errors docs/model.md tabulates.

    python benchmarks/strength_predict.py
"""

from __future__ import annotations

import statistics
import timeit

import numpy as np

from sass_tui.model.body.figure import Figure
from sass_tui.model.strength.strength import MOTIONS, StrengthSheet, fit_summary, read_strength_file


def best_of(fn, number: int = 2000, repeat: int = 7) -> tuple[float, float]:
    times = [t / number for t in timeit.repeat(fn, number=number, repeat=repeat)]
    return min(times), statistics.median(times)


def main() -> None:
    data = read_strength_file()
    figure = Figure.default("male")
    figure.set_strength_parameter("strength_type", "isokinetic")
    figure.set_strength_parameter("motion_speed", 30)
    figure.set_strength_parameter("fatigue_level", 20)
    sheet = StrengthSheet(data, figure)
    stored_best, stored_median = best_of(sheet.values)
    sheet.angles = sheet.angles + 2.5  # off every stored configuration
    values, stored = sheet.values()
    assert not stored.any() and np.isfinite(values).all()
    predicted_best, predicted_median = best_of(sheet.values)
    model = data.model("male", "right")
    motions = np.arange(len(MOTIONS))
    batch_best, batch_median = best_of(lambda: model.predict_median(motions, sheet.angles))
    print(f"rows per page: {len(MOTIONS)}")
    print(
        f"page, all predicted (values()): best {predicted_best * 1e6:.1f} us, "
        f"median {predicted_median * 1e6:.1f} us"
    )
    print(
        f"page, all stored (values()):    best {stored_best * 1e6:.1f} us, "
        f"median {stored_median * 1e6:.1f} us"
    )
    print(
        f"prediction equation alone:      best {batch_best * 1e6:.1f} us, "
        f"median {batch_median * 1e6:.1f} us"
    )
    print("\nfit error (relative, over the stored configurations):")
    for gender, side, fit in fit_summary(data):
        print(
            f"  {gender:6} {side:5} {fit.motion:26} n={fit.points}  "
            f"rms {fit.rms_percent:5.1f} %  max {fit.max_percent:5.1f} %  "
            f"varied {', '.join(fit.varied)}"
        )


if __name__ == "__main__":
    main()
