"""Populations made from a selection of people (what SASS's users did by hand):
the empirical 5th, 50th and 95th percentile, per gender, of every girth and
center-of-mass row, from the selected people's own values.

The result is one PopulationData per group (report figure 7's format), ready
for `popfile.write_population_file` or for loading into the spreadsheet.  A
cell with fewer than MIN_PEOPLE values is left empty (999 in the file).  No
Textual import here.
"""

from __future__ import annotations

import datetime as _dt
import sqlite3
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from sass_tui.db.progress import Cancel, Progress, Steps, interruptible
from sass_tui.db.schema import CENTER_OF_MASS_NAMES, GIRTH_NAMES
from sass_tui.db.values import load_values
from sass_tui.model.errors import SassError
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, GLOBAL_ROWS
from sass_tui.model.popfile import PopulationData
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.targets import TargetWeights

MIN_PEOPLE = 20
PERCENTILES = (5.0, 50.0, 95.0)
_GROUPS = ((GIRTH, "girth", GIRTH_NAMES), (CENTER_OF_MASS, "center_of_mass", CENTER_OF_MASS_NAMES))
_PLURAL = {"male": "men", "female": "women"}


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
    groups: dict[str, PopulationData]  # GIRTH, CENTER_OF_MASS (groups with no value left out)
    empty_groups: tuple[str, ...]  # groups none of the people has a value of


def group_fields(word: str, rows: Sequence[str]) -> list[str]:
    return [f"{word}.{row}.{axis}" for row in rows for axis in ("x", "y", "z")]


def population_of(
    conn: sqlite3.Connection,
    query: str | None = None,
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
    With a `target` (sass_tui/db/targets.py) the people are the target's (of
    `query`/`ids` if given), and the percentiles are weighted empirical
    percentiles (`model.targets.weighted_percentile`); the title says so."""
    if target is not None:
        base = target.target.base_query
        query = base if query is None else f"({query}) AND {base}"
    if query is None and ids is None:
        raise PopulationError("a population needs a query or a list of people")
    when = date or _dt.date.today().isoformat()
    fields = [f for _g, word, rows in _GROUPS for f in group_fields(word, rows)]
    steps = Steps(progress, cancel, "making the population")
    total = len(fields) * len(GENDERS) + 1
    steps(0, total)
    with interruptible(conn, cancel, "making the population"):
        values = load_values(conn, fields, query, ids=ids)
    steps(1, total)
    what = _selection_words(query, ids, ids_from)
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
    empty: list[str] = []
    start = 0
    done = [1]

    def column_done() -> None:
        done[0] += 1
        steps(done[0], total)

    for group, _word, rows in _GROUPS:
        width = len(rows) * 3
        block = values.matrix[:, start : start + width]
        start += width
        if np.isnan(block).all():
            empty.append(group)
            continue
        data = PopulationData(
            group=group,
            title=f"{heading} ({described}; sass query, {when})",
            path="",
        )
        for gender in counts:
            people = block[genders == gender]
            weights = None if target is None else target.of(values.ids[genders == gender])
            data.sections[gender] = _percentiles(people, column_done, weights).reshape(
                len(rows), 3, 3
            )
            data.lines[gender] = [0] * len(rows)
        groups[group] = data
    if target is not None:
        # Weighting moves stature and mass most: a weighted population carries its own
        # global statistics (the file `sass fig --global` reads).
        whole = load_values(conn, [r.name for r in GLOBAL_ROWS], query, ids=ids)
        data = PopulationData(
            group=GLOBAL, title=f"{heading} ({described}; sass query, {when})", path=""
        )
        for gender in counts:
            mine = np.array(whole.genders, dtype=object) == gender
            weights = target.of(whole.ids[mine])
            data.sections[gender] = _percentiles(whole.matrix[mine], lambda: None, weights).reshape(
                len(GLOBAL_ROWS), 1, 3
            )
            data.lines[gender] = [0] * len(GLOBAL_ROWS)
        groups[GLOBAL] = data
    steps(total, total)
    return SelectionPopulation(what.removeprefix("the query "), counts, groups, tuple(empty))


def _selection_words(query: str | None, ids: Sequence[int] | None, ids_from: str) -> str:
    if ids is None:
        return f"the query {query}"
    listed = f"{ids_from} of {len(ids):,} {'person' if len(ids) == 1 else 'people'}"
    return listed if query is None else f"{listed} AND {query}"


def _percentiles(
    people: np.ndarray, column_done: Callable[[], None], weights: np.ndarray | None = None
) -> np.ndarray:
    """Per column, 5th/50th/95th of the values present (NaN below MIN_PEOPLE);
    weighted empirical percentiles when `weights` are given."""
    out = np.full((people.shape[1], len(PERCENTILES)), np.nan)
    for k in range(people.shape[1]):
        column_done()
        column = people[:, k]
        present = ~np.isnan(column)
        if present.sum() < MIN_PEOPLE:
            continue
        if weights is None:
            out[k] = np.percentile(column[present], PERCENTILES)
        else:
            from sass_tui.model.targets import weighted_percentile

            out[k] = weighted_percentile(column, weights, PERCENTILES)
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
            from sass_tui.model.text import printable

            raise IdListError(
                f"{where}:{number}: {printable(field)!r} is not a person id "
                "(expected a whole number, one a line, or `sass query --format csv` output)"
            )
        ids[int(digits)] = None
    if not ids:
        raise IdListError(f"{where}: no person ids in it")
    return list(ids)


def missing_ids(conn: sqlite3.Connection, ids: Sequence[int]) -> list[int]:
    """The ids of `ids` no person in the database has, in their order."""
    import json

    rows = conn.execute(
        "SELECT value FROM json_each(?) WHERE value NOT IN (SELECT id_num FROM person) "
        "ORDER BY key",
        (json.dumps([int(i) for i in ids]),),
    )
    return [value for (value,) in rows]
