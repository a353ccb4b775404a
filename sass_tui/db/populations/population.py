"""Populations made from a selection of people (what SASS's users did by hand):
the empirical 5th, 50th and 95th percentile, per gender, of every girth and
center-of-mass row, from the selected people's own values.

The result is one PopulationData per group (report figure 7's format), ready
for `popfile.render_population_file` or for loading into the spreadsheet.

Every cell has a value, so that any population of real people makes a
figure.  A cell at least MIN_PEOPLE of the people have a value of is theirs
(the girth rows derived from ANSUR II measurements, docs/data-sources.md).
Any other cell (ANSUR II measures no head length, hand thickness, eyes,
ball-of-foot length, knuckle thickness, and no center of mass at all) is the
report's value (`datasets/girth.dat`, appendices B and C; `datasets/cmass.dat`,
appendix L.2) scaled by the population's own stature against the report
population's (`datasets/global.dat`), percentile by percentile:

    cell(p) = report cell(p) × stature of the people(p) / global.dat stature(p)

A segment's dimensions grow in proportion to stature to a first
approximation (geometric similarity, the assumption behind SASS's own
scaling by percentile).  A center-of-mass cell appendix L.1 defines from
segment lengths (lower leg, foot, a woman's head, neck, arms, upper legs and
hands) is made by that rule from the population's own girth instead
(`_apply_center_of_mass_rules`), so the files pass the rules their reader
checks.  The file says, row by row in its comments, which cells are the
people's and which the model's.

With them comes the people's own stature and mass (the GLOBAL group,
written as NAME-global.dat): the figure of a population is sized by its own
people, not by the report's crew.  No Textual import here.
"""

from __future__ import annotations

import datetime as _dt
import sqlite3
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from sass_tui.db.engine.dialect import ids_in
from sass_tui.db.engine.schema import CENTER_OF_MASS_NAMES, GIRTH_NAMES
from sass_tui.db.people.values import Values, load_values
from sass_tui.db.progress import Cancel, Progress, Steps, interruptible
from sass_tui.db.query.query import ParsedQuery, joined, parsed
from sass_tui.model import datasets
from sass_tui.model.body.appendix_l import (
    FOOT_FRACTION,
    HEEL_BEHIND_ANKLE,
    LOWER_LEG_FRACTION,
    SCALED_BY_LENGTH,
    foot_center,
    lower_leg_center,
)
from sass_tui.model.errors import SassError
from sass_tui.model.files.popfile import PopulationData, read_population_file
from sass_tui.model.names import (
    AXES,
    CENTER_OF_MASS,
    GIRTH,
    GLOBAL,
    GLOBAL_ROWS,
    ROWS,
    row_index,
)
from sass_tui.model.text import quoted
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.populations.targets import TargetWeights

MIN_PEOPLE = 20
PERCENTILES = (5.0, 50.0, 95.0)
_GROUPS = ((GIRTH, "girth", GIRTH_NAMES), (CENTER_OF_MASS, "center_of_mass", CENTER_OF_MASS_NAMES))
_PLURAL = {"male": "men", "female": "women"}
_POSSESSIVE = {"male": "men's", "female": "women's"}
# The report's tables the model scales (see the module's docstring).
REPORT_TABLES = {
    GIRTH: "report appendix B (men) / C (women), datasets/girth.dat",
    CENTER_OF_MASS: "report appendix L.2, datasets/cmass.dat",
}


def people_words(counts: dict[str, int]) -> str:
    """{"male": 3, "female": 1} -> "3 men and 1 woman"."""
    single = {"male": "man", "female": "woman"}
    return " and ".join(f"{n} {single[g] if n == 1 else _PLURAL[g]}" for g, n in counts.items())


class PopulationError(ValueError, SassError):
    """A selection that cannot make a population (nothing was written)."""


@dataclass(frozen=True)
class SelectionPopulation:
    query: str
    counts: dict[str, int]  # people per gender
    groups: dict[str, PopulationData]  # GIRTH, CENTER_OF_MASS, every cell filled
    modelled: dict[str, int]  # group -> cells (both genders) from the stature model


def group_fields(word: str, rows: Sequence[str]) -> list[str]:
    return [f"{word}.{row}.{axis}" for row in rows for axis in ("x", "y", "z")]


def population_of(
    conn: sqlite3.Connection,
    query: str | ParsedQuery | None = None,
    *,
    ids: Sequence[int] | None = None,
    title: str | None = None,
    date: str | None = None,
    ids_from: str = "the selected list",
    progress: Progress | None = None,
    cancel: Cancel | None = None,
    target: TargetWeights | None = None,
) -> SelectionPopulation:
    """The population of the people `query` selects, or of the people `ids`
    names (the query screen's selected list; with both, the people of `ids`
    the query selects; `ids_from` names the list in the title).  See the
    module's docstring.  Raises PopulationError
    when nobody is selected or a gender has fewer than MIN_PEOPLE people;
    QueryError for a bad query.  `progress(columns done, columns)`; `cancel`
    stops it with Cancelled (it writes nothing anyway: the caller writes).
    With a `target` (sass_tui/db/populations/targets.py) the people are the target's (of
    `query`/`ids` if given), and the percentiles are weighted empirical
    percentiles (`model.targets.weighted_percentile`); the title says so."""
    # Parsed once; the files' titles say its text.
    selection = None if query is None else parsed(query)
    if target is not None:
        base = target.target.base_query
        selection = (
            parsed(base)
            if selection is None
            else joined(selection, base, text=f"({selection.text}) AND {base}")
        )
    if selection is None and ids is None:
        raise PopulationError("a population needs a query or a list of people")
    when = date or _dt.date.today().isoformat()
    fields = [f for _g, word, rows in _GROUPS for f in group_fields(word, rows)]
    fields += [row.name for row in GLOBAL_ROWS]  # stature, mass: the last columns
    steps = Steps(progress, cancel, "making the population")
    total = len(fields) * len(GENDERS) + 1
    steps(0, total)
    with interruptible(conn, cancel, "making the population"):
        values = load_values(conn, fields, selection, ids=ids)
    steps(1, total)
    what = _selection_words(None if selection is None else selection.text, ids, ids_from)
    genders = np.array(values.genders, dtype=object)
    counts: dict[str, int] = {g: int(np.sum(genders == g)) for g in GENDERS if np.any(genders == g)}
    if not counts:
        raise PopulationError(f"{what} selects nobody")
    small = {g: n for g, n in counts.items() if n < MIN_PEOPLE}
    if small:
        said = people_words(small)
        widen = (
            "widen the query, or leave that gender out with `AND gender = ...`"
            if ids is None
            else "select more people, or delete that gender's people from the list"
        )
        raise PopulationError(
            f"{what} selects only {said}; a population needs at least {MIN_PEOPLE} "
            f"people of each gender it holds ({widen})"
        )
    described = people_words(counts)
    if target is not None:
        what = f"{target.target.words()}, {what}"
        described += f", weighted: effective n {target.target.effective_n:.0f}"
    heading = title or f"Population of {what.removeprefix('the query ')}"
    groups: dict[str, PopulationData] = {}
    modelled: dict[str, int] = {}
    start = 0
    done = [1]

    def column_done() -> None:
        done[0] += 1
        steps(done[0], total)

    statures = values.matrix[:, -len(GLOBAL_ROWS) + row_index(GLOBAL, "stature")]
    scales = {g: _stature_scale(statures[genders == g], g) for g in counts}
    file_title = f"{heading} ({described}; sass query, {when})"
    for group, _word, rows in _GROUPS:
        width = len(rows) * 3
        block = values.matrix[:, start : start + width]
        start += width
        data = PopulationData(group=group, title=file_title, path="")
        modelled[group] = 0
        for gender in counts:
            people = block[genders == gender]
            ids = values.ids[genders == gender]
            stats = _percentiles(people, column_done, target, ids).reshape(len(rows), 3, 3)
            have = np.sum(~np.isnan(people), axis=0).reshape(len(rows), 3)
            modelled[group] += _fill_from_report(data, gender, stats, have, scales[gender])
            data.sections[gender] = stats
            data.lines[gender] = [0] * len(rows)
            if group == CENTER_OF_MASS:
                _apply_center_of_mass_rules(data, gender, have, groups[GIRTH])
        groups[group] = data
    groups[GLOBAL] = _own_stature_and_mass(values, genders, counts, target, file_title)
    steps(total, total)
    return SelectionPopulation(what.removeprefix("the query "), counts, groups, modelled)


def _own_stature_and_mass(
    values: Values,
    genders: np.ndarray,
    counts: dict[str, int],
    target: TargetWeights | None,
    title: str,
) -> PopulationData:
    """The people's own stature and mass, 5th/50th/95th per gender (weighted
    with a target): what the population's figure is sized from (FILE-global.dat
    beside the girth file, read with it by `sass fig --girth` and Make
    Population).  A row too few of the people have (under MIN_PEOPLE) is
    datasets/global.dat's, and its comment says so."""
    columns = values.matrix[:, -len(GLOBAL_ROWS) :]
    report = _report(GLOBAL)
    data = PopulationData(group=GLOBAL, title=title, path="")
    for gender in counts:
        mine = genders == gender
        stats = _percentiles(columns[mine], lambda: None, target, values.ids[mine]).reshape(
            len(GLOBAL_ROWS), 1, 3
        )
        have = np.sum(~np.isnan(columns[mine]), axis=0)
        notes = []
        for r, row in enumerate(GLOBAL_ROWS):
            if have[r] >= MIN_PEOPLE:
                notes.append(f"{row.label}: the people's own ({int(have[r])} have it)")
            else:
                stats[r, 0] = report.stats(gender)[r, 0]
                notes.append(
                    f"{row.label}: datasets/global.dat's (only {int(have[r])} of the people have it)"
                )
        weighted = ", weighted to the target" if target is not None else ""
        data.notes[gender] = [
            f"The {_POSSESSIVE[gender]} own stature (cm) and mass (kg), 5th/50th/95th "
            f"percentile{weighted}: the Stature and Mass of the population's figure."
        ]
        data.sections[gender] = stats
        data.lines[gender] = [0] * len(GLOBAL_ROWS)
        data.row_notes[gender] = notes
    return data


def _apply_center_of_mass_rules(
    cmass: PopulationData, gender: str, have: np.ndarray, girth: PopulationData
) -> None:
    """The center-of-mass cells the people lack (all: ANSUR II measures no
    center of mass) that appendix L.1 defines from segment lengths, made from
    the population's own girth instead of the report's table scaled by
    stature: the lower leg, the foot, and the women's segments scaled from
    the men's by length (the population's own men where it has them, else
    the report's).  The files then agree with the rules their reader checks
    (popfile.check_center_of_mass_rules); each row's comment names the rule."""
    stats = cmass.stats(gender)
    lengths = girth.stats(gender)
    com = {row.name: i for i, row in enumerate(ROWS[CENTER_OF_MASS])}
    seg = {row.name: i for i, row in enumerate(ROWS[GIRTH])}
    ruled: dict[tuple[int, int], str] = {}

    def rule(row: str, axis: int, cell: Sequence[float], said: str) -> None:
        if have[com[row], axis] < MIN_PEOPLE:
            stats[com[row], axis] = cell
            ruled[com[row], axis] = said

    for side in ("right", "left"):
        leg = lengths[seg[f"{side}_lower_leg"], 2]
        rule(
            f"{side}_lower_leg",
            2,
            [lower_leg_center(v) for v in leg],
            f"L.1 {LOWER_LEG_FRACTION} x length",
        )
        foot, toes = lengths[seg[f"{side}_foot"], 0], lengths[seg[f"{side}_ball_of_foot"], 0]
        rule(f"{side}_foot", 0, [foot_center(f, t) for f, t in zip(foot, toes)], "L.1 foot rule")
    if gender == "female":
        if cmass.has("male"):
            men_com, men_len, men = cmass.stats("male"), girth.stats("male"), "the men's"
        else:
            men_com = _report(CENTER_OF_MASS).stats("male")
            men_len, men = _report(GIRTH).stats("male"), "the report's men's"
        for row, parts in SCALED_BY_LENGTH.items():
            women = sum(lengths[seg[part], 2] for part in parts)
            male = sum(men_len[seg[part], 2] for part in parts)
            rule(row, 2, men_com[com[row], 2] * women / male, f"L.1 {men} x length ratio")
    cmass.notes[gender].append(
        "'L.1 ...' = appendix L.1's rule applied to the population's own girth values "
        f"(lower leg {LOWER_LEG_FRACTION} x its length; foot {FOOT_FRACTION} (foot x + toes x) "
        f"- {HEEL_BEHIND_ANKLE} foot x; a woman's segment = a man's x her length / his)."
    )
    notes = cmass.row_notes[gender]
    for (r, a), said in ruled.items():
        notes[r] = notes[r].replace(f"{AXES[a]} model", f"{AXES[a]} {said}")


def _stature_scale(statures: np.ndarray, gender: str) -> tuple[np.ndarray, str]:
    """Per percentile (5, 50, 95): the people's stature over global.dat's, and
    how that reads in the file's comments."""
    report = _report(GLOBAL).stats(gender)[0, 0]  # the stature row: 5/50/95 cm
    measured = statures[~np.isnan(statures)]
    if len(measured) < MIN_PEOPLE:
        return np.ones(3), (
            f"unscaled: only {len(measured)} of the people have a stature "
            f"(at least {MIN_PEOPLE} are needed)"
        )
    own = np.percentile(measured, PERCENTILES)
    scale = own / report
    said = "/".join(f"{v:.1f}" for v in own)
    return scale, (
        f"× the people's stature {said} cm / datasets/global.dat's "
        f"{'/'.join(f'{v:.1f}' for v in report)} cm = "
        f"{'/'.join(f'{v:.3f}' for v in scale)} (5th/50th/95th)"
    )


def _report(group: str) -> PopulationData:
    name = "global.dat" if group == GLOBAL else datasets.FILES[group]
    return read_population_file(datasets.path(name), group)


def _fill_from_report(
    data: PopulationData,
    gender: str,
    stats: np.ndarray,
    have: np.ndarray,
    scale: tuple[np.ndarray, str],
) -> int:
    """Fill the cells of `stats` (rows, axes, 5/50/95) too few people have
    (`have`: people with a value per cell) from the report's table scaled by
    stature, writing where each cell came from into `data`'s notes; returns
    the cells filled."""
    factor, how = scale
    report = _report(data.group).stats(gender)
    data.notes[gender] = [
        f"Where each value comes from: 'people' = the {_POSSESSIVE[gender]} own values "
        f"(5th/50th/95th percentile of those who have it, at least {MIN_PEOPLE}); "
        f"'model' = {REPORT_TABLES[data.group]} {how}; a cell whose three values this "
        "would reorder (report values that barely differ, e.g. the eyes) is scaled by the "
        "50th's ratio alone (docs/data-sources.md)."
    ]
    notes: list[str] = []
    filled = 0
    for r, row in enumerate(ROWS[data.group]):
        said = []
        for a, axis in enumerate(AXES):
            if have[r, a] >= MIN_PEOPLE:
                said.append(f"{axis} people ({int(have[r, a])})")
                continue
            scaled = report[r, a] * factor
            if not np.array_equal(np.sign(np.diff(scaled)), np.sign(np.diff(report[r, a]))):
                scaled = report[r, a] * factor[1]
            stats[r, a] = scaled
            filled += 1
            said.append(f"{axis} model")
        notes.append(f"{row.label}: {', '.join(said)}")
    data.row_notes[gender] = notes
    return filled


def _selection_words(query: str | None, ids: Sequence[int] | None, ids_from: str) -> str:
    if ids is None:
        return f"the query {query}"
    listed = f"{ids_from} of {len(ids):,} {'person' if len(ids) == 1 else 'people'}"
    return listed if query is None else f"{listed} AND {query}"


def _percentiles(
    people: np.ndarray,
    column_done: Callable[[], None],
    target: TargetWeights | None = None,
    ids: Any = None,  # the people's ids (Values.ids) when a target is given
) -> np.ndarray:
    """Per column, 5th/50th/95th of the values present (NaN below MIN_PEOPLE);
    weighted empirical percentiles of the people `ids` when a `target` is
    given (its module, db/populations/targets.py, is imported only when one is)."""
    out = np.full((people.shape[1], len(PERCENTILES)), np.nan)
    weights = None if target is None or ids is None else target.of(ids)
    for k in range(people.shape[1]):
        column_done()
        column = people[:, k]
        present = ~np.isnan(column)
        if present.sum() < MIN_PEOPLE:
            continue
        if target is None or weights is None:
            out[k] = np.percentile(column[present], PERCENTILES)
        else:
            out[k] = target.percentiles(column, weights, PERCENTILES)
    return out


class IdListError(ValueError, SassError):
    """A list of person ids that cannot be read (nothing was made)."""


def parse_id_list(text: str, where: str) -> list[int]:
    """Person ids, one a line: a plain list, or `sass query --format csv`'s
    output (its first column; the header line is skipped).  Blank lines and
    lines starting with # are skipped; an id listed twice counts once.
    IdListError says which line (`where`:N) holds what is not an id."""
    ids: dict[int, None] = {}
    for number, line in enumerate(text.splitlines(), 1):
        field = line.split(",", 1)[0].strip()
        if not field or field.startswith("#") or (not ids and field.lower() == "id"):
            continue
        # SQLite's integers are 64-bit: a longer number names nobody.
        digits = field.lstrip("0") or "0"
        if not (field.isascii() and field.isdigit() and len(digits) < 20 and int(digits) < 2**63):
            raise IdListError(
                f"{where}:{number}: {quoted(field, escape=True)} is not a person id "
                "(expected a whole number, one a line, or `sass query --format csv` output)"
            )
        ids[int(digits)] = None
    if not ids:
        raise IdListError(f"{where}: no person ids in it")
    return list(ids)


def missing_ids(conn: sqlite3.Connection, ids: Sequence[int]) -> list[int]:
    """The ids of `ids` no person in the database has, in their order."""
    condition, listed = ids_in(conn, "id_num", ids)
    stored = {
        int(i) for (i,) in conn.execute(f"SELECT id_num FROM person WHERE {condition}", (listed,))
    }
    return [int(i) for i in ids if int(i) not in stored]
