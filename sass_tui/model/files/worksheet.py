"""The worksheet file: what an engineer has open in the spreadsheet, saved
to be opened again (Save / Save As / Open, `sass --open FILE`).

One JSON file, readable and written by sass alone: sass's version; the
figure's global data (gender, figure type, mass and stature with their
percentiles, the strength settings); every group's percentile, display unit,
values and percentiles cell by cell; each group's population statistics
(5th, 50th and 95th per cell and gender) with the title and file they were
read from, so the sheet opens the same even where that file has moved; and
the strength sheet's file, side, unit, percentile, non-dominant factor and
angles.  Values are in sass's canonical units (cm, deg, kg; strength angles
in deg); JSON's `null` is "no value" (999 in a population file).

A file that is not a worksheet, or one whose cells do not fit the model's
rows, is refused whole with `WorksheetError` naming the file and the field;
nothing already open changes.  Every number goes through the checks a typed
one does: finite, a stature and a mass a human's (model/body/human.py), a
percentile between 0 and 100, a length or an angle no body has beyond
(`LARGEST_CELL`), a version a whole number: worksheets are what engineers
hand each other, and one with a stature of 1e308 made the figure's ruler
take 11 GB.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sass_tui.model.body.figure import Figure, GroupState
from sass_tui.model.body.human import MAX_STATURE_CM, not_human
from sass_tui.model.datasets import is_shipped
from sass_tui.model.errors import SassError
from sass_tui.model.files.gltf import sass_version
from sass_tui.model.files.paths import PathError, inside, read_user_text
from sass_tui.model.files.popfile import Cells, PopulationData
from sass_tui.model.files.task_settings import (
    TaskSettings,
    read_task_settings,
    task_settings_out,
)
from sass_tui.model.names import AXES_OF, GLOBAL, GROUPS, ROWS, STRENGTH
from sass_tui.model.session import Session
from sass_tui.model.strength.strength import (
    StrengthData,
    StrengthError,
    StrengthSheet,
    read_strength_file,
)
from sass_tui.model.units import GROUP_UNITS, LARGEST_NUMBER
from sass_tui.model.vocabulary import (
    FIGURE_TYPES,
    GENDERS,
    HANDEDNESS,
    JOINT_AXES,
    MOTION_NAMES,
    STRENGTH_TYPES,
)

FORMAT = "sass worksheet"
FORMAT_VERSION = 1
# The file name Save offers first.
DEFAULT_NAME = "worksheet.sass.json"

GLOBAL_NUMBERS = (
    "mass",
    "mass_percentile",
    "stature",
    "stature_percentile",
    "motion_speed",
    "training_level",
    "fatigue_level",
)
GLOBAL_WORDS = {
    "gender": GENDERS,
    "figure_type": FIGURE_TYPES,
    "strength_type": STRENGTH_TYPES,
    "handedness": HANDEDNESS,
}
STRENGTH_SIDES = ("right", "left")
# The largest size of a cell in its canonical unit: no segment, center of
# mass or landmark is longer than the tallest stature; no joint turns more
# than a full turn.
LARGEST_CELL = {"cm": MAX_STATURE_CM, "deg": 360.0}
GLOBAL_PERCENTILES = ("mass_percentile", "stature_percentile")
HUMAN_GLOBALS = ("mass", "stature")


class WorksheetError(ValueError, SassError):
    """The file is not a worksheet sass can open; nothing was opened."""


@dataclass(frozen=True)
class StrengthSettings:
    """The strength sheet as saved: its file and what the user set on it."""

    path: str
    side: str
    unit: str
    percentile: float
    non_dominant_factor: float
    angles: list[list[float]]


@dataclass(frozen=True)
class Worksheet:
    """A worksheet read back: the figure, the strength sheet's settings
    (None: none was loaded) and the version of sass that wrote it."""

    figure: Figure
    strength: StrengthSettings | None
    sass_version: str
    task: TaskSettings | None = None  # the Task panel's (model/files/task_settings.py)


# --- writing --------------------------------------------------------------------
def worksheet_text(session: Session) -> str:
    """The figure shown and the strength sheet, as the worksheet file's text."""
    figure = session.figure
    document: dict[str, Any] = {
        "format": FORMAT,
        "format_version": FORMAT_VERSION,
        "sass_version": sass_version(),
        "figure": {
            "population": figure.population,
            "person": figure.person,
            **{name: getattr(figure, name) for name in GLOBAL_WORDS},
            **{name: _number_out(getattr(figure, name)) for name in GLOBAL_NUMBERS},
            "hand_set_lengths": sorted(figure.hand_set_lengths),
            "landmarks": dict(sorted(figure.landmarks.items())),
        },
        "global_statistics": _statistics_out(figure.global_stats),
        "groups": {group: _group_out(figure.groups[group]) for group in GROUPS},
        "strength": _strength_out(session),
        "task": task_settings_out(session.task),
    }
    return _rows_on_one_line(json.dumps(document, indent=2, ensure_ascii=False)) + "\n"


def _number_out(value: float) -> float | None:
    return None if math.isnan(value) else float(value)


def _group_out(state: GroupState) -> dict[str, Any]:
    out: dict[str, Any] = {
        "percentile": state.percentile,
        "unit": state.unit,
        "statistics": _statistics_out(state.source),
        "values": None,
        "percentiles": None,
    }
    if state.loaded:
        cells = [
            [state.cell(row, axis) for axis in range(AXES_OF[state.group])]
            for row in range(len(state.rows))
        ]
        out["values"] = [[_number_out(value) for value, _ in row] for row in cells]
        out["percentiles"] = [[_number_out(pct) for _, pct in row] for row in cells]
    return out


def _statistics_out(data: PopulationData | None) -> dict[str, Any] | None:
    if data is None:
        return None
    rows = len(ROWS[data.group])
    axes = AXES_OF[data.group]
    return {
        "title": data.title,
        "file": data.path,
        "notes": data.notes,
        "row_notes": data.row_notes,
        "by_gender": {
            gender: [
                [[_number_out(v) for v in data.cell(gender, row, axis)] for axis in range(axes)]
                for row in range(rows)
            ]
            for gender in GENDERS
            if data.has(gender)
        },
    }


def _strength_out(session: Session) -> dict[str, Any] | None:
    sheet = session.strength_sheets.made()
    if sheet is None:
        return None
    return {
        "file": sheet.data.path,
        "side": sheet.side,
        "unit": sheet.unit,
        "percentile": sheet.percentile,
        "non_dominant_factor": sheet.non_dominant_factor,
        "angles": [[float(a) for a in row] for row in sheet.angles],
    }


def _rows_on_one_line(text: str) -> str:
    """json.dumps(indent=...) puts every number on a line of its own: a row
    of numbers goes back on one line, as a population file has it."""
    return re.sub(
        r"\[\s+((?:-?[\d.eE+-]+|null)(?:,\s+(?:-?[\d.eE+-]+|null))*)\s+\]",
        lambda match: "[" + ", ".join(item.strip() for item in match[1].split(",")) + "]",
        text,
    )


# --- reading --------------------------------------------------------------------
def read_worksheet(path: str | Path) -> Worksheet:
    """The worksheet in `path`; WorksheetError (file and field) or PathError."""
    try:
        where, text = read_user_text(path)
    except PathError as exc:
        raise WorksheetError(f"{path}: cannot read: {exc.reason}") from None
    return parse_worksheet(text, str(where))


def parse_worksheet(text: str, name: str = "<text>") -> Worksheet:
    try:
        document = json.loads(text)
    except json.JSONDecodeError as exc:
        raise WorksheetError(
            f"{name}:{exc.lineno}: not a sass worksheet (JSON: {exc.msg})"
        ) from None
    except (ValueError, RecursionError) as exc:  # a number of 5,000 digits; [[[... 100,000 deep
        why = "nested too deep" if isinstance(exc, RecursionError) else str(exc).split(";")[0]
        raise WorksheetError(f"{name}: not a sass worksheet (JSON: {why})") from None
    reader = _Reader(name)
    if not isinstance(document, dict) or document.get("format") != FORMAT:
        raise WorksheetError(f'{name}: not a sass worksheet (no "format": "{FORMAT}")')
    version = document.get("format_version")
    if isinstance(version, bool) or not isinstance(version, int) or version != FORMAT_VERSION:
        raise WorksheetError(
            f"{name}: format_version {document.get('format_version')!r}: this sass "
            f"opens version {FORMAT_VERSION}"
        )
    top = reader.mapping(document, "")
    figure_data = reader.mapping(top.get("figure"), "figure")
    figure = Figure(
        population=reader.text(figure_data.get("population"), "figure.population"),
        person=reader.optional_text(figure_data.get("person"), "figure.person"),
    )
    for field, words in GLOBAL_WORDS.items():
        setattr(figure, field, reader.word(figure_data.get(field), f"figure.{field}", words))
    for field in GLOBAL_NUMBERS:
        setattr(figure, field, reader.global_number(figure_data.get(field), field))
    girth_rows = {row.name for row in ROWS[GROUPS[0]]}
    lengths = reader.sequence(figure_data.get("hand_set_lengths", []), "figure.hand_set_lengths")
    figure.hand_set_lengths = frozenset(
        reader.word(item, "figure.hand_set_lengths", tuple(girth_rows)) for item in lengths
    )
    landmarks = reader.mapping(figure_data.get("landmarks", {}), "figure.landmarks")
    figure.landmarks = {
        str(key): reader.bounded(value, f"figure.landmarks.{key}", 0.0, MAX_STATURE_CM, "cm")
        for key, value in landmarks.items()
    }
    figure.global_stats = reader.statistics(top.get("global_statistics"), GLOBAL)
    groups = reader.mapping(top.get("groups"), "groups")
    for group in GROUPS:
        reader.group(figure.groups[group], reader.mapping(groups.get(group), f"groups.{group}"))
    strength = top.get("strength")
    return Worksheet(
        figure=figure,
        strength=None if strength is None else reader.strength(strength),
        sass_version=reader.text(top.get("sass_version"), "sass_version"),
        task=read_task_settings(top.get("task"), name),
    )


class _Reader:
    """Reads the parts of one worksheet, saying which field is wrong."""

    def __init__(self, name: str) -> None:
        self.name = name

    def fail(self, field: str, expected: str, got: object) -> WorksheetError:
        shown = json.dumps(got)
        shown = shown if len(shown) <= 40 else shown[:37] + "..."
        return WorksheetError(f"{self.name}: {field}: expected {expected}, not {shown}")

    def mapping(self, value: object, field: str) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(field or "the file", "an object {...}", value)
        return value

    def sequence(self, value: object, field: str, length: int | None = None) -> list[Any]:
        if not isinstance(value, list) or (length is not None and len(value) != length):
            expected = "a list" if length is None else f"a list of {length}"
            raise self.fail(field, expected, value)
        return value

    def text(self, value: object, field: str) -> str:
        if not isinstance(value, str):
            raise self.fail(field, "a text", value)
        return value

    def optional_text(self, value: object, field: str) -> str | None:
        return None if value is None else self.text(value, field)

    def word(self, value: object, field: str, words: tuple[str, ...]) -> str:
        if value not in words:
            raise self.fail(field, " or ".join(f'"{w}"' for w in sorted(words)), value)
        return str(value)

    def number(self, value: object, field: str, largest: float = LARGEST_NUMBER) -> float:
        """A number at most `largest` in size, or null for no value."""
        if value is None:
            return float("nan")
        return self.finite(value, field, largest)

    def finite(self, value: object, field: str, largest: float = LARGEST_NUMBER) -> float:
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise self.fail(field, "a number", value)
        try:
            number = float(value)
        except OverflowError:  # an integer of 1,000 digits
            number = math.inf
        if not math.isfinite(number):
            raise self.fail(field, "a finite number", value)
        if abs(number) > largest:
            raise self.fail(field, f"a number of at most {largest:g} in size", value)
        return number

    def bounded(self, value: object, field: str, low: float, high: float, unit: str) -> float:
        number = self.finite(value, field)
        if not low <= number <= high:
            raise self.fail(field, f"a number {low:g}-{high:g}{' ' + unit if unit else ''}", value)
        return number

    def percentile(self, value: object, field: str) -> float:
        number = self.finite(value, field)
        if not 0 < number < 100:
            raise self.fail(field, "a percentile between 0 and 100", value)
        return number

    def global_number(self, value: object, name: str) -> float:
        """One of the figure's global numbers, checked as a typed one is."""
        field = f"figure.{name}"
        if name in HUMAN_GLOBALS:
            number = self.number(value, field, math.inf)
            refused = None if math.isnan(number) else not_human(name, number)
            if refused:
                raise WorksheetError(f"{self.name}: {field}: {refused}")
            return number
        if name in GLOBAL_PERCENTILES:
            return float("nan") if value is None else self.percentile(value, field)
        number = self.number(value, field)
        if number < 0:  # motion speed, training and fatigue levels (Figure.set_strength_parameter)
            raise self.fail(field, "a number of at least 0", value)
        return number

    def grid(
        self, value: object, field: str, rows: int, axes: int, largest: float = LARGEST_NUMBER
    ) -> list[list[float]]:
        return [
            [
                self.number(cell, f"{field}[{r}][{a}]", largest)
                for a, cell in enumerate(self.sequence(row, f"{field}[{r}]", axes))
            ]
            for r, row in enumerate(self.sequence(value, field, rows))
        ]

    def statistics(self, value: object, group: str) -> PopulationData | None:
        field = "global_statistics" if group == GLOBAL else f"groups.{group}.statistics"
        if value is None:
            return None
        data = self.mapping(value, field)
        rows, axes = len(ROWS[group]), AXES_OF[group]
        sections: dict[str, Cells | Any] = {}
        by_gender = self.mapping(data.get("by_gender"), f"{field}.by_gender")
        # A global file's statures and masses: not_human below.
        largest = math.inf if group == GLOBAL else LARGEST_CELL[GROUP_UNITS[group][0]]
        for gender, cells in by_gender.items():
            where = f"{field}.by_gender.{gender}"
            self.word(gender, f"{field}.by_gender", GENDERS)
            sections[gender] = [
                [
                    (*self.grid([triple], f"{where}[{r}][{a}]", 1, 3, largest)[0],)
                    for a, triple in enumerate(self.sequence(row, f"{where}[{r}]", axes))
                ]
                for r, row in enumerate(self.sequence(cells, where, rows))
            ]
            if group == GLOBAL:
                self._human_globals(sections[gender], where)
        return PopulationData(
            group,
            self.text(data.get("title"), f"{field}.title"),
            self.text(data.get("file"), f"{field}.file"),
            sections=sections,
            notes=self._notes(data.get("notes", {}), f"{field}.notes"),
            row_notes=self._notes(data.get("row_notes", {}), f"{field}.row_notes"),
        )

    def _human_globals(self, cells: Cells, where: str) -> None:
        for r, row in enumerate(ROWS[GLOBAL]):
            for value in cells[r][0]:
                refused = None if math.isnan(value) else not_human(row.name, value)
                if refused:
                    raise WorksheetError(f"{self.name}: {where}[{r}]: {refused}")

    def _notes(self, value: object, field: str) -> dict[str, list[str]]:
        notes = self.mapping(value, field)
        return {
            str(key): [self.text(line, f"{field}.{key}") for line in self.sequence(lines, field)]
            for key, lines in notes.items()
        }

    def group(self, state: GroupState, data: dict[str, Any]) -> None:
        field = f"groups.{state.group}"
        rows, axes = len(state.rows), AXES_OF[state.group]
        state.percentile = self.percentile(data.get("percentile"), f"{field}.percentile")
        state.unit = self.word(data.get("unit"), f"{field}.unit", GROUP_UNITS[state.group])
        state.source = self.statistics(data.get("statistics"), state.group)
        values, percentiles = data.get("values"), data.get("percentiles")
        if values is None or percentiles is None:
            state.values = state.percentiles = None
            return
        if state.source is None:
            raise self.fail(f"{field}.statistics", "the statistics its values came from", None)
        largest = LARGEST_CELL[GROUP_UNITS[state.group][0]]
        state.values = self.grid(values, f"{field}.values", rows, axes, largest)
        state.percentiles = self.grid(percentiles, f"{field}.percentiles", rows, axes, 100.0)

    def strength(self, value: object) -> StrengthSettings:
        data = self.mapping(value, "strength")
        factor = self.bounded(
            data.get("non_dominant_factor"), "strength.non_dominant_factor", 0.0, 2.0, ""
        )
        rows = self.sequence(data.get("angles"), "strength.angles", len(MOTION_NAMES))
        angles = [
            [self.finite(a, f"strength.angles[{r}][{c}]", 360.0) for c, a in enumerate(row)]
            for r, row in enumerate(
                self.sequence(row, f"strength.angles[{r}]", len(JOINT_AXES))
                for r, row in enumerate(rows)
            )
        ]
        return StrengthSettings(
            path=self.text(data.get("file"), "strength.file"),
            side=self.word(data.get("side"), "strength.side", STRENGTH_SIDES),
            unit=self.word(data.get("unit"), "strength.unit", GROUP_UNITS[STRENGTH]),
            percentile=self.percentile(data.get("percentile"), "strength.percentile"),
            non_dominant_factor=factor,
            angles=angles,
        )


def apply_strength(settings: StrengthSettings, sheet: StrengthSheet) -> None:
    """Set a strength sheet as the worksheet saved it (its file read again;
    the reader checked the angles' shape: a row per motion, MOTION_NAMES)."""
    sheet.side, sheet.unit = settings.side, settings.unit
    sheet.percentile = settings.percentile
    sheet.non_dominant_factor = settings.non_dominant_factor
    for row, angles in enumerate(settings.angles):
        sheet.angles[row] = angles


def named_file(text: str | Path, workdir: Path | None = None) -> Path:
    """A file a worksheet names (its strength file), as the path to read.
    In a served session (`workdir`) it must lie inside the workdir, as a
    typed name must (paths.inside): a worksheet handed in named /etc/shadow
    and ../../etc/hostname, and their first word was shown to the web
    user.  A name saved there absolute is taken relative to the workdir; a
    shipped data set (datasets/) is read wherever sass is installed."""
    if workdir is None or is_shipped(text):
        return Path(text)
    if Path(text).is_absolute():
        try:
            text = Path(text).relative_to(workdir.resolve())
        except ValueError:
            pass  # refused by `inside`, naming the workdir
    return inside(workdir, text)


def read_worksheet_and_strength(
    path: str | Path, workdir: Path | None = None
) -> tuple[Worksheet, StrengthData | None, SassError | OSError | None]:
    """A worksheet and the strength file it names (inside `workdir`, when
    served): that file's data, or None and why it could not be read (a file
    moved since the worksheet was saved leaves the strength page as it is;
    the worksheet still opens)."""
    worksheet = read_worksheet(path)
    if worksheet.strength is None:
        return worksheet, None, None
    try:
        return worksheet, read_strength_file(named_file(worksheet.strength.path, workdir)), None
    except (SassError, OSError) as exc:
        return worksheet, None, exc


def population_strength_sheet(
    path: str | Path | None,
    figure: Figure,
    settings: StrengthSettings | None,
    workdir: Path | None = None,
) -> StrengthSheet:
    """The population's strength sheet from the strength file `path` (None:
    the shipped datasets/strength.dat; inside `workdir` when served), set as
    a worksheet saved it, its equations fitted now rather than on the first
    look at the page (a gender the file has no data for is said when the
    page is shown)."""
    sheet = StrengthSheet(
        read_strength_file(None if path is None else named_file(path, workdir)), figure
    )
    if settings is not None:
        apply_strength(settings, sheet)
    try:
        sheet.rows()
    except StrengthError:
        pass  # no data for this gender: the page says so when shown
    return sheet
