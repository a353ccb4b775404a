"""The reach model (sass_tui/model/body/reach.py) against ANSUR II's measured
reach (docs/reach.md).

For every ANSUR II person (4,082 men, 1,986 women; Gordon et al. 2014), the
survey's three reach measures -- thumbtipreach, overheadfingertipreachsitting,
span -- computed from the person's OTHER measurements (acromial height,
biacromial breadth, acromion-radiale length, wrist height, hand length,
forearm-hand and forearm-centre-of-grip lengths, chest depth, sitting
height, stature, iliocristale height; the reach measures withheld) through
the same linkage `sass reach` uses, against the measured values.

The shoulder travels (reach.TRAVEL) are the model's only numbers fitted to
reach: here they are fitted on one half of each gender (odd subject ids)
and the errors printed for the other half (even ids), then the other way
round, so every person's error is out of sample.  The travels over everyone
(what reach.py ships) and the grip share and sitting-height fraction are
recomputed and compared with the module's.

    python scripts/reach_validation.py [--ansur DIR] [--markdown]
"""

from __future__ import annotations

import argparse
import csv
import sys
from pathlib import Path

import numpy as np

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.body.reach import (
    GRIP_SHARE,
    LINKAGE_MEASURES,
    REACH_MEASURES,
    SITTING_HEIGHT_FRACTION,
    TRAVEL,
    Linkage,
    arm_limits,
    linkage_from_measures,
    overhead_rise,
    reach_measures,
)

ROOT = Path(__file__).resolve().parents[1]
FILES = {"male": "ANSUR_II_MALE_Public.csv", "female": "ANSUR_II_FEMALE_Public.csv"}
INPUTS = ("subjectid", *LINKAGE_MEASURES)


def read(folder: Path, gender: str) -> dict[str, np.ndarray]:
    """The columns (cm; the CSV holds mm) of every person of `gender`."""
    with open(folder / FILES[gender], encoding="latin-1", newline="") as handle:
        rows = [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(handle)]
    out = {name: np.array([float(r[name]) for r in rows]) / 10.0 for name in INPUTS}
    out["subjectid"] *= 10.0
    for name in REACH_MEASURES:
        out[name] = np.array([float(r[name]) for r in rows]) / 10.0
    return out


def fitted_travel(linkage: Linkage, measured: dict[str, np.ndarray], chosen: np.ndarray):
    """The mean travel (m) that gives the `chosen` people's measured reach."""
    bare = reach_measures(linkage, travel=np.zeros_like(linkage.travel))
    rise = overhead_rise(linkage.limits)
    forward = (measured["thumbtipreach"] - bare["thumbtipreach"])[chosen].mean() / 100
    up = (
        (measured["overheadfingertipreachsitting"] - bare["overheadfingertipreachsitting"])[
            chosen
        ].mean()
        / 100
        / rise**2
    )
    sideways = (measured["span"] - bare["span"])[chosen].mean() / 200
    return np.array([forward, up, sideways])


def validate(folder: Path) -> tuple[list[str], bool]:
    lines = [
        "| gender | measure | people | measured mean (cm) | mean error (cm) | RMSE (cm) "
        "| SD of the measure (cm) |",
        "|---|---|---|---|---|---|---|",
    ]
    notes = []
    ok = True
    for gender in ("male", "female"):
        values = read(folder, gender)
        limits = arm_limits(build_humanoid(Figure.default(gender)), "right")
        linkage = linkage_from_measures(gender, values, limits)
        ids = values["subjectid"].astype(np.int64)
        halves = (ids % 2 == 1, ids % 2 == 0)
        predicted = {name: np.empty(linkage.count) for name in REACH_MEASURES}
        for fit_on, test_on in (halves, halves[::-1]):
            travel = np.tile(fitted_travel(linkage, values, fit_on), (linkage.count, 1))
            got = reach_measures(linkage, travel=travel)
            for name in REACH_MEASURES:
                predicted[name][test_on] = got[name][test_on]
        for name in REACH_MEASURES:
            error = predicted[name] - values[name]
            lines.append(
                f"| {gender} | `{name}` | {linkage.count} | {values[name].mean():.1f} "
                f"| {error.mean():+.2f} | {np.sqrt((error**2).mean()):.2f} "
                f"| {values[name].std():.2f} |"
            )
        everyone = fitted_travel(linkage, values, np.ones(linkage.count, dtype=bool))
        shipped = np.array(TRAVEL[gender])
        notes.append(
            f"{gender}: travel over everyone (forward, up, sideways) "
            f"{', '.join(f'{v * 100:.2f}' for v in everyone)} cm; reach.TRAVEL "
            f"{', '.join(f'{v * 100:.2f}' for v in shipped)} cm"
        )
        ok &= bool(np.abs(everyone - shipped).max() < 0.0005)
        grip = (
            values["handlength"]
            - (values["forearmhandlength"] - values["forearmcenterofgriplength"])
        ) / values["handlength"]
        sitting = (values["sittingheight"] / values["stature"]).mean()
        notes.append(
            f"{gender}: grip share {grip.mean():.3f} (reach.GRIP_SHARE {GRIP_SHARE[gender]}), "
            f"sitting height / stature {sitting:.4f} "
            f"(reach.SITTING_HEIGHT_FRACTION {SITTING_HEIGHT_FRACTION[gender]})"
        )
        ok &= abs(grip.mean() - GRIP_SHARE[gender]) < 0.0005
        ok &= abs(sitting - SITTING_HEIGHT_FRACTION[gender]) < 0.00005
    return [*lines, "", *(f"- {note}" for note in notes)], ok


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument(
        "--ansur",
        type=Path,
        default=ROOT.parent / "shared" / "data" / "ansur2",
        help="the folder of the ANSUR II public CSV files",
    )
    args = parser.parse_args()
    lines, ok = validate(args.ansur)
    print("\n".join(lines))
    if not ok:
        print("reach.py's constants differ from these: update them", file=sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
