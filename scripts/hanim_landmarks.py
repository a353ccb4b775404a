"""How far the HAnim humanoid's joints stand from where a real body's landmarks
put them (docs/hanim.md, "Joint centres").

1. The landmark/stature ratios of sass_tui.model.body.hanim.LANDMARK_FRACTIONS,
   recomputed from the ANSUR II public files (means over every person).
2. ANSUR II people (all 6,068, or a sample) imported into a fresh database
   (`sass db import-ansur`), fetched back and exported as `sass export hanim
   --person` exports them (db.individual.person_figure against the shipped
   population, hanim.build_humanoid); for each, the height of every site
   their measurements place (model/body/landmarks.py) against the CSV column it
   comes from, the acromion sites' spacing against biacromialbreadth, the
   joints placed at a landmark against it, and the whole-body centre of
   mass (de Leva 1996) as a share of the stature.
3. The same centre of mass for the shipped male 50th and female 5th
   percentile figures.

    python scripts/hanim_landmarks.py [--people 200]   # default: everyone

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
    from sass_tui.model.body.hanim import Humanoid

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
# (site, the CSV column of its height (mm); None: derived, see SITE_HEIGHTS)
SITES = (
    ("skull_vertex_pt", "stature"),
    ("cervicale_pt", "cervicaleheight"),
    ("suprasternale_pt", "suprasternaleheight"),
    ("r_acromion_pt", "acromialheight"),
    ("l_acromion_pt", "acromialheight"),
    ("r_radiale_pt", None),
    ("l_radiale_pt", None),
    ("r_iliocristale_pt", "iliocristaleheight"),
    ("l_iliocristale_pt", "iliocristaleheight"),
    ("r_trochanterion_pt", "trochanterionheight"),
    ("l_trochanterion_pt", "trochanterionheight"),
    ("r_tibiale_pt", "tibialheight"),
    ("l_tibiale_pt", "tibialheight"),
    ("r_lateral_malleolus_pt", "lateralmalleolusheight"),
    ("l_lateral_malleolus_pt", "lateralmalleolusheight"),
)
# (joint, the CSV column of the landmark that places it)
JOINTS = (
    ("r_radiocarpal", "wristheight"),
    ("r_hip", "trochanterionheight"),
    ("r_knee", "lateralfemoralepicondyleheight"),
    ("r_talocrural", "lateralmalleolusheight"),
)


def site_height(site: str, row: dict[str, str]) -> float:
    """The height (m) the person's own measurements give `site`: its column,
    or for the radiale (ANSUR II has no radiale height) the acromial height
    less the acromion-radiale length, both measured standing, arm hanging."""
    column = dict(SITES)[site]
    if column is None:
        return (float(row["acromialheight"]) - float(row["acromionradialelength"])) / 1000
    return float(row[column]) / 1000


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


def biacromial_fractions(folder: Path = ANSUR) -> dict[str, float]:
    """Mean biacromial breadth / stature per gender, to 4 decimals: the
    breadth whose 17 % (Rab et al. 2002) puts a percentile figure's shoulder
    centre below its acromion (landmarks.BIACROMIAL_FRACTION)."""
    out = {}
    for gender in FILES:
        rows = read_csv(gender, folder)
        stature = np.array([float(r["stature"]) for r in rows])
        breadth = np.array([float(r["biacromialbreadth"]) for r in rows])
        out[gender] = round(float(np.mean(breadth / stature)), 4)
    return out


def center_of_mass_share(humanoid: Humanoid, stature: float) -> float:
    """The humanoid's whole-body centre-of-mass height over `stature` (m)."""
    segments = humanoid.segments.values()
    mass = sum(s.mass for s in segments)
    return float(sum(s.mass * s.center_of_mass[1] for s in segments) / mass / stature)


def percentile_figures() -> dict[str, float]:
    """Centre of mass / stature of the shipped male 50th and female 5th figures."""
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.body.hanim import build_humanoid

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


def measure(people: int | None = None, folder: Path = ANSUR) -> dict[str, object]:
    """Export ANSUR II people (every one, or `people` evenly spread over each
    file, half men and half women) as `sass export hanim --person` does, and
    measure their sites and joints against their own measurements."""
    from sass_tui.db.engine.schema import connect
    from sass_tui.db.people.ansur import import_ansur
    from sass_tui.db.people.individual import fetch_individual, person_figure
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.body.hanim import build_humanoid

    errors: dict[str, list[float]] = {
        **{site: [] for site, _ in SITES},
        "acromion spacing": [],
        **{joint: [] for joint, _ in JOINTS},
    }
    com_share: list[float] = []
    upper_arm: dict[str, list[float]] = {g: [] for g in FILES}  # shoulder - elbow centre (m)
    population = {g: Figure.default(g) for g in FILES}
    with tempfile.TemporaryDirectory() as tmp:
        conn = connect(Path(tmp) / "ansur.db", create=True)
        import_ansur(conn, [folder / FILES["male"], folder / FILES["female"]])
        ids = {
            str(name): int(i)
            for i, name in conn.execute("SELECT id_num, name FROM person WHERE source = 'ansur2'")
        }
        for gender in FILES:
            rows = read_csv(gender, folder)
            if people is not None:
                step = len(rows) / (people // 2)
                rows = [rows[int(k * step)] for k in range(people // 2)]
            letter = "M" if gender == "male" else "F"
            for row in rows:
                person = fetch_individual(conn, ids[f"ANSUR II {letter} {row['subjectid']}"])
                humanoid = build_humanoid(person_figure(person, population[gender]))
                sites = {site.name: site.translation for site in humanoid.sites}
                for site, _ in SITES:
                    errors[site].append(sites[site][1] - site_height(site, row))
                spacing = sites["l_acromion_pt"][0] - sites["r_acromion_pt"][0]
                errors["acromion spacing"].append(spacing - float(row["biacromialbreadth"]) / 1000)
                for joint, column in JOINTS:
                    target = float(row[column]) / 1000
                    errors[joint].append(humanoid.centers[joint][1] - target)
                com_share.append(center_of_mass_share(humanoid, float(row["stature"]) / 1000))
                centres = humanoid.centers
                upper_arm[gender].append(centres["r_shoulder"][1] - centres["r_elbow"][1])
        conn.close()
    shares = np.array(com_share) * 100
    return {
        "people": len(com_share),
        "mae_mm": {k: float(np.mean(np.abs(v)) * 1000) for k, v in errors.items()},
        "max_mm": {k: float(np.max(np.abs(v)) * 1000) for k, v in errors.items()},
        "com_shares": com_share,
        "upper_arm_mm": {g: float(np.mean(v) * 1000) for g, v in upper_arm.items()},
        "com_percent": (
            float(shares.min()),
            float(shares.mean()),
            float(shares.max()),
            float(shares.std(ddof=1)),
        ),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--people", type=int, default=None, help="a sample of this many (default: all 6,068)"
    )
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT))
    from sass_tui.model.body.hanim import LANDMARK_FRACTIONS
    from sass_tui.model.body.landmarks import BIACROMIAL_FRACTION

    fractions = landmark_fractions()
    print("landmark / stature (ANSUR II means):")
    for gender, values in fractions.items():
        same = values == LANDMARK_FRACTIONS[gender]
        print(f"  {gender}: {values}  {'= hanim.LANDMARK_FRACTIONS' if same else 'DIFFERS'}")
    breadths = biacromial_fractions()
    same = breadths == BIACROMIAL_FRACTION
    print(
        f"biacromial breadth / stature: {breadths}  "
        f"{'= landmarks.BIACROMIAL_FRACTION' if same else 'DIFFERS'}"
    )
    result = measure(args.people)
    print(f"\n{result['people']} ANSUR II people exported from a database:")
    print("| site or joint | against the person's | mean abs. error | max |")
    print("|---|---|---|---|")
    labels = {
        **{site: (column or "acromialheight - acromionradialelength") for site, column in SITES},
        "acromion spacing": "biacromialbreadth",
        **{joint: column for joint, column in JOINTS},
    }
    for key, label in labels.items():
        print(
            f"| `{key}` | {label} | {result['mae_mm'][key]:.2f} mm | "
            f"{result['max_mm'][key]:.2f} mm |"
        )
    low, mean, high, sd = result["com_percent"]
    print(
        f"\nwhole-body centre of mass: {low:.2f} - {high:.2f} % of stature "
        f"(mean {mean:.2f} %, SD {sd:.2f} %)"
    )
    arm = result["upper_arm_mm"]
    print(
        f"mean upper arm (shoulder - elbow centre): male {arm['male']:.1f} mm, "
        f"female {arm['female']:.1f} mm"
    )
    for name, share in percentile_figures().items():
        print(f"  {name} percentile figure: {share * 100:.2f} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
