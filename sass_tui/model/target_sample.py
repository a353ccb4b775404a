"""A target population's sample: a CSV file, one person a row.

Columns are named like `sass predict --known`: `stature`, `mass`,
`measure.<name>` (ANSUR II's names); a unit in brackets after the name
(`stature[cm]`, `mass [lb]`, `stature[in]`) is the unit of the column's bare
numbers, and a value may carry its own (`64 in`), as everywhere in sass
(`sass_tui.model.units`).  Without either, values are in the field's
canonical unit (cm; kg for mass).  Other columns (an id, age, a survey
weight) are passed over; an empty cell is a value the person lacks.
Every error names the file, the line and the column.
"""

from __future__ import annotations

import csv
import io
import re
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from sass_tui.model.errors import SassError
from sass_tui.model.text import quoted
from sass_tui.model.units import UnitError, convert, parse_quantity, unit_name

_HEADER = re.compile(r"^\s*([^\[\]]*?)\s*(?:\[([^\[\]]*)\])?\s*$")


class SampleError(ValueError, SassError):
    """A sample file sass cannot read (nothing was stored)."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


@dataclass(frozen=True)
class Sample:
    fields: tuple[str, ...]  # the --by fields, in their order
    matrix: npt.NDArray[np.float64]  # (rows with every field, fields), canonical units
    rows: int  # data rows in the file
    incomplete: int  # rows lacking a value of some field (left out)


def is_weighting_field(field: str) -> bool:
    """A field a target can be made over: stature, mass, measure.<name>."""
    return field in ("stature", "mass") or field.startswith("measure.")


def header_field(name: str) -> str | None:
    """The field a column name stands for, None for a column passed over."""
    # deferred: model.accommodation — off sass target (sass_tui/startup.py)
    from sass_tui.model.accommodation import measure_field

    word = name.strip().lower()
    if word not in ("stature", "mass") and not word.startswith("measure."):
        return None
    return measure_field(word)


def read_sample(text: str, fields: Sequence[str], where: str) -> Sample:
    """The values of `fields` (query-language names) in the CSV `text` (the
    file `where`).  SampleError says file:line and the column."""
    # deferred: model.prediction — off sass target (sass_tui/startup.py)
    from sass_tui.model.prediction import field_unit

    fields = tuple(fields)
    reader = csv.reader(io.StringIO(text.removeprefix("\ufeff"), newline=""))
    try:
        header = next(reader)
    except StopIteration:
        raise SampleError(f"{where}:1: the file is empty; expected a header row") from None
    except csv.Error as exc:
        raise SampleError(f"{where}:1: {exc}", where=f"{where}:1") from None
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
    absent = [f for f in fields if f not in columns]
    if absent:
        have = ", ".join(repr(h) for h in header[:8]) + (", ..." if len(header) > 8 else "")
        raise SampleError(
            f"{where}:1: no column for {', '.join(absent)} (the header has {have}); "
            "name columns like `sass predict --known`: stature, mass, measure.<name>, "
            "with the unit in brackets, e.g. stature[cm], mass[lb]",
            where=f"{where}:1",
        )
    values: list[list[float]] = []
    rows = 0
    try:
        for row in reader:
            line = reader.line_num
            if not any(cell.strip() for cell in row):
                continue
            rows += 1
            if len(row) != len(header):
                raise SampleError(
                    f"{where}:{line}: expected {len(header)} fields, found {len(row)}",
                    where=f"{where}:{line}",
                )
            values.append([_cell(row, columns[f], f, field_unit(f), where, line) for f in fields])
    except csv.Error as exc:
        raise SampleError(
            f"{where}:{reader.line_num}: {exc}", where=f"{where}:{reader.line_num}"
        ) from None
    matrix = np.array(values, dtype=float).reshape(len(values), len(fields))
    complete = ~np.isnan(matrix).any(axis=1)
    return Sample(fields, matrix[complete], rows, int((~complete).sum()))


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
    return value
