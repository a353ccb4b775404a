"""How far the HAnim humanoid's joints stand from where a real body's landmarks
put them (docs/hanim.md, "Joint centres").

1. The landmark/stature ratios of sass_tui.model.hanim.LANDMARK_FRACTIONS,
   recomputed from the ANSUR II public files (means over every person).
2. ANSUR II people imported into a fresh database (`sass db import-ansur`),
   fetched back and exported as sass exports them (Figure.for_person against
   the shipped population, hanim.build_humanoid); for each, the exported
   joint centres against the person's own landmark heights in the CSV:
     skull vertex      stature
     shoulder          acromialheight - SHOULDER_BELOW_ACROMION
     hip               trochanterionheight
     knee              lateralfemoralepicondyleheight (and tibialheight)
     ankle             lateralmalleolusheight
   and the whole-body centre of mass (segment masses and centres of the
   export, de Leva 1996) as a share of the stature.
3. The same centre of mass for the shipped male 50th and female 5th
   percentile figures.

    python scripts/hanim_landmarks.py [--people 200]

Needs ../shared/data/ansur2 (the ANSUR II CSV files).
"""

from __future__ import annotations

import argparse
import csv
import sys
import tempfile
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from sass_tui.model.hanim import Humanoid

ROOT = Path(__file__).resolve().parents[1]
ANSUR = ROOT.parent / "shared" / "data" / "ansur2"
FILES = {"male": "ANSUR_II_MALE_Public.csv", "female": "ANSUR_II_FEMALE_Public.csv"}
COLUMNS = {
    "lateral_malleolus": "lateralmalleolusheight",
    "femoral_epicondyle": "lateralfemoralepicondyleheight",
    "trochanterion": "trochanterionheight",
    "iliocristale": "iliocristaleheight",
    "acromion": "acromialheight",
    "cervicale": "cervicaleheight",
    "omphalion": "waistheightomphalion",
}
# (joint, the CSV column whose height (mm) puts it, offset below that landmark in m)
CHECKS = (
    ("r_shoulder", "acromialheight", "shoulder"),
    ("r_hip", "trochanterionheight", 0.0),
    ("r_knee", "lateralfemoralepicondyleheight", 0.0),
    ("r_talocrural", "lateralmalleolusheight", 0.0),
)


def read_csv(gender: str, folder: Path = ANSUR) -> list[dict[str, str]]:
    with (folder / FILES[gender]).open(encoding="latin-1", newline="") as handle:
        return [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(handle)]


def landmark_fractions(folder: Path = ANSUR) -> dict[str, dict[str, float]]:
    """Mean landmark height / stature per gender, to 4 decimals."""
    out = {}
    for gender in FILES:
        rows = read_csv(gender, folder)
        stature = np.array([float(r["stature"]) for r in rows])
        fractions = {
            name: float(np.mean(np.array([float(r[c]) for r in rows]) / stature))
            for name, c in COLUMNS.items()
        }
        top = np.array([float(r["tragiontopofhead"]) for r in rows])
        fractions["tragion"] = float(np.mean(1 - top / stature))
        out[gender] = {k: round(v, 4) for k, v in fractions.items()}
    return out


def center_of_mass_share(humanoid: Humanoid, stature: float) -> float:
    """The humanoid's whole-body centre-of-mass height over `stature` (m)."""
    segments = humanoid.segments.values()
    mass = sum(s.mass for s in segments)
    return float(sum(s.mass * s.center_of_mass[1] for s in segments) / mass / stature)


def percentile_figures() -> dict[str, float]:
    """Centre of mass / stature of the shipped male 50th and female 5th figures."""
    from sass_tui.model.figure import Figure
    from sass_tui.model.hanim import build_humanoid

    out = {}
    for gender, percentile in (("male", 50.0), ("female", 5.0)):
        figure = Figure.default(gender)
        for group in figure.groups:
            figure.set_group_percentile(group, percentile)
        figure.set_mass_percentile(percentile)
        figure.set_stature_percentile(percentile)
        out[f"{gender} {percentile:g}th"] = center_of_mass_share(
            build_humanoid(figure), figure.stature / 100
        )
    return out


def measure(people: int = 200, folder: Path = ANSUR) -> dict[str, object]:
    """Export `people` ANSUR II people (half men, half women, evenly spread
    over each file) and measure their joints against their own landmarks."""
    from sass_tui.db.ansur import import_ansur
    from sass_tui.db.individual import fetch_individual, find_person
    from sass_tui.db.schema import connect
    from sass_tui.model.figure import Figure
    from sass_tui.model.hanim import SHOULDER_BELOW_ACROMION, build_humanoid
    from sass_tui.model.names import GROUPS

    errors: dict[str, list[float]] = {
        "vertex": [],
        **{joint: [] for joint, _, _ in CHECKS},
        "knee vs tibiale": [],
    }
    com_share: list[float] = []
    population = {g: Figure.default(g) for g in FILES}
    with tempfile.TemporaryDirectory() as tmp:
        conn = connect(Path(tmp) / "ansur.db", create=True)
        import_ansur(conn, [folder / FILES["male"], folder / FILES["female"]])
        for gender in FILES:
            rows = read_csv(gender, folder)
            step = len(rows) / (people // 2)
            letter = "M" if gender == "male" else "F"
            for k in range(people // 2):
                row = rows[int(k * step)]
                person = fetch_individual(
                    conn, find_person(conn, f"ANSUR II {letter} {row['subjectid']}")
                )
                figure = population[gender].for_person(
                    person.name,
                    person.gender,
                    {g: person.groups[g] for g in GROUPS},
                    mass=person.mass,
                    stature=person.stature,
                )
                humanoid = build_humanoid(figure)
                vertex = humanoid.sites[0].translation[1]
                errors["vertex"].append(vertex - float(row["stature"]) / 1000)
                for joint, column, offset in CHECKS:
                    below = SHOULDER_BELOW_ACROMION if offset == "shoulder" else offset
                    target = float(row[column]) / 1000 - below
                    errors[joint].append(humanoid.centers[joint][1] - target)
                errors["knee vs tibiale"].append(
                    humanoid.centers["r_knee"][1] - float(row["tibialheight"]) / 1000
                )
                com_share.append(center_of_mass_share(humanoid, float(row["stature"]) / 1000))
        conn.close()
    return {
        "people": people,
        "mae_cm": {k: float(np.mean(np.abs(v)) * 100) for k, v in errors.items()},
        "max_cm": {k: float(np.max(np.abs(v)) * 100) for k, v in errors.items()},
        "bias_cm": {k: float(np.mean(v) * 100) for k, v in errors.items()},
        "com_shares": com_share,
        "com_percent": (
            float(np.min(com_share) * 100),
            float(np.mean(com_share) * 100),
            float(np.max(com_share) * 100),
        ),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--people", type=int, default=200)
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT))
    from sass_tui.model.hanim import LANDMARK_FRACTIONS

    fractions = landmark_fractions()
    print("landmark / stature (ANSUR II means):")
    for gender, values in fractions.items():
        same = values == LANDMARK_FRACTIONS[gender]
        print(f"  {gender}: {values}  {'= hanim.LANDMARK_FRACTIONS' if same else 'DIFFERS'}")
    result = measure(args.people)
    print(f"\n{result['people']} ANSUR II people exported from a database:")
    print("| joint | landmark | mean abs. error | max | mean (export - landmark) |")
    print("|---|---|---|---|---|")
    names = {
        "vertex": "stature",
        "r_shoulder": "acromion height - 4 cm",
        "r_hip": "trochanterion height",
        "r_knee": "lateral femoral epicondyle height",
        "knee vs tibiale": "tibiale height",
        "r_talocrural": "lateral malleolus height",
    }
    for key, label in names.items():
        print(
            f"| {key} | {label} | {result['mae_cm'][key]:.2f} cm | "
            f"{result['max_cm'][key]:.2f} cm | {result['bias_cm'][key]:+.2f} cm |"
        )
    low, mean, high = result["com_percent"]
    print(f"\nwhole-body centre of mass: {low:.2f} - {high:.2f} % of stature (mean {mean:.2f} %)")
    for name, share in percentile_figures().items():
        print(f"  {name} percentile figure: {share * 100:.2f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
