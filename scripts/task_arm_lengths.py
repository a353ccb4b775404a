"""The arm's segment lengths of the 50th-percentile figures, as `sass task`
poses them, beside the ANSUR II medians (the shipped public data) and de
Leva (1996)'s mean lengths; the numbers of docs/task.md "The hand".

    python scripts/task_arm_lengths.py

- upper arm: the shoulder to the elbow joint centre; ANSUR II
  acromion-radiale length (from the acromion, above the joint centre);
- forearm: the elbow to the wrist joint centre; ANSUR II radiale-stylion;
- hand to the grip: the wrist to the third knuckle; ANSUR II hand length
  (wrist crease to fingertip) x 36.24/79.00 (men) or 34.27/74.74 (women),
  de Leva's MET3.
De Leva (1996) table 4, mm (men, women): upper arm 281.7, 275.1; forearm
268.9, 264.3; hand (wrist to MET3) 86.2, 78.0.
"""

from __future__ import annotations

import csv
import gzip
import statistics

import numpy as np

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import DE_LEVA_HAND_COM, pose_figure
from sass_tui.model.datasets import path

DE_LEVA_MM = {"male": (281.7, 268.9, 86.2), "female": (275.1, 264.3, 78.0)}
FILES = {
    "male": "ansur2/ANSUR_II_MALE_Public.csv.gz",
    "female": "ansur2/ANSUR_II_FEMALE_Public.csv.gz",
}


def ansur_medians(gender: str) -> tuple[float, float, float]:
    with gzip.open(path(FILES[gender]), "rt", encoding="latin-1", newline="") as handle:
        rows = list(csv.DictReader(handle))
    to_knuckle, to_fingertip = DE_LEVA_HAND_COM[gender]
    upper = statistics.median(float(r["acromionradialelength"]) for r in rows)
    forearm = statistics.median(float(r["radialestylionlength"]) for r in rows)
    hand = statistics.median(float(r["handlength"]) for r in rows) * to_fingertip / to_knuckle
    return upper, forearm, hand


def main() -> None:
    print(f"{'':8} {'segment':10} {'figure':>8} {'ANSUR II':>9} {'de Leva':>8}  (mm)")
    for gender in ("female", "male"):
        body = pose_figure(Figure.default(gender))
        s = "r"
        c = body.centers
        figure = (
            float(np.linalg.norm(c[f"{s}_shoulder"] - c[f"{s}_elbow"])) * 1000,
            float(np.linalg.norm(c[f"{s}_elbow"] - c[f"{s}_radiocarpal"])) * 1000,
            float(np.linalg.norm(body.grip("right") - c[f"{s}_radiocarpal"])) * 1000,
        )
        for name, mine, ansur, leva in zip(
            ("upper arm", "forearm", "hand-grip"), figure, ansur_medians(gender), DE_LEVA_MM[gender]
        ):
            print(f"{gender:8} {name:10} {mine:8.1f} {ansur:9.1f} {leva:8.1f}")


if __name__ == "__main__":
    main()
