"""Write datasets/global.dat: stature and mass at 5/50/95 for each gender.

The SASS report does not tabulate them.  Its one fixed point is the male 50th
percentile mass, 82.2 kg, which appendix F's segment masses imply with the
appendix K fractions.  The spread around it, and the other statistics, come
from the ANSUR II public survey (../shared/data/ansur2), as docs/data-sources.md
explains.  Run from the repository root:  python scripts/make_global_stats.py
"""

from __future__ import annotations

import csv
import sys
from pathlib import Path

import numpy as np

from sass_tui.model.files.atomic import write_text_atomic

ROOT = Path(__file__).resolve().parent.parent
ANSUR = ROOT.parent / "shared" / "data" / "ansur2"
REPORT_MALE_MEDIAN_MASS = 82.2  # kg: appendix F masses / appendix K fractions


def column(path: Path, name: str) -> np.ndarray:
    with path.open(encoding="latin-1", newline="") as handle:
        return np.array([float(r[name]) for r in csv.DictReader(handle)])


def main() -> None:
    lines = [
        "C NASA Crewmember Trainees",
        "C Global statistics: stature (cm) and mass (kg) at the 5th, 50th, 95th percentiles",
        "C Format: the population file format with one value triple per row (sass extension).",
        "C Male 50th mass 82.2 kg: SASS report appendix F masses over appendix K fractions.",
        "C Male 5th/95th mass: 82.2 kg times the ANSUR II male ratios p5/p50 and p95/p50.",
        "C Stature (both genders) and female mass: ANSUR II public data (Gordon et al. 2014),",
        "C percentiles computed by scripts/make_global_stats.py; the NASA-STD-3000 tables",
        "C could not be checked (docs/data-sources.md).",
    ]
    for gender, fname in (
        ("MALE", "ANSUR_II_MALE_Public.csv"),
        ("FEMALE", "ANSUR_II_FEMALE_Public.csv"),
    ):
        stature = np.percentile(column(ANSUR / fname, "stature"), [5, 50, 95]) / 10.0
        mass = np.percentile(column(ANSUR / fname, "weightkg"), [5, 50, 95]) / 10.0
        if gender == "MALE":
            mass = mass / mass[1] * REPORT_MALE_MEDIAN_MASS
        lines += ["C", f"T {gender}", "C   05%     50%     95%   comment"]
        lines.append("  " + "  ".join(f"{v:6.1f}" for v in stature) + "   /* stature */")
        lines.append("  " + "  ".join(f"{v:6.1f}" for v in mass) + "   /* mass */")
    text = "\n".join(lines) + "\n"
    write_text_atomic(ROOT / "datasets" / "global.dat", text)
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
