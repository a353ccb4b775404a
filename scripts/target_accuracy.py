"""How closely a target population's weighted people answer like the target:
the figures of docs/target-populations.md.

    python scripts/target_accuracy.py [--db PATH] [--seeds N]

Samples of civilian-like women (shorter and heavier than ANSUR II's; the
generator below, as tests/db/test_targets.py's) of 300 and 3,000 rows, N
seeds each.  For each: make the target over stature and mass (default
database, 1,986 ANSUR II women), then compare the weighted people with the
sample itself, computed here with numpy: the share with stature <= S and
mass <= M for S, M the sample's 50th and 90th percentiles; the 5th/50th/95th
stature and mass; and the Kish effective size.  Prints a Markdown table.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from sass_tui.db.engine.schema import connect  # noqa: E402
from sass_tui.db.populations.targets import make_target  # noqa: E402
from sass_tui.model.population.target_sample import Sample  # noqa: E402
from sass_tui.model.population.targets import weighted_percentile  # noqa: E402
from scripts.default_database import add_db_option, default_database  # noqa: E402

# U.S. civilian-like adult women: mean stature 160.5 cm (SD 6.8), median
# mass 74 kg (log SD 0.19), correlation 0.3 between stature and log mass.
STATURE_MEAN, STATURE_SD = 160.5, 6.8
MASS_MEDIAN, LOG_MASS_SD, CORRELATION = 74.0, 0.19, 0.3


def civilian_women(rows: int, seed: int) -> np.ndarray:
    """(rows, 2): stature cm, mass kg."""
    rng = np.random.default_rng(seed)
    z1, z2 = rng.standard_normal((2, rows))
    stature = STATURE_MEAN + STATURE_SD * z1
    log_mass = np.log(MASS_MEDIAN) + LOG_MASS_SD * (
        CORRELATION * z1 + np.sqrt(1 - CORRELATION**2) * z2
    )
    return np.column_stack([stature, np.exp(log_mass)])


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    parser.add_argument("--seeds", type=int, default=5)
    args = parser.parse_args()
    with default_database(args.db, say_build_time=False) as (path, _tmp):
        conn = connect(path)
        from sass_tui.db.people.values import load_values

        people = load_values(conn, ["stature", "mass"], "source = ansur2 AND gender = female")
        print(
            "| rows | seed | share at 50th: sample / weighted / unweighted "
            "| share at 90th: sample / weighted / unweighted "
            "| 50th stature: sample / weighted | 95th mass: sample / weighted | Kish n |"
        )
        print("|---|---|---|---|---|---|---|")
        for rows in (300, 3000):
            for seed in range(1, args.seeds + 1):
                values = civilian_women(rows, seed)
                sample = Sample(("stature", "mass"), values, rows, 0)
                target, weights, _ = make_target(conn, "check", "female", sample, "generated")
                w = weights.of(people.ids)
                cells = []
                for q in (50, 90):
                    s, m = np.percentile(values, q, axis=0)
                    own = 100 * np.mean((values[:, 0] <= s) & (values[:, 1] <= m))
                    inside = (people.matrix[:, 0] <= s) & (people.matrix[:, 1] <= m)
                    cells.append(
                        f"{own:.1f} / {100 * w[inside].sum() / w.sum():.1f} / "
                        f"{100 * inside.mean():.1f}"
                    )
                median = weighted_percentile(people.matrix[:, 0], w, [50])[0]
                mass95 = weighted_percentile(people.matrix[:, 1], w, [95])[0]
                print(
                    f"| {rows} | {seed} | {cells[0]} | {cells[1]} | "
                    f"{np.median(values[:, 0]):.1f} / {median:.1f} | "
                    f"{np.percentile(values[:, 1], 95):.1f} / {mass95:.1f} | "
                    f"{target.effective_n:.0f} |"
                )
        conn.close()


if __name__ == "__main__":
    main()
