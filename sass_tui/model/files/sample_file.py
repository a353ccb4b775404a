"""A target population's sample file: a CSV file, one person a row, read into
a `Sample` (model/population/target_sample.py).

Columns are named like `sass predict --known`: `stature`, `mass`,
`measure.<name>` (ANSUR II's names); a unit in brackets after the name
(`stature[cm]`, `mass [lb]`, `stature[in]`) is the unit of the column's bare
numbers, and a value may carry its own (`64 in`), as everywhere in sass
(`sass_tui.model.units`).  Without either, values are in the field's
canonical unit (cm; kg for mass).  An empty cell is a value the person
lacks.  Three more columns are read when there: `gender` (male or female:
a target of one gender keeps that gender's rows, a target of both needs
it), `age` (years; a virtual person keeps it) and the survey weight that
`--weight COLUMN` names (NHANES's WTMECPRP: each row stands for that many
people, so an oversampled group counts its share, not its rows).  Other
columns (an id, a code) are passed over; a column named like a survey
weight that no `--weight` names is reported (`Sample.unused_weights`).
Every error names the file, the line and the column.
"""

from __future__ import annotations

import csv
import io
import math
import re
from collections.abc import Sequence

import numpy as np

from sass_tui.model.body.human import MAX_STATURE_CM, not_human
from sass_tui.model.errors import SassError
from sass_tui.model.population.measure_fields import measure_field
from sass_tui.model.population.prediction import field_unit
from sass_tui.model.population.target_sample import Sample, SampleError, is_survey_weight
from sass_tui.model.text import other_separator, quoted
from sass_tui.model.units import LARGEST_NUMBER, UnitError, convert, parse_quantity, unit_name
from sass_tui.model.vocabulary import GENDERS

_HEADER = re.compile(r"^\s*([^\[\]]*?)\s*(?:\[([^\[\]]*)\])?\s*$")
GENDER_WORDS = {"male": "male", "m": "male", "female": "female", "f": "female"}
MAX_AGE = 130.0


# NHANES's body-measure columns that stand for ANSUR II measures
# (docs/target-populations.md, "Keep what NHANES measured"): its hip is
# ANSUR II's buttock circumference (both at the buttocks' maximum
# protrusion); its waist, at the iliac crest, is taken for ANSUR II's at
# omphalion, a cross-walk the validation checks.
NHANES_COLUMNS = {
    "hip_circumference": "measure.buttockcircumference",
    "waist_circumference": "measure.waistcircumference",
}


def header_field(name: str) -> str | None:
    """The field a column name stands for, None for a column passed over."""
    word = name.strip().lower()
    if word in NHANES_COLUMNS:
        return NHANES_COLUMNS[word]
    if word not in ("stature", "mass") and not word.startswith("measure."):
        return None
    return measure_field(word)


def read_sample(
    text: str,
    fields: Sequence[str],
    where: str,
    *,
    weight: str | None = None,
    gender: str | None = None,
    need_gender: bool = False,
    optional: Sequence[str] = (),
) -> Sample:
    """The values of `fields` (query-language names) in the CSV `text` (the
    file `where`): with `gender`, only that gender's rows when the sample has
    a gender column; `need_gender`: the sample must have one.  `weight` names
    the survey weight column.  `optional` fields are read too when the file
    has their columns (an empty cell: NaN; a row is not left out for lacking
    one).  SampleError says file:line and the column."""
    fields = tuple(fields)
    reader = csv.reader(io.StringIO(text.removeprefix("\ufeff"), newline=""))
    try:
        header = next(reader)
    except StopIteration:
        raise SampleError(f"{where}:1: the file is empty; expected a header row") from None
    except csv.Error as exc:
        raise SampleError(f"{where}:1: {exc}", where=f"{where}:1") from None
    wrong = other_separator(header)
    if wrong is not None:
        raise SampleError(f"{where}:1: {wrong}", where=f"{where}:1")
    columns: dict[str, tuple[int, str, str]] = {}  # field -> (column, unit, header)
    for c, cell in enumerate(header):
        match = _HEADER.match(cell)
        name, unit_text = (match.group(1), match.group(2)) if match else (cell, None)
        place = f"{where}:1"
        try:
            field = header_field(name)
        except SassError as exc:
            raise SampleError(
                f"{place}: column {c + 1} {quoted(cell)}: {exc}", where=place
            ) from None
        if field is None:
            continue
        canonical = field_unit(field)
        unit = canonical
        if unit_text is not None:
            try:
                unit = unit_name(unit_text)
                convert(1.0, unit, canonical)
            except UnitError as exc:
                raise SampleError(
                    f"{place}: column {c + 1} {quoted(cell)}: {exc}; expected a unit of "
                    f"{'mass (kg, lb)' if canonical == 'kg' else 'length (cm, mm, in)'}",
                    where=place,
                ) from None
        if field in columns:
            raise SampleError(
                f"{place}: column {c + 1} {quoted(cell)} repeats column "
                f"{columns[field][0] + 1} {columns[field][2]!r}",
                where=place,
            )
        columns[field] = (c, unit, cell)
    lower = {cell.strip().lower(): c for c, cell in enumerate(header)}
    weight_column = _weight_column(header, weight, where)
    gender_column = lower.get("gender")
    if gender_column is None and need_gender:
        raise SampleError(
            f"{where}:1: no gender column; a target of both genders (no --gender) needs "
            "each row's gender: a column `gender` of male or female",
            where=f"{where}:1",
        )
    age_column = lower.get("age")
    absent = [f for f in fields if f not in columns]
    if absent:
        have = ", ".join(repr(h) for h in header[:8]) + (", ..." if len(header) > 8 else "")
        raise SampleError(
            f"{where}:1: no column for {', '.join(absent)} (the header has {have}); "
            "name columns like `sass predict --known`: stature, mass, measure.<name>, "
            "with the unit in brackets, e.g. stature[cm], mass[lb]",
            where=f"{where}:1",
        )
    extra = tuple(f for f in optional if f in columns and f not in fields)
    values: list[list[float]] = []
    measured: list[list[float]] = []
    weights: list[float] = []
    genders: list[str] = []
    ages: list[float] = []
    rows = 0
    try:
        for row in reader:
            line = reader.line_num
            if not any(cell.strip() for cell in row):
                continue
            if len(row) != len(header):
                raise SampleError(
                    f"{where}:{line}: expected {len(header)} fields, found {len(row)}",
                    where=f"{where}:{line}",
                )
            if gender_column is not None:
                word = _gender(row, gender_column, header, where, line)
                if gender is not None and word != gender:
                    continue
                genders.append(word)
            rows += 1
            values.append([_cell(row, columns[f], f, field_unit(f), where, line) for f in fields])
            measured.append([_cell(row, columns[f], f, field_unit(f), where, line) for f in extra])
            if weight_column is not None:
                weights.append(_weight(row, weight_column, header, where, line))
            if age_column is not None:
                ages.append(_age(row, age_column, header, where, line))
    except csv.Error as exc:
        raise SampleError(
            f"{where}:{reader.line_num}: {exc}", where=f"{where}:{reader.line_num}"
        ) from None
    matrix = np.array(values, dtype=float).reshape(len(values), len(fields))
    complete = ~np.isnan(matrix).any(axis=1)
    unused = tuple(
        cell.strip()
        for c, cell in enumerate(header)
        if c != weight_column and is_survey_weight(cell) and header_field(cell) is None
    )
    return Sample(
        fields,
        matrix[complete],
        rows,
        int((~complete).sum()),
        np.array(weights)[complete] if weight_column is not None else None,
        tuple(g for g, k in zip(genders, complete) if k) if gender_column is not None else None,
        np.array(ages)[complete] if age_column is not None else None,
        header[weight_column].strip() if weight_column is not None else None,
        unused,
        extra,
        np.array(measured, dtype=float).reshape(len(measured), len(extra))[complete]
        if extra
        else None,
    )


def _weight_column(header: Sequence[str], weight: str | None, where: str) -> int | None:
    if weight is None:
        return None
    for c, cell in enumerate(header):
        if cell.strip().lower() == weight.strip().lower():
            return c
    have = ", ".join(repr(h) for h in header[:12]) + (", ..." if len(header) > 12 else "")
    raise SampleError(
        f"{where}:1: --weight {weight!r}: no such column (the header has {have})",
        where=f"{where}:1",
    )


def _weight(row: list[str], c: int, header: Sequence[str], where: str, line: int) -> float:
    """A row's survey weight: over 0 and at most LARGEST_NUMBER, as every number
    sass reads (weights of 1e308 added up to infinity, and the calibration's
    least squares failed with numpy's "SVD did not converge")."""
    text = row[c].strip()
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    place = f"{where}:{line}"
    if not value > 0:
        why = "a survey weight must be a number greater than 0"
    elif not (math.isfinite(value) and value <= LARGEST_NUMBER):
        why = f"a survey weight must be a number of at most {LARGEST_NUMBER:g}"
    else:
        return value
    raise SampleError(f"{place}: column {c + 1} {header[c]!r}: {text!r}: {why}", where=place)


def _gender(row: list[str], c: int, header: Sequence[str], where: str, line: int) -> str:
    text = row[c].strip()
    word = GENDER_WORDS.get(text.lower())
    if word is None:
        place = f"{where}:{line}"
        raise SampleError(
            f"{place}: column {c + 1} {header[c]!r}: {text!r}: expected {' or '.join(GENDERS)}",
            where=place,
        )
    return word


def _age(row: list[str], c: int, header: Sequence[str], where: str, line: int) -> float:
    text = row[c].strip()
    if not text:
        return math.nan
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and 0 <= value <= MAX_AGE):
        place = f"{where}:{line}"
        raise SampleError(
            f"{place}: column {c + 1} {header[c]!r}: {text!r}: an age must be a number of "
            f"years from 0 to {MAX_AGE:.0f}",
            where=place,
        )
    return value


def _cell(
    row: list[str], column: tuple[int, str, str], field: str, canonical: str, where: str, line: int
) -> float:
    c, unit, name = column
    text = row[c].strip()
    if not text:
        return float("nan")
    try:
        value = convert(parse_quantity(text, unit), unit, canonical)
    except UnitError as exc:
        place = f"{where}:{line}"
        raise SampleError(f"{place}: column {c + 1} {name!r}: {exc}", where=place) from None
    if value <= 0:
        place = f"{where}:{line}"
        raise SampleError(
            f"{place}: column {c + 1} {name!r}: {quoted(text)}: a {field} must be greater than 0",
            where=place,
        )
    # The check a typed stature or mass gets (model/body/human.py); no other
    # measure of a body is longer than its tallest stature.
    if canonical == "kg" or field == "stature":
        refused = not_human("mass" if canonical == "kg" else "stature", value)
    elif value > MAX_STATURE_CM:
        refused = f"{field} {value:g} cm is longer than any body's ({MAX_STATURE_CM:g} cm at most)"
    else:
        refused = None
    if refused:
        place = f"{where}:{line}"
        raise SampleError(f"{place}: column {c + 1} {name!r}: {refused}", where=place)
    return value
