"""Write datasets/arm_force_field.json: the Arm Force Field's published
coefficients, read from the authors' own script without running it.

La Delfa, N. J., Potvin, J. R. (2017). The 'Arm Force Field' method to
predict manual arm strength based on only hand location and force direction.
Applied Ergonomics 59A:410-421, doi:10.1016/j.apergo.2016.09.012.  The
coefficients are the authors', CC-BY 4.0, from their repository
nladelfa/Arm-Force-Field (AFFinPython - v1.0.py, commit
152710fe80403b79307c9d38a58b6b528401c0d4); the men's factor (x1.66) and the
men's body mass (88.1 kg) and stature (1.758 m) are their Excel worksheet's
(v2.09).  THIRD_PARTY_NOTICES.md and docs/strength.md credit them.

    python scripts/make_arm_force_field.py [path/to/AFFinPython - v1.0.py]

The script's module-level assignments are read with `ast` (literals only):
nothing of it is executed.
"""

from __future__ import annotations

import ast
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_SCRIPT = ROOT.parent / "shared" / "reference" / "arm-force-field" / "AFFinPython - v1.0.py"
OUTPUT = ROOT / "datasets" / "arm_force_field.json"

# The script's variable -> the data file's key.
NAMES = {
    "CV": "coefficient_of_variation",
    "bm": "women_body_mass_kg",
    "ht": "women_stature_m",
    "UAcogR": "upper_arm_cog_ratio",
    "FAcogR": "forearm_cog_ratio",
    "HcogR": "hand_cog_ratio",
    "UAmassR": "upper_arm_mass_ratio",
    "FAmassR": "forearm_mass_ratio",
    "HmassR": "hand_mass_ratio",
    "in1offset": "input_offset",
    "in1gain": "input_gain",
    "in1min": "input_min",
    "Layer1b": "layer1_bias",
    "Layer1c": "layer1_weights",
    "Layer2b": "layer2_bias",
    "Layer2c": "layer2_weights",
    "OUTmin": "output_min",
    "OUTgain": "output_gain",
    "OUToffset": "output_offset",
    "MinMAS": "bound_min_N",
    "MaxMAS": "bound_max_N",
    "Htband": "height_band_m",
}

# The worksheet's (v2.09), not in the script.
WORKSHEET = {"men_factor": 1.66, "men_body_mass_kg": 88.1, "men_stature_m": 1.758}

SOURCE = (
    "La Delfa NJ, Potvin JR (2017). The 'Arm Force Field' method to predict manual arm "
    "strength based on only hand location and force direction. Applied Ergonomics "
    "59A:410-421, doi:10.1016/j.apergo.2016.09.012. Coefficients from the authors' "
    "repository nladelfa/Arm-Force-Field (AFFinPython - v1.0.py, commit "
    "152710fe80403b79307c9d38a58b6b528401c0d4; men's factor, body mass and stature from "
    "their worksheet v2.09), CC-BY 4.0, copyright Nicholas J. La Delfa and Jim R. Potvin."
)


def literal(node: ast.expr) -> object:
    """A number, a list of numbers, or np.array([...]) of them."""
    if isinstance(node, ast.Call) and node.args:
        return ast.literal_eval(node.args[0])
    return ast.literal_eval(node)


def read_coefficients(script: Path) -> dict[str, object]:
    tree = ast.parse(script.read_text(encoding="utf-8"))
    found: dict[str, object] = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and len(node.targets) == 1:
            target = node.targets[0]
            if isinstance(target, ast.Name) and target.id in NAMES:
                found.setdefault(NAMES[target.id], literal(node.value))
    missing = sorted(set(NAMES.values()) - set(found))
    if missing:
        raise SystemExit(f"{script}: no {', '.join(missing)}")
    return found


def main(argv: list[str]) -> int:
    script = Path(argv[0]) if argv else DEFAULT_SCRIPT
    data = {"source": SOURCE, "licence": "CC-BY-4.0", **WORKSHEET, **read_coefficients(script)}
    OUTPUT.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    print(f"wrote {OUTPUT}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
