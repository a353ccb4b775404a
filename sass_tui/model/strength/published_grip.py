"""Published grip strength: FAA HFDS 2003, exhibit 14.5.2.1 (continued).

The FAA Human Factors Design Standard (HFDS 2003, amended October 2009),
chapter 14, page 14-45, prints the continuation of exhibit 14.5.2.1, "Design
criteria for male muscle strength of the arm, hand, and thumb for control
forces (5th percentile values)", from MIL-STD-1472D and MIL-HDBK-759B: hand
grip, left and right, and thumb-finger grip (palmar and tips), momentary
hold, in N (lb).  The four values are shipped in datasets/hfds2003_grip.csv,
newtons as the values and the printed pounds beside them; docs/strength.md
says what the page covers.  The lookups answer exactly what the page
prints: another gender or percentile is refused with what the table has,
never filled in or extrapolated.

Pure Python: no numpy, no Textual.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path

from sass_tui.model import datasets
from sass_tui.model.population.percentile import check_percentile
from sass_tui.model.strength.published_strength import (
    GENDER_WORDS,
    PublishedStrengthError,
    ordinal,
    read_published_text,
)

FILE_NAME = "hfds2003_grip.csv"
GRIP_DATA_SET = "hfds2003"
CITATION = "FAA HFDS 2003 exhibit 14.5.2.1"
# The exhibit's own source, named on every answer beside the citation.
ORIGIN = "MIL-STD-1472D"

GRIP_MOTIONS: tuple[str, ...] = (
    "hand_grip",
    "thumb_finger_grip_palmar",
    "thumb_finger_grip_tips",
)
# How answers name them; the page's own headings are each row's `column`.
GRIP_LABELS = {
    "hand_grip": "hand grip",
    "thumb_finger_grip_palmar": "thumb-finger grip (palmar)",
    "thumb_finger_grip_tips": "thumb-finger grip (tips)",
}
HANDS: tuple[str, ...] = ("right", "left")
# A row the page prints without left or right (the thumb-finger grips).
EITHER = "either"

_HEADER = (
    "motion",
    "side",
    "gender",
    "percentile",
    "condition",
    "newtons",
    "printed_lb",
    "column",
)


@dataclass(frozen=True)
class GripRow:
    """One value of the page: a force as printed, in N and (lb)."""

    motion: str
    side: str  # right, left or either
    gender: str
    percentile: float
    condition: str  # "momentary hold"
    newtons: float
    printed_lb: float
    column: str  # the column's heading as printed
    line: int


@dataclass(frozen=True)
class GripTable:
    path: str
    rows: tuple[GripRow, ...]


@dataclass(frozen=True)
class GripStrength:
    """The force of one grip, as the page prints it, with its source."""

    motion: str
    side: str  # the hand asked
    force: float  # N
    printed_lb: float
    gender: str
    percentile: float
    condition: str
    column: str
    source: str
    sided: bool  # False: the page gives one value for either hand


def default_path() -> Path:
    return datasets.path(FILE_NAME)


@cache
def read_hfds2003(path: str | None = None) -> GripTable:
    """The shipped grip table (or a file of the same layout)."""
    where = str(path or default_path())
    return parse_hfds2003_text(read_published_text(where), where)


def _number(text: str, where: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not math.isfinite(value) or value <= 0:
        raise PublishedStrengthError(f"{where}: {what} {text.strip()!r} is not a positive number")
    return value


def parse_hfds2003_text(text: str, where: str = "<text>") -> GripTable:
    """The grip table's text (its layout: datasets/hfds2003_grip.csv)."""
    lines = [
        (n, ln)
        for n, ln in enumerate(text.split("\n"), start=1)
        if ln.strip() and not ln.startswith("#")
    ]
    try:
        rows = list(csv.reader(ln for _, ln in lines))
    except csv.Error as exc:
        raise PublishedStrengthError(f"{where}: not comma-separated values: {exc}") from None
    if not rows or tuple(rows[0]) != _HEADER:
        first = lines[0][0] if lines else 1
        raise PublishedStrengthError(f"{where}:{first}: expected the header {','.join(_HEADER)}")
    table: dict[tuple[str, str, str, float, str], GripRow] = {}
    for (lineno, _), row in zip(lines[1:], rows[1:]):
        at = f"{where}:{lineno}"
        if len(row) != len(_HEADER):
            raise PublishedStrengthError(f"{at}: expected {len(_HEADER)} fields, found {len(row)}")
        motion, side, gender, percentile_text, condition, newtons, pounds, column = row
        if motion not in GRIP_MOTIONS:
            raise PublishedStrengthError(
                f"{at}: unknown motion {motion!r}; expected one of {', '.join(GRIP_MOTIONS)}"
            )
        if side not in (*HANDS, EITHER):
            raise PublishedStrengthError(
                f"{at}: side {side!r}; expected {', '.join((*HANDS, EITHER))}"
            )
        if gender not in GENDER_WORDS:
            raise PublishedStrengthError(f"{at}: gender {gender!r}; expected male or female")
        percentile = _number(percentile_text, at, "percentile")
        if percentile >= 100:
            raise PublishedStrengthError(f"{at}: percentile {percentile_text!r} is not below 100")
        if not condition.strip() or not column.strip():
            raise PublishedStrengthError(f"{at}: no condition or column heading")
        key = (motion, side, gender, percentile, condition)
        if key in table:
            raise PublishedStrengthError(
                f"{at}: a second {motion} {side} {gender} {percentile:g} {condition} "
                f"(the first on line {table[key].line})"
            )
        table[key] = GripRow(
            motion,
            side,
            gender,
            percentile,
            condition,
            _number(newtons, at, "newtons"),
            _number(pounds, at, "printed_lb"),
            column,
            lineno,
        )
    missing = [m for m in GRIP_MOTIONS if not any(r.motion == m for r in table.values())]
    if missing:
        raise PublishedStrengthError(f"{where}: no values for {', '.join(missing)}")
    for motion in GRIP_MOTIONS:
        sides = {r.side for r in table.values() if r.motion == motion}
        if EITHER in sides and len(sides) > 1:
            raise PublishedStrengthError(
                f"{where}: {motion} has both one value for either hand and one per hand"
            )
        conditions = {r.condition for r in table.values() if r.motion == motion}
        if len(conditions) > 1:
            # One condition per motion: an answer names it, it is not asked for.
            raise PublishedStrengthError(
                f"{where}: {motion} under {' and '.join(sorted(conditions))}; "
                "expected one condition per motion"
            )
    return GripTable(where, tuple(table.values()))


def grip_motion(text: str) -> str | None:
    """'hand grip', 'Thumb-finger grip palmar' -> the motion's name; None: not a grip."""
    key = "_".join(text.strip().lower().replace("-", " ").replace("_", " ").split())
    return key if key in GRIP_MOTIONS else None


def _covers(rows: list[GripRow]) -> str:
    """What the table has, in words: 'the 5th percentile of men'."""
    pairs = sorted({(r.percentile, r.gender) for r in rows})
    return " and ".join(f"the {ordinal(p)} percentile of {GENDER_WORDS[g]}" for p, g in pairs)


def source_label(row: GripRow) -> str:
    """'FAA HFDS 2003 exhibit 14.5.2.1 (MIL-STD-1472D), men, 5th percentile,
    momentary hold' (the words every answer carries)."""
    return (
        f"{CITATION} ({ORIGIN}), {GENDER_WORDS[row.gender]}, "
        f"{ordinal(row.percentile)} percentile, {row.condition}"
    )


def grip_strength(
    motion: str,
    side: str = "right",
    gender: str = "male",
    percentile: float | None = None,
    data: GripTable | None = None,
) -> GripStrength:
    """The page's force for `motion` by the `side` hand; `percentile` None:
    the one the table gives (refused if it gives several)."""
    if motion not in GRIP_MOTIONS:
        raise PublishedStrengthError(
            f"{CITATION} as shipped has no {motion}; it covers {', '.join(GRIP_MOTIONS)} "
            "(its arm-strength table was not reachable as printed)"
        )
    if side not in HANDS:
        raise PublishedStrengthError(f"side must be right or left, not {side!r}")
    if gender not in GENDER_WORDS:
        raise PublishedStrengthError(f"gender must be male or female, not {gender!r}")
    data = data or read_hfds2003()
    rows = [r for r in data.rows if r.motion == motion and r.side in (side, EITHER)]
    if not rows:
        raise PublishedStrengthError(f"{CITATION} gives no {motion} for the {side} hand")
    covers = _covers(rows)
    asked = [r for r in rows if r.gender == gender]
    if not asked:
        raise PublishedStrengthError(
            f"{CITATION} gives only {covers} for {motion}; it has no values for "
            f"{GENDER_WORDS[gender]}"
        )
    if percentile is not None:
        check_percentile(percentile)
        asked = [r for r in asked if r.percentile == percentile]
        if not asked:
            raise PublishedStrengthError(
                f"{CITATION} gives only {covers} for {motion}, not the "
                f"{ordinal(percentile)} percentile"
            )
    if len({r.percentile for r in asked}) > 1:
        raise PublishedStrengthError(
            f"{CITATION} gives {covers} for {motion}; choose one with --percentile"
        )
    row = asked[0]
    return GripStrength(
        motion=motion,
        side=side,
        force=row.newtons,
        printed_lb=row.printed_lb,
        gender=row.gender,
        percentile=row.percentile,
        condition=row.condition,
        column=row.column,
        source=source_label(row),
        sided=row.side != EITHER,
    )


def table_words() -> str:
    """The shipped table in one line, with its source (the strength group's
    Input Data says it: the page's forces are not the strength page's torques)."""
    data = read_hfds2003()
    parts = []
    for motion in GRIP_MOTIONS:
        values = [
            f"{'' if r.side == EITHER else r.side + ' '}{r.newtons:g} N"
            for r in data.rows
            if r.motion == motion
        ]
        parts.append(f"{GRIP_LABELS[motion]} {', '.join(values)}")
    sources = sorted({source_label(r) for r in data.rows})
    return f"{' / '.join(sources)}: {'; '.join(parts)}"
