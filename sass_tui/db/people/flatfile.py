"""Legacy flat files, one relation per file (report §12.3.3, figure 12).

    1,BOTTOM_HEAD, 9.80, 7.75, 24.41, 1.40

Fields in the order of the relation, after id_num; 999.0 = no value.  Files
and their fields (units of the stored values in brackets):

    person.db          id, name, gender, stature [cm], mass [kg], handedness, age, source
                       (source is the rest of the line and may hold commas)
    girth.db           id, segment, thickness, width, length [cm], mass [kg]
    jntlmt.db          id, joint-limit row, x, y, z [deg]
    cmass.db           id, segment, x, y, z [cm]
    strgh-par.db       id, exp_num, side, strength type, speed, fatigue, training,
                       angle unit, strength unit, speed unit
    shoulder-strgh.db  id, exp_num, shoulder x, y, z, elbow, axis, pstrgh, nstrgh
    elbow-strgh.db     id, exp_num, elbow, shoulder x, y, z, wrist x, y, z, pstrgh, nstrgh
    wrist-strgh.db     id, exp_num, wrist x, y, z, elbow, axis, pstrgh, nstrgh

Strength rows are in the units their experiment's strgh-par row names
(deg|rad, ft-lb|N-m, deg/s|rad/s) and stored converted.  Segment names may be
spelled as figure 12 does (R_UPPER_ARM, R_TOES, R_FINGERS).  Every file of one
import is read before anything is written, and everything is written in one
transaction: a bad line rejects the whole import with file:line.
"""

from __future__ import annotations

import math
import sqlite3
from collections.abc import Iterator, Sequence
from contextvars import ContextVar
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, NoReturn

import numpy as np

from sass_tui.db.engine import staging
from sass_tui.db.engine.schema import (
    CENTER_OF_MASS_NAMES,
    GIRTH_NAMES,
    JOINT_LIMIT_NAMES,
    MASS_ONLY_SEGMENTS,
    SqlRow,
    check_writable,
    transaction,
)
from sass_tui.db.people.people_store import PeopleBatch, store_people
from sass_tui.db.progress import Cancel, Progress, Steps, interruptible
from sass_tui.db.query.scope import source_label
from sass_tui.model.errors import SassError, reason_text
from sass_tui.model.files.atomic import write_files_atomic
from sass_tui.model.files.paths import LARGEST_TABLE_FILE, PathError, regular_file
from sass_tui.model.text import control_character, quoted
from sass_tui.model.units import UnitError, convert, unit_name
from sass_tui.model.vocabulary import GENDERS, SIDES, STRENGTH_TYPES
from sass_tui.model.vocabulary import PERSON_HANDEDNESS as HANDEDNESS

if TYPE_CHECKING:
    from sass_tui.db.engine.database import Database

NO_VALUE = 999.0
# Ids stay below 10^12: exact in a float, and far from SQLite's 64-bit limit
# (the next id after the largest is always representable).
MAX_ID = 10**12 - 1
FILE_NAMES = {
    "person": "person.db",
    "girth": "girth.db",
    "joint_limits": "jntlmt.db",
    "center_of_mass": "cmass.db",
    "strength_par": "strgh-par.db",
    "shoulder": "shoulder-strgh.db",
    "elbow": "elbow-strgh.db",
    "wrist": "wrist-strgh.db",
}


class FlatFileError(ValueError, SassError):
    """A flat file breaks the format; nothing of the import was stored."""


@dataclass(frozen=True)
class FlatFiles:
    person: Path
    girth: Path | None = None
    joint_limits: Path | None = None
    center_of_mass: Path | None = None
    strength_par: Path | None = None
    shoulder: Path | None = None
    elbow: Path | None = None
    wrist: Path | None = None

    @classmethod
    def in_directory(cls, directory: str | Path) -> FlatFiles:
        directory = Path(directory)
        found = {
            key: directory / name
            for key, name in FILE_NAMES.items()
            if (directory / name).is_file()
        }
        return cls(**found)


# Lines between two progress reports of an import.
REPORT_LINES = 500


class _LineCount:
    """Lines read so far of an import's files, reported to its Steps."""

    def __init__(self, steps: Steps, total: int) -> None:
        self.steps = steps
        self.total = total
        self.done = 0

    def tick(self) -> None:
        self.done += 1
        if self.done % REPORT_LINES == 0:
            self.steps(min(self.done, self.total), self.total)


# The import being read in this thread (None: nobody is told).
_LINES: ContextVar[_LineCount | None] = ContextVar("flatfile_lines", default=None)


class _Reader:
    def __init__(self, path: Path):
        self.path = path
        try:
            # a FIFO or a device would never end; a huge file is refused unread
            regular_file(path, largest=LARGEST_TABLE_FILE, kind="a flat file")
        except PathError as exc:
            raise FlatFileError(f"{path}: cannot read: {exc.reason}") from None
        try:
            self.text = path.read_text(encoding="utf-8-sig")
        except UnicodeDecodeError:
            self.text = path.read_text(encoding="cp1252", errors="replace")
        except OSError as exc:
            raise FlatFileError(f"{path}: cannot read: {reason_text(exc)}") from None
        self.line = 0

    def records(self, width: int, what: str, rest: bool = False) -> Iterator[list[str]]:
        lines = _LINES.get()
        for line_number, text in enumerate(self.text.splitlines(), start=1):
            self.line = line_number  # fail() names it
            if lines is not None:
                lines.tick()
            if not text.strip():
                continue
            fields = [f.strip() for f in (text.split(",", width - 1) if rest else text.split(","))]
            if len(fields) != width:
                self.fail(f"expected {width} comma-separated fields ({what}), found {len(fields)}")
            yield fields

    def fail(self, message: str) -> NoReturn:
        raise FlatFileError(f"{self.path}:{self.line}: {message}")

    def number(self, text: str, field_name: str) -> float:
        try:
            value = float(text)
        except ValueError:
            self.fail(f"{field_name}: expected a number, found {quoted(text)}")
        if not math.isfinite(value):
            self.fail(f"{field_name}: expected a finite number, found {quoted(text)}")
        return math.nan if value == NO_VALUE else value

    def integer(self, text: str, field_name: str) -> int:
        try:
            value = int(text)
        except ValueError:
            self.fail(f"{field_name}: expected a whole number, found {quoted(text)}")
        if not 0 <= value <= MAX_ID:
            self.fail(
                f"{field_name}: expected a whole number from 0 to {MAX_ID}, found {quoted(text)}"
            )
        return value

    def plausible(self, text: str, field_name: str, high: float, unit: str) -> float:
        """A person's stature, mass or age: no value (999), or 0 < v <= high."""
        value = self.number(text, field_name)
        if value == value and not 0 < value <= high:
            self.fail(
                f"{field_name}: {quoted(text)} is not plausible "
                f"(expected more than 0 and at most {high:g} {unit}, or 999.0 for no value)"
            )
        return value

    def choice(self, text: str, choices: Sequence[str], field_name: str) -> str:
        word = text.strip().lower()
        if word not in choices:
            self.fail(f"{field_name}: expected one of {', '.join(choices)}, found {quoted(text)}")
        return word


def legacy_name(text: str) -> str:
    """'R_UPPER_ARM' -> 'right_upper_arm', 'L_TOES' -> 'left_ball_of_foot'."""
    name = text.strip().lower().replace(" ", "_")
    if name.startswith("r_"):
        name = "right_" + name[2:]
    elif name.startswith("l_"):
        name = "left_" + name[2:]
    return {
        "right_toes": "right_ball_of_foot",
        "left_toes": "left_ball_of_foot",
        "right_fingers": "right_knuckles",
        "left_fingers": "left_knuckles",
    }.get(name, name)


def read_flat_files(files: FlatFiles) -> PeopleBatch:
    """Parse and check every file; raises FlatFileError (file:line) on the first bad line."""
    if (files.shoulder or files.elbow or files.wrist) and not files.strength_par:
        raise FlatFileError("strength files need the strength parameter file (strgh-par.db)")
    people = _read_person(_Reader(Path(files.person)))
    index = {pid: i for i, pid in enumerate(people["id_num"])}
    n = len(index)
    batch = PeopleBatch(
        id_num=np.array(people["id_num"], dtype=np.int64),
        name=people["name"],
        gender=people["gender"],
        stature=np.array(people["stature"]),
        mass=np.array(people["mass"]),
        handedness=people["handedness"],
        age=np.array(people["age"]),
        source=people["source"],
        source_key=[None] * n,
    )
    if files.girth:
        batch.girth, batch.extra_girth = _read_group(
            _Reader(Path(files.girth)), index, GIRTH_NAMES, 4, MASS_ONLY_SEGMENTS
        )
    if files.joint_limits:
        batch.joint_limits, _ = _read_group(
            _Reader(Path(files.joint_limits)), index, JOINT_LIMIT_NAMES, 3
        )
    if files.center_of_mass:
        batch.center_of_mass, _ = _read_group(
            _Reader(Path(files.center_of_mass)), index, CENTER_OF_MASS_NAMES, 3
        )
    if files.strength_par:
        _read_strength(files, files.strength_par, index, batch)
    return batch


def _person_id(reader: _Reader, text: str, index: dict[int, int]) -> int:
    pid = reader.integer(text, "id_num")
    if pid not in index:
        reader.fail(f"id_num {pid} is not in the person file")
    return index[pid]


def _read_person(reader: _Reader) -> dict[str, list[Any]]:
    out: dict[str, list[Any]] = {
        k: []
        for k in ("id_num", "name", "gender", "stature", "mass", "handedness", "age", "source")
    }
    seen: dict[int, int] = {}
    for f in reader.records(
        8, "id, name, gender, stature, mass, handedness, age, source", rest=True
    ):
        pid = reader.integer(f[0], "id_num")
        if pid in seen:
            reader.fail(f"duplicate id_num {pid} (first on line {seen[pid]})")
        seen[pid] = reader.line
        if not f[1]:
            reader.fail("name: expected a name, found nothing")
        if not f[7]:
            reader.fail("source: say where the data come from")
        for field_name, text in (("name", f[1]), ("source", f[7])):
            found = control_character(text)
            if found:  # an escape sequence would act on the terminal that shows it
                reader.fail(f"{field_name}: {found}; expected printable text")
        out["id_num"].append(pid)
        out["name"].append(f[1])
        out["gender"].append(reader.choice(f[2], GENDERS, "gender"))
        out["stature"].append(reader.plausible(f[3], "stature", 300.0, "cm"))
        out["mass"].append(reader.plausible(f[4], "mass", 500.0, "kg"))
        out["handedness"].append(
            None if f[5] == "999.0" or not f[5] else reader.choice(f[5], HANDEDNESS, "handedness")
        )
        out["age"].append(reader.plausible(f[6], "age", 130.0, "years"))
        out["source"].append(source_label(f[7]))
    if not seen:
        raise FlatFileError(f"{reader.path}:1: the person file holds no person")
    return out


def _read_group(
    reader: _Reader,
    index: dict[int, int],
    names: Sequence[str],
    width: int,
    extra_names: Sequence[str] = (),
) -> tuple[np.ndarray, list[SqlRow]]:
    values = np.full((len(index), len(names), width), np.nan)
    row_of = {name: r for r, name in enumerate(names)}
    seen: dict[tuple[int, str], int] = {}
    extra: list[SqlRow] = []
    what = "id, name, " + ", ".join(f"value {k + 1}" for k in range(width))
    for f in reader.records(width + 2, what):
        i = _person_id(reader, f[0], index)
        name = legacy_name(f[1])
        if name not in row_of and name not in extra_names:
            reader.fail(f"unknown row {f[1]!r}; expected one of {', '.join(names)}")
        if (i, name) in seen:
            reader.fail(f"duplicate row {f[1]!r} for id_num {f[0]} (first on line {seen[i, name]})")
        seen[i, name] = reader.line
        numbers = [reader.number(text, f"value {k + 1}") for k, text in enumerate(f[2:])]
        if name in row_of:
            values[i, row_of[name]] = numbers
        else:
            extra.append((i, name, *[None if v != v else v for v in numbers]))
    return values, extra


def _unit(reader: _Reader, text: str, canonical: str) -> str:
    try:
        unit = unit_name(text)
        convert(1.0, unit, canonical)
    except UnitError as exc:
        reader.fail(f"{exc}")
    return unit


def _read_strength(
    files: FlatFiles, strength_par: Path, index: dict[int, int], batch: PeopleBatch
) -> None:
    reader = _Reader(Path(strength_par))
    units: dict[tuple[int, int], tuple[str, str]] = {}
    for f in reader.records(
        10,
        "id, exp_num, side, type, speed, fatigue, training, angle unit, strength unit, speed unit",
    ):
        i = _person_id(reader, f[0], index)
        exp = reader.integer(f[1], "exp_num")
        if (i, exp) in units:
            reader.fail(f"duplicate experiment {exp} for id_num {f[0]}")
        angle_unit = _unit(reader, f[7], "deg")
        strength_unit = _unit(reader, f[8], "N_m")
        speed_unit = _unit(reader, f[9], "deg/s")
        units[i, exp] = (angle_unit, strength_unit)
        speed = convert(reader.number(f[4], "speed"), speed_unit, "deg/s")
        batch.strength_par.append(
            (
                i,
                exp,
                reader.choice(f[2], SIDES, "side_of_limb"),
                reader.choice(f[3], STRENGTH_TYPES, "strgh_type"),
                _none(speed),
                _none(reader.number(f[5], "fatigue")),
                _none(reader.number(f[6], "training")),
            )
        )

    def experiment(reader: _Reader, f: list[str]) -> tuple[int, int, str, str]:
        i = _person_id(reader, f[0], index)
        exp = reader.integer(f[1], "exp_num")
        if (i, exp) not in units:
            reader.fail(f"experiment {exp} of id_num {f[0]} is not in the strength parameter file")
        return (i, exp, *units[i, exp])

    def angles(reader: _Reader, texts: list[str], unit: str) -> list[float | None]:
        return [_none(convert(reader.number(t, "angle"), unit, "deg")) for t in texts]

    def strengths(reader: _Reader, texts: list[str], unit: str) -> list[float | None]:
        return [_none(convert(reader.number(t, "strength"), unit, "N_m")) for t in texts]

    for key, target in (("shoulder", batch.shoulder), ("wrist", batch.wrist)):
        if getattr(files, key) is None:
            continue
        reader = _Reader(Path(getattr(files, key)))
        seen: set[tuple[int, int, str]] = set()
        for f in reader.records(9, f"id, exp_num, {key} x, y, z, elbow, axis, pstrgh, nstrgh"):
            i, exp, angle_unit, strength_unit = experiment(reader, f)
            axis = reader.choice(f[6], ("x", "y", "z"), "axis")
            if (i, exp, axis) in seen:
                reader.fail(f"duplicate axis {axis} for experiment {exp} of id_num {f[0]}")
            seen.add((i, exp, axis))
            target.append(
                (
                    i,
                    exp,
                    *angles(reader, f[2:6], angle_unit),
                    axis,
                    *strengths(reader, f[7:9], strength_unit),
                )
            )
    if files.elbow is not None:
        reader = _Reader(Path(files.elbow))
        seen_experiments: set[tuple[int, int]] = set()
        for f in reader.records(
            11, "id, exp_num, elbow, shoulder x, y, z, wrist x, y, z, pstrgh, nstrgh"
        ):
            i, exp, angle_unit, strength_unit = experiment(reader, f)
            if (i, exp) in seen_experiments:
                reader.fail(f"duplicate experiment {exp} for id_num {f[0]}")
            seen_experiments.add((i, exp))
            batch.elbow.append(
                (
                    i,
                    exp,
                    *angles(reader, f[2:9], angle_unit),
                    *strengths(reader, f[9:11], strength_unit),
                )
            )


def _none(value: float) -> float | None:
    return None if value != value else value


def _count_lines(files: FlatFiles) -> int:
    total = 0
    for name in FILE_NAMES:
        path = getattr(files, name)
        # not a FIFO, nor a file too large: the reader refuses them unread
        if path is not None and path.is_file():
            try:
                if path.stat().st_size > LARGEST_TABLE_FILE:
                    continue
                with open(path, "rb") as handle:
                    total += sum(
                        chunk.count(b"\n") for chunk in iter(lambda: handle.read(1 << 20), b"")
                    )
            except OSError:
                pass  # the reader says what is wrong with it, with its name
    return max(total, 1)


def import_flat_files(
    conn: sqlite3.Connection,
    files: FlatFiles,
    progress: Progress | None = None,
    cancel: Cancel | None = None,
) -> int:
    """Read every file, then store them in one transaction.  Returns the number of people.
    People whose id_num is already stored are replaced.

    `progress(lines read, lines in all files)`; the storing comes after the
    last line.  `cancel` stops the import where it is, reading or storing,
    with Cancelled: the transaction is rolled back and nothing is stored."""
    steps = Steps(progress, cancel, "the import")
    counter = _LineCount(steps, _count_lines(files))
    token = _LINES.set(counter)
    try:
        batch = read_flat_files(files)
    finally:
        _LINES.reset(token)
    steps(counter.total, counter.total)
    check_writable(conn)
    with transaction(conn), interruptible(conn, cancel, "the import"):
        store_people(conn, batch)
    return len(batch)


def import_flat_into(
    db: Database,
    files: FlatFiles,
    progress: Progress | None = None,
    cancel: Cancel | None = None,
) -> int:
    """Import legacy flat files into `db` in one transaction, as
    db/engine/staging.py's store_people decides (on PostgreSQL through a staging
    file); how many people."""
    with db.connection() as conn:
        return staging.store_people(
            conn, lambda storing: import_flat_files(storing, files, progress, cancel), cancel
        )


# --- writing (the default data set generator) ------------------------------


def _fmt(value: float | None) -> str:
    if value is None or value != value:
        return "999.0"
    return f"{value:.2f}"


def write_flat_files(batch: PeopleBatch, directory: str | Path) -> list[Path]:
    """Write a batch as the eight flat files (strength in N-m, deg, deg/s)."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    ids = batch.id_num.tolist()
    lines: dict[str, list[str]] = {k: [] for k in FILE_NAMES}
    for i, pid in enumerate(ids):
        lines["person"].append(
            f"{pid},{batch.name[i]},{batch.gender[i]},{_fmt(batch.stature[i])},{_fmt(batch.mass[i])},"
            f"{batch.handedness[i] or '999.0'},{_fmt(batch.age[i])},{batch.source[i]}"
        )
    for key, names, values in (
        ("girth", GIRTH_NAMES, batch.girth),
        ("joint_limits", JOINT_LIMIT_NAMES, batch.joint_limits),
        ("center_of_mass", CENTER_OF_MASS_NAMES, batch.center_of_mass),
    ):
        if values is None:
            continue
        for i, pid in enumerate(ids):
            for r, name in enumerate(names):
                if not np.all(np.isnan(values[i, r])):
                    lines[key].append(
                        f"{pid},{name.upper()}," + ",".join(_fmt(v) for v in values[i, r])
                    )
    for i, exp, side, kind, speed, fatigue, training in batch.strength_par:
        lines["strength_par"].append(
            f"{ids[i]},{exp},{side},{kind},{_fmt(speed)},{_fmt(fatigue)},"
            f"{_fmt(training)},deg,N-m,deg/s"
        )
    for key in ("shoulder", "elbow", "wrist"):
        for i, exp, *rest in getattr(batch, key):
            lines[key].append(
                f"{ids[i]},{exp}," + ",".join(v if isinstance(v, str) else _fmt(v) for v in rest)
            )
    files = {
        directory / name: "\n".join(lines[key]) + "\n"
        for key, name in FILE_NAMES.items()
        if lines[key]
    }
    write_files_atomic(files)  # all or none
    return list(files)
