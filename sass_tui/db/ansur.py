"""Import the ANSUR II public CSV files (Gordon et al. 2014) as they are published.

Both files are read as cp1252 (the male file is not UTF-8); the id column is
`subjectid` in one and `SubjectId` in the other, so headers are matched without
regard to case.  Measurements are in mm, `weightkg` in 0.1 kg.  Each girth
segment is derived from standard measurements as report §10.1 prescribes; the
table of derivations (with the ANSUR column names) is in docs/data-sources.md,
"Database", and in DERIVATIONS below, which is what the code runs.  ANSUR II
measured no joint ranges, centers of mass or strengths: those groups stay empty.
"""

from __future__ import annotations

import csv
import io
import math
import sqlite3
from collections.abc import Callable, Sequence
from pathlib import Path

import numpy as np

from sass_tui.db.schema import (
    GIRTH_MASS_FRACTIONS,
    GIRTH_NAMES,
    PeopleBatch,
    store_people,
    transaction,
)
from sass_tui.model.errors import SassError

SOURCE = "ANSUR II public data (Gordon et al. 2014)"
ANSUR_HANDEDNESS = {
    "right hand": "right",
    "left hand": "left",
    "either hand (no preference)": "either",
}
GENDER = {"male": "male", "female": "female"}
ID_COLUMN = "subjectid"
UPPER_ARM_RATIO = 17 / 20  # report §10.1: x/y of the biceps ellipse
FOREARM_RATIO = 3 / 2


class AnsurImportError(ValueError, SassError):
    """An ANSUR file that cannot be imported; nothing was stored."""


def ellipse_axes(circumference: np.ndarray, ratio: float) -> tuple[np.ndarray, np.ndarray]:
    """Report §10.1 ellipse axis procedure: C = 2 pi sqrt((A^2 + B^2)/2), K = A/B.
    Returns the full axes (2A, 2B)."""
    a = circumference * ratio * math.sqrt(2.0 / (ratio**2 + 1.0)) / (2.0 * math.pi)
    return 2.0 * a, 2.0 * a / ratio


def _diameter(circumference: np.ndarray) -> np.ndarray:
    return circumference / math.pi


# segment -> (x, y, z) as functions of the column table (cm).  x = thickness
# (depth), y = width, z = length, the axes of appendix B.  Appendix B's arm
# rows have y/x equal to the report's ratio, so the ellipse's 2A goes to y.
# Where report 10.1 allows more than one measurement, the one closest to what
# the report measured is taken; docs/data-sources.md ("ANSUR II derivations
# against appendices B and C", written by scripts/ansur_derivations.py) has
# every cell's 5/50/95 against the report's and why each differs:
# - lower torso depth: abdominal extension depth (10.1's first choice for the
#   two-segment torso, #10; ANSUR II measures it sitting), not buttock depth
#   (the three-segment torso's);
# - thigh depth: thigh clearance (10.1's alternative to the unmeasured thigh
#   depth); thigh breadth: the diameter of the mid-thigh circumference, taken
#   as the mean of ANSUR II's two, at the gluteal furrow (the thigh's largest,
#   +31 % against appendix B as a diameter) and above the knee (-15 %);
# - foot z: 10.1's ankle height (#64, at the ankle's narrowest) is not in
#   ANSUR II; the lateral malleolus height is (-45 %: a lower landmark), and
#   the lower leg (tibiale - malleolus) takes up the difference.
def _derive(c: dict[str, np.ndarray], n: int) -> np.ndarray:
    nan = np.full(n, np.nan)
    one = np.ones(n)
    arm_y, arm_x = ellipse_axes(c["bicepscircumferenceflexed"], UPPER_ARM_RATIO)
    fore_y, fore_x = ellipse_axes(c["forearmcircumferenceflexed"], FOREARM_RATIO)
    neck = _diameter(c["neckcircumference"])
    mid_thigh = _diameter((c["thighcircumference"] + c["lowerthighcircumference"]) / 2)
    calf = _diameter(c["calfcircumference"])
    upper_leg = c["trochanterionheight"] - c["tibialheight"]
    lower_leg = c["tibialheight"] - c["lateralmalleolusheight"]
    segments = {
        "bottom_head": (c["headlength"], c["headbreadth"], nan),
        "neck": (neck, neck, neck),
        "center_torso": (c["chestdepth"], c["interscyei"], c["waistbacklength"]),
        "lower_torso": (
            c["abdominalextensiondepthsitting"],
            c["hipbreadth"],
            c["waistheightomphalion"] - c["crotchheight"],
        ),
        "upper_arm": (arm_x, arm_y, c["acromionradialelength"]),
        "lower_arm": (fore_x, fore_y, c["radialestylionlength"]),
        "upper_leg": (c["thighclearance"], mid_thigh, upper_leg),
        "lower_leg": (calf, calf, lower_leg),
        "foot": (c["balloffootlength"], c["footbreadthhorizontal"], c["lateralmalleolusheight"]),
        "hand": (nan, c["handbreadth"], c["palmlength"]),
        "clavicle": (one, one, c["shoulderlength"]),
        "eye": (nan, nan, nan),
        "eye_location": (nan, nan, nan),
        "ball_of_foot": (c["footlength"] - c["balloffootlength"], c["footbreadthhorizontal"], nan),
        "knuckles": (nan, c["handbreadth"], c["handlength"] - c["palmlength"]),
    }
    out = np.full((n, len(GIRTH_NAMES), 3), np.nan)
    for r, name in enumerate(GIRTH_NAMES):
        stem = name.removeprefix("right_").removeprefix("left_")
        out[:, r, :] = np.stack(segments[stem], axis=1)
    return out


MEASUREMENTS = (
    "headlength",
    "headbreadth",
    "neckcircumference",
    "chestdepth",
    "interscyei",
    "waistbacklength",
    "abdominalextensiondepthsitting",
    "hipbreadth",
    "waistheightomphalion",
    "crotchheight",
    "bicepscircumferenceflexed",
    "acromionradialelength",
    "forearmcircumferenceflexed",
    "radialestylionlength",
    "thighcircumference",
    "lowerthighcircumference",
    "thighclearance",
    "trochanterionheight",
    "tibialheight",
    "calfcircumference",
    "lateralmalleolusheight",
    "balloffootlength",
    "footbreadthhorizontal",
    "footlength",
    "handbreadth",
    "palmlength",
    "handlength",
    "shoulderlength",
    "stature",
)
REQUIRED = (ID_COLUMN, "gender", "weightkg", "age", "writingpreference") + MEASUREMENTS


def read_ansur(path: str | Path) -> PeopleBatch:
    path = Path(path)
    try:
        text = path.read_bytes().decode("cp1252", errors="replace")
    except OSError as exc:
        raise AnsurImportError(f"{path}: cannot read: {exc.strerror or exc}") from None
    rows = list(csv.reader(io.StringIO(text, newline="")))
    if not rows:
        raise AnsurImportError(f"{path}:1: the file is empty; expected the ANSUR II header")
    header = [h.strip().lstrip("\ufeff").lower() for h in rows[0]]
    column = {name: k for k, name in enumerate(header)}
    missing = [name for name in REQUIRED if name not in column]
    if missing:
        raise AnsurImportError(
            f"{path}:1: missing column{'s' if len(missing) > 1 else ''} "
            f"{', '.join(missing)} (ANSUR II public file expected)"
        )
    body = rows[1:]
    for lineno, row in enumerate(body, start=2):
        if len(row) != len(header):
            raise AnsurImportError(
                f"{path}:{lineno}: expected {len(header)} fields, found {len(row)}"
            )
    n = len(body)
    if n == 0:
        raise AnsurImportError(f"{path}:2: the file holds no subject")

    def numbers(name: str) -> np.ndarray:
        k = column[name]
        texts = [row[k] for row in body]
        try:
            return np.array(texts, dtype=float)
        except ValueError:
            for lineno, t in enumerate(texts, start=2):
                try:
                    float(t)
                except ValueError:
                    raise AnsurImportError(
                        f"{path}:{lineno}: column {name}: expected a number, found {t!r}"
                    ) from None
            raise

    def words(name: str, table: dict[str, str]) -> list[str]:
        k = column[name]
        out = []
        for lineno, row in enumerate(body, start=2):
            key = row[k].strip().lower()
            if key not in table:
                raise AnsurImportError(
                    f"{path}:{lineno}: column {name}: expected one of "
                    f"{', '.join(sorted(table))}, found {row[k]!r}"
                )
            out.append(table[key])
        return out

    cm = {name: numbers(name) / 10.0 for name in MEASUREMENTS}
    subject = numbers(ID_COLUMN).astype(np.int64)
    if len(np.unique(subject)) != n:
        values, counts = np.unique(subject, return_counts=True)
        raise AnsurImportError(f"{path}: duplicate subject id {int(values[counts > 1][0])}")
    gender = words("gender", GENDER)
    mass = numbers("weightkg") / 10.0
    girth = np.empty((n, len(GIRTH_NAMES), 4))
    girth[:, :, :3] = _derive(cm, n)
    girth[:, :, 3] = mass[:, None] * GIRTH_MASS_FRACTIONS[None, :]
    letter = {"male": "M", "female": "F"}
    return PeopleBatch(
        id_num=np.zeros(n, dtype=np.int64),
        name=[f"ANSUR II {letter[g]} {s}" for g, s in zip(gender, subject.tolist())],
        gender=gender,
        stature=cm["stature"],
        mass=mass,
        handedness=words("writingpreference", ANSUR_HANDEDNESS),
        age=numbers("age"),
        source=[f"{SOURCE}, {g} file" for g in gender],
        source_key=[f"ANSUR II:{g}:{s}" for g, s in zip(gender, subject.tolist())],
        girth=girth,
    )


def _assign_ids(conn: sqlite3.Connection, batch: PeopleBatch) -> None:
    """Reuse the id of a person already imported from the same subject; new ids after the last."""
    conn.execute("CREATE TEMP TABLE IF NOT EXISTS _keys (source_key TEXT PRIMARY KEY)")
    conn.execute("DELETE FROM _keys")
    conn.executemany("INSERT INTO _keys VALUES (?)", ((k,) for k in batch.source_key))
    known = dict(
        conn.execute(
            "SELECT p.source_key, p.id_num FROM person p "
            "JOIN _keys k ON k.source_key = p.source_key"
        )
    )
    next_id = (conn.execute("SELECT max(id_num) FROM person").fetchone()[0] or 0) + 1
    for i, key in enumerate(batch.source_key):
        if key in known:
            batch.id_num[i] = known[key]
        else:
            batch.id_num[i] = next_id
            next_id += 1


def import_ansur(
    conn: sqlite3.Connection,
    paths: Sequence[str | Path],
    progress: Callable[[int, int], None] | None = None,
    chunk: int = 1000,
) -> dict[str, int]:
    """Import the files in one transaction.  Returns people per gender."""
    batches = [read_ansur(p) for p in paths]
    total = sum(len(b) for b in batches)
    done = 0
    counts = {"male": 0, "female": 0}
    with transaction(conn):
        for batch in batches:
            _assign_ids(conn, batch)
            for start in range(0, len(batch), chunk):
                store_people(conn, _slice(batch, slice(start, start + chunk)))
                done += min(chunk, len(batch) - start)
                if progress:
                    progress(done, total)
            for g in batch.gender:
                counts[g] += 1
    return counts


def _slice(batch: PeopleBatch, part: slice) -> PeopleBatch:
    return PeopleBatch(
        id_num=batch.id_num[part],
        name=batch.name[part],
        gender=batch.gender[part],
        stature=batch.stature[part],
        mass=batch.mass[part],
        handedness=batch.handedness[part],
        age=batch.age[part],
        source=batch.source[part],
        source_key=batch.source_key[part],
        girth=None if batch.girth is None else batch.girth[part],
    )
