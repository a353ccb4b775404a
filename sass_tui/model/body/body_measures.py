"""The ANSUR II measurements the body's surface passes through (model/body/body_surface.py),
for any figure.

A real person's are their own (the database's measure table, loaded with
the landmarks: model/body/landmarks.py LANDMARK_MEASURES).  Any other figure (a
percentile or population figure, a predicted person) and any measurement a
person lacks take the value `sass predict` predicts from the stature and
the mass: the conditional mean of the ANSUR II people of the same gender
(model/population/prediction.py).  Given those two values that mean is linear in them,

    value = intercept + per_cm * stature + per_kg * mass,

so `scripts/body_measures.py` asks sass's own predictor (fitted on the
default database) for the three numbers of each measurement and writes them
to `datasets/body_measures.csv`; tests/model/test_body_measures.py checks
the table against the predictor.  Every value says where it came from.
"""

from __future__ import annotations

import csv
import functools
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from sass_tui.model import datasets
from sass_tui.model.errors import SassError

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure

TABLE = "body_measures.csv"
TABLE_COLUMNS = ("gender", "measure", "intercept_cm", "per_cm_stature", "per_kg_mass")

# The ANSUR II measurements (survey names, cm) the surface is built from:
# heights of the sections, their breadths, depths and circumferences, the
# limbs' girths, the hands' and feet's lengths and breadths.
SURFACE_MEASURES: tuple[str, ...] = (
    "crotchheight",
    "buttockheight",
    "buttockcircumference",
    "buttockdepth",
    "hipbreadth",
    "iliocristaleheight",
    "trochanterionheight",
    "waistheightomphalion",
    "waistcircumference",
    "waistbreadth",
    "waistdepth",
    "tenthribheight",
    "chestheight",
    "chestcircumference",
    "chestbreadth",
    "chestdepth",
    "axillaheight",
    "acromialheight",
    "biacromialbreadth",
    "suprasternaleheight",
    "cervicaleheight",
    "neckcircumferencebase",
    "neckcircumference",
    "tragiontopofhead",
    "mentonsellionlength",
    "bizygomaticbreadth",
    "headbreadth",
    "headlength",
    "headcircumference",
    "thighcircumference",
    "lowerthighcircumference",
    "lateralfemoralepicondyleheight",
    "calfcircumference",
    "anklecircumference",
    "lateralmalleolusheight",
    "footlength",
    "footbreadthhorizontal",
    "heelbreadth",
    "balloffootlength",
    "balloffootcircumference",
    "bicepscircumferenceflexed",
    "forearmcircumferenceflexed",
    "wristcircumference",
    "wristheight",
    "handlength",
    "handbreadth",
    "handcircumference",
    "palmlength",
)

MEASURED = "measured"
PREDICTED = "predicted from stature and mass (sass predict, ANSUR II)"


class BodyMeasuresError(ValueError, SassError):
    """The body's measurements cannot be had for the figure."""


@dataclass(frozen=True)
class BodyMeasures:
    """The surface's measurements (cm) and where each came from."""

    values: dict[str, float]
    sources: dict[str, str]

    def m(self, name: str) -> float:
        """The measurement `name` in metres."""
        return self.values[name] / 100.0

    def counts(self) -> dict[str, int]:
        """How many values came from each source."""
        out: dict[str, int] = {}
        for source in self.sources.values():
            out[source] = out.get(source, 0) + 1
        return out


@functools.cache
def coefficients() -> dict[str, dict[str, tuple[float, float, float]]]:
    """gender -> measure -> (intercept cm, cm per cm of stature, cm per kg of
    mass), read from the shipped table (scripts/body_measures.py writes it)."""
    path = datasets.path(TABLE)
    out: dict[str, dict[str, tuple[float, float, float]]] = {}
    with open(path, encoding="utf-8", newline="") as handle:
        rows = csv.reader(handle)
        header = next(rows, None)
        if header is None or tuple(header) != TABLE_COLUMNS:
            raise BodyMeasuresError(f"{path}:1: expected the columns {', '.join(TABLE_COLUMNS)}")
        for line, row in enumerate(rows, start=2):
            try:
                gender, measure = row[0], row[1]
                numbers = tuple(float(v) for v in row[2:5])
            except (IndexError, ValueError):
                raise BodyMeasuresError(
                    f"{path}:{line}: expected gender, measure and three numbers"
                ) from None
            if len(row) != len(TABLE_COLUMNS) or not all(math.isfinite(v) for v in numbers):
                raise BodyMeasuresError(
                    f"{path}:{line}: expected gender, measure and three numbers"
                )
            out.setdefault(gender, {})[measure] = (numbers[0], numbers[1], numbers[2])
    return out


def predicted_measures(gender: str, stature_cm: float, mass_kg: float) -> dict[str, float]:
    """Every surface measurement (cm) sass predict gives a person of `gender`
    with this stature and mass."""
    table = coefficients().get(gender)
    if table is None:
        raise BodyMeasuresError(f"no body measurements for gender {gender!r}")
    if not (math.isfinite(stature_cm) and math.isfinite(mass_kg)):
        raise BodyMeasuresError("cannot shape the body: the figure has no stature or no mass")
    missing = [name for name in SURFACE_MEASURES if name not in table]
    if missing:
        raise BodyMeasuresError(f"{TABLE}: no row for {gender} {missing[0]}")
    return {
        name: table[name][0] + table[name][1] * stature_cm + table[name][2] * mass_kg
        for name in SURFACE_MEASURES
    }


def body_measures(
    gender: str, stature_cm: float, mass_kg: float, own: Mapping[str, float] | None = None
) -> BodyMeasures:
    """The surface's measurements: `own` (a person's, cm) where they hold a
    positive finite value, the prediction from stature and mass elsewhere."""
    predicted = predicted_measures(gender, stature_cm, mass_kg)
    values: dict[str, float] = {}
    sources: dict[str, str] = {}
    for name in SURFACE_MEASURES:
        value = (own or {}).get(name)
        if value is not None and math.isfinite(value) and value > 0:
            values[name], sources[name] = float(value), MEASURED
        else:
            values[name], sources[name] = predicted[name], PREDICTED
    return BodyMeasures(values, sources)


def figure_measures(figure: Figure, stature_cm: float) -> BodyMeasures:
    """The measurements of `figure` standing `stature_cm` tall: a person's own
    (figure.landmarks); a predicted person's as sass predict gave them
    (figure.predicted_measures, from all their known values); else predicted
    from the stature and the figure's mass."""
    measures = body_measures(figure.gender, stature_cm, figure.output_mass(), figure.landmarks)
    source = f"sass predict: {figure.person}"
    for name, value in figure.predicted_measures.items():
        if measures.sources.get(name) == PREDICTED and math.isfinite(value) and value > 0:
            measures.values[name], measures.sources[name] = float(value), source
    return measures
