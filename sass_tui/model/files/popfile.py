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

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from sass_tui.model.body.appendix_l import (
    FOOT_FRACTION,
    HEEL_BEHIND_ANKLE,
    LOWER_LEG_FRACTION,
    SCALED_BY_LENGTH,
    lower_leg_center,
    toes_implied,
)
from sass_tui.model.body.human import not_human
from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import PathError, read_user_text
from sass_tui.model.floats import divide, median
from sass_tui.model.names import (
    AXES,
    AXES_OF,
    CENTER_OF_MASS,
    GIRTH,
    GLOBAL,
    GROUP_TITLES,
    JOINT_LIMITS,
    ROWS,
    label_lookup,
    normalise_label,
)
from sass_tui.model.text import quoted
from sass_tui.model.units import UnitError, finite_number
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    import numpy as np

NO_VALUE = 999.0

# What a file of each group is called when it is loaded as another group's.
FILE_KINDS = {
    GIRTH: "a girth (segment dimensions) file",
    JOINT_LIMITS: "a joint-limits file",
    CENTER_OF_MASS: "a center-of-mass file",
    GLOBAL: "a global statistics file",
}


# Possessive quantifiers (++, *+): a 20,000-digit token followed by a letter
# took 20 s with plain ones (each split of the digits between \d+ and \d* tried).
_NUMBER = re.compile(r"[-+]?(?:\d++(?:\.\d*+)?|\.\d++)(?:[eE][-+]?\d++)?$")


class PopulationFileError(ValueError, SassError):
    """The file breaks the format; nothing of it was loaded."""


# One gender's statistics as a file gives them: per row, per axis, the
# (5th, 50th, 95th) values; NaN = no value.
Cells = list[list[tuple[float, float, float]]]


@dataclass
class PopulationData:
    """One group's statistics: per gender (rows, axes, 3 percentiles).

    A file's are read into plain floats (`Cells`), so that the TUI's first
    screen is computed before numpy is imported (a faster start); `stats` makes the
    array from them once, on first use, and `cell` goes on reading the plain
    floats (faster than an array's elements).  A population made from the
    database sets the array itself."""

    group: str
    title: str
    path: str
    sections: dict[str, Cells | np.ndarray] = field(default_factory=dict)
    lines: dict[str, list[int]] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)
    # Where the values came from, written as comments (a population made from
    # the database, db/populations/population.py): per gender, lines after its 'T' line,
    # and one line per row, before the row.
    notes: dict[str, list[str]] = field(default_factory=dict)
    row_notes: dict[str, list[str]] = field(default_factory=dict)
    # Per gender: the array made from a file's plain floats (read once).
    _arrays: dict[str, np.ndarray] = field(default_factory=dict, repr=False, compare=False)

    def stats(self, gender: str) -> np.ndarray:
        section = self.sections[gender]
        if not isinstance(section, list):
            return section
        if gender not in self._arrays:
            # deferred: numpy — off the first screen (sass_tui/startup.py)
            import numpy as np

            self._arrays[gender] = np.array(section, dtype=float)
        return self._arrays[gender]

    def cell(self, gender: str, row: int, axis: int) -> tuple[float, float, float]:
        """One cell's (5th, 50th, 95th) values, without numpy."""
        v5, v50, v95 = self.sections[gender][row][axis]
        return float(v5), float(v50), float(v95)

    def has(self, gender: str) -> bool:
        return gender in self.sections


def cmass_path(girth_path: Path) -> Path:
    """Where `sass population` and Make Population write the center-of-mass
    file of a girth file: NAME-cmass.dat beside it."""
    return girth_path.with_name(f"{girth_path.stem}-cmass{girth_path.suffix or '.dat'}")


def global_path(girth_path: Path) -> Path:
    """Where they write the people's own stature and mass: NAME-global.dat
    beside the girth file (read with it by `sass fig --girth`, `sass export`
    and Input Data)."""
    return girth_path.with_name(f"{girth_path.stem}-global{girth_path.suffix or '.dat'}")


def read_global_beside(girth_path: str | Path) -> PopulationData | None:
    """The stature and mass file beside a girth file, if there is one."""
    beside = global_path(Path(girth_path))
    return read_population_file(beside, GLOBAL) if beside.is_file() else None


def read_population_file(path: str | Path, group: str) -> PopulationData:
    try:
        path, text = read_user_text(path, "a population file")
    except PathError as exc:
        raise PopulationFileError(f"{path}: cannot read: {exc.reason}") from None
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
                    f"{where}: expected 'T MALE' or 'T FEMALE', found {quoted(line.strip())}"
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

    for entries in raw.values():
        _check_kind(entries, group, name)
    data = PopulationData(group=group, title=title or Path(name).name, path=name)
    for gender, entries in raw.items():
        data.sections[gender], data.lines[gender] = _place_rows(
            entries, gender, group, lookup, name, section_line, data.warnings
        )
    _refuse_negative_sizes(data, name)
    _refuse_inhuman_globals(data, name)
    _check_rows(data, name)
    _check_cross_gender(data, name)
    return data


def _refuse_negative_sizes(data: PopulationData, name: str) -> None:
    """A segment size (girth file) is a length: a negative one is refused at
    its line, as a typed cell's is (Figure.set_value); it went on into the
    .fig as `botheadx = -25.00cm`.  Joint limits and centers of mass may be
    negative."""
    if data.group != GIRTH:
        return
    for gender in data.sections:
        for i, row in enumerate(ROWS[GIRTH]):
            for a, axis in enumerate(AXES):
                cell = data.cell(gender, i, a)
                if any(v < 0 for v in cell):  # NaN (999, no value) compares False
                    raise PopulationFileError(
                        f"{name}:{data.lines[gender][i]}: {row.label} {axis}: "
                        f"{'/'.join(f'{v:g}' for v in cell)} cm; a segment size cannot "
                        "be negative; nothing was loaded"
                    )


def _refuse_inhuman_globals(data: PopulationData, name: str) -> None:
    """A global file's statures and masses pass the check a typed one does
    (model/body/human.py): a stature of 1e6 cm went on into the body's mesh
    (gigabytes, minutes)."""
    if data.group != GLOBAL:
        return
    for gender in data.sections:
        for i, row in enumerate(ROWS[GLOBAL]):
            for value in data.cell(gender, i, 0):
                refused = None if math.isnan(value) else not_human(row.name, value)
                if refused:
                    raise PopulationFileError(
                        f"{name}:{data.lines[gender][i]}: {gender} {refused}; nothing was loaded"
                    )


def _check_kind(entries: list[tuple[int, list[float], str]], group: str, name: str) -> None:
    """Refuse a file of another group (its row labels are that group's, not
    this one's): `--girth jntlmt.dat` would otherwise load joint limits as
    segment sizes, by position."""
    labels = [(lineno, normalise_label(label)) for lineno, _, label in entries if label]
    if not labels or group == GLOBAL:
        return

    def score(kind: str) -> tuple[int, bool]:
        lookup = label_lookup(kind)
        return sum(label in lookup for _, label in labels), len(ROWS[kind]) == len(entries)

    mine = label_lookup(group)
    kinds = [k for k in (GIRTH, JOINT_LIMITS, CENTER_OF_MASS) if AXES_OF[k] == AXES_OF[group]]
    best = max(kinds, key=score)
    if best != group and score(best) > score(group):
        lineno, label = next(((n, lb) for n, lb in labels if lb not in mine), labels[0])
        what = (
            f"row {label!r} is not a {GROUP_TITLES[group]} row"
            if label not in mine
            else (
                f"its {len(entries)} rows are the {GROUP_TITLES[best]} rows ({GROUP_TITLES[group]} has {len(ROWS[group])})"
            )
        )
        raise PopulationFileError(
            f"{name}:{lineno}: {what}; this looks like {FILE_KINDS[best]}, not "
            f"{FILE_KINDS[group]}; nothing was loaded"
        )


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
            raise error(f"{where}: unexpected {quoted(line[end + 2 :].strip())} after the comment")
        numbers_text, label = line[:start], line[start + 2 : end].strip()
    tokens = [t for t in re.split(r"[,\s]+", numbers_text.strip()) if t]
    for col, token in enumerate(tokens, start=1):
        if not _NUMBER.match(token):
            raise error(
                f"{where}: value {col} is {quoted(token)}; expected a number (999 = no value)"
            )
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


def _place_rows(
    entries: list[tuple[int, list[float], str]],
    gender: str,
    group: str,
    lookup: Mapping[str, int],
    name: str,
    section_line: int,
    warnings: list[str],
) -> tuple[Cells, list[int]]:
    rows = ROWS[group]
    n = len(rows)
    stats: Cells = [[] for _ in range(n)]
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
        cells = [math.nan if v == NO_VALUE else v for v in values]
        stats[index] = [
            (cells[a], cells[a + 1], cells[a + 2]) for a in range(0, 3 * AXES_OF[group], 3)
        ]
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
    for gender in data.sections:
        for i, row in enumerate(rows):
            for a, axis in enumerate(AXES[: AXES_OF[data.group]]):
                v5, v50, v95 = data.cell(gender, i, a)
                if math.isnan(v5) or math.isnan(v50) or math.isnan(v95):
                    continue
                where = f"{name}:{data.lines[gender][i]}: {row.label}"
                if AXES_OF[data.group] > 1:
                    where += f" {axis}"
                if not (min(v5, v95) <= v50 <= max(v5, v95)):
                    data.warnings.append(
                        f"{where}: 50th value {v50:g} is not between the 5th ({v5:g}) "
                        f"and the 95th ({v95:g})"
                    )
                signs = [math.copysign(1.0, v) for v in (v5, v50, v95) if v != 0]
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


# A cell whose female/male ratio is this many times the median ratio of its
# axis over all rows (or 1/this) is suspect: segment sizes of the two genders
# differ by 5-20 %, and appendix C's lower torso length (2.3x the median)
# and ball-of-foot x (1.8x) stand out where the next largest is 1.4x (the
# neck length, which the report says it took from the neck diameter).
CROSS_GENDER_LIMIT = 1.5


def _check_cross_gender(data: PopulationData, name: str) -> None:
    """Girth: the female/male ratio of each cell at the 50th percentile
    against the median ratio of its axis."""
    if data.group != GIRTH or not (data.has("male") and data.has("female")):
        return
    rows, axes = range(len(ROWS[GIRTH])), range(len(AXES))

    def ratio(i: int, a: int) -> float:
        male, female = data.cell("male", i, a)[1], data.cell("female", i, a)[1]
        return female / male if male > 0 else math.nan

    ratios = [[ratio(i, a) for a in axes] for i in rows]
    # Per axis over the finite ratios.
    medians = [median([r[a] for r in ratios if math.isfinite(r[a])]) for a in axes]
    for i, row in enumerate(ROWS[GIRTH]):
        for a, axis in enumerate(AXES):
            relative = divide(ratios[i][a], medians[a])
            if math.isnan(relative) or 1 / CROSS_GENDER_LIMIT <= relative <= CROSS_GENDER_LIMIT:
                continue
            data.warnings.append(
                f"{name}:{data.lines['female'][i]}: {row.label} {axis}: the female values "
                f"({_three(data.cell('female', i, a))}) are {ratios[i][a]:.2f} times the male "
                f"({_three(data.cell('male', i, a))}) where the {axis} of the other "
                f"rows are {medians[a]:.2f} times; a misprint? (docs/model.md, "
                "suspected misprints)"
            )


def _three(values: tuple[float, ...] | list[float]) -> str:
    return "/".join(f"{v:g}" for v in values)


# A cell is suspect when it is this far off the rule AND off its own row's
# agreement with the rule (a whole row off by the same factor is another
# source of lengths, e.g. appendix F's arm lengths, not a misprint).
RULE_TOLERANCE = 0.05
IMPLIED_TOLERANCE = 0.20


def check_center_of_mass_rules(cmass: PopulationData, girth: PopulationData) -> list[str]:
    """Appendix L.1's own rules, applied to a center-of-mass file and the girth
    it goes with; warnings name the file:line of the suspect cell."""
    out: list[str] = []
    com_rows = {row.name: i for i, row in enumerate(ROWS[CENTER_OF_MASS])}
    girth_rows = {row.name: i for i, row in enumerate(ROWS[GIRTH])}
    percentiles = ("5th", "50th", "95th")

    def where(data: PopulationData, gender: str, index: int, group: str, axis: str) -> str:
        return f"{data.path}:{data.lines[gender][index]}: {ROWS[group][index].label} {axis}"

    # Plain floats, three percentiles each (the first screen's files are
    # checked before numpy is imported).
    if all(cmass.has(g) and girth.has(g) for g in ("male", "female")):
        for row, parts in SCALED_BY_LENGTH.items():
            i = com_rows[row]
            lengths = {
                g: [sum(girth.cell(g, girth_rows[part], 2)[k] for part in parts) for k in range(3)]
                for g in ("male", "female")
            }
            male = cmass.cell("male", i, 2)
            expected = [
                divide(male[k] * lengths["female"][k], lengths["male"][k]) for k in range(3)
            ]
            actual = cmass.cell("female", i, 2)
            q = [divide(actual[k], expected[k]) for k in range(3)]
            if any(math.isnan(v) for v in q):
                continue
            for k in range(3):
                if abs(q[k] - 1) > RULE_TOLERANCE and abs(q[k] - median(q)) > RULE_TOLERANCE:
                    out.append(
                        f"{where(cmass, 'female', i, CENTER_OF_MASS, 'z')}: the {percentiles[k]} "
                        f"value {actual[k]:g} is not what appendix L.1's scaling rule gives "
                        f"(male {male[k]:g} x female length "
                        f"{lengths['female'][k]:g} / male {lengths['male'][k]:g} = "
                        f"{expected[k]:.1f}), though the other percentiles follow it; "
                        "a misprint? (docs/model.md, suspected misprints)"
                    )
    for gender in ("male", "female"):
        if not (cmass.has(gender) and girth.has(gender)):
            continue
        for side in ("right", "left"):
            i = com_rows[f"{side}_lower_leg"]
            actual = cmass.cell(gender, i, 2)
            leg = girth.cell(gender, girth_rows[f"{side}_lower_leg"], 2)
            expected = [lower_leg_center(leg[k]) for k in range(3)]
            for k in range(3):
                if abs(divide(actual[k], expected[k]) - 1) > RULE_TOLERANCE:
                    out.append(
                        f"{where(cmass, gender, i, CENTER_OF_MASS, 'z')}: the {percentiles[k]} "
                        f"value {actual[k]:g} is not appendix L.1's {LOWER_LEG_FRACTION} x lower leg length "
                        f"({expected[k]:.1f})"
                    )
            foot_x = girth.cell(gender, girth_rows[f"{side}_foot"], 0)
            toes_row = girth_rows[f"{side}_ball_of_foot"]
            toes_x = girth.cell(gender, toes_row, 0)
            foot_com = cmass.cell(gender, com_rows[f"{side}_foot"], 0)
            implied = [toes_implied(foot_com[k], foot_x[k]) for k in range(3)]
            off = [
                k for k in range(3) if abs(divide(toes_x[k], implied[k]) - 1) > IMPLIED_TOLERANCE
            ]
            if off:
                out.append(
                    f"{where(girth, gender, toes_row, GIRTH, 'x')}: {_three(toes_x)}, but "
                    f"appendix L.1's foot rule, center of mass = {FOOT_FRACTION} (foot x + toes x) - "
                    f"{HEEL_BEHIND_ANKLE} foot x, with the foot's center of mass {_three(foot_com)} "
                    f"({cmass.path}) and foot x {_three(foot_x)} gives "
                    f"{'/'.join(f'{v:.1f}' for v in implied)}; a misprint? "
                    "(docs/model.md, suspected misprints)"
                )
    return out


def render_population_file(data: PopulationData) -> str:
    """The text of a population file of `data` (report §12.2.4).  The title is
    one comment line: a query of two lines (the default title) or a --title
    with a line break wrote its second line as a row of values, and the file
    no longer read back."""
    lines = [f"C {' '.join(data.title.splitlines())}"]
    for gender, stats in data.sections.items():
        lines += ["C", f"T {gender.upper()}"]
        lines += [f"C {note}" for note in data.notes.get(gender, ())]
        row_notes = data.row_notes.get(gender, [])
        for k, (row, cells) in enumerate(zip(ROWS[data.group], stats)):
            if k < len(row_notes):
                lines.append(f"C {row_notes[k]}")
            flat = [NO_VALUE if math.isnan(v) else v for cell in cells for v in cell]
            lines.append(" " + " ".join(f"{v:8g}" for v in flat) + f"  /* {row.label} */")
    return "\n".join(lines) + "\n"
