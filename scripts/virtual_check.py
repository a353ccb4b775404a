"""Check the shipped virtual population nhanes-2017-2020 against NHANES
itself (docs/target-populations.md, "Virtual populations: the check").

    python scripts/virtual_check.py [--db PATH]

For each gender, weighted 5th/50th/95th percentiles (cumulative weight, by
WTMECPRP) of
- stature and mass: NHANES's own, kept by every virtual person;
- hip circumference (BMXHIP) / buttockcircumference: NHANES's own, kept
  (predicted for the rows without one);
- upper arm length (BMXARML, acromion to olecranon) / shoulderelbowlength,
  which the virtual people have predicted (NHANES's is not used: a
  different landmark; scripts/virtual_validation.py validates the rest).
NHANES is read from ../shared/data/nhanes (the published file), not through sass.
"""

from __future__ import annotations

import argparse
import csv
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from sass_tui.db.engine.schema import connect  # noqa: E402
from sass_tui.db.people.values import load_values  # noqa: E402
from sass_tui.db.populations.shipped import load_weights  # noqa: E402
from scripts.default_database import add_db_option, default_database  # noqa: E402

PUBLISHED = ROOT.parent / "shared" / "data" / "nhanes" / "nhanes_p_demo_bmx_2020.csv"
PAIRS = (
    ("BMXHT", "stature"),
    ("BMXWT", "mass"),
    ("BMXHIP", "measure.buttockcircumference"),
    ("BMXARML", "measure.shoulderelbowlength"),
)


def by_cumulative_weight(values: np.ndarray, weights: np.ndarray, q: float) -> float:
    keep = ~np.isnan(values)
    values, weights = values[keep], weights[keep]
    order = np.argsort(values)
    share = np.cumsum(weights[order]) / weights.sum()
    return float(values[order][np.searchsorted(share, q)])


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    args = parser.parse_args()
    lines = [line for line in PUBLISHED.read_text().splitlines() if not line.startswith("#")]
    rows = [
        r
        for r in csv.DictReader(lines)
        if r["RIDAGEYR"] != "NA"
        and float(r["RIDAGEYR"]) >= 20
        and r["BMXHT"] != "NA"
        and r["BMXWT"] != "NA"
    ]
    with default_database(args.db, say_build_time=False) as (path, _tmp):
        conn = connect(path)
        weights = load_weights(conn, "virtual:nhanes-2017-2020")
        print("| gender | NHANES measured | virtual (predicted) | 5th | 50th | 95th |")
        print("| --- | --- | --- | --- | --- | --- |")
        for gender, code in (("female", "2"), ("male", "1")):
            mine = [r for r in rows if r["RIAGENDR"] == code]
            survey = np.array([float(r["WTMECPRP"]) for r in mine])
            values = load_values(
                conn,
                [field for _, field in PAIRS],
                f'source = "virtual:nhanes-2017-2020" AND gender = {gender}',
            )
            w = weights.of(values.ids)
            for j, (column, field) in enumerate(PAIRS):
                measured = np.array(
                    [np.nan if r[column] == "NA" else float(r[column]) for r in mine]
                )
                cells = []
                for q in (0.05, 0.50, 0.95):
                    own = by_cumulative_weight(measured, survey, q)
                    virtual = by_cumulative_weight(values.matrix[:, j], w, q)
                    cells.append(f"{own:.1f} / {virtual:.1f}")
                print(f"| {gender} | {column} | {field} | " + " | ".join(cells) + " |")
        conn.close()


if __name__ == "__main__":
    main()
