"""Write datasets/body_measures.csv: for each gender and each measurement the
body's surface passes through (model/body/body_measures.py SURFACE_MEASURES), the
three numbers of `sass predict`'s prediction from stature and mass alone.

The predictor (model/population/prediction.py, fitted on the ANSUR II people of the
default database) gives the conditional mean of every measurement given the
known values; given stature and mass that mean is linear in them, so three
predictions per gender give it exactly:

    intercept = f(0, 0),  per_cm = f(s + 1, m) - f(s, m),  per_kg = f(s, m + 1) - f(s, m)

(evaluated at the population's typical stature and mass, then carried back to
zero).  tests/model/test_body_measures.py checks the table against a fresh
predictor at other statures and masses.

    python scripts/body_measures.py [--db PATH]   # default: a fresh default database
"""

from __future__ import annotations

import argparse
import csv
import io
import tempfile
from pathlib import Path

from sass_tui.db.people.default import create_default_database, open_database
from sass_tui.db.populations.predict import open_predictor
from sass_tui.model import datasets
from sass_tui.model.body.body_measures import SURFACE_MEASURES, TABLE, TABLE_COLUMNS
from sass_tui.model.files.atomic import write_text_atomic

# Where the three predictions are taken (cm, kg): inside each gender's range,
# so the predictor refuses none of them.
ANCHORS = {"male": (175.0, 85.0), "female": (163.0, 68.0)}


def table_rows(predictor) -> list[list[str]]:
    rows = []
    for gender, (stature, mass) in ANCHORS.items():
        base = predictor.predict(gender, {"stature": stature, "mass": mass})
        taller = predictor.predict(gender, {"stature": stature + 1.0, "mass": mass})
        heavier = predictor.predict(gender, {"stature": stature, "mass": mass + 1.0})
        for name in SURFACE_MEASURES:
            field = f"measure.{name}"
            value = base.value(field)
            per_cm = taller.value(field) - value
            per_kg = heavier.value(field) - value
            intercept = value - per_cm * stature - per_kg * mass
            rows.append([gender, name, f"{intercept:.6f}", f"{per_cm:.8f}", f"{per_kg:.8f}"])
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--db", help="a database holding ANSUR II (default: build one)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        path = args.db
        if path is None:
            path = str(Path(folder) / "sass.db")
            create_default_database(path)
        conn = open_database(path)
        try:
            predictor = open_predictor(conn, cache=False)
        finally:
            conn.close()
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(TABLE_COLUMNS)
    writer.writerows(table_rows(predictor))
    target = datasets.directory() / TABLE
    write_text_atomic(target, out.getvalue())
    print(f"wrote {target}")


if __name__ == "__main__":
    main()
