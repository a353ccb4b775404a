"""Render docs/body-people.png: four real ANSUR II people -- the thinnest and
the heaviest man by BMI, the shortest woman and the tallest man -- each
exported by `sass export gltf --person` from the default database, their
bodies lofted through their own measurements (docs/gltf.md, "The surface").

The people are chosen from the shipped ANSUR II files (datasets/ansur2);
the picture is scripts/gltf_pictures.py's (three.js in Debian's headless
Chromium).  Run it to re-render the picture:

    python scripts/body_pictures.py [OUT.png] [--db PATH]
"""

from __future__ import annotations

import argparse
import csv
import gzip
import sys
import tempfile
from pathlib import Path

from gltf_pictures import ROOT, screenshot  # scripts/ is on the path

from sass_tui.cli import main as sass
from sass_tui.model import datasets

SIZE = (1200, 900)


def _rows(gender: str) -> list[dict[str, str]]:
    path = datasets.directory() / "ansur2" / f"ANSUR_II_{gender}_Public.csv.gz"
    with gzip.open(path, "rt", encoding="latin-1") as handle:
        return [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(handle)]


def _bmi(row: dict[str, str]) -> float:
    return float(row["weightkg"]) / 10 / (float(row["stature"]) / 1000) ** 2


def four_people() -> list[tuple[str, str]]:
    """(label, sass person name): thin, heavy, short, tall."""
    men, women = _rows("MALE"), _rows("FEMALE")
    chosen = (
        ("thin", "M", min(men, key=_bmi)),
        ("heavy", "M", max(men, key=_bmi)),
        ("short", "F", min(women, key=lambda r: float(r["stature"]))),
        ("tall", "M", max(men, key=lambda r: float(r["stature"]))),
    )
    return [(label, f"ANSUR II {letter} {row['subjectid']}") for label, letter, row in chosen]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", nargs="?", type=Path, default=ROOT / "docs" / "body-people.png")
    parser.add_argument("--db", help="a database holding ANSUR II (default: build one)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        db = args.db or str(Path(tmp) / "sass.db")
        if args.db is None and sass(["--db", db, "db", "init"]) != 0:
            return 1
        files = []
        for label, person in four_people():
            glb = Path(tmp) / f"{label}.glb"
            if sass(["export", "gltf", "--db", db, "--person", person, "-o", str(glb)]) != 0:
                return 1
            print(f"{label}: {person}")
            files.append(glb)
        return screenshot(files, args.out, SIZE, distance=5.2)


if __name__ == "__main__":
    sys.exit(main())
