"""Print the coefficient table of docs/model.md ("Strength"): the prediction
equation fitted to the shipped strength file, male right limb.

    python scripts/strength_fit_table.py
"""

from __future__ import annotations

from sass_tui.model.strength.strength import N_ANGLES, fit_summary, read_strength_file
from sass_tui.model.vocabulary import JOINT_AXES


def main() -> None:
    data = read_strength_file()
    print("| motion | b0 | b (angle) | c (angle²) | angle | n | fit error RMS / max |")
    print("|---|---|---|---|---|---|---|")
    for gender, side, fit in fit_summary(data):
        if (gender, side) != ("male", "right"):
            continue
        axis = fit.varied[0] if fit.varied else JOINT_AXES[0]
        j = JOINT_AXES.index(axis)
        b0, b, c = fit.coefficients[0], fit.coefficients[1 + j], fit.coefficients[1 + N_ANGLES + j]
        print(
            f"| {fit.motion.replace('_', ' ')} | {b0:.4f} | {b:.4f} | {c:.4f} | {axis} | "
            f"{fit.points} | {fit.rms_percent:.1f} % / {fit.max_percent:.1f} % |"
        )


if __name__ == "__main__":
    main()
