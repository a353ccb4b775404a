"""Import the ANSUR II public CSV files (Gordon et al. 2014) as they are published.

Each line is read as UTF-8 (a byte-order mark dropped), else cp1252 (the male
file is not UTF-8); the id column is `subjectid` in one and `SubjectId` in the
other, so headers are matched without regard to case.  Measurements are in
mm, `weightkg` in 0.1 kg, `interpupillarybreadth` in 0.1 mm; all 93 are stored
in the measure table in canonical units (cm, kg), with the survey's component,
branch, race and ethnicity fields.  Files are read a chunk of rows at a time
and every value is checked (finite, plausible, whole unique subject ids) with
file:line.  Each girth
segment is derived from standard measurements as report §10.1 prescribes; the
table of derivations (with the ANSUR column names) is in docs/data-sources.md,
"Database", and in DERIVATIONS below, which is what the code runs.  ANSUR II
measured no joint ranges, centers of mass or strengths: those groups stay empty.
"""

from __future__ import annotations

import csv
import gzip
import math
import os
import sqlite3
from collections.abc import Callable, Iterable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any, BinaryIO, NoReturn, cast

import numpy as np

from sass_tui.db.engine import staging
from sass_tui.db.engine.schema import GIRTH_NAMES, PERSON_ATTRIBUTES, check_writable, transaction
from sass_tui.db.people.people_store import PeopleBatch, girth_mass_fractions, store_people
from sass_tui.db.progress import Cancel, Progress, Steps
from sass_tui.model.errors import SassError, reason_text
from sass_tui.model.files.paths import PathError, regular_file
from sass_tui.model.measures import MEASURE_UNITS, MEASURES, PUBLISHED_TO_CANONICAL
from sass_tui.model.text import control_character, other_separator, printable, quoted

if TYPE_CHECKING:
    from sass_tui.db.engine.database import Database

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

DEFAULT_LABEL = "ansur2"
# Largest subject id accepted: ids are whole numbers below 10^12 (the survey's
# run to 920103), so they stay exact in a float and in SQLite's 64-bit integers.
MAX_SUBJECT_ID = 10**12 - 1
# Plausible values in canonical units: a body dimension 0 < v <= 300 cm, a
# mass 0 < m <= 500 kg, an age 0 < a <= 130 years.
MEASURE_LIMITS = {name: (0.0, 500.0 if name == "weightkg" else 300.0) for name in MEASURES}
AGE_LIMITS = (0.0, 130.0)
# Survey fields kept as they are (text) and as numeric codes; optional columns.
TEXT_ATTRIBUTES = ("component", "branch", "ethnicity")
CODE_ATTRIBUTES = ("subjectnumericrace", "dodrace")
CHUNK_ROWS = 2000


def _open_bytes(path: Path) -> tuple[BinaryIO, BinaryIO]:
    """(raw file, byte stream): `.gz` files are decompressed as they are read."""
    raw = open(path, "rb")  # closed by the caller
    if path.suffix == ".gz":
        return raw, cast(BinaryIO, gzip.GzipFile(fileobj=raw))
    return raw, raw


def looks_like_ansur(path: str | Path) -> bool:
    """The file's first line is an ANSUR II header (it names the `subjectid`
    column, in any case): Input DB imports it as a survey file, not a person
    file.  A file that cannot be read is not one (its import says why).  At
    most 64 KiB are read: it runs on the UI thread."""
    if not Path(path).is_file():  # a FIFO would block the read; the import says why
        return False
    try:
        raw, stream = _open_bytes(Path(path))
        with raw:
            first = stream.readline(1 << 16)
    except (OSError, EOFError, gzip.BadGzipFile):
        return False
    fields = next(_decoded_lines(iter([first])), "").strip().lower().split(",")
    return ID_COLUMN in (field.strip().strip('"') for field in fields)


def _decoded_lines(stream: Iterable[bytes]) -> Iterator[str]:
    """Each line as text: UTF-8 (a byte-order mark dropped), else cp1252 (the
    published male file is cp1252)."""
    first = True
    for raw_line in stream:
        if first and raw_line.startswith(b"\xef\xbb\xbf"):
            raw_line = raw_line[3:]
        first = False
        try:
            yield raw_line.decode("utf-8")
        except UnicodeDecodeError:
            yield raw_line.decode("cp1252", errors="replace")


class _LineNamedReader:
    """csv.reader whose own errors (a stray carriage return, a field over csv's
    size limit) come out as AnsurImportError naming the line."""

    def __init__(self, path: str | Path, reader: Any) -> None:
        self.path = path
        self.reader = reader

    @property
    def line_num(self) -> int:
        return int(self.reader.line_num)

    def __iter__(self) -> _LineNamedReader:
        return self

    def __next__(self) -> list[str]:
        try:
            row: list[str] = next(self.reader)
        except csv.Error as exc:
            raise AnsurImportError(
                f"{self.path}:{self.reader.line_num}: not a CSV record the survey's "
                f"format allows ({exc})"
            ) from None
        return row


class _Chunk:
    """Rows of one chunk of the file and their line numbers, checked column by column."""

    def __init__(
        self, path: Path, rows: list[list[str]], lines: list[int], columns: dict[str, int]
    ):
        self.path = path
        self.rows = rows
        self.lines = lines
        self.columns = columns

    def fail(self, k: int, message: str) -> NoReturn:
        raise AnsurImportError(f"{self.path}:{self.lines[k]}: {message}")

    def numbers(self, column: int | None, name: str) -> np.ndarray:
        if column is None:
            return np.full(len(self.rows), np.nan)
        texts = [row[column] for row in self.rows]
        try:
            values = np.array(texts, dtype=float)
        except ValueError:
            for k, text in enumerate(texts):
                try:
                    float(text)
                except ValueError:
                    self.fail(k, f"column {name}: expected a number, found {quoted(text)}")
            raise
        return values

    def check(self, values: np.ndarray, name: str, limits: tuple[float, float], unit: str) -> None:
        """Refuse non-finite and implausible values (limits in canonical units)."""
        low, high = limits
        bad = np.flatnonzero(~(np.isfinite(values) & (values > low) & (values <= high)))
        if bad.size:
            k = int(bad[0])
            found = self.rows[k][self.columns[name]]
            self.fail(
                k,
                f"column {name}: {quoted(found)} is not a plausible value "
                f"(expected more than {low:g} and at most {high:g} {unit} once converted)",
            )

    def words(self, column: int, name: str, table: dict[str, str]) -> list[str]:
        out = []
        for k, row in enumerate(self.rows):
            key = row[column].strip().lower()
            if key not in table:
                self.fail(
                    k,
                    f"column {name}: expected one of {', '.join(sorted(table))}, "
                    f"found {quoted(row[column])}",
                )
            out.append(table[key])
        return out

    def texts(self, column: int | None, name: str) -> list[object]:
        """A text field's values; one holding a control character (an escape
        sequence would act on the terminal that shows it) is refused."""
        if column is None:
            return [None] * len(self.rows)
        out: list[object] = [row[column].strip() or None for row in self.rows]
        for k, text in enumerate(out):
            found = control_character(text) if isinstance(text, str) else None
            if found:
                self.fail(k, f"column {name}: {found}; a text field takes printable text only")
        return out

    def codes(self, column: int | None, name: str) -> list[object]:
        if column is None:
            return [None] * len(self.rows)
        out: list[object] = []
        for k, row in enumerate(self.rows):
            text = row[column].strip()
            if not text:
                out.append(None)
            elif text.isdigit() and len(text) <= 9:
                out.append(int(text))
            else:
                self.fail(k, f"column {name}: expected a whole-number code, found {quoted(text)}")
        return out


def iter_ansur(
    path: str | Path,
    *,
    label: str = DEFAULT_LABEL,
    chunk_rows: int = CHUNK_ROWS,
    progress: Callable[[int], None] | None = None,
) -> Iterator[PeopleBatch]:
    """Read an ANSUR II format CSV file (`.csv` or `.csv.gz`) a chunk of rows at
    a time: memory stays bounded whatever the file's size.  Every row is
    checked; the first bad one raises AnsurImportError naming file:line (the
    caller's transaction then stores nothing).  `progress(bytes_read)`."""
    path = Path(path)
    try:
        raw, stream = _open_bytes(regular_file(path))  # a FIFO or a device would never end
    except PathError as exc:
        raise AnsurImportError(f"{path}: cannot read: {exc.reason}") from None
    except OSError as exc:
        raise AnsurImportError(f"{path}: cannot read: {reason_text(exc)}") from None
    with raw:
        try:
            yield from _read_chunks(path, stream, raw, label, chunk_rows, progress)
        except (OSError, EOFError) as exc:  # read errors, damaged or cut gzip data
            reason = getattr(exc, "strerror", None) or exc or "the file ends too early"
            raise AnsurImportError(f"{path}: cannot read: {reason}") from None


def _read_chunks(
    path: Path,
    stream: BinaryIO,
    raw: BinaryIO,
    label: str,
    chunk_rows: int,
    progress: Callable[[int], None] | None,
) -> Iterator[PeopleBatch]:
    reader = _LineNamedReader(path, csv.reader(_decoded_lines(stream)))
    header_row = next(reader, None)
    if header_row is None:
        raise AnsurImportError(f"{path}:1: the file is empty; expected the ANSUR II header")
    wrong = other_separator(header_row)  # a survey file saved again by a spreadsheet
    if wrong is not None:
        raise AnsurImportError(f"{path}:1: {wrong}")
    header = [h.strip().lower() for h in header_row]
    column = {name: k for k, name in enumerate(header)}
    missing = [name for name in REQUIRED if name not in column]
    if missing:
        raise AnsurImportError(
            f"{path}:1: missing column{'s' if len(missing) > 1 else ''} "
            f"{', '.join(missing)} (ANSUR II public file expected)"
        )
    seen: dict[int, int] = {}
    rows: list[list[str]] = []
    lines: list[int] = []
    total = 0
    last_line = reader.line_num
    for row in reader:
        # A quote in a value makes csv read on into the next lines: name the
        # line where the record starts, where the fault is.
        lineno, last_line = last_line + 1, reader.line_num
        if not row:
            continue
        if len(row) != len(header):
            spans = f" (an unclosed quote runs to line {last_line})" if last_line > lineno else ""
            raise AnsurImportError(
                f"{path}:{lineno}: expected {len(header)} fields, found {len(row)}{spans}"
            )
        rows.append(row)
        lines.append(lineno)
        if len(rows) >= chunk_rows:
            yield _batch(path, _Chunk(path, rows, lines, column), column, seen, label)
            total += len(rows)
            rows, lines = [], []
            if progress:
                progress(raw.tell())
    if rows:
        yield _batch(path, _Chunk(path, rows, lines, column), column, seen, label)
        total += len(rows)
    if progress:
        progress(raw.tell())
    if total == 0:
        raise AnsurImportError(f"{path}:2: the file holds no subject")


def _subject_ids(chunk: _Chunk, column: int, seen: dict[int, int]) -> list[int]:
    out = []
    for k, row in enumerate(chunk.rows):
        text = row[column].strip()
        # isascii: str.isdigit also takes superscripts such as "¹", which int()
        # refuses; the length bound keeps int() off a 30,000-digit string.
        if (
            not (text.isascii() and text.isdigit())
            or len(text) > 20
            or not 1 <= int(text) <= MAX_SUBJECT_ID
        ):
            shown = text if len(text) <= 40 else f"{text[:20]}… ({len(text)} characters)"
            chunk.fail(
                k,
                f"column {ID_COLUMN}: expected a whole number from 1 to {MAX_SUBJECT_ID}, "
                f"found {shown!r}",
            )
        subject = int(text)
        if subject in seen:
            chunk.fail(k, f"duplicate subject id {subject} (first on line {seen[subject]})")
        seen[subject] = chunk.lines[k]
        out.append(subject)
    return out


def derived_girth(measures: np.ndarray) -> np.ndarray:
    """The girth relation (people, rows, x/y/z/mass) of people with the 93
    ANSUR II measures (people, MEASURES; cm, kg), derived as report §10.1
    prescribes (_derive): ANSUR II people and virtual people alike."""
    n = len(measures)
    by_name = {name: measures[:, j] for j, name in enumerate(MEASURES)}
    girth = np.empty((n, len(GIRTH_NAMES), 4))
    girth[:, :, :3] = _derive(by_name, n)
    girth[:, :, 3] = by_name["weightkg"][:, None] * girth_mass_fractions()[None, :]
    return girth


def _batch(
    path: Path, chunk: _Chunk, column: dict[str, int], seen: dict[int, int], label: str
) -> PeopleBatch:
    n = len(chunk.rows)
    subject = _subject_ids(chunk, column[ID_COLUMN], seen)
    gender = chunk.words(column["gender"], "gender", GENDER)
    measures = np.empty((n, len(MEASURES)))
    for j, name in enumerate(MEASURES):
        values = chunk.numbers(column.get(name), name)
        if name in column:
            # mm -> cm exactly as printed (164.1, not 164.10000000000002)
            values = np.round(values * PUBLISHED_TO_CANONICAL[name], 6)
            chunk.check(values, name, MEASURE_LIMITS[name], MEASURE_UNITS[name])
        measures[:, j] = values
    age = chunk.numbers(column["age"], "age")
    chunk.check(age, "age", AGE_LIMITS, "years")
    by_name = {name: measures[:, j] for j, name in enumerate(MEASURES)}
    mass = by_name["weightkg"]
    girth = derived_girth(measures)
    letter = {"male": "M", "female": "F"}
    if label == DEFAULT_LABEL:
        names = [f"ANSUR II {letter[g]} {s}" for g, s in zip(gender, subject)]
        keys: list[str | None] = [f"ANSUR II:{g}:{s}" for g, s in zip(gender, subject)]
    else:
        names = [f"{label} {letter[g]} {s}" for g, s in zip(gender, subject)]
        keys = [f"{label}:{g}:{s}" for g, s in zip(gender, subject)]
    attributes: dict[str, list[object]] = {
        name: chunk.texts(column.get(name), name) for name in TEXT_ATTRIBUTES
    }
    attributes.update({name: chunk.codes(column.get(name), name) for name in CODE_ATTRIBUTES})
    return PeopleBatch(
        id_num=np.zeros(n, dtype=np.int64),
        name=names,
        gender=gender,
        stature=by_name["stature"].copy(),
        mass=mass.copy(),
        handedness=list(
            chunk.words(column["writingpreference"], "writingpreference", ANSUR_HANDEDNESS)
        ),
        age=age,
        source=[label] * n,
        source_key=keys,
        girth=girth,
        attributes=attributes,
        measures=measures,
    )


def read_ansur(path: str | Path, *, label: str = DEFAULT_LABEL) -> PeopleBatch:
    """The whole file as one batch (tests and small files; imports stream)."""
    parts = list(iter_ansur(path, label=label))
    return concat_batches(parts)


def concat_batches(parts: Sequence[PeopleBatch]) -> PeopleBatch:
    def join(name: str) -> np.ndarray | None:
        arrays = [getattr(p, name) for p in parts]
        return None if any(a is None for a in arrays) else np.concatenate(arrays)

    return PeopleBatch(
        id_num=np.concatenate([p.id_num for p in parts]),
        name=[x for p in parts for x in p.name],
        gender=[x for p in parts for x in p.gender],
        stature=np.concatenate([p.stature for p in parts]),
        mass=np.concatenate([p.mass for p in parts]),
        handedness=[x for p in parts for x in p.handedness],
        age=np.concatenate([p.age for p in parts]),
        source=[x for p in parts for x in p.source],
        source_key=[x for p in parts for x in p.source_key],
        girth=join("girth"),
        attributes={
            name: [x for p in parts for x in p.attributes.get(name, [None] * len(p))]
            for name in PERSON_ATTRIBUTES
        },
        measures=join("measures"),
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


def store_ansur(
    conn: sqlite3.Connection,
    paths: Sequence[str | Path],
    *,
    label: str = DEFAULT_LABEL,
    progress: Progress | None = None,
) -> dict[str, int]:
    """Stream the files into the database inside the caller's transaction.
    Returns people per gender; progress(bytes done, bytes in all files)."""
    sizes = [Path(p).stat().st_size if Path(p).is_file() else 0 for p in paths]
    total = sum(sizes)
    before = 0
    counts = {"male": 0, "female": 0}
    for path, size in zip(paths, sizes):

        def report(done: int, before: int = before) -> None:
            if progress:
                progress(before + done, total)

        for batch in iter_ansur(path, label=label, progress=report):
            _assign_ids(conn, batch)
            store_people(conn, batch)
            for g in batch.gender:
                counts[g] += 1
        before += size
    return counts


def import_ansur(
    conn: sqlite3.Connection,
    paths: Sequence[str | Path],
    progress: Progress | None = None,
    *,
    label: str = DEFAULT_LABEL,
    cancel: Cancel | None = None,
) -> dict[str, int]:
    """Import the files in one transaction (a bad line stores nothing).
    Returns people per gender.  `progress(bytes read, bytes in all files)`;
    `cancel` stops it at the next chunk with Cancelled, everything rolled back."""
    if not label.strip():
        raise AnsurImportError("the source label is empty; expected e.g. ansur2")
    found = control_character(label)
    if found:
        raise AnsurImportError(
            f"the source label {printable(label)!r} holds {found}; expected printable text, "
            "e.g. mysurvey"
        )
    named: dict[str, str | Path] = {}
    for path in paths:
        # one file twice stored its people once, but counted them twice
        real = os.path.realpath(path)
        if real in named:
            also = "" if str(named[real]) == str(path) else f" (also as {named[real]})"
            raise AnsurImportError(f"{path} is named twice{also}; name each file once")
        named[real] = path
    check_writable(conn)
    with transaction(conn):
        return store_ansur(conn, paths, label=label, progress=Steps(progress, cancel, "the import"))


def import_ansur_into(
    db: Database,
    files: Sequence[str | Path],
    *,
    label: str,
    progress: Progress | None = None,
    cancel: Cancel | None = None,
) -> dict[str, int]:
    """Import ANSUR II format files into `db` in one transaction, as
    db/engine/staging.py's store_people decides (on PostgreSQL through a staging
    file); people per gender."""
    with db.connection() as conn:
        return staging.store_people(
            conn,
            lambda storing: import_ansur(storing, files, progress, label=label, cancel=cancel),
            cancel,
        )
