"""The segment dimensions sass derives from ANSUR II (sass_tui/db/people/ansur.py,
_derive) against the report's appendices B and C (datasets/girth.dat), at the
5th, 50th and 95th percentiles of each gender: the table of docs/data-sources.md,
"ANSUR II derivations against appendices B and C".

    python scripts/ansur_derivations.py > table.md

Needs ../shared/data/ansur2 (the ANSUR II CSV files).  ANSUR II measured no
centres of mass, so no centre-of-mass cell is derived from it.
"""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
ANSUR = ROOT.parent / "shared" / "data" / "ansur2"
FILES = {"male": "ANSUR_II_MALE_Public.csv", "female": "ANSUR_II_FEMALE_Public.csv"}

# What each derived cell is made of (the ANSUR II columns, as _derive uses them).
MEASURED = {
    ("bottom_head", "x"): "headlength",
    ("bottom_head", "y"): "headbreadth",
    ("neck", "x"): "neckcircumference / π",
    ("neck", "y"): "neckcircumference / π",
    ("neck", "z"): "neckcircumference / π (as the report, 10.1)",
    ("center_torso", "x"): "chestdepth",
    ("center_torso", "y"): "interscyei",
    ("center_torso", "z"): "waistbacklength",
    ("lower_torso", "x"): "abdominalextensiondepthsitting",
    ("lower_torso", "y"): "hipbreadth",
    ("lower_torso", "z"): "waistheightomphalion − crotchheight",
    ("right_upper_arm", "x"): "bicepscircumferenceflexed, ellipse 17:20",
    ("right_upper_arm", "y"): "bicepscircumferenceflexed, ellipse 17:20",
    ("right_upper_arm", "z"): "acromionradialelength",
    ("right_lower_arm", "x"): "forearmcircumferenceflexed, ellipse 3:2",
    ("right_lower_arm", "y"): "forearmcircumferenceflexed, ellipse 3:2",
    ("right_lower_arm", "z"): "radialestylionlength",
    ("right_upper_leg", "x"): "thighclearance",
    ("right_upper_leg", "y"): "mean of thighcircumference and lowerthighcircumference / π",
    ("right_upper_leg", "z"): "trochanterionheight − tibialheight",
    ("right_lower_leg", "x"): "calfcircumference / π",
    ("right_lower_leg", "y"): "calfcircumference / π",
    ("right_lower_leg", "z"): "tibialheight − lateralmalleolusheight",
    ("right_foot", "x"): "balloffootlength",
    ("right_foot", "y"): "footbreadthhorizontal",
    ("right_foot", "z"): "lateralmalleolusheight",
    ("right_hand", "y"): "handbreadth",
    ("right_hand", "z"): "palmlength",
    ("right_clavicle", "x"): "1 (10.1: fixed)",
    ("right_clavicle", "y"): "1 (10.1: fixed)",
    ("right_clavicle", "z"): "shoulderlength",
    ("right_ball_of_foot", "x"): "footlength − balloffootlength",
    ("right_ball_of_foot", "y"): "footbreadthhorizontal",
    ("right_knuckles", "y"): "handbreadth",
    ("right_knuckles", "z"): "handlength − palmlength",
}


def derived_percentiles(folder: Path = ANSUR) -> dict[str, np.ndarray]:
    """gender -> (rows, 3 axes, 3 percentiles) of the derived girth, cm."""
    from sass_tui.db.people.ansur import read_ansur

    out = {}
    for gender, name in FILES.items():
        girth = read_ansur(folder / name).girth[:, :, :3]
        with warnings.catch_warnings():  # cells ANSUR II does not measure are all NaN
            warnings.simplefilter("ignore", RuntimeWarning)
            out[gender] = np.moveaxis(np.nanpercentile(girth, [5, 50, 95], axis=0), 0, -1)
    return out


def table(folder: Path = ANSUR) -> str:
    from sass_tui.model import datasets
    from sass_tui.model.files.popfile import read_population_file
    from sass_tui.model.names import AXES, GIRTH, ROWS

    report = read_population_file(datasets.path("girth.dat"), GIRTH)
    derived = derived_percentiles(folder)
    rows = {row.name: i for i, row in enumerate(ROWS[GIRTH])}
    lines = [
        "| segment, axis | ANSUR II | men: derived 5/50/95 | appendix B | Δ 50th "
        "| women: derived 5/50/95 | appendix C | Δ 50th |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for (row, axis), measured in MEASURED.items():
        i, a = rows[row], AXES.index(axis)
        cells = []
        for gender in FILES:
            mine, theirs = derived[gender][i, a], report.stats(gender)[i, a]
            change = (mine[1] / theirs[1] - 1) * 100 if theirs[1] else float("nan")
            cells += [
                "/".join(f"{v:.1f}" for v in mine),
                "/".join(f"{v:g}" for v in theirs),
                f"{change:+.0f} %",
            ]
        label = f"{ROWS[GIRTH][i].label.replace('Right ', '')} {axis}"
        lines.append(f"| {label} | {measured} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def main() -> int:
    sys.path.insert(0, str(ROOT))
    sys.stdout.write(table())
    return 0


if __name__ == "__main__":
    sys.exit(main())
