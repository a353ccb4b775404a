"""Validate a virtual population against what its survey measured
(docs/target-populations.md, "Validated against what NHANES measured").

    python scripts/virtual_validation.py [--db PATH] [--sample FILE --weight COLUMN]

The virtual people are made here as `sass target NAME --virtual` makes them
(db/populations/virtual.py's make_virtual, the same seed), in memory, from
the shipped NHANES 2017-March 2020 adults (default) or from any sample file
with a gender column (`--sample`; `--weight` its survey weight column), and
compared with the sample's own measurements:

1. Held out: a virtual population made with one measured column left out
   of the sample (waist, then hip), so that sass predicts it from the rest
   (stature, mass, the other girth, age), against what the survey measured:
   weighted mean and SD per gender and mass band, and per age band.
2. The virtual population as made (hip and waist kept): popliteal height
   (a leg length nobody measured on the civilians) per mass band, beside
   the real people of the database in the same band (stature band of each
   gender's median), and the share flagged outside the real people's range.
3. The joint distribution: weighted correlations of stature, mass, hip,
   waist and upper arm (the virtual people's shoulderelbowlength against
   NHANES's BMXARML, a different landmark: its level differs, its
   correlations are comparable), virtual against measured.

Weights: the survey's (the virtual people's are the same, rescaled).
Prints markdown tables.
"""

from __future__ import annotations

import argparse
import csv
import io
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from sass_tui.db.engine.schema import connect  # noqa: E402
from sass_tui.db.people.values import load_values  # noqa: E402
from sass_tui.db.populations.virtual import (  # noqa: E402
    MEASURED,
    PREDICTED_FROM,
    make_virtual,
    shipped_sample,
)
from sass_tui.model.datasets import NHANES, shipped_text  # noqa: E402
from sass_tui.model.files.sample_file import read_sample  # noqa: E402
from sass_tui.model.measures import MEASURES  # noqa: E402
from sass_tui.model.population.target_sample import Sample  # noqa: E402
from sass_tui.model.vocabulary import GENDERS  # noqa: E402
from scripts.default_database import add_db_option, default_database  # noqa: E402

HIP, WAIST = MEASURED
MASS_BANDS = ((0, 60), (60, 80), (80, 100), (100, 120), (120, 1000))
AGE_BANDS = ((20, 40), (40, 60), (60, 200))
STATURE_BANDS = {"female": (160.0, 165.0), "male": (172.5, 177.5)}
UPPER_ARM = "upper_arm_length"  # NHANES's BMXARML in the shipped file


def weighted(x: np.ndarray, w: np.ndarray) -> tuple[float, float, int]:
    keep = ~np.isnan(x)
    x, w = x[keep], w[keep]
    if len(x) < 2:
        return np.nan, np.nan, len(x)
    mean = float(np.average(x, weights=w))
    return mean, float(np.sqrt(np.average((x - mean) ** 2, weights=w))), len(x)


def correlation(x: np.ndarray, y: np.ndarray, w: np.ndarray) -> float:
    keep = ~(np.isnan(x) | np.isnan(y))
    x, y, w = x[keep], y[keep], w[keep]
    mx, my = np.average(x, weights=w), np.average(y, weights=w)
    cov = np.average((x - mx) * (y - my), weights=w)
    return float(
        cov / np.sqrt(np.average((x - mx) ** 2, weights=w) * np.average((y - my) ** 2, weights=w))
    )


def column(people_measures: np.ndarray, field: str) -> np.ndarray:
    name = {"stature": "stature", "mass": "weightkg"}.get(field, field.removeprefix("measure."))
    return people_measures[:, MEASURES.index(name)]


def without(sample: Sample, field: str) -> Sample:
    """The sample with one measured column left out (predicted then)."""
    keep = [j for j, f in enumerate(sample.optional_fields) if f != field]
    optional = None if sample.optional is None else sample.optional[:, keep]
    return replace(
        sample,
        optional_fields=tuple(sample.optional_fields[j] for j in keep),
        optional=optional,
    )


def in_batch_order(sample: Sample) -> np.ndarray:
    """The sample's row of each virtual person: make_virtual makes the
    genders in GENDERS order, each gender's rows in the sample's."""
    genders = np.array(sample.genders, dtype=object)
    return np.concatenate([np.flatnonzero(genders == g) for g in GENDERS])


def cell(mean: float, sd: float) -> str:
    return "-" if np.isnan(mean) else f"{mean:.1f} / {sd:.1f}"


def held_out(conn, sample: Sample, name: str) -> None:
    print("\n#### Held out: predicted (virtual) against measured (survey), mean / SD cm\n")
    print("| gender | band | n | waist measured | waist predicted | hip measured | hip predicted |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    made = {f: make_virtual(conn, "check", without(sample, f), name) for f in (WAIST, HIP)}
    genders = np.array(made[WAIST].people.gender, dtype=object)
    order = in_batch_order(sample)
    # make_virtual lists the genders in GENDERS order; the sample's rows follow it
    measured = {f: sample.optional[order, sample.optional_fields.index(f)] for f in (WAIST, HIP)}
    mass = sample.matrix[order, 1]
    ages = sample.ages[order] if sample.ages is not None else np.full(len(order), np.nan)
    w = made[WAIST].weights
    bands = [("mass", lo, hi, mass) for lo, hi in MASS_BANDS] + [
        ("age", lo, hi, ages) for lo, hi in AGE_BANDS
    ]
    for gender in ("female", "male"):
        for what, lo, hi, x in bands:
            sel = (genders == gender) & (x >= lo) & (x < hi)
            label = f"{what} {lo}-{hi}" if hi < 200 else f"{what} {lo}+"
            cells = []
            for f in (WAIST, HIP):
                cells.append(cell(*weighted(measured[f][sel], w[sel])[:2]))
                cells.append(cell(*weighted(column(made[f].people.measures, f)[sel], w[sel])[:2]))
            print(f"| {gender} | {label} | {int(sel.sum())} | " + " | ".join(cells) + " |")


def as_made(conn, sample: Sample, name: str) -> None:
    print("\n#### As made: popliteal height in the stature band, mean / SD cm\n")
    print("| gender | stature band | mass band | virtual n | virtual | real n | real people |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    made = make_virtual(conn, "check", sample, name)
    genders = np.array(made.people.gender, dtype=object)
    popliteal = column(made.people.measures, "measure.poplitealheight")
    real = load_values(
        conn, ["stature", "mass", "measure.poplitealheight"], "gender = male OR gender = female"
    )
    real_gender = np.array(real.genders, dtype=object)
    for gender in ("female", "male"):
        lo_s, hi_s = STATURE_BANDS[gender]
        for lo, hi in MASS_BANDS:
            sel = (genders == gender) & (made.people.stature >= lo_s) & (made.people.stature < hi_s)
            sel &= (made.people.mass >= lo) & (made.people.mass < hi)
            mean, sd, n = weighted(popliteal[sel], made.weights[sel])
            r = (real_gender == gender) & (real.matrix[:, 0] >= lo_s) & (real.matrix[:, 0] < hi_s)
            r &= (real.matrix[:, 1] >= lo) & (real.matrix[:, 1] < hi)
            rmean, rsd, rn = weighted(real.matrix[r, 2], np.ones(int(r.sum())))
            band = f"{lo}-{hi}" if hi < 1000 else f"over {lo}"
            print(
                f"| {gender} | {lo_s:g}-{hi_s:g} | {band} kg | {n} | {cell(mean, sd)} | {rn} | {cell(rmean, rsd)} |"
            )
        mine = genders == gender
        share = made.weights[mine & made.outside].sum() / made.weights[mine].sum()
        print(
            f"| {gender} | flagged outside the real people's range | | {int((mine & made.outside).sum())} | {100 * share:.1f} % of the weight | | |"
        )


def joint(conn, sample: Sample, name: str, arm: np.ndarray | None) -> None:
    print("\n#### Joint distribution: weighted correlations, virtual / measured\n")
    order = in_batch_order(sample)
    survey = {
        "stature": sample.matrix[order, 0],
        "mass": sample.matrix[order, 1],
        "hip": sample.optional[order, sample.optional_fields.index(HIP)],
        "waist": sample.optional[order, sample.optional_fields.index(WAIST)],
    }
    if arm is not None:
        survey["upper arm"] = arm[order]
    fields = {
        "stature": "stature",
        "mass": "mass",
        "hip": HIP,
        "waist": WAIST,
        "upper arm": "measure.shoulderelbowlength",
    }
    pairs = [
        ("stature", "upper arm"),
        ("mass", "upper arm"),
        ("stature", "hip"),
        ("mass", "hip"),
        ("mass", "waist"),
        ("hip", "waist"),
    ]
    pairs = [p for p in pairs if all(k in survey for k in p)]
    print("| virtual people | gender | " + " | ".join(f"{a}-{b}" for a, b in pairs) + " |")
    print("| --- | --- |" + " --- |" * len(pairs))
    variants = (
        ("as made (hip, waist kept)", sample),
        ("hip and waist predicted", without(without(sample, WAIST), HIP)),
    )
    for label, variant in variants:
        made = make_virtual(conn, "check", variant, name)
        genders = np.array(made.people.gender, dtype=object)
        for gender in ("female", "male"):
            sel = genders == gender
            w = made.weights[sel]
            cells = []
            for a, b in pairs:
                va, vb = (column(made.people.measures, fields[k])[sel] for k in (a, b))
                mine = correlation(va, vb, w)
                cells.append(f"{mine:.2f} / {correlation(survey[a][sel], survey[b][sel], w):.2f}")
            print(f"| {label} | {gender} | " + " | ".join(cells) + " |")


def main() -> None:
    parser = argparse.ArgumentParser()
    add_db_option(parser)
    parser.add_argument(
        "--sample", help="a sample file with a gender column (default: the shipped NHANES adults)"
    )
    parser.add_argument("--weight", help="its survey weight column")
    args = parser.parse_args()
    if args.sample is None:
        name, sample = "nhanes-2017-2020", shipped_sample()
        text = shipped_text(NHANES)
    else:
        name = args.sample
        text = Path(args.sample).read_text(encoding="utf-8")
        sample = read_sample(
            text, PREDICTED_FROM, name, weight=args.weight, need_gender=True, optional=MEASURED
        )
    if set(sample.optional_fields) != set(MEASURED):
        raise SystemExit(f"{name}: the sample needs a hip and a waist column to validate against")
    arm_values = _upper_arm(text, sample)
    with default_database(args.db, say_build_time=False) as (path, _tmp):
        conn = connect(path)
        held_out(conn, sample, name)
        as_made(conn, sample, name)
        joint(conn, sample, name, arm_values)
        conn.close()


def _upper_arm(text: str, sample: Sample) -> np.ndarray | None:
    """The sample's upper arm length column, row for row with `sample` (the
    shipped NHANES file's `upper_arm_length[cm]`), or None."""
    rows = list(csv.DictReader(io.StringIO(text)))
    key = next((k for k in rows[0] if k.lower().startswith(UPPER_ARM)), None) if rows else None
    if key is None:
        return None
    complete = [
        r for r in rows if r.get("stature[cm]", "").strip() and r.get("mass[kg]", "").strip()
    ]
    if len(complete) != len(sample.matrix):
        return None
    return np.array([float(r[key]) if r[key].strip() else np.nan for r in complete])


if __name__ == "__main__":
    main()
