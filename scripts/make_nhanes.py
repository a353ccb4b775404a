"""Write datasets/nhanes/nhanes_2017_2020_adults.csv.gz from the published NHANES file.

The input is the CDC's P_DEMO (demographics, sample weights) and P_BMX (body
measures) files of NHANES 2017-March 2020 pre-pandemic, merged on SEQN: the
14,300-row file `marek/nhanes_p_demo_bmx_2020.csv` of the public repository
gagolews/teaching-data (a copy is ../shared/data/nhanes/).  Kept: the adults
(RIDAGEYR >= 20: 8,544 rows), every one of them, with an empty cell where the
survey has no value (NA).  Columns, named as `sass target --sample` reads
them (docs/target-populations.md):

    seqn                      SEQN, the respondent's sequence number
    gender                    RIAGENDR: 1 male, 2 female
    age                       RIDAGEYR, years (80 = 80 and over)
    stature[cm]               BMXHT, standing height
    mass[kg]                  BMXWT, weight
    bmi                       BMXBMI, kg/m^2
    waist_circumference[cm]   BMXWAIST (NHANES's, at the iliac crest: not ANSUR II's)
    hip_circumference[cm]     BMXHIP
    upper_arm_length[cm]      BMXARML
    upper_leg_length[cm]      BMXLEG
    race_ethnicity            RIDRETH3, the survey's code (1, 2, 3, 4, 6, 7)
    WTMECPRP                  the examination sample weight (`--weight WTMECPRP`)

Values are copied as printed (no rounding, no conversion).  The gzip header
carries no time stamp, so the same input gives the same bytes.

    python scripts/make_nhanes.py [PUBLISHED.csv [OUTPUT.csv.gz]]
"""

from __future__ import annotations

import csv
import gzip
import io
import sys
from pathlib import Path

from sass_tui.model.files.atomic import write_bytes_atomic

ROOT = Path(__file__).resolve().parent.parent
PUBLISHED = ROOT.parent / "shared" / "data" / "nhanes" / "nhanes_p_demo_bmx_2020.csv"
SHIPPED = ROOT / "datasets" / "nhanes" / "nhanes_2017_2020_adults.csv.gz"
ADULT_AGE = 20
GENDER_CODES = {"1": "male", "2": "female"}
# shipped column -> the published column
COLUMNS = {
    "seqn": "SEQN",
    "gender": "RIAGENDR",
    "age": "RIDAGEYR",
    "stature[cm]": "BMXHT",
    "mass[kg]": "BMXWT",
    "bmi": "BMXBMI",
    "waist_circumference[cm]": "BMXWAIST",
    "hip_circumference[cm]": "BMXHIP",
    "upper_arm_length[cm]": "BMXARML",
    "upper_leg_length[cm]": "BMXLEG",
    "race_ethnicity": "RIDRETH3",
    "WTMECPRP": "WTMECPRP",
}


def adult_rows(text: str) -> list[list[str]]:
    """The shipped rows of the published file's text (comment lines start with #)."""
    lines = [line for line in text.splitlines() if not line.startswith("#")]
    rows = []
    for record in csv.DictReader(lines):
        if record["RIDAGEYR"] in ("", "NA") or float(record["RIDAGEYR"]) < ADULT_AGE:
            continue
        row = ["" if record[name] == "NA" else record[name] for name in COLUMNS.values()]
        row[1] = GENDER_CODES[record["RIAGENDR"]]
        rows.append(row)
    return rows


def main(argv: list[str]) -> None:
    source = Path(argv[0]) if argv else PUBLISHED
    output = Path(argv[1]) if len(argv) > 1 else SHIPPED
    rows = adult_rows(source.read_text(encoding="utf-8"))
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(COLUMNS)
    writer.writerows(rows)
    data = gzip.compress(buffer.getvalue().encode(), compresslevel=9, mtime=0)
    output.parent.mkdir(exist_ok=True)
    write_bytes_atomic(output, data)
    print(f"wrote {output}: {len(rows)} adults, {len(data)} bytes")


if __name__ == "__main__":
    main(sys.argv[1:])
