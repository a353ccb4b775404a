"""Design limits solved: the values of `?` limits that accommodate a share of a population.

`sass design` (db/populations/design.py reads the people; this module only
computes, over arrays of values and weights).  The share is the one `sass
fit` reports for the same limits: the weight of the people who pass every
limit over the weight of the people measured for every limit (a person
lacking a value is left out of both, as the fit test does).

The method (docs/accommodation.md, "Design"):

- Each limit with an unknown is given a share of the population to exclude
  on its own (its *marginal* exclusion e_k, over the measured people with
  their weights).  An unknown upper end is the smallest value of a person
  with at most e_k of the weight above it, an unknown lower end the largest
  with at most e_k below it.
- A range with both ends unknown (`BETWEEN ? AND ?`) splits its e_k between
  its ends so that the range is the shortest holding 1 - e_k of the people
  (searched on a grid of 200 splits), unless a split is given.
- The limits' shares are e_k = s * split_k, equal by default (split_k = 1) or
  in the proportions `--split` gives; one scale s is found by bisection so
  that the joint share (the people passing every limit, fixed ones too) is
  the largest design not below the share asked for; where the people's
  weights come in large steps, single ends are then moved inward by one
  person's value at a time while the share stays at or above it.  People fail several
  limits at once, so the e_k add up to more than the share excluded.
- One unknown end and no fixed limit: the weighted quantile itself, exactly
  (Q(PCT) for `<= ?`, Q(100 - PCT) for `>= ?`): model/population/targets.py's
  `weighted_percentile`, the one `sass stats --target` gives.

No database, no printing; numpy only.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt

from sass_tui.model.errors import SassError
from sass_tui.model.population.targets import weighted_percentile

FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]

RANGE_SPLITS: Final = 200  # the grid on which a range's shortest split is searched
BISECTIONS: Final = 60
TIGHTEN_STEPS: Final = 20  # one person's value at a time (_tighten)


class DesignError(ValueError, SassError):
    """A design that cannot be solved (no unknown, a share out of reach)."""


@dataclass(frozen=True)
class LimitSpec:
    """One limit of the design on a numeric field: each end None (no bound),
    a number (fixed) or NaN (unknown, to solve); `strict` ends are < and >."""

    field: str
    unit: str
    low: float | None
    high: float | None
    low_strict: bool = False
    high_strict: bool = False

    @property
    def unknowns(self) -> int:
        return sum(1 for end in (self.low, self.high) if end is not None and math.isnan(end))


@dataclass(frozen=True)
class SolvedLimit:
    spec: LimitSpec
    low: float | None  # the limit's lower end (solved or fixed), None if it has none
    high: float | None
    excluded_below: float  # weighted share (0-1) of the measured people below `low`
    excluded_above: float


@dataclass(frozen=True)
class Design:
    limits: tuple[SolvedLimit, ...]
    share: float  # the joint share (0-1) the solved values accommodate, before rounding
    split: tuple[float, ...]  # each limit's share of the exclusion (sums to 1 over the unknown)


class _Cuts:
    """One column's cuts by weight: `lower(e)`, the largest value with at most
    the share e of the weight below it, and `upper(e)`, the smallest value with
    at most e above it (the people's own values, so the share a limit excludes
    is what was asked as nearly as the people's weights allow)."""

    def __init__(self, values: FloatArray, weights: FloatArray) -> None:
        order = np.argsort(values, kind="stable")
        x, w = values[order], weights[order]
        self.x, first = np.unique(x, return_index=True)
        per_value = np.add.reduceat(w, first)
        cumulative = np.cumsum(per_value) / float(per_value.sum())
        self.through = cumulative  # share at or below each value
        self.before = np.concatenate([[0.0], cumulative[:-1]])  # share below each value

    def lower(self, share: npt.ArrayLike) -> FloatArray:
        e = np.asarray(share, dtype=float)
        k = np.searchsorted(self.before, e + 1e-12, side="right") - 1
        result: FloatArray = self.x[np.clip(k, 0, len(self.x) - 1)]
        return result

    def upper(self, share: npt.ArrayLike) -> FloatArray:
        e = np.asarray(share, dtype=float)
        k = np.searchsorted(self.through, 1.0 - e - 1e-12, side="left")
        result: FloatArray = self.x[np.clip(k, 0, len(self.x) - 1)]
        return result


def _ends(
    spec: LimitSpec, cuts: _Cuts, share: float, low_fraction: float | None
) -> tuple[float | None, float | None]:
    """The limit's ends when it alone excludes `share` (0-1) of the people."""
    low_unknown = spec.low is not None and math.isnan(spec.low)
    high_unknown = spec.high is not None and math.isnan(spec.high)
    if low_unknown and high_unknown:
        if low_fraction is None:
            below = np.linspace(0.0, share, RANGE_SPLITS + 1)
            width = cuts.upper(share - below) - cuts.lower(below)
            a = float(below[int(np.argmin(width))])
        else:
            a = share * low_fraction
        return float(cuts.lower(a)), float(cuts.upper(share - a))
    low = float(cuts.lower(share)) if low_unknown else spec.low
    high = float(cuts.upper(share)) if high_unknown else spec.high
    return low, high


def passes(values: FloatArray, low: float | None, high: float | None, spec: LimitSpec) -> BoolArray:
    """Who passes the limit with these ends (NaN values fail)."""
    ok: BoolArray = ~np.isnan(values)
    with np.errstate(invalid="ignore"):
        if low is not None:
            ok &= values > low if spec.low_strict else values >= low
        if high is not None:
            ok &= values < high if spec.high_strict else values <= high
    return ok


def solve(
    specs: Sequence[LimitSpec],
    columns: FloatArray,
    weights: FloatArray,
    fixed: BoolArray,
    percent: float,
    split: Sequence[float] | None = None,
    range_split: Sequence[float | None] | None = None,
    decimals: int | None = 1,
) -> Design:
    """Solve the unknown ends of `specs` (columns: people x specs, the measured
    people only, NaN nowhere) so that `percent` (0-100) of the weight passes
    every limit and `fixed` (the fixed limits' verdict per person).  `split`:
    each spec's relative share of the exclusion (default equal over the specs
    with an unknown); `range_split`: per spec, the fraction of its share below
    a range (None: the shortest range).  The solved ends are rounded outward
    to `decimals` of their unit (a lower end down, an upper end up: the
    limits as printed accommodate at least the share asked for)."""
    if not 0.0 < percent < 100.0:
        raise DesignError(f"the share to accommodate must lie between 0 and 100 %, not {percent:g}")
    k = len(specs)
    values = np.asarray(columns, dtype=float).reshape(-1, k)
    w = np.asarray(weights, dtype=float)
    if len(w) == 0 or float(w.sum()) <= 0:
        raise DesignError("nobody is measured for every limit")
    target = percent / 100.0
    solving = [s.unknowns > 0 for s in specs]
    if not any(solving):
        raise DesignError("no limit has an unknown ?; write e.g. stature <= ? (sass fit checks)")
    shares = np.array(
        [1.0 if solving[j] else 0.0 for j in range(k)]
        if split is None
        else [float(x) if solving[j] else 0.0 for j, x in enumerate(split)]
    )
    if len(shares) != k or np.any(shares < 0) or not np.isfinite(shares).all():
        raise DesignError("--split: one share >= 0 per limit with a ?")
    if shares.max() <= 0:
        raise DesignError("--split: the shares of the limits with a ? add up to 0")
    shares = shares / shares.max()  # first: 1e308 and 1e308 add up to infinity
    shares = shares / shares.sum()
    fractions = list(range_split) if range_split is not None else [None] * k
    quantiles = [_Cuts(values[:, j], w) if solving[j] else None for j in range(k)]
    total = float(w.sum())

    def design(scale: float) -> list[tuple[float | None, float | None]]:
        out = []
        for j, spec in enumerate(specs):
            q = quantiles[j]
            out.append(
                (spec.low, spec.high)
                if q is None
                else _ends(spec, q, min(1.0, scale * shares[j]), fractions[j])
            )
        return out

    def joint(ends: list[tuple[float | None, float | None]]) -> float:
        ok = fixed.copy()
        for j, (low, high) in enumerate(ends):
            ok &= passes(values[:, j], low, high, specs[j])
        return float(w[ok].sum()) / total

    def finish(ends: list[tuple[float | None, float | None]]) -> Design:
        if decimals is not None:
            ends = [_outward(spec, end, decimals) for spec, end in zip(specs, ends)]
        return _design(specs, values, w, ends, joint(ends), shares)

    if k == 1 and (specs[0].low is None or specs[0].high is None) and bool(fixed.all()):
        # One unknown end and nothing else: the weighted quantile itself.
        column = values[:, 0]
        if specs[0].high is not None:
            return finish([(None, float(weighted_percentile(column, w, [percent])[0]))])
        return finish([(float(weighted_percentile(column, w, [100.0 - percent])[0]), None)])
    best = design(0.0)
    reached = joint(best)
    if reached < target:
        raise DesignError(
            f"the fixed limits alone accommodate {100 * reached:.1f} %, less than {percent:g} %"
        )
    low, high = 0.0, 1.0 / float(shares.max())
    for _ in range(BISECTIONS):
        middle = 0.5 * (low + high)
        ends = design(middle)
        share = joint(ends)
        if share >= target:
            low, best, reached = middle, ends, share
        else:
            high = middle
    return finish(_tighten(specs, quantiles, best, joint, target, reached))


def _tighten(
    specs: Sequence[LimitSpec],
    cuts: Sequence[_Cuts | None],
    ends: list[tuple[float | None, float | None]],
    joint: Callable[[list[tuple[float | None, float | None]]], float],
    target: float,
    reached: float,
) -> list[tuple[float | None, float | None]]:
    """Where people's weights come in steps (a target's few heavy people), the
    split's scale can stop well above the share asked for: move one unknown
    end inward by one person's value at a time while the joint share stays at
    or above the target, each time the move that comes closest to it."""
    for _ in range(TIGHTEN_STEPS):
        best: tuple[float, list[tuple[float | None, float | None]]] | None = None
        for j, spec in enumerate(specs):
            c = cuts[j]
            if c is None:
                continue
            low, high = ends[j]
            moves: list[tuple[float | None, float | None]] = []
            if spec.low is not None and math.isnan(spec.low) and low is not None:
                k = int(np.searchsorted(c.x, low, side="right"))
                if k < len(c.x) and (high is None or c.x[k] <= high):
                    moves.append((float(c.x[k]), high))
            if spec.high is not None and math.isnan(spec.high) and high is not None:
                k = int(np.searchsorted(c.x, high, side="left")) - 1
                if k >= 0 and (low is None or c.x[k] >= low):
                    moves.append((low, float(c.x[k])))
            for move in moves:
                trial = [*ends[:j], move, *ends[j + 1 :]]
                share = joint(trial)
                if target <= share < reached and (best is None or share < best[0]):
                    best = (share, trial)
        if best is None:
            return ends
        reached, ends = best
    return ends


def _design(
    specs: Sequence[LimitSpec],
    values: FloatArray,
    w: FloatArray,
    ends: list[tuple[float | None, float | None]],
    share: float,
    shares: FloatArray,
) -> Design:
    total = float(w.sum())
    solved = []
    for j, (spec, (low, high)) in enumerate(zip(specs, ends)):
        column = values[:, j]
        below = (
            0.0
            if low is None
            else float(w[column < low if not spec.low_strict else column <= low].sum())
        )
        above = (
            0.0
            if high is None
            else float(w[column > high if not spec.high_strict else column >= high].sum())
        )
        solved.append(SolvedLimit(spec, low, high, below / total, above / total))
    return Design(tuple(solved), share, tuple(float(s) for s in shares))


def _outward(
    spec: LimitSpec, ends: tuple[float | None, float | None], decimals: int
) -> tuple[float | None, float | None]:
    """Solved ends rounded outward to `decimals`; fixed ends as they are."""
    scale = 10.0**decimals
    low, high = ends
    if spec.low is not None and math.isnan(spec.low) and low is not None:
        low = math.floor(round(low * scale, 6)) / scale
    if spec.high is not None and math.isnan(spec.high) and high is not None:
        high = math.ceil(round(high * scale, 6)) / scale
    return low, high
