"""ANSUR II as training values built straight from the published CSVs: the
measurements converted with `PUBLISHED_TO_CANONICAL`, the girth cells as the
import derives them.  An independent path to the data the database holds."""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from sass_tui.db.people.ansur import read_ansur
from sass_tui.model.measures import PUBLISHED_TO_CANONICAL
from sass_tui.model.names import AXES, GIRTH_ROWS
from sass_tui.model.population.prediction import predicted_fields


@dataclass
class CsvValues:
    fields: tuple[str, ...]
    ids: np.ndarray
    names: list[str]
    genders: list[str]
    matrix: np.ndarray


def ansur_values(directory: Path) -> CsvValues:
    fields = predicted_fields()
    col = {f: i for i, f in enumerate(fields)}
    blocks, ids, names, genders = [], [], [], []
    for n, file in enumerate(("ANSUR_II_MALE_Public.csv", "ANSUR_II_FEMALE_Public.csv")):
        path = directory / file
        with path.open(encoding="cp1252", newline="") as handle:
            rows = list(csv.DictReader(handle))
        batch = read_ansur(path)
        block = np.full((len(rows), len(fields)), np.nan)
        for name, factor in PUBLISHED_TO_CANONICAL.items():
            target = {"stature": "stature", "weightkg": "mass"}.get(name, f"measure.{name}")
            block[:, col[target]] = [float(r[name]) * factor for r in rows]
        for r, row in enumerate(GIRTH_ROWS):
            for a, axis in enumerate(AXES):
                block[:, col[f"girth.{row.name}.{axis}"]] = batch.girth[:, r, a]
        blocks.append(block)
        ids += [10_000 * (n + 1) + i for i in range(len(rows))]
        names += batch.name
        genders += batch.gender
    return CsvValues(fields, np.array(ids), names, genders, np.vstack(blocks))
