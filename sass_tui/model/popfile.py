"""Population statistics files (report §12.2.4, figure 7).

    C comment            (the first comment with text is the title)
    T MALE | T FEMALE    (starts a section; data rows follow)
    v v v v v v v v v /* label */   (x 5/50/95, y 5/50/95, z 5/50/95)

Numbers may be separated by blanks and/or commas.  999 means "no value" and
is held as NaN.  Rows are matched to the model's fixed rows by their label
comment (falling back on position), so a file whose rows are in display order
needs no particular labels.  A file that breaks the format is rejected whole
(PopulationFileError, "file:line: what was expected"); suspicious rows give
warnings and loading goes on.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from sass_tui.model.errors import SassError
from sass_tui.model.names import (
    AXES,
    AXES_OF,
    GROUP_TITLES,
    JOINT_LIMITS,
    ROWS,
    label_lookup,
    normalise_label,
)
from sass_tui.model.units import UnitError, finite_number
from sass_tui.model.vocabulary import GENDERS

NO_VALUE = 999.0

# Possessive quantifiers (++, *+): a 20,000-digit token followed by a letter
# took 20 s with plain ones (each split of the digits between \d+ and \d* tried).
_NUMBER = re.compile(r"[-+]?(?:\d++(?:\.\d*+)?|\.\d++)(?:[eE][-+]?\d++)?$")


class PopulationFileError(ValueError, SassError):
    """The file breaks the format; nothing of it was loaded."""


@dataclass
class PopulationData:
    """One group's statistics: per gender an array (rows, 3 axes, 3 percentiles)."""

    group: str
    title: str
    path: str
    sections: dict[str, np.ndarray] = field(default_factory=dict)
    lines: dict[str, list[int]] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)

    def stats(self, gender: str) -> np.ndarray:
        return self.sections[gender]

    def has(self, gender: str) -> bool:
        return gender in self.sections


def read_population_file(path: str | Path, group: str) -> PopulationData:
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        text = path.read_text(encoding="latin-1")
    except OSError as exc:
        raise PopulationFileError(f"{path}: cannot read: {exc.strerror or exc}") from None
    return parse_population_text(text, group, str(path))


def parse_population_text(text: str, group: str, name: str = "<text>") -> PopulationData:
    width = 3 * AXES_OF[group]
    lookup = label_lookup(group)
    title = ""
    gender: str | None = None
    section_line = 0
    raw: dict[str, list[tuple[int, list[float], str]]] = {}
    lines = text.splitlines()
    if not any(ln.strip() for ln in lines):
        raise PopulationFileError(
            f"{name}:1: the file is empty; expected 'C' comments, "
            "'T MALE' or 'T FEMALE', and rows of 9 numbers"
        )
    for lineno, line in enumerate(lines, start=1):
        where = f"{name}:{lineno}"
        if not line.strip():
            continue
        if line[0] == "C":
            if not title and line[1:].strip() and not line[1:].strip().startswith("-"):
                title = line[1:].strip()
            continue
        if line[0] == "T":
            word = line[1:].strip().lower()
            if word not in GENDERS:
                raise PopulationFileError(
                    f"{where}: expected 'T MALE' or 'T FEMALE', found {line.strip()!r}"
                )
            if word in raw:
                raise PopulationFileError(f"{where}: a second 'T {word.upper()}' section")
            gender, section_line = word, lineno
            raw[gender] = []
            continue
        layout = "(x 5/50/95%, y 5/50/95%, z 5/50/95%)" if width == 9 else "(5/50/95%)"
        numbers, label = split_data_row(line, where, width, layout)
        if gender is None:
            raise PopulationFileError(f"{where}: data before 'T MALE' or 'T FEMALE'")
        raw[gender].append((lineno, numbers, label))
    if not raw:
        raise PopulationFileError(f"{name}:{len(lines)}: no 'T MALE' or 'T FEMALE' section")

    data = PopulationData(group=group, title=title or Path(name).name, path=name)
    for gender, entries in raw.items():
        data.sections[gender], data.lines[gender] = _place_rows(
            entries, gender, group, lookup, name, section_line, data.warnings
        )
    _check_rows(data, name)
    return data


def split_data_row(
    line: str, where: str, width: int, layout: str, error: type[ValueError] = PopulationFileError
) -> tuple[list[float], str]:
    """'v v v ... /* label */' -> (numbers, label), or `error` saying where and what."""
    start = line.find("/*")
    numbers_text, label = line, ""
    if start >= 0:
        end = line.find("*/", start + 2)
        if end < 0:
            raise error(f"{where}: comment '/*' is not closed with '*/'")
        if line[end + 2 :].strip():
            raise error(f"{where}: unexpected {line[end + 2 :].strip()!r} after the comment")
        numbers_text, label = line[:start], line[start + 2 : end].strip()
    tokens = [t for t in re.split(r"[,\s]+", numbers_text.strip()) if t]
    for col, token in enumerate(tokens, start=1):
        if not _NUMBER.match(token):
            raise error(f"{where}: value {col} is {token!r}; expected a number (999 = no value)")
    if len(tokens) != width:
        raise error(
            f"{where}: {len(tokens)} numbers; expected {width} {layout} and a /* comment */"
        )
    values = []
    for col, token in enumerate(tokens, start=1):
        try:
            values.append(finite_number(token))
        except UnitError as exc:
            raise error(f"{where}: value {col}: {exc}") from None
    return values, label


def _place_rows(entries, gender, group, lookup, name, section_line, warnings):
    rows = ROWS[group]
    n = len(rows)
    stats = np.full((n, AXES_OF[group], 3), np.nan)
    filled: dict[int, int] = {}
    for position, (lineno, values, label) in enumerate(entries):
        index = lookup.get(normalise_label(label)) if label else None
        if index is None:
            if position >= n:
                warnings.append(
                    f"{name}:{lineno}: extra row {label!r} beyond the "
                    f"{n} rows of {GROUP_TITLES[group]}; ignored"
                )
                continue
            index = position
            if label:
                warnings.append(
                    f"{name}:{lineno}: unknown row label {label!r}; "
                    f"taken by position as {rows[index].label!r}"
                )
        if index in filled:
            warnings.append(
                f"{name}:{lineno}: {rows[index].label!r} given again "
                f"(first at line {filled[index]}); this later row is used"
            )
        filled[index] = lineno
        arr = np.array(values).reshape(AXES_OF[group], 3)
        arr[arr == NO_VALUE] = np.nan
        stats[index] = arr
    if len(entries) != n:
        warnings.append(
            f"{name}:{section_line}: T {gender.upper()} has {len(entries)} rows; expected {n}"
        )
    missing = [rows[i].label for i in range(n) if i not in filled]
    if missing:
        last = entries[-1][0] if entries else section_line
        raise PopulationFileError(
            f"{name}:{last}: T {gender.upper()} ends without "
            f"{len(missing)} of its {n} rows (missing: {', '.join(missing[:5])}"
            f"{', …' if len(missing) > 5 else ''})"
        )
    return stats, [filled[i] for i in range(n)]


def _check_rows(data: PopulationData, name: str) -> None:
    """Warn about rows that load but look wrong (spec §2)."""
    rows = ROWS[data.group]
    for gender, stats in data.sections.items():
        for i, row in enumerate(rows):
            for a, axis in enumerate(AXES[: AXES_OF[data.group]]):
                v5, v50, v95 = stats[i, a]
                if np.isnan([v5, v50, v95]).any():
                    continue
                where = f"{name}:{data.lines[gender][i]}: {row.label}"
                if AXES_OF[data.group] > 1:
                    where += f" {axis}"
                if not (min(v5, v95) <= v50 <= max(v5, v95)):
                    data.warnings.append(
                        f"{where}: 50th value {v50:g} is not between the 5th ({v5:g}) "
                        f"and the 95th ({v95:g})"
                    )
                signs = [np.sign(v) for v in (v5, v50, v95) if v != 0]
                if len(signs) == 3 and len(set(signs)) > 1:
                    odd = ("5th", "50th", "95th")[signs.index(min(set(signs), key=signs.count))]
                    data.warnings.append(
                        f"{where}: the {odd} value's sign is unlike its "
                        f"neighbours' ({v5:g}, {v50:g}, {v95:g})"
                    )
                elif data.group == JOINT_LIMITS:
                    lower = row.name.endswith("_ll")
                    if (lower and min(v5, v50, v95) > 0) or (not lower and max(v5, v50, v95) < 0):
                        data.warnings.append(
                            f"{where}: a {'lower' if lower else 'upper'} limit that is "
                            f"{'positive' if lower else 'negative'} ({v5:g}, {v50:g}, {v95:g})"
                        )


def write_population_file(data: PopulationData, path: str | Path) -> None:
    """Write statistics back in the same format (atomically)."""
    from sass_tui.model.atomic import write_text_atomic

    lines = [f"C {data.title}"]
    for gender, stats in data.sections.items():
        lines += ["C", f"T {gender.upper()}"]
        for row, values in zip(ROWS[data.group], stats):
            flat = [NO_VALUE if np.isnan(v) else v for v in values.ravel()]
            lines.append(" " + " ".join(f"{v:8g}" for v in flat) + f"  /* {row.label} */")
    write_text_atomic(path, "\n".join(lines) + "\n")
