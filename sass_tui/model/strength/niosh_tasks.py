"""A multi-task job for the NIOSH lifting equation, from a file
(`sass niosh --tasks FILE.json|.csv`): one task a row (CSV, a header naming
the columns) or an object (JSON, a list of them, or {"tasks": [...]}), the
columns `name, load, load_max, h, v, d, a, f, coupling, dest_h, dest_v,
dest_a, dest_coupling` (h, v, f and load required; d, when absent, from
dest_v; load is the average load, load_max the heaviest, for FILI).  Cells
are typed as the options are (model/strength/niosh_input.py): the first h
with a unit chooses the form.  A bad row is refused with its file:line.
"""

from __future__ import annotations

import csv
import io
import json
from collections.abc import Mapping
from typing import Any

from sass_tui.model.strength.niosh import Form, Lift, NioshError, Point, form
from sass_tui.model.strength.niosh_input import (
    angle,
    coupling,
    form_of,
    frequency,
    length,
    load,
    travel,
)
from sass_tui.model.text import other_separator, quoted
from sass_tui.model.units import UnitError, quantity_unit

COLUMNS = (
    "name",
    "load",
    "load_max",
    "h",
    "v",
    "d",
    "a",
    "f",
    "coupling",
    "dest_h",
    "dest_v",
    "dest_a",
    "dest_coupling",
)
REQUIRED = ("h", "v", "f", "load")
MAX_TASKS = 1000


def read_tasks(text: str, file: str, duration: str) -> tuple[Form, list[tuple[str, Lift]]]:
    """The tasks of a job file (its text; `file` names it in messages, and its
    suffix, .json or else CSV, says how to read it)."""
    rows = _json_rows(text, file) if file.lower().endswith(".json") else _csv_rows(text, file)
    if not rows:
        raise NioshError("the job has no task", where=file)
    if len(rows) > MAX_TASKS:
        raise NioshError(f"{len(rows)} tasks: at most {MAX_TASKS}", where=file)
    of = _job_form(rows, file)
    tasks: list[tuple[str, Lift]] = []
    first_line: dict[str, int] = {}  # each name's line: the results name each task by it
    for line, row in rows:
        try:
            name, lift = _task(row, of, duration, f"task {len(tasks) + 1}")
        except (UnitError, NioshError) as exc:
            raise NioshError(f"{exc}", where=f"{file}:{line}") from None
        if name in first_line:
            raise NioshError(
                f"task name {quoted(name)} is given twice (first on line {first_line[name]}); "
                "name each task once",
                where=f"{file}:{line}",
            )
        first_line[name] = line
        tasks.append((name, lift))
    return of, tasks


def _job_form(rows: list[tuple[int, dict[str, str]]], file: str) -> Form:
    """The form the first h typed with a unit asks for (metric if none)."""
    for line, row in rows:
        text = row.get("h")
        try:
            if text and quantity_unit(text) is not None:
                return form_of([text])
        except (UnitError, NioshError) as exc:
            raise NioshError(str(exc), where=f"{file}:{line}") from None
    return form("metric")


def _task(row: Mapping[str, str], of: Form, duration: str, default: str) -> tuple[str, Lift]:
    unknown = sorted(set(row) - set(COLUMNS))
    if unknown:
        raise NioshError(f"unknown column {quoted(unknown[0])} (expected {', '.join(COLUMNS)})")
    missing = [name for name in REQUIRED if not row.get(name)]
    if missing:
        raise NioshError(f"no {missing[0]} (each task needs {', '.join(REQUIRED)})")
    v = length(row["v"], of)
    dest_v = length(row["dest_v"], of) if row.get("dest_v") else None
    origin = Point(
        length(row["h"], of),
        v,
        angle(row["a"]) if row.get("a") else 0.0,
        coupling(row["coupling"]) if row.get("coupling") else "fair",
    )
    destination = None
    if row.get("dest_h") or dest_v is not None:
        if not row.get("dest_h") or dest_v is None:
            raise NioshError("a destination needs both dest_h and dest_v")
        destination = Point(
            length(row["dest_h"], of),
            dest_v,
            angle(row["dest_a"]) if row.get("dest_a") else origin.a,
            coupling(row["dest_coupling"]) if row.get("dest_coupling") else origin.coupling,
        )
    average = load(row["load"], of)
    heaviest = load(row["load_max"], of) if row.get("load_max") else None
    if heaviest is not None and heaviest < average:
        raise NioshError("load_max is below load (the average)")
    lift = Lift(
        of,
        origin,
        travel(row.get("d") or None, v, dest_v, of),
        frequency(row["f"]),
        duration,
        average,
        destination,
        heaviest,
    )
    return (row.get("name") or default).strip() or default, lift


def _csv_rows(text: str, file: str) -> list[tuple[int, dict[str, str]]]:
    reader = csv.reader(io.StringIO(text))
    rows: list[tuple[int, dict[str, str]]] = []
    header: list[str] | None = None
    try:
        for fields in reader:
            line = reader.line_num
            if not any(cell.strip() for cell in fields) or fields[0].lstrip().startswith("#"):
                continue
            if header is None:
                header = [cell.strip().lower() for cell in fields]
                _check_header(header, f"{file}:{line}")
                continue
            if len(fields) != len(header):
                raise NioshError(
                    f"{len(fields)} cells, the header has {len(header)}", where=f"{file}:{line}"
                )
            rows.append(
                (line, {k: cell.strip() for k, cell in zip(header, fields, strict=True) if k})
            )
    except csv.Error as exc:
        raise NioshError(f"not CSV: {exc}", where=f"{file}:{reader.line_num}") from None
    if header is None:
        raise NioshError("no header row (name,load,h,v,d,a,f,coupling,...)", where=file)
    return rows


def _check_header(header: list[str], where: str) -> None:
    """A CSV header's unknown column, said at the header's line (the rows
    below would each say it)."""
    wrong = other_separator(header)
    if wrong is not None:
        raise NioshError(wrong, where=where)
    unknown = [name for name in header if name and name not in COLUMNS]
    if unknown:
        raise NioshError(
            f"unknown column {quoted(unknown[0])} (expected {', '.join(COLUMNS)})", where=where
        )
    # a column given twice would leave one of its cells unread, unsaid
    for k, name in enumerate(header):
        if name and name in header[:k]:
            raise NioshError(
                f"column {quoted(name)} is given twice (cells {header.index(name) + 1} "
                f"and {k + 1}); give it once",
                where=where,
            )


def _json_rows(text: str, file: str) -> list[tuple[int, dict[str, str]]]:
    try:
        data: Any = json.loads(text, object_pairs_hook=_JsonObject.of)
    except json.JSONDecodeError as exc:
        raise NioshError(f"not JSON: {exc.msg}", where=f"{file}:{exc.lineno}") from None
    if isinstance(data, _JsonObject):  # every object json.loads made here
        if "tasks" in data.twice:
            raise NioshError('"tasks" is given twice; give the job\'s tasks once', where=file)
        data = data.get("tasks")
    if not isinstance(data, list):
        raise NioshError('expected a list of tasks (or {"tasks": [...]})', where=file)
    lines = _object_lines(text)
    rows = []
    for i, item in enumerate(data):
        where = f"{file}:{lines[i] if i < len(lines) else 1}"
        if not isinstance(item, _JsonObject):
            raise NioshError(f"task {i + 1} is not an object", where=where)
        if item.twice:  # json.loads would keep the last of a key given twice
            raise NioshError(f"task {i + 1}: {quoted(item.twice[0])} is given twice", where=where)
        cells: dict[str, str] = {}
        for key, value in item.items():
            if isinstance(value, bool) or not isinstance(value, (str, int, float)):
                raise NioshError(
                    f"task {i + 1}: {quoted(str(key))} is not a number or text", where=where
                )
            cells[str(key).lower()] = str(value)
        rows.append((lines[i] if i < len(lines) else 1, cells))
    return rows


class _JsonObject(dict[str, Any]):
    """A JSON object that remembers the keys given twice in it (`twice`), in
    any case: a job's columns are read lower-cased, so "H" and "h" are one."""

    twice: list[str]

    @classmethod
    def of(cls, pairs: list[tuple[str, Any]]) -> _JsonObject:
        made = cls(pairs)
        seen: set[str] = set()
        made.twice = []
        for key, _ in pairs:
            if key.lower() in seen:
                made.twice.append(key)
            seen.add(key.lower())
        return made


def _object_lines(text: str) -> list[int]:
    """The line of each task object's "{" at depth 2 (a list of objects, or the
    "tasks" list of one object): the file:line of a bad task."""
    lines: list[int] = []
    target = 2 if text.lstrip().startswith("[") else 3
    depth, line, in_string, escaped = 0, 1, False, False
    for char in text:
        if char == "\n":
            line += 1
        if in_string:
            if escaped:
                escaped = False
            elif char == "\\":
                escaped = True
            elif char == '"':
                in_string = False
            continue
        if char == '"':
            in_string = True
        elif char in "[{":
            depth += 1
            if char == "{" and depth == target:
                lines.append(line)
        elif char in "]}":
            depth -= 1
    return lines
