"""The published NHANES 2017-March 2020 file (../shared/data/nhanes), read
here for the tests that hold sass's numbers to it, not through sass."""

from __future__ import annotations

import csv

import numpy as np

from tests._paths import nhanes_lines


def nhanes(gender_code: str, *columns: str) -> tuple[np.ndarray, np.ndarray]:
    """Adults 20+ of one gender (RIAGENDR: "1" male, "2" female) with a
    height and a weight: the columns (NaN: not measured) and WTMECPRP, in
    the file's order."""
    lines = nhanes_lines()  # the test skips, naming the file, without ../shared
    rows = [
        r
        for r in csv.DictReader(lines)
        if r["RIAGENDR"] == gender_code
        and r["RIDAGEYR"] != "NA"
        and float(r["RIDAGEYR"]) >= 20
        and r["BMXHT"] != "NA"
        and r["BMXWT"] != "NA"
    ]
    values = np.array([[np.nan if r[c] == "NA" else float(r[c]) for c in columns] for r in rows])
    return values, np.array([float(r["WTMECPRP"]) for r in rows])


def by_cumulative_weight(values: np.ndarray, weights: np.ndarray, q: float) -> float:
    """The smallest value whose cumulative weight share reaches q."""
    keep = ~np.isnan(values)
    values, weights = values[keep], weights[keep]
    order = np.argsort(values)
    share = np.cumsum(weights[order]) / weights.sum()
    return float(values[order][np.searchsorted(share, q)])
