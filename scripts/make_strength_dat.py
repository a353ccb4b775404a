"""Write datasets/strength.dat: the default strength file (report §12.2.4, figure 8).

Most of the values are test data made here, from published peak torques and
stated assumptions (docs/data-sources.md, "Strength"):

* Peak isometric torques and the angle of peak torque / angular width of the
  active torque-angle curve: Millard et al. 2016, table GymnastWholeBody of
  RBDL's addons/muscle/Millard2016TorqueMuscle.cc (one elite male gymnast).
  That gymnast is assumed to be the 95th percentile man, and the rows are
  stored with percentile 95.
* The value at other angles is peak * max(0.3, 1 - ((angle - peak angle) /
  (width / 2))**2), an inverted parabola across Millard's width with a floor
  of 30 % (an assumption: the Bezier curves of the model are not reproduced).
* Millard's angles are anatomical, each in the sense its passive curve gives
  (a muscle is stretched away from the direction it acts): flexion +, 0 with
  the limb straight, for the shoulder, elbow and wrist flexion/extension;
  external rotation + at the shoulder; supination + of the forearm; ulnar
  deviation + at the wrist.  SASS's columns count lateral rotation, pronation
  and radial deviation positive, so forearm and wrist-deviation angles change
  sign (MILLARD's `sign` column); docs/model.md, "Strength", has the table.
* Elbow flexion is the exception to Millard's shapes: the gymnast table's
  curve (scaled from one tennis player, Kentel et al. 2011) peaks at 19 deg
  of flexion, where the usual elbow-flexion strength curve peaks near 90 deg
  and keeps about half its peak with the arm straight (the strength-curve
  review of Kulig, Andrews & Hay 1984, Exerc Sport Sci Rev 12:417-466).  The
  test data follow the usual curve: peak at 90 deg, 55 % at 0 deg
  (ELBOW_FLEXION_PEAK_DEG, ELBOW_FLEXION_AT_STRAIGHT).
* Shoulder abduction and adduction are not in that table.  Abduction is built
  around the report's own point (right shoulder x 30, y 45, elbow 90 =
  17.98 ft-lb, figure 5, taken as the male 50th percentile), with the same
  parabola, peak at 0 deg and a 180 deg width; adduction is abduction mirrored
  (peak at 90 deg) times 128.50 / 94.68, the gymnast's horizontal adduction
  to horizontal abduction ratio.
* Women: men's values times 0.50 for the shoulder (Clin Biomech 1989,
  doi:10.1016/0268-0033(89)90046-6), 0.641 for the forearm and wrist
  (J Funct Morphol Kinesiol 2025;10(4):377) and 0.57, the mean of the two,
  for the elbow (an assumption).

Run from the repository root:  python scripts/make_strength_dat.py
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

N_M_PER_FT_LB = 1.3558179483314004

# Joint-angle columns of figure 8: shoulder x y z, elbow y, wrist x y z (deg).
SHOULDER_BASE = (0.0, 0.0, 0.0, 90.0, 0.0, 0.0, 0.0)
ABDUCTION_BASE = (30.0, 45.0, 0.0, 90.0, 0.0, 0.0, 0.0)
COLUMN = {
    "shoulder_x": 0,
    "shoulder_y": 1,
    "shoulder_z": 2,
    "elbow_y": 3,
    "wrist_x": 4,
    "wrist_y": 5,
    "wrist_z": 6,
}
# Male 50th percentile joint ranges (datasets/jntlmt.dat), less 5 deg a side,
# so that every stored configuration is reachable by the default figure.
RANGE = {
    "shoulder_x": (-43.0, 175.0),
    "shoulder_y": (-56.0, 182.0),
    "shoulder_z": (-103.0, 66.0),
    "elbow_y": (5.0, 144.0),
    "wrist_x": (-28.0, 21.0),
    "wrist_y": (-54.0, 73.0),
    "wrist_z": (-99.0, 92.0),
}

# motion, varied column, Millard peak N·m, angle of peak (rad), width (rad),
# joint, sign (SASS angle = sign x Millard angle; see the module docstring)
MILLARD = [
    ("shoulder flexion", "shoulder_y", 91.1388, 0.890118, 1.2898, "shoulder", 1),
    ("shoulder extension", "shoulder_y", 127.401, 2.14675, 1.83085, "shoulder", 1),
    ("shoulder medial rotation", "shoulder_z", 50.522, -1.18761, 2.80524, "shoulder", 1),
    ("shoulder lateral rotation", "shoulder_z", 43.5837, -0.670796, 1.98361, "shoulder", 1),
    ("elbow flexion", "elbow_y", 101.384, 0.33, 3.62155, "elbow", 1),
    ("elbow extension", "elbow_y", 69.8728, 1.64319, 1.30795, "elbow", 1),
    ("forearm pronation", "wrist_z", 12.976, -0.212389, 0.991803, "forearm", -1),
    ("forearm supination", "wrist_z", 13.5361, -0.209204, 1.33735, "forearm", -1),
    ("wrist flexion", "wrist_y", 39.2252, 0.663225, 1.71042, "wrist", 1),
    ("wrist extension", "wrist_y", 15.5653, 1.55334, 1.38928, "wrist", 1),
    ("wrist radial deviation", "wrist_x", 23.8345, -1.14319, 2.56082, "wrist", -1),
    ("wrist ulnar deviation", "wrist_x", 31.4217, 0.43, 1.47849, "wrist", -1),
]
DEG_PER_RAD = 57.29577951308232
# The usual elbow-flexion curve (see the docstring): peak and share kept straight.
ELBOW_FLEXION_PEAK_DEG = 90.0
ELBOW_FLEXION_AT_STRAIGHT = 0.55
FEMALE_RATIO = {"shoulder": 0.50, "elbow": 0.57, "forearm": 0.641, "wrist": 0.641}
REPORT_POINT = 17.98  # ft-lb, figure 5
ADDUCTION_RATIO = 128.496 / 94.6839
FLOOR = 0.3


def shape(angle: float, peak: float, width: float) -> float:
    return max(FLOOR, 1.0 - ((angle - peak) / (width / 2.0)) ** 2)


def sample_angles(column: str, peak: float, width: float) -> list[float]:
    lo, hi = RANGE[column]
    lo, hi = math.ceil(lo / 5.0) * 5.0, math.floor(hi / 5.0) * 5.0
    out = []
    for step in (None, -2, -1, 0, 1, 2):
        angle = 0.0 if step is None else peak + step * width / 6
        snapped = float(min(max(round(angle / 5.0) * 5.0, lo), hi))
        if snapped not in out:
            out.append(snapped)
    return out


def rows_for(gender: str) -> list[tuple[tuple[float, ...], float, float, str]]:
    rows = []
    abduction_peak = REPORT_POINT / shape(30.0, 0.0, 180.0)
    female = gender == "female"
    shoulder_ratio = FEMALE_RATIO["shoulder"] if female else 1.0
    for x in (30.0, 0.0, 60.0, 90.0):
        angles = (x,) + ABDUCTION_BASE[1:]
        value = REPORT_POINT if x == 30.0 else abduction_peak * shape(x, 0.0, 180.0)
        note = "report figure 5" if x == 30.0 and not female else "test data"
        rows.append((angles, value * shoulder_ratio, 50.0, f"shoulder abduction: {note}"))
    for x in (0.0, 30.0, 60.0, 90.0):
        angles = (x,) + ABDUCTION_BASE[1:]
        value = abduction_peak * ADDUCTION_RATIO * shape(x, 90.0, 180.0)
        rows.append((angles, value * shoulder_ratio, 50.0, "shoulder adduction: test data"))
    for motion, column, peak_nm, peak_rad, width_rad, joint, sign in MILLARD:
        peak, width = sign * peak_rad * DEG_PER_RAD, width_rad * DEG_PER_RAD
        note = "Millard 2016 shape"
        if motion == "elbow flexion":
            # 1 - (peak / (width / 2))**2 = the share kept with the arm straight
            peak = ELBOW_FLEXION_PEAK_DEG
            width = 2 * peak / math.sqrt(1 - ELBOW_FLEXION_AT_STRAIGHT)
            note = "Millard 2016 peak, usual shape"
        ratio = FEMALE_RATIO[joint] if female else 1.0
        base = list(SHOULDER_BASE)
        for angle in sample_angles(column, peak, width):
            base[COLUMN[column]] = angle
            value = peak_nm / N_M_PER_FT_LB * shape(angle, peak, width) * ratio
            rows.append((tuple(base), value, 95.0, f"{motion}: {note}"))
    return rows


def render() -> str:
    lines = [
        "P Strength test data, not a survey (docs/data-sources.md)",
        "C Values are TEST DATA made by scripts/make_strength_dat.py, not a survey:",
        "C peak torques of one elite male gymnast (Millard et al. 2016, RBDL",
        "C Millard2016TorqueMuscle.cc, GymnastWholeBody) taken as the 95th percentile",
        "C man; other angles by an inverted parabola over Millard's angular width",
        "C (floor 30%), Millard's angles mapped to SASS's columns (forearm and wrist",
        "C deviation change sign), elbow flexion peaking at 90 deg as usual;",
        "C shoulder abduction around the report's figure 5 point",
        "C (17.98 ft-lb, male 50th, right); adduction = abduction mirrored x 1.357;",
        "C women = men x 0.50 (shoulder), 0.57 (elbow), 0.641 (forearm, wrist).",
        "C Strength in ft-lb, angles in degrees; 999 = no value.  Measured on the",
        "C dominant limb (report 12.2.4); the left limb is scaled from it.",
    ]
    for gender in ("male", "female"):
        lines += [
            "C",
            f"G {gender.upper()}",
            "L RIGHT",
            "C  Shoulder Angle         Elbow   Wrist Angle           Strength",
            "C     x      y      z       y      x      y      z     Value      %  comment",
        ]
        for angles, value, percentile, comment in rows_for(gender):
            numbers = " ".join(f"{a:6.1f}" for a in angles[:3])
            numbers += f"  {angles[3]:6.1f}  " + " ".join(f"{a:6.1f}" for a in angles[4:])
            lines.append(f"  {numbers}  {value:8.2f}  {percentile:5.1f}  /* {comment} */")
    return "\n".join(lines) + "\n"


def main() -> int:
    root = Path(__file__).resolve().parents[1]
    sys.path.insert(0, str(root))
    from sass_tui.model.files.atomic import write_text_atomic

    target = root / "datasets" / "strength.dat"
    write_text_atomic(target, render())
    print(f"wrote {target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
