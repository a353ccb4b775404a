"""`sass design`'s database side: read the people the design is for, solve the
`?` limits (model/population/design.py) and check the answer with the fit test.

LIMITS is a query (db/query/query.py, parsed with `?` allowed): the terms its
top-level AND joins are the limits, as for `sass fit`.  A term with a `?`
must be one numeric field's limit: `FIELD <= ?` (or <, >=, >),
`FIELD BETWEEN ? AND ?`, `FIELD BETWEEN 40 cm AND ?`, or the same range
written `(FIELD >= ? AND FIELD <= ?)`.  Every other term is a fixed limit,
evaluated by the fit test's own SQL.

The people and their weights are the fit test's (db/populations/fit.py): the
population query, within a target's people when one is given; each person's
weight is the target's (survey) weight, or 1; the genders are then weighed
by the mix when one is given (without a target: equal, as `sass fit`), else
left in the survey's own proportions.  The share solved is the one `sass
fit` prints first for the same limits, and the fit test is run on the
solved limits to report it (`Designed.fit`).

No Textual, no argument parsing; `format_design` is the text `sass design`
prints and the Fit Test screen shows.
"""

from __future__ import annotations

import math
import sqlite3
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from sass_tui.db.people.values import load_values
from sass_tui.db.populations.fit import (
    DEFAULT_POPULATION,
    FitResult,
    check_mix,
    fit_test,
    limit_verdicts,
    one_field,
    target_population,
)
from sass_tui.db.query.query import (
    ParsedQuery,
    QueryError,
    compile_conjuncts,
    parse,
    parsed,
    resolve_field,
)
from sass_tui.db.query.query_tree import And, Comparison, Expr
from sass_tui.model.population.design import Design, DesignError, LimitSpec, SolvedLimit, solve

if TYPE_CHECKING:
    from sass_tui.db.populations.targets import TargetWeights


@dataclass(frozen=True)
class Designed:
    """A solved design: the limits as `sass fit` takes them, and its fit test."""

    percent: float  # the share asked for
    texts: tuple[str, ...]  # every limit, in the order given, solved ones with their values
    solved: tuple[SolvedLimit | None, ...]  # per limit: the solved one, None for a fixed one
    design: Design
    fit: FitResult  # the fit test of `texts` over the same people, same weighting
    weighted_by: str  # who the shares are of

    def to_json(self) -> dict[str, Any]:
        genders = {g: {"percent": _round(s.percent)} for g, s in self.fit.genders.items()}
        limits = []
        for text, limit in zip(self.texts, self.solved):
            entry: dict[str, Any] = {"text": text}
            if limit is not None:
                unit = limit.spec.unit
                entry |= {
                    "measure": limit.spec.field,
                    "low": None if limit.low is None else {"value": limit.low, "unit": unit},
                    "high": None if limit.high is None else {"value": limit.high, "unit": unit},
                    "excluded_below": round(100.0 * limit.excluded_below, 4),
                    "excluded_above": round(100.0 * limit.excluded_above, 4),
                }
            limits.append(entry)
        return {
            "accommodate": self.percent,
            "accommodated": {"percent": _round(self.fit.weighted_percent)} | genders,
            "limits": limits,
            "mix": self.fit.mix,
            "weighted_by": self.weighted_by,
        }


def _round(value: float | None) -> float | None:
    return None if value is None else round(value, 4)


def _is_unknown(c: Comparison) -> bool:
    return isinstance(c.value, float) and math.isnan(c.value)


def limit_spec(text: str, expr: Expr, query: str) -> LimitSpec | None:
    """The term's limit with unknowns, or None for a term without `?`."""
    if not any(_is_unknown(c) for c in expr.comparisons()):
        return None
    comparisons = one_field(expr)
    if comparisons is None:
        raise QueryError(
            f"{text}: a limit with ? is one field's: FIELD <= ?, FIELD >= ?, "
            "FIELD BETWEEN ? AND ? (joined to the other limits by AND)",
            query,
        )
    field = comparisons[0].field
    _table, _column, unit, _words = resolve_field(field.split("."))
    low: float | None = None
    high: float | None = None
    low_strict = high_strict = False
    for c in comparisons:
        value = float(c.value)
        if c.op in (">", ">="):
            low, low_strict = value, c.op == ">"
        else:
            high, high_strict = value, c.op == "<"
    return LimitSpec(field, unit or "", low, high, low_strict, high_strict)


def limit_text(limit: SolvedLimit) -> str:
    """The solved limit as the query language writes it (what `sass fit` takes)."""
    spec = limit.spec
    unit = f" {spec.unit}" if spec.unit else ""

    def number(value: float) -> str:
        return f"{value:.1f}{unit}" if value == round(value, 1) else f"{value:g}{unit}"

    if limit.low is not None and limit.high is not None:
        if not spec.low_strict and not spec.high_strict:
            return f"{spec.field} BETWEEN {number(limit.low)} AND {number(limit.high)}"
        low_op = ">" if spec.low_strict else ">="
        high_op = "<" if spec.high_strict else "<="
        return (
            f"({spec.field} {low_op} {number(limit.low)} AND "
            f"{spec.field} {high_op} {number(limit.high)})"
        )
    if limit.high is not None:
        return f"{spec.field} {'<' if spec.high_strict else '<='} {number(limit.high)}"
    assert limit.low is not None
    return f"{spec.field} {'>' if spec.low_strict else '>='} {number(limit.low)}"


def person_weights(
    gender: npt.NDArray[Any],
    survey: npt.NDArray[np.float64] | None,
    mix: dict[str, float] | None,
) -> npt.NDArray[np.float64]:
    """Each person's weight in the headline share: the survey's (or 1), each
    gender's total then scaled to the mix when there is one (`sass fit`'s
    default without a target: equal genders)."""
    w = np.ones(len(gender)) if survey is None else np.asarray(survey, dtype=float).copy()
    if survey is not None and mix is None:
        return w
    for g, share in check_mix(mix).items():
        mine = gender == g
        total = float(w[mine].sum())
        if total > 0:
            w[mine] *= share / total
    for g in set(gender.tolist()) - set(check_mix(mix)):
        w[gender == g] = 0.0
    return w


def _refuse_an_end_asked_twice(
    terms: Sequence[tuple[str, Expr]], specs: Sequence[LimitSpec | None]
) -> None:
    """`mass <= ? AND mass <= ?` asks one value twice: the two limits would take
    two shares of the exclusion for what is one limit."""
    asked: dict[tuple[str, str], str] = {}
    for (text, _expr), spec in zip(terms, specs):
        if spec is None:
            continue
        for end, value in (("lower", spec.low), ("upper", spec.high)):
            if value is None or not math.isnan(value):
                continue
            if (spec.field, end) in asked:
                raise DesignError(
                    f"{text}: the {end} limit of {spec.field} is asked for twice "
                    f"(also by {asked[spec.field, end]}); ask for it once"
                )
            asked[spec.field, end] = text


def design(
    conn: sqlite3.Connection,
    limits: str | ParsedQuery,
    percent: float,
    population: str | ParsedQuery = DEFAULT_POPULATION,
    mix: dict[str, float] | None = None,
    target: TargetWeights | None = None,
    split: Sequence[float] | None = None,
    range_split: Sequence[float | None] | None = None,
) -> Designed:
    """Solve the `?` of `limits` so that `percent` of the population passes them all."""
    limit_query = limits if isinstance(limits, ParsedQuery) else parse(limits, unknowns=True)
    compile_terms = [(text, expr) for text, expr in limit_query.terms]
    specs_of = [limit_spec(text, expr, limit_query.text) for text, expr in compile_terms]
    designed = [k for k, spec in enumerate(specs_of) if spec is not None]
    if limit_query.or_column is not None:
        compile_conjuncts(limit_query)  # refuses an OR at the top level, pointing at it
    if not designed:
        raise DesignError("no limit has an unknown ?; write e.g. stature <= ? (sass fit checks)")
    _refuse_an_end_asked_twice(compile_terms, specs_of)
    specs = [s for s in specs_of if s is not None]
    if split is not None and len(split) != len(specs):
        raise DesignError(
            f"--split gives {len(split)} share{'s' * (len(split) != 1)} for {len(specs)}"
            f" limit{'s' * (len(specs) != 1)} with a ?; give one each"
        )
    people = target_population(parsed(population), target)
    fields = list(dict.fromkeys(s.field for s in specs))
    values = load_values(conn, fields, people)
    if len(values) == 0:
        raise DesignError(f"the population {people.text!r} selects nobody")
    columns = np.column_stack([values.column(s.field) for s in specs])
    gender = np.array(values.genders, dtype=object)
    fixed = np.ones(len(values), dtype=bool)
    measured = ~np.isnan(columns).any(axis=1)
    fixed_terms = [(t, e) for k, (t, e) in enumerate(compile_terms) if k not in designed]
    if fixed_terms:
        ok, known = _fixed(conn, fixed_terms, people, values.ids)
        fixed &= ok
        measured &= known
    w = person_weights(gender, None if target is None else target.of(values.ids), mix)
    counted = measured & (w > 0)
    solved = solve(
        specs,
        columns[counted],
        w[counted],
        fixed[counted],
        percent,
        split,
        range_split,
    )
    by_term: list[SolvedLimit | None] = [None] * len(compile_terms)
    texts = [text for text, _ in compile_terms]
    for k, limit in zip(designed, solved.limits):
        by_term[k] = limit
        texts[k] = limit_text(limit)
    check = fit_test(conn, " AND ".join(texts), population, mix, target=target)
    weighted_by = (
        "every person alike" if target is None else target.target.words()
    ) + f"; genders: {', '.join(f'{g} {100 * s:.1f} %' for g, s in check.mix.items())}"
    return Designed(percent, tuple(texts), tuple(by_term), solved, check, weighted_by)


def _fixed(
    conn: sqlite3.Connection,
    terms: list[tuple[str, Expr]],
    people: ParsedQuery,
    ids: npt.NDArray[np.int64],
) -> tuple[npt.NDArray[np.bool_], npt.NDArray[np.bool_]]:
    """Per person of `ids`: passes every fixed limit, and is measured for them
    (the fit test's own evaluation of each limit)."""
    query = ParsedQuery(
        " AND ".join(t for t, _ in terms), And(tuple(e for _, e in terms)), tuple(terms), None
    )
    verdict_ids, passes = limit_verdicts(conn, query, people)
    where = np.clip(np.searchsorted(verdict_ids, ids), 0, max(len(verdict_ids) - 1, 0))
    found = (verdict_ids[where] == ids) if len(verdict_ids) else np.zeros(len(ids), dtype=bool)
    rows = passes[where]
    known = found & ~np.isnan(rows).any(axis=1)
    ok = known & (np.nan_to_num(rows, nan=0.0) > 0.5).all(axis=1)
    return ok, known


def _share(value: float | None) -> str:
    return "-" if value is None else f"{value:.1f} %"


def format_design(result: Designed) -> str:
    fit = result.fit
    lines = [
        f"Design for {result.percent:g} % of: {fit.population} ({fit.population_size} people)",
        f"Weighted: {result.weighted_by}",
        "",
    ]
    width = max(len("limit"), *(len(t) for t in result.texts))
    lines.append(f"{'limit':<{width}}  {'excludes below':>14}  {'excludes above':>14}")
    for text, limit in zip(result.texts, result.solved):
        if limit is None:
            lines.append(f"{text:<{width}}  {'(fixed)':>14}  {'':>14}")
            continue
        below = "-" if limit.low is None else _share(100.0 * limit.excluded_below)
        above = "-" if limit.high is None else _share(100.0 * limit.excluded_above)
        lines.append(f"{text:<{width}}  {below:>14}  {above:>14}")
    solving = [s for s in result.design.split if s > 0]
    how = (
        "the weighted quantile"
        if len(solving) == 1 and sum(1 for s in result.solved if s is not None) == 1
        else "exclusion split "
        + ("equally" if len(set(result.design.split)) == 1 else "as --split gives")
        + " between the limits with ?"
    )
    lines += [
        f"Solved: {how}; a range with both ends ? is the shortest for its share; "
        "values rounded outward (0.1)",
        "",
        f"Accommodated (checked with sass fit): {_share(fit.weighted_percent)}   "
        + ", ".join(f"{g} {_share(s.percent)}" for g, s in fit.genders.items()),
    ]
    if fit.not_measured:
        lines.append(f"Not measured for {fit.not_measured} people: left out of every share")
    return "\n".join(lines) + "\n"
