"""Strength answers: one Arm Force Field evaluation (spec: under 1 ms), and
percent capable over the 6,068 real people of ANSUR II (spec: under 50 ms),
each beside a baseline measured in the same run.

- arm_force(): the shoulder axes, the network, the bounds and the arm's
  weight for one hand; baseline: one Anderson et al. 2007 lookup
  (lower_limb_strength), sass's other published strength model.
- lower_limb_capable(): each person's probability of exerting a knee
  extension torque (their own gender, age, mass and stature), the
  arithmetic of `sass fit --strength` and `sass task --target`; baseline:
  the same people one at a time (lower_limb_percent_capable), as the fit
  test did before.

    python benchmarks/strength_capable.py
"""

from __future__ import annotations

import statistics
import timeit

import numpy as np

from sass_tui.db.engine.database import Database
from sass_tui.db.people.values import load_values
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure
from sass_tui.model.strength.arm_force_field import arm_force
from sass_tui.model.strength.percent_capable import lower_limb_capable
from sass_tui.model.strength.published_strength import (
    Subject,
    lower_limb_percent_capable,
    lower_limb_strength,
)


def best_of(fn, number: int, repeat: int = 7) -> tuple[float, float]:
    times = [t / number for t in timeit.repeat(fn, number=number, repeat=repeat)]
    return min(times), statistics.median(times)


def main() -> None:
    body = pose_figure(Figure.default("female"), parse_angles(["shoulder_y=90", "elbow_y=0"]))
    aff = best_of(lambda: arm_force(body.points, "right", (0, 1, 0), "female", 66.8), 2000)
    subject = Subject("female", 22, 66.8, 1.626)
    anderson = best_of(lambda: lower_limb_strength("knee_extension", subject, 60.0), 2000)
    print(
        f"arm_force, one hand:           best {aff[0] * 1e6:7.1f} us, median {aff[1] * 1e6:7.1f} us"
    )
    print(
        f"baseline lower_limb_strength:  best {anderson[0] * 1e6:7.1f} us, median {anderson[1] * 1e6:7.1f} us"
    )
    print(f"ratio (median): {aff[1] / anderson[1]:.1f}x")

    db = Database.open(None)
    with db.connection() as conn:
        values = load_values(conn, ["age", "mass", "stature"], "source = ansur2")
    db.close()
    genders = np.array(values.genders, dtype=object)
    age, mass, stature = values.matrix.T
    people = len(values.ids)

    def many() -> np.ndarray:
        return lower_limb_capable("knee_extension", genders, age, mass, stature / 100, 150.0, 60.0)

    def one_by_one() -> list[float]:
        return [
            lower_limb_percent_capable("knee_extension", Subject(g, a, m, s / 100), 150.0, 60.0)
            for g, a, m, s in zip(genders, age, mass, stature)
            if 18 <= a <= 100
        ]

    vector = best_of(many, 20)
    loop = best_of(one_by_one, 2, repeat=3)
    shares = many()
    print(f"\npercent capable over {people} ANSUR II people (knee extension 150 N-m at 60 deg):")
    print(
        f"  numpy, all at once:          best {vector[0] * 1e3:7.2f} ms, median {vector[1] * 1e3:7.2f} ms"
    )
    print(
        f"  baseline, one at a time:     best {loop[0] * 1e3:7.2f} ms, median {loop[1] * 1e3:7.2f} ms"
    )
    print(
        f"  ratio (median): {loop[1] / vector[1]:.0f}x faster; mean share {100 * np.nanmean(shares):.1f} %"
    )


if __name__ == "__main__":
    main()
