"""The percentile table (`sass stats`, the query screen's Stats): n,
effective n, mean, SD and percentiles of any measures over the people a
query selects, weighted to a target population or a virtual population's
survey weights when one is given.

Weighted percentiles are model/population/targets.py's `weighted_percentile` (numpy's
linear method when the weights are equal); the mean and SD are the weighted
people's as a population (weights as frequencies, Summary.of's); effective
n is Kish's.  `outside_share` is, for a target made over the measure, the
share of the target's weight beyond every person weighted (db/populations/targets.py).

No Textual, no printing.
"""

from __future__ import annotations

import math
import sqlite3
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from sass_tui.db.people.values import load_values
from sass_tui.db.populations.targets import TargetWeights
from sass_tui.db.populations.virtual import FIELDS
from sass_tui.db.query.scope import VIRTUAL_PREFIX
from sass_tui.model.errors import SassError
from sass_tui.model.population.prediction import field_unit
from sass_tui.model.population.targets import kish_effective_n, weighted_percentile
from sass_tui.model.units import UnitError, convert, unit_name
from sass_tui.model.vocabulary import GENDERS

DEFAULT_PERCENTILES = (1.0, 5.0, 50.0, 95.0, 99.0)
EVERY_MEASURE = FIELDS  # stature, mass and ANSUR II's other 91 measures
REAL_PEOPLE = (
    "gender = male OR gender = female"  # everyone, real people by scope (db/query/scope.py)
)


class StatsError(ValueError, SassError):
    """A table that cannot be made as asked (nobody selected, a unit of the wrong kind)."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


@dataclass(frozen=True)
class MeasureStats:
    field: str
    unit: str
    n: int  # people with a value
    mean: float
    sd: float
    percentiles: dict[float, float]
    outside_share: float | None


@dataclass(frozen=True)
class StatsTable:
    query: str  # the query the people were selected by
    n: int  # people selected (with a weight, when weighted)
    effective_n: float
    weighted_by: str | None  # "target NAME" / "virtual population NAME (WTMECPRP)"; None
    population: str  # how the people are named (a virtual population: said to be VIRTUAL)
    virtual: bool
    measures: tuple[MeasureStats, ...]


def stats_query(query: str | None, gender: str | None, weights: TargetWeights | None) -> str:
    """The query whose people the table is about."""
    parts = [f"({query})"] if query else []
    if weights is not None:
        parts.append(weights.target.base_query)
    if gender is not None:
        parts.append(f"gender = {gender}")
    return " AND ".join(parts) if parts else REAL_PEOPLE


def shown_unit(field: str, unit: str | None) -> str:
    """The unit a field is shown in: `unit` when it is of the field's kind, else canonical."""
    canonical = field_unit(field)
    if unit is None:
        return canonical
    try:
        convert(1.0, canonical, unit)
    except UnitError:
        return canonical
    return unit


def check_unit(text: str | None) -> str | None:
    """`--unit`: a unit of length or mass (StatsError otherwise)."""
    if text is None:
        return None
    try:
        unit = unit_name(text)
    except UnitError as exc:
        raise StatsError(f"--unit: {exc}", where=text) from None
    for canonical in ("cm", "kg"):
        try:
            convert(1.0, canonical, unit)
            return unit
        except UnitError:
            continue
    raise StatsError(f"--unit {text!r}: expected a unit of length (cm, mm, in) or mass (kg, lb)")


def stats_table(
    conn: sqlite3.Connection,
    fields: Sequence[str],
    query: str | None = None,
    *,
    gender: str | None = None,
    weights: TargetWeights | None = None,
    percentiles: Sequence[float] = DEFAULT_PERCENTILES,
    unit: str | None = None,
) -> StatsTable:
    """The table of `fields` (query-language names) over the people `query`
    selects (of `gender`; of the target's or virtual population's people,
    weighted, with `weights`).  A `unit` no field is shown in (`--unit kg`
    of lengths alone) is refused rather than passed over in silence."""
    if unit is not None and fields and all(shown_unit(f, unit) != unit for f in fields):
        kind = "mass" if field_unit(fields[0]) == "kg" else "length"
        other = "length" if kind == "mass" else "mass"
        raise StatsError(
            f"--unit {unit} is a unit of {other}, and no measure asked is a {other} "
            f"({fields[0].removeprefix('measure.')} is a {kind}); give a unit of {kind}",
            where=unit,
        )
    where = stats_query(query, gender, weights)
    values = load_values(conn, list(fields), where)
    w = np.ones(len(values)) if weights is None else weights.of(values.ids)
    keep = w > 0
    if not keep.any():
        raise StatsError(f"the query {where!r} selects nobody")
    matrix, w = values.matrix[keep], w[keep]
    genders = np.array(values.genders, dtype=object)[keep]
    target = None if weights is None else weights.target
    measures = []
    for j, field in enumerate(fields):
        column = matrix[:, j]
        has = ~np.isnan(column)
        shown = shown_unit(field, unit)
        x = convert(column[has], field_unit(field), shown)
        weight = w[has]
        total = float(weight.sum())
        mean = float(np.sum(weight * x)) / total if total > 0 else math.nan
        sd = math.sqrt(max(0.0, float(np.sum(weight * (x - mean) ** 2)) / total)) if total else 0.0
        cuts = weighted_percentile(x, weight, list(percentiles)) if total else None
        measures.append(
            MeasureStats(
                field=field,
                unit=shown,
                n=int(has.sum()),
                mean=mean,
                sd=sd if total else math.nan,
                percentiles={
                    p: (math.nan if cuts is None else float(c))
                    for p, c in zip(percentiles, cuts if cuts is not None else percentiles)
                },
                outside_share=_outside(weights, field, genders, w),
            )
        )
    if target is None:
        weighted_by, population, virtual = None, f"the people of {where}", False
    elif target.is_virtual:
        weighted_by = f"virtual population {target.name.removeprefix(VIRTUAL_PREFIX)}" + (
            f" ({target.weighted_by})" if target.weighted_by else ""
        )
        population, virtual = target.words(), True
    else:
        weighted_by, population, virtual = f"target {target.name}", target.words(), False
    return StatsTable(
        query=where,
        n=int(keep.sum()),
        effective_n=kish_effective_n(w),
        weighted_by=weighted_by,
        population=population,
        virtual=virtual,
        measures=tuple(measures),
    )


def _outside(
    weights: TargetWeights | None,
    field: str,
    genders: np.ndarray,
    w: np.ndarray,
) -> float | None:
    """The target's outside_share of `field` over the genders selected, each
    gender counted by its share of the selected weight; None when the target
    was not made over `field` (or is a virtual population)."""
    if weights is None:
        return None
    weight_of = {g: float(w[genders == g].sum()) for g in GENDERS}
    return weights.target.outside_shares(weight_of).get(field)


def percentile_key(p: float) -> str:
    """How a percentile is named in a table and in JSON: 5, 50, 2.5."""
    return f"{p:g}"


def format_stats(table: StatsTable) -> str:
    """The table as `sass stats` prints it and the Stats screen shows it."""
    keys = [percentile_key(p) for p in (table.measures[0].percentiles if table.measures else {})]
    lines = []
    if table.virtual:  # the target's words say VIRTUAL and "not measured" first
        lines.append(table.population)
    elif table.weighted_by:
        lines.append(f"weighted: {table.population}")
    lines.append(
        f"{table.n} people selected by: {table.query}; effective n {table.effective_n:.0f}"
    )
    head = f"{'measure':<32} {'unit':<4} {'n':>6} {'mean':>8} {'SD':>7}" + "".join(
        f" {'p' + k:>8}" for k in keys
    )
    with_outside = any(m.outside_share is not None for m in table.measures)
    lines.append(head + (f" {'outside':>8}" if with_outside else ""))
    for m in table.measures:
        row = (
            f"{m.field.removeprefix('measure.'):<32} {m.unit:<4} {m.n:>6} {m.mean:8.2f} {m.sd:7.2f}"
        )
        row += "".join(f" {v:8.2f}" for v in m.percentiles.values())
        if with_outside:
            row += f" {100 * m.outside_share:7.1f}%" if m.outside_share is not None else f" {'':>8}"
        lines.append(row)
    if with_outside:
        lines.append("outside: the share of the target's weight beyond every person weighted")
    return "\n".join(lines) + "\n"
