"""The fit test: what share of a population a set of design limits accommodates.

The design limits are a query in the query language (`sass_tui.db.query.query`);
the terms its top-level AND joins are the limits (a parenthesised group, AND
or OR, is one limit; an OR at the top level is refused).  The population is another
query, by default the ANSUR II people.  One SELECT evaluates every limit for
every person of the population: each limit is 1 (passes), 0 (fails) or NULL
(the person lacks a value the limit reads, e.g. strength for ANSUR II people).

Shares are counted, never modelled, but for a strength limit (`sass fit
--strength`): there each person has a probability of meeting it, from the
published spread of strength (model/strength/percent_capable.py), and the counts and
shares below are the expected ones (the mean of each person's probability):
- A person lacking any limited value is "not measured" and left out of every
  share (never counted as fitting); each limit reports how many people of the
  population lack its value.
- Per gender: the measured people `n`, those passing every limit `fit`, and
  `percent = 100 fit / n`.
- The naive estimate per gender is the product of each limit's own share over
  the same measured people: what univariate percentiles suggest.
- Weighted by the mix (default equal): sum of mix[g] * percent[g] over the
  genders the population has (the mix renormalised over them).
- With a target population (`--target`, `--virtual`): every share is weighted
  by the people's survey weights, and the headline weighted share has the
  genders in the survey's own proportions (the mix is each gender's weight
  over the measured people's), unless a mix is given: then it is that mix of
  the per-gender weighted shares.
- Per limit: `excluded`, the measured people failing it (whatever the other
  limits say), and `only_limit`, those it alone excludes (they pass every
  other limit).

No Textual, no argument parsing, no printing.
"""

from __future__ import annotations

import dataclasses
import math
import sqlite3
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from sass_tui.db.engine.dialect import dialect_of, ids_in
from sass_tui.db.people.values import load_values
from sass_tui.db.progress import Cancel, Progress, Steps, interruptible
from sass_tui.db.query.query import (
    CompiledQuery,
    ParsedQuery,
    compile_conjuncts,
    joined,
    parse_query,
    parsed,
    real_people_only,
    resolve_field,
)
from sass_tui.db.query.query_tree import And, Comparison, Expr
from sass_tui.model.errors import SassError
from sass_tui.model.population.targets import kish_effective_n, weighted_percentile
from sass_tui.model.strength.percent_capable import strength_limit_probability
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.populations.targets import TargetWeights
    from sass_tui.model.strength.published_strength import StrengthLimit

DEFAULT_POPULATION = "source = ansur2"


class FitError(ValueError, SassError):
    """A fit test that cannot be run (bad mix, empty population)."""


@dataclass(frozen=True)
class GenderShare:
    """One gender's result: `n` measured people, `fit` of them accommodated."""

    gender: str
    n: int
    fit: float  # people accommodated: a whole number, or expected with strength limits
    not_measured: int
    percent: float | None  # None when n == 0
    naive_percent: float | None


@dataclass(frozen=True)
class LimitBounds:
    """A limit on one numeric field's value: `FIELD op v` or a range of two."""

    field: str
    column: tuple[str, str]  # (table, column) it reads
    unit: str
    low: float | None
    high: float | None
    index: int = 0  # which of the fields read per person (fit_test's `read` columns)


def one_field(expr: Expr) -> list[Comparison] | None:
    """The comparisons of a limit on one field: `FIELD op v`, or a range
    (`BETWEEN`, or `FIELD > a AND FIELD < b` in parentheses); None otherwise."""
    comparisons = list(expr.comparisons())
    one = isinstance(expr, Comparison) or (
        isinstance(expr, And)
        and len(comparisons) == 2  # a range: its two ends
        and all(isinstance(t, Comparison) for t in expr.terms)
        and comparisons[0].field == comparisons[1].field
        and {c.op[0] for c in comparisons} == {"<", ">"}
    )
    return comparisons if one else None


def limit_bounds(expr: Expr) -> LimitBounds | None:
    """The bounds of a limit on one numeric field (None for any other limit:
    words, an OR, several fields)."""
    comparisons = one_field(expr)
    if comparisons is None or any(
        isinstance(c.value, str) or c.op not in ("<", "<=", ">", ">=") for c in comparisons
    ):
        return None
    low = high = None
    for c in comparisons:
        if c.op[0] == ">":
            low = float(c.value)
        else:
            high = float(c.value)
    first = comparisons[0]
    _table, _column, unit, _words = resolve_field(first.field.split("."))
    return LimitBounds(first.field, (first.table, first.column), unit or "", low, high)


@dataclass(frozen=True)
class ExcludedSide:
    """The people a limit excludes at one end (below its low or above its high)."""

    n: int
    percent: float  # their weight over the measured people's (the headline's weighting)
    median_stature: float | None  # weighted, cm
    median_mass: float | None  # weighted, kg
    genders: dict[str, float]  # each gender's share of them (percent of their weight)

    def to_json(self) -> dict[str, Any]:
        return {
            "n": self.n,
            "percent": round(self.percent, 4),
            "median_stature": _round(self.median_stature),
            "median_mass": _round(self.median_mass),
            "genders": {g: round(v, 4) for g, v in self.genders.items()},
        }


@dataclass(frozen=True)
class LimitShare:
    limit: str
    excluded: float  # measured people failing this limit (expected, for a strength limit)
    only_limit: float  # measured people failing this limit and no other
    not_measured: int  # population people lacking the value(s) it reads
    percent: dict[str, float | None]  # its own share per gender (measured people)
    below: ExcludedSide | None = None  # a one-field numeric limit's excluded, by end
    above: ExcludedSide | None = None


@dataclass(frozen=True)
class FailedLimit:
    limit: str
    measure: str | None  # None: not one field's numeric limit
    value: float | None
    unit: str
    side: str | None  # "below" its low end, "above" its high end


@dataclass(frozen=True)
class FailingPerson:
    id: int
    name: str
    gender: str
    limits: tuple[str, ...]
    failed: tuple[FailedLimit, ...] = ()


@dataclass(frozen=True)
class TargetShare:
    """The share of a target population (sass_tui/db/populations/targets.py) accommodated:
    the fitting people's weight over the measured people's weight."""

    name: str
    words: str  # how the answer names its target (Target.words)
    percent: float | None
    effective_n: float  # Kish, over the measured people of the target
    virtual: bool = False  # a virtual population's people: the per-gender shares are weighted
    # per --by field: the share of the target beyond every person weighted
    # (Target.outside_shares); `percent` is of the rest, which the people cover
    outside_share: dict[str, float] = dataclasses.field(default_factory=dict)

    def to_json(self) -> dict[str, Any]:
        return (
            {
                "name": self.name,
                "percent": _round(self.percent),
                "effective_n": round(self.effective_n, 2),
            }
            | ({"virtual": True, "people": self.words} if self.virtual else {})
            | (
                {"outside_share": {f: round(x, 6) for f, x in self.outside_share.items()}}
                if not self.virtual
                else {}
            )
        )


@dataclass(frozen=True)
class FitResult:
    limits: tuple[str, ...]
    population: str
    mix: dict[str, float]  # the weights used (renormalised over the genders present)
    genders: dict[str, GenderShare]
    weighted_percent: float | None
    naive_percent: float | None  # weighted like the accommodated share
    by_limit: tuple[LimitShare, ...]
    failing: tuple[FailingPerson, ...] | None  # None unless asked for
    target: TargetShare | None = None  # weighted to a target population, when asked

    @property
    def population_size(self) -> int:
        return sum(g.n + g.not_measured for g in self.genders.values())

    @property
    def not_measured(self) -> int:
        return sum(g.not_measured for g in self.genders.values())

    def to_json(self) -> dict[str, Any]:
        """The JSON of docs/accommodation.md; per gender it also gives `naive_percent` and
        `not_measured`, per limit `not_measured` and `percent` (per gender)."""
        accommodated: dict[str, Any] = {
            g.gender: {
                "n": g.n,
                "fit": g.fit,
                "percent": _round(g.percent),
                "naive_percent": _round(g.naive_percent),
                "not_measured": g.not_measured,
            }
            for g in self.genders.values()
        }
        accommodated["weighted"] = {"percent": _round(self.weighted_percent)}
        return {
            "limits": list(self.limits),
            "population": self.population,
            "mix": self.mix,
            "accommodated": accommodated,
            "naive_percent": _round(self.naive_percent),
            "by_limit": [
                {
                    "limit": b.limit,
                    "excluded": b.excluded,
                    "only_limit": b.only_limit,
                    "not_measured": b.not_measured,
                    "percent": {g: _round(p) for g, p in b.percent.items()},
                    "below": None if b.below is None else b.below.to_json(),
                    "above": None if b.above is None else b.above.to_json(),
                }
                for b in self.by_limit
            ],
            "failing": None
            if self.failing is None
            else [
                {
                    "id": f.id,
                    "name": f.name,
                    "limits": list(f.limits),
                    "failed": [
                        {
                            "limit": x.limit,
                            "measure": x.measure,
                            "value": _round(x.value),
                            "unit": x.unit,
                            "side": x.side,
                        }
                        for x in f.failed
                    ],
                }
                for f in self.failing
            ],
        } | ({} if self.target is None else {"target": self.target.to_json()})


def _round(value: float | None) -> float | None:
    return None if value is None else round(value, 4)


def check_mix(mix: dict[str, float] | None) -> dict[str, float]:
    """The gender weights, normalised to sum 1 (default: equal).  One gender's
    weight alone is its share, and the other gender has the rest
    (`male=0.8` is `male=0.8,female=0.2`)."""
    if mix is None:
        return {g: 1.0 / len(GENDERS) for g in GENDERS}
    for gender, weight in mix.items():
        if gender not in GENDERS:
            raise FitError(f"mix: unknown gender {gender!r}; expected {' or '.join(GENDERS)}")
        if not math.isfinite(weight) or weight < 0:
            raise FitError(f"mix: the weight of {gender} must be a number >= 0, not {weight}")
    if len(mix) == 1 and len(GENDERS) == 2:
        ((gender, share),) = mix.items()
        if share > 1:
            raise FitError(
                f"mix: {gender}={share:g} alone is a share from 0 to 1 (the other gender has "
                f"the rest); give both weights to weigh them otherwise, e.g. "
                f"{gender}=0.8,{'female' if gender == 'male' else 'male'}=0.2"
            )
        other = next(g for g in GENDERS if g != gender)
        # rounded: 1 - 0.8 is 0.19999999999999996 in binary, and male=0.8 is male=0.8,female=0.2
        rest = round(1.0 - share, 12)
        mix = {gender: share, other: rest} if rest > 0 else {gender: share}
    largest = max(mix.values())
    if largest <= 0:
        raise FitError("mix: the weights add up to 0; give at least one gender a weight > 0")
    # scaled by the largest first: male=1e308,female=1e308 add up to infinity
    total = sum(weight / largest for weight in mix.values())
    return {g: mix[g] / largest / total for g in GENDERS if g in mix}


def fit_test(
    conn: sqlite3.Connection,
    limits: str | ParsedQuery,
    population: str | ParsedQuery = DEFAULT_POPULATION,
    mix: dict[str, float] | None = None,
    failing: bool = False,
    progress: Progress | None = None,
    cancel: Cancel | None = None,
    target: TargetWeights | None = None,
    strength_limits: Sequence[StrengthLimit] = (),
) -> FitResult:
    """Run the design limits `limits` over the people `population` selects.
    `progress(steps done, 3)`; `cancel` stops it (also mid-statement) with Cancelled.
    With a `target`, its people (of `population`) are tested and their weighted
    share is given too (`FitResult.target`). `strength_limits` are limits on each
    person's strength predicted from their own gender, age, mass and stature
    (docs/strength.md), after the query's."""
    # Each query parsed once; a query's errors point into its own text.
    limit_query = parsed(limits)
    people_query = target_population(parsed(population), target)
    steps = Steps(progress, cancel, "the fit test")
    steps(0, 3)
    weights = check_mix(mix)
    rows, terms, bounds = _limit_rows(conn, limit_query, people_query, cancel)
    if target is not None and target.target.is_virtual:
        # a virtual population's people are its weighted ones (--within-range leaves some out)
        member = frozenset(target.ids.tolist())
        rows = [r for r in rows if r[0] in member]
    steps(1, 3)
    if not rows:
        raise FitError(f"the population {people_query.text!r} selects nobody")
    ids = np.fromiter((r[0] for r in rows), dtype=np.int64, count=len(rows))
    gender = np.array([r[1] for r in rows], dtype=object)
    # (people, limits): 1.0 passes, 0.0 fails, NaN not measured; a strength
    # limit's column is each person's probability of meeting it (docs/strength.md).
    first = len(rows[0]) - len(terms)
    passes = np.array([r[first:] for r in rows], dtype=float).reshape(len(rows), len(terms))
    # age, mass, stature, then the limits' fields: who is excluded, and how
    read = np.array([r[2:first] for r in rows], dtype=float).reshape(len(rows), first - 2)
    texts = tuple(t.text for t in terms)
    if strength_limits:
        body_of = [
            np.array([math.nan if r[i] is None else float(r[i]) for r in rows]) for i in (2, 3, 4)
        ]
        predicted = [
            strength_limit_probability(limit, gender, *body_of) for limit in strength_limits
        ]
        passes = np.hstack([passes, np.column_stack(predicted)])
        texts += tuple(f"{limit.text} (predicted)" for limit in strength_limits)
        bounds += [None] * len(strength_limits)
    steps(2, 3)
    # A target's people stand for their survey's: every share is weighted by
    # them, the genders in the survey's proportions unless a mix is given.
    survey = target.of(ids) if target is not None else None
    result = _summarise(
        conn,
        texts,
        people_query.text,
        weights,
        ids,
        gender,
        passes,
        failing,
        survey,
        survey_mix=target is not None and mix is None,
        read=read,
        bounds=bounds,
    )
    if target is not None:
        result = replace(result, target=_target_share(target, ids, passes, gender))
    steps(3, 3)
    return result


def _limit_rows(
    conn: sqlite3.Connection,
    limit_query: ParsedQuery,
    people_query: ParsedQuery,
    cancel: Cancel | None,
) -> tuple[list[Any], list[CompiledQuery], list[LimitBounds | None]]:
    """One row per person of the population: id, gender, age, mass, stature,
    the value of each one-field numeric limit's field (`bounds`), then each
    limit 1/0 (SQLite) or true/false (PostgreSQL), NULL not measured; the
    limits compiled, and each one's bounds (None: not one field's numbers)."""
    # One compilation of both, so the population's terms share the limits' joins
    # and its WHERE runs inline (a subquery for it costs half as much again).
    people, *terms = compile_conjuncts(limit_query, first=people_query)
    # The population's term is compiled as a part, unscoped: real people unless it names a source.
    people = real_people_only(people)
    dialect = dialect_of(conn)
    limit_sql = [t.sql(dialect) for t in terms]
    where, where_params = people.sql(dialect)
    bounds = [limit_bounds(t.tree) for t in terms]
    alias_of = {"person": "p"} | {table: alias for alias, table in people.tables}
    read = list(dict.fromkeys(b.column for b in bounds if b is not None))
    columns = ", ".join(
        ["p.age", "p.mass", "p.stature"]
        + [f"{alias_of[table]}.{column}" for table, column in read]
        + [f"({condition})" for condition, _ in limit_sql]
    )
    sql = (
        f"SELECT p.id_num, p.gender, {columns} FROM {people.from_clause()} "
        f"WHERE {where} ORDER BY p.id_num"
    )
    params = tuple(v for _, values in limit_sql for v in values) + where_params
    with interruptible(conn, cancel, "the fit test"):
        rows: list[Any] = conn.execute(sql, params).fetchall()
    bounds = [None if b is None else replace(b, index=read.index(b.column)) for b in bounds]
    return rows, terms, bounds


def limit_verdicts(
    conn: sqlite3.Connection, limits: ParsedQuery, people: ParsedQuery
) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.float64]]:
    """The people of `people` (id order) and, per limit of `limits`, 1.0 if they
    pass it, 0.0 if not, NaN not measured: the fit test's own evaluation."""
    rows, terms, _bounds = _limit_rows(conn, limits, people, None)
    ids = np.fromiter((r[0] for r in rows), dtype=np.int64, count=len(rows))
    first = len(rows[0]) - len(terms) if rows else 0
    passes = np.array([r[first:] for r in rows], dtype=float).reshape(len(rows), len(terms))
    return ids, passes


def target_population(people: ParsedQuery, target: TargetWeights | None) -> ParsedQuery:
    """The people a fit test (or a design) runs over: `people`, within the target's."""
    if target is None:
        return people
    base = target.target.base_query
    if people.text == target.target.population:
        return parsed(base)
    return joined(people, base, text=f"({people.text}) AND {base}")


def _target_share(
    target: TargetWeights,
    ids: npt.NDArray[np.int64],
    passes: npt.NDArray[np.float64],
    genders: npt.NDArray[np.object_],
) -> TargetShare:
    w = target.of(ids)
    measured = ~np.isnan(passes).any(axis=1)
    fits = np.where(measured, np.nan_to_num(passes, nan=1.0).prod(axis=1), 0.0)
    total = float(w[measured].sum())
    gender = np.asarray(genders, dtype=object)
    weight_of = {g: float(w[measured & (gender == g)].sum()) for g in GENDERS}
    return TargetShare(
        name=target.target.name,
        words=target.target.words(),
        percent=100.0 * float((w * fits).sum()) / total if total > 0 else None,
        effective_n=kish_effective_n(w[measured]),
        virtual=target.target.is_virtual,
        outside_share=target.target.outside_shares(weight_of),
    )


def _summarise(
    conn: sqlite3.Connection,
    limits: tuple[str, ...],
    population: str,
    weights: dict[str, float],
    ids: npt.NDArray[np.int64],
    gender: npt.NDArray[Any],
    passes: npt.NDArray[np.float64],
    want_failing: bool,
    person_weights: npt.NDArray[np.float64] | None = None,
    survey_mix: bool = False,
    read: npt.NDArray[np.float64] | None = None,
    bounds: Sequence[LimitBounds | None] = (),
) -> FitResult:
    w = np.ones(len(ids)) if person_weights is None else person_weights
    unmeasured = np.isnan(passes)
    measured = ~unmeasured.any(axis=1)
    # Each limit's probability of being met: 1 or 0 for a measured value, a
    # person's predicted probability for a strength limit; the expected counts
    # are whole numbers where every limit is measured.
    met = np.nan_to_num(passes, nan=1.0)
    fits = met.prod(axis=1)
    fails = passes < 0.5  # NaN compares False: only a failure (or a likely one)
    alone = [(1.0 - met[:, k]) * np.delete(met, k, axis=1).prod(axis=1) for k in range(len(limits))]
    genders: dict[str, GenderShare] = {}
    limit_percent: list[dict[str, float | None]] = [{} for _ in limits]
    for g in GENDERS:
        mine = gender == g
        if not mine.any():
            continue
        counted = mine & measured
        n = int(counted.sum())
        fit = _count(float(fits[counted].sum()))
        weight = float(w[counted].sum())
        own = [
            100.0 * float((w[counted] * met[counted, k]).sum()) / weight if n else None
            for k in range(len(limits))
        ]
        for k, share in enumerate(own):
            limit_percent[k][g] = share
        naive = 100.0 * math.prod(s / 100.0 for s in own if s is not None) if n else None
        genders[g] = GenderShare(
            gender=g,
            n=n,
            fit=fit,
            not_measured=int((mine & ~measured).sum()),
            percent=100.0 * float((w[counted] * fits[counted]).sum()) / weight if n else None,
            naive_percent=naive,
        )
    if survey_mix:  # each gender's share of the measured people's weight
        weights = {g: float(w[(gender == g) & measured].sum()) for g in genders}
    used = {g: w for g, w in weights.items() if g in genders and genders[g].n > 0 and w > 0}
    total = sum(used.values())
    mix = {g: w / total for g, w in used.items()} if total > 0 else {}
    weighted = _weighted(mix, {g: s.percent for g, s in genders.items()})
    naive = _weighted(mix, {g: s.naive_percent for g, s in genders.items()})
    # The headline's weight of each person: theirs (or 1) scaled to the mix.
    headline = np.zeros(len(ids))
    for name, share in mix.items():
        mine = (gender == name) & measured
        total_g = float(w[mine].sum())
        if total_g > 0:
            headline[mine] = w[mine] * share / total_g
    padded = (list(bounds) + [None] * len(limits))[: len(limits)]
    sides = [
        (None, None)
        if read is None or b is None
        else _sides(read, b, fails[:, k], headline, gender)
        for k, b in enumerate(padded)
    ]
    by_limit = tuple(
        LimitShare(
            limit=limit,
            excluded=_count(float((1.0 - met[measured, k]).sum())),
            only_limit=_count(float(alone[k][measured].sum())),
            not_measured=int(unmeasured[:, k].sum()),
            percent=limit_percent[k],
            below=sides[k][0],
            above=sides[k][1],
        )
        for k, limit in enumerate(limits)
    )
    failing = (
        _failing(conn, limits, ids, gender, fails, read, list(bounds)) if want_failing else None
    )
    return FitResult(
        limits=limits,
        population=population,
        mix=mix,
        genders=genders,
        weighted_percent=weighted,
        naive_percent=naive,
        by_limit=by_limit,
        failing=failing,
    )


def _below(bounds: LimitBounds, value: npt.NDArray[np.float64]) -> npt.NDArray[np.bool_]:
    """Of people failing the limit: who fails its low end (the rest fail its high end)."""
    if bounds.low is None:
        return np.zeros(len(value), dtype=bool)
    if bounds.high is None:
        return np.ones(len(value), dtype=bool)
    with np.errstate(invalid="ignore"):
        below: npt.NDArray[np.bool_] = value <= bounds.low
    return below


def _sides(
    read: npt.NDArray[np.float64],
    bounds: LimitBounds,
    fails: npt.NDArray[np.bool_],
    headline: npt.NDArray[np.float64],
    gender: npt.NDArray[Any],
) -> tuple[ExcludedSide | None, ExcludedSide | None]:
    """Who a one-field limit excludes below its low end and above its high end."""
    below = _below(bounds, read[:, 3 + bounds.index])
    total = float(headline.sum())
    out: list[ExcludedSide | None] = []
    for end, beyond in ((bounds.low, fails & below), (bounds.high, fails & ~below)):
        if end is None:
            out.append(None)
            continue
        mine = beyond & (headline > 0)
        weight = float(headline[mine].sum())
        out.append(
            ExcludedSide(
                n=int(mine.sum()),
                percent=100.0 * weight / total if total > 0 else 0.0,
                median_stature=_median(read[mine, 2], headline[mine]),
                median_mass=_median(read[mine, 1], headline[mine]),
                genders={
                    str(g): 100.0 * float(headline[mine & (gender == g)].sum()) / weight
                    for g in GENDERS
                    if weight > 0 and bool((mine & (gender == g)).any())
                },
            )
        )
    return out[0], out[1]


def _median(values: npt.NDArray[np.float64], weights: npt.NDArray[np.float64]) -> float | None:
    keep = ~np.isnan(values)
    if not keep.any():
        return None
    return float(weighted_percentile(values[keep], weights[keep], [50.0])[0])


def _count(expected: float) -> float:
    """An expected number of people: whole (an int) when it is one, else to 0.01."""
    whole = round(expected)
    return whole if abs(expected - whole) < 1e-9 else round(expected, 2)


def _weighted(mix: dict[str, float], percent: dict[str, float | None]) -> float | None:
    if not mix:
        return None
    total = 0.0
    for g, w in mix.items():
        value = percent.get(g)
        if value is None:
            return None
        total += w * value
    return total


def _failing(
    conn: sqlite3.Connection,
    limits: tuple[str, ...],
    ids: npt.NDArray[np.int64],
    gender: npt.NDArray[Any],
    fails: npt.NDArray[np.bool_],
    read: npt.NDArray[np.float64] | None = None,
    bounds: list[LimitBounds | None] | None = None,
) -> tuple[FailingPerson, ...]:
    rows = np.flatnonzero(fails.any(axis=1))
    condition, listed = ids_in(conn, "id_num", [int(i) for i in ids[rows]])
    names: dict[int, str] = dict(
        conn.execute(f"SELECT id_num, name FROM person WHERE {condition}", (listed,))
    )
    return tuple(
        FailingPerson(
            id=int(ids[r]),
            name=names.get(int(ids[r]), ""),
            gender=str(gender[r]),
            limits=tuple(limit for k, limit in enumerate(limits) if fails[r, k]),
            failed=tuple(
                _failed(limit, read, int(r), (bounds or [])[k] if k < len(bounds or []) else None)
                for k, limit in enumerate(limits)
                if fails[r, k]
            ),
        )
        for r in rows
    )


def _failed(
    limit: str, read: npt.NDArray[np.float64] | None, row: int, bounds: LimitBounds | None
) -> FailedLimit:
    """The person's value of the limit's field, and which end they fail."""
    if bounds is None or read is None:
        return FailedLimit(limit, None, None, "", None)
    value = read[row : row + 1, 3 + bounds.index]
    side = "below" if bool(_below(bounds, value)[0]) else "above"
    return FailedLimit(limit, bounds.field, float(value[0]), bounds.unit, side)


@dataclass(frozen=True)
class LimitLine:
    """One numeric comparison of the design limits: `field op value` (canonical unit)."""

    field: str  # query-language name, e.g. "measure.sittingheight"
    op: str
    value: float


@dataclass(frozen=True)
class LimitHistogram:
    """The population's values of one limited field, binned per gender.
    Bin k holds edges[k] <= v < edges[k+1] (the last bin also holds its right
    edge); people lacking the value are counted in `missing`."""

    field: str
    unit: str
    edges: npt.NDArray[np.float64]
    counts: dict[str, npt.NDArray[np.int64]]  # gender -> people per bin
    lines: tuple[LimitLine, ...]  # the limits on this field
    missing: int


def limit_lines(limits: str) -> tuple[LimitLine, ...]:
    """The comparisons of `limits` on numeric fields, in the order written
    (word and text fields, e.g. gender or branch, have no place on an axis)."""
    out: list[LimitLine] = []
    for term in parse_query(limits).comparisons():
        # A word or text field's value is a word; a numeric field's is a number,
        # already converted to the field's stored unit by the query's compiler.
        if not isinstance(term.value, str):
            out.append(LimitLine(term.field, term.op, term.value))
    return tuple(out)


def limit_histograms(
    conn: sqlite3.Connection,
    limits: str,
    population: str = DEFAULT_POPULATION,
    bins: int = 20,
    cancel: Cancel | None = None,
) -> tuple[LimitHistogram, ...]:
    """One histogram per limited numeric field (in the order the limits name
    them) of the people `population` selects, with each limit's value inside
    the binned range so that it can be drawn on it."""
    lines = limit_lines(limits)
    fields = list(dict.fromkeys(line.field for line in lines))
    if not fields:
        return ()
    with interruptible(conn, cancel, "the fit test"):
        values = load_values(conn, fields, population)
    genders = np.array(values.genders, dtype=object)
    out = []
    for k, field in enumerate(fields):
        column = values.matrix[:, k]
        present = ~np.isnan(column)
        mine = tuple(line for line in lines if line.field == field)
        span = np.concatenate([column[present], [line.value for line in mine]])
        edges = np.histogram_bin_edges(span, bins=bins)
        counts: dict[str, npt.NDArray[np.int64]] = {
            g: np.histogram(column[present & (genders == g)], bins=edges)[0].astype(np.int64)
            for g in GENDERS
            if np.any(genders == g)
        }
        out.append(
            LimitHistogram(
                field=field,
                unit=values.units[k],
                edges=edges,
                counts=counts,
                lines=mine,
                missing=int((~present).sum()),
            )
        )
    return tuple(out)
