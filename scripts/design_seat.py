"""The worked seat of docs/accommodation.md, "Design": the limits of a seat pan
that accommodate 95 % of U.S. civilian adults (the shipped virtual population
nhanes-2017-2020, weighted by NHANES's examination weights, the genders in
the survey's proportions), solved by `sass design`, beside what the usual
2.5th-97.5th / 5th-95th percentile limits accommodate (counted by `sass fit`).

    python scripts/design_seat.py [--db PATH]

Without --db it builds the default database in a temporary directory.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sass_tui.db.engine.schema import connect
from sass_tui.db.people.values import load_values
from sass_tui.db.populations.design import design
from sass_tui.db.populations.fit import fit_test
from sass_tui.db.populations.shipped import load_weights
from sass_tui.model.population.targets import weighted_percentile

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from scripts.default_database import add_db_option, default_database

POPLITEAL = "measure.poplitealheight"
DEPTH = "measure.buttockpopliteallength"
HIP = "measure.hipbreadthsitting"
SEAT = f"{POPLITEAL} BETWEEN ? AND ? AND {DEPTH} >= ? AND {HIP} <= ?"


def percentile_limits(conn, people, target, low: float, high: float) -> str:
    """The seat's limits at the population's own weighted percentiles: the
    range from `low` to `high`, the one-sided limits at the same tails."""
    values = load_values(conn, [POPLITEAL, DEPTH, HIP], people)
    w = target.of(values.ids)

    def at(column: int, percent: float) -> float:
        return float(weighted_percentile(values.matrix[:, column], w, [percent])[0])

    return (
        f"{POPLITEAL} BETWEEN {at(0, low):.1f} cm AND {at(0, high):.1f} cm AND "
        f"{DEPTH} >= {at(1, 100 - high):.1f} cm AND {HIP} <= {at(2, high):.1f} cm"
    )


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    args = parser.parse_args()
    with default_database(args.db, say_build_time=False) as (path, _out):
        conn = connect(path)
        target = load_weights(conn, "virtual:nhanes-2017-2020")
        people = target.target.population
        print(f"sass design --virtual nhanes-2017-2020 --accommodate 95 {SEAT!r}\n")
        for percent in (95.0, 90.0):
            solved = design(conn, SEAT, percent, people, None, target)
            print(f"accommodate {percent:g} %:")
            for text, limit in zip(solved.texts, solved.solved):
                assert limit is not None
                print(
                    f"  {text:<56} below {100 * limit.excluded_below:4.1f} %  "
                    f"above {100 * limit.excluded_above:4.1f} %"
                )
            fit = solved.fit
            genders = ", ".join(f"{g} {s.percent:.1f} %" for g, s in fit.genders.items())
            print(f"  sass fit of these limits: {fit.weighted_percent:.1f} % ({genders})\n")
        for low, high in ((2.5, 97.5), (5.0, 95.0)):
            limits = percentile_limits(conn, people, target, low, high)
            fit = fit_test(conn, limits, people, target=target)
            genders = ", ".join(f"{g} {s.percent:.1f} %" for g, s in fit.genders.items())
            print(f"percentiles {low:g}-{high:g}: {limits}")
            print(f"  sass fit: {fit.weighted_percent:.1f} % ({genders})\n")
        conn.close()


if __name__ == "__main__":
    main()
