"""Target populations: weights that make the real people look like the people
a design is for (docs/target-populations.md).

ANSUR II is soldiers; a product is for civilians.  Parkinson & Reed
("Creating virtual user populations by analysis of anthropometric data",
International Journal of Industrial Ergonomics 40(1), 2010) keep the
detailed real people and weight them so that a few key measurements have
the target's distribution.  The weights here are calibration weights
(Deville & Särndal, "Calibration estimators in survey sampling", JASA 87,
1992) with the exponential (raking) distance of Deville, Särndal & Sautory
("Generalized raking procedures in survey sampling", JASA 88, 1993); the
same solution is known as entropy balancing (Hainmueller, Political
Analysis 20, 2012): of all weights that reproduce the target's

- mean and second moment of each `--by` measurement (its mean and SD),
- cross moment of each pair (their covariance, so the correlation),
- share below each of the sample's 10th, 25th, 50th, 75th and 90th
  percentiles of each measurement (raking on binned marginals), and
- each pair's joint share below both its 25th, both its 50th and both its
  75th percentiles (without them the share under a pair of limits was ~2
  points off: scripts/target_accuracy.py),

the weights closest to equal in Kullback-Leibler divergence,
w_i proportional to exp(lambda . g(x_i)).  lambda minimises the convex dual
log sum_i exp(lambda . (g(x_i) - t)) (t the sample's moments), found by Newton's
method with a backtracking line search.  When no weights reproduce the
target (it lies outside the people: a share the people cannot reach) the
dual has no minimum and the solve is refused; so are weights whose Kish
effective sample size is under MIN_EFFECTIVE (a handful of people standing
for everybody).

Weighted percentiles (`weighted_percentile`) interpolate linearly between
the sorted values at positions made from the cumulative weights; with equal
weights they are numpy's default (Hyndman & Fan's type 7), so the figures of
an unweighted population do not change.  Pure numpy; no database.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Final

import numpy as np
import numpy.typing as npt

from sass_tui.model.errors import SassError

FloatArray = npt.NDArray[np.float64]

MIN_SAMPLE: Final = 30  # sample rows with every --by value
MIN_PEOPLE: Final = 30  # real people with every --by value
CUT_PERCENTILES: Final = (10.0, 25.0, 50.0, 75.0, 90.0)
JOINT_CUTS: Final = [1, 2, 3]  # of CUT_PERCENTILES: the quartiles, for each pair's joint shares
SUMMARY_PERCENTILES: Final = (5.0, 50.0, 95.0)
LOW_EFFECTIVE_SHARE: Final = 0.10  # warn below this Kish size / people
OUTSIDE_WARNING: Final = 0.005  # warn when this share of the target lies beyond the people
# Refuse below this Kish size: a handful of people standing for everybody.
MIN_EFFECTIVE: Final = 30
# The calibration is met when every weighted moment is within this of the
# target (moments of standardised values; shares as fractions).
TOLERANCE: Final = 1e-7
MAX_ITERATIONS: Final = 100


class TargetError(ValueError, SassError):
    """A target that cannot be made as asked; nothing was stored."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


def weighted_percentile(
    values: npt.ArrayLike, weights: npt.ArrayLike | None, percentiles: npt.ArrayLike
) -> FloatArray:
    """The `percentiles` (0-100) of `values` weighted by `weights` (NaN values
    and zero weights left out).  Sorted values x_1..x_n with weights w_k sit
    at positions p_k = (S_k - w_k/2 - w_1/2) / (S_n - w_1/2 - w_n/2), S_k the
    cumulative weight: p_1 = 0, p_n = 1, equal weights give (k-1)/(n-1),
    numpy's linear method.  Empty: NaN."""
    x = np.asarray(values, dtype=float).ravel()
    w = np.ones_like(x) if weights is None else np.asarray(weights, dtype=float).ravel()
    q = np.asarray(percentiles, dtype=float) / 100.0
    keep = ~np.isnan(x) & (w > 0)
    x, w = x[keep], w[keep]
    if len(x) == 0:
        return np.full(q.shape, np.nan)
    if len(x) == 1:
        return np.full(q.shape, x[0])
    order = np.argsort(x, kind="stable")
    x, w = x[order], w[order]
    cumulative = np.cumsum(w)
    position = (cumulative - w / 2 - w[0] / 2) / (cumulative[-1] - w[0] / 2 - w[-1] / 2)
    result: FloatArray = np.interp(q, position, x)
    return result


def kish_effective_n(weights: npt.ArrayLike) -> float:
    """Kish's effective sample size (sum w)^2 / sum w^2 (Kish, Survey Sampling, 1965)."""
    w = np.asarray(weights, dtype=float)
    squares = float(np.sum(w * w))
    return float(np.sum(w)) ** 2 / squares if squares > 0 else 0.0


@dataclass(frozen=True)
class Summary:
    """Mean, SD and the 5th/50th/95th percentile of one measurement."""

    mean: float
    sd: float
    p5: float
    p50: float
    p95: float

    @classmethod
    def of(cls, values: FloatArray, weights: FloatArray | None = None) -> Summary:
        w = np.ones_like(values) if weights is None else weights
        total = float(w.sum())
        mean = float(np.sum(w * values)) / total
        # The SD of the weighted people as a population (weights as frequencies).
        sd = math.sqrt(max(0.0, float(np.sum(w * (values - mean) ** 2)) / total))
        p5, p50, p95 = (float(v) for v in weighted_percentile(values, w, SUMMARY_PERCENTILES))
        return cls(mean, sd, p5, p50, p95)

    def as_list(self) -> list[float]:
        return [self.mean, self.sd, self.p5, self.p50, self.p95]


@dataclass(frozen=True)
class MeasureCheck:
    """One --by measurement: the target's (the sample's), the weighted people's
    and the unweighted people's summary."""

    field: str
    target: Summary
    weighted: Summary
    unweighted: Summary
    # The share of the target's weight beyond every person's value (below the
    # lightest, above the heaviest): no weighting of the people reaches it.
    outside_share: float = 0.0


@dataclass(frozen=True)
class Weighting:
    fields: tuple[str, ...]
    weights: FloatArray  # (people,), mean 1 over the people used
    used: npt.NDArray[np.bool_]  # (people,): has every --by value (others weigh 0)
    sample_rows: int
    checks: tuple[MeasureCheck, ...]
    iterations: int

    @property
    def people(self) -> int:
        return int(self.used.sum())

    @property
    def effective_n(self) -> float:
        return kish_effective_n(self.weights[self.used])

    def warnings(self) -> list[str]:
        """Where the target lies outside the people (the weights still match it)."""
        out = []
        share = self.effective_n / self.people
        if share < LOW_EFFECTIVE_SHARE:
            out.append(
                f"the effective sample size {self.effective_n:.0f} is {100 * share:.1f} % of "
                f"the {self.people} people (under {100 * LOW_EFFECTIVE_SHARE:.0f} %): the target "
                "lies largely outside them, a few people carry most of the weight"
            )
        for check in self.checks:
            if check.outside_share >= OUTSIDE_WARNING:
                out.append(
                    f"{check.field}: {100 * check.outside_share:.1f} % of the target's weight "
                    "lies beyond every person's value; weighting cannot reach it (a virtual "
                    "population can: sass target --virtual)"
                )
            for word, goal, got in (
                ("5th", check.target.p5, check.weighted.p5),
                ("95th", check.target.p95, check.weighted.p95),
            ):
                if abs(goal - got) > 0.25 * check.target.sd:
                    out.append(
                        f"{check.field}: the target's {word} percentile {goal:.1f} is beyond "
                        f"what the weighted people reach ({got:.1f})"
                    )
        return out


def _features(
    x: FloatArray, center: FloatArray, scale: FloatArray, cuts: list[FloatArray]
) -> FloatArray:
    """The calibration variables g(x) of each row (see the module docstring)."""
    z = (x - center) / scale
    k = z.shape[1]
    columns = [z[:, i] for i in range(k)]
    columns += [z[:, i] * z[:, j] for i in range(k) for j in range(i, k)]
    below = [x[:, i, None] <= cuts[i][None, :] for i in range(k)]
    columns += [b.astype(float).T for b in below]
    # Each pair's joint share below both of its quartiles (25th, 50th, 75th).
    # Very unequal survey weights make cuts coincide (np.unique leaves fewer):
    # the pair is then asked of the cuts both still have, the same for the
    # sample and the people (a 60-row sample raised IndexError here).
    for i in range(k):
        for j in range(i + 1, k):
            both = [c for c in JOINT_CUTS if c < min(len(cuts[i]), len(cuts[j]))]
            joint = below[i][:, both] & below[j][:, both]
            columns.append(joint.astype(float).T)
    flat: list[FloatArray] = []
    for column in columns:
        flat.extend(column if column.ndim == 2 else [column])
    return np.column_stack(flat)


def outside_share(people: FloatArray, sample: FloatArray, weights: FloatArray) -> float:
    """The share of the sample's weight whose value lies outside the range of
    `people` (NaN left out of both): the honest limit of weighting them."""
    known = people[~np.isnan(people)]
    keep = ~np.isnan(sample)
    total = float(weights[keep].sum())
    if len(known) == 0 or total <= 0:
        return math.nan
    beyond = keep & ((sample < known.min()) | (sample > known.max()))
    return float(weights[beyond].sum()) / total


def calibrate(
    fields: Sequence[str],
    people: FloatArray,
    sample: FloatArray,
    *,
    where: str = "the sample",
    sample_weights: FloatArray | None = None,
    within_range: bool = False,
) -> Weighting:
    """Weights for the rows of `people` (people x fields, NaN = not measured)
    that reproduce the joint moments and marginal shares of `sample` (rows x
    fields, complete), each sample row counted by its `sample_weights` (a
    survey's weights; None: equally).  `within_range`: match only the sample
    rows inside the people's range of every field (the part weighting can
    reach; `outside_share` says how much of each field is beyond).
    TargetError when the sample or the people are too few or the target
    cannot be reached."""
    fields = tuple(fields)
    people = np.asarray(people, dtype=float)
    sample = np.asarray(sample, dtype=float)
    sw = np.ones(len(sample)) if sample_weights is None else np.asarray(sample_weights, float)
    beyond = [outside_share(people[:, i], sample[:, i], sw) for i in range(len(fields))]
    full = sample, sw
    if within_range and len(sample) and np.isfinite(people).all(axis=1).any():
        known = people[np.isfinite(people).all(axis=1)]
        inside = ((sample >= known.min(axis=0)) & (sample <= known.max(axis=0))).all(axis=1)
        sample, sw = sample[inside], sw[inside]
    if len(sample) < MIN_SAMPLE:
        raise TargetError(
            f"{where}: {len(sample)} rows have every one of {', '.join(fields)}; "
            f"a target needs at least {MIN_SAMPLE}",
            where=where,
        )
    used = np.asarray(~np.isnan(people).any(axis=1), dtype=bool)
    x = people[used]
    if len(x) < MIN_PEOPLE:
        raise TargetError(
            f"only {len(x)} people have every one of {', '.join(fields)}; "
            f"a target needs at least {MIN_PEOPLE}"
        )
    center, scale = x.mean(axis=0), x.std(axis=0)
    for field, s, spread in zip(fields, scale, sample.std(axis=0)):
        if s <= 0 or spread <= 0:
            who = "the people" if s <= 0 else where
            raise TargetError(f"{field}: every one of {who} has the same value", where=where)
    cuts = [
        np.unique(weighted_percentile(sample[:, i], sw, CUT_PERCENTILES))
        for i in range(len(fields))
    ]
    _reachable(fields, x, sample, cuts, where)
    g = _features(x, center, scale, cuts)
    goal = np.average(_features(sample, center, scale, cuts), axis=0, weights=sw)
    lam, iterations = _solve(g - goal, fields, where)
    exponent = (g - goal) @ lam
    w = np.exp(exponent - exponent.max())
    w *= len(w) / w.sum()
    effective = kish_effective_n(w)
    if effective < MIN_EFFECTIVE:
        raise TargetError(
            f"{where}: the target lies outside the people: the weights that match it leave "
            f"an effective sample size of {effective:.0f} of {len(w)} people (at least "
            f"{MIN_EFFECTIVE} needed); nothing stored",
            where=where,
        )
    weights = np.zeros(len(people))
    weights[used] = w
    checks = tuple(
        MeasureCheck(
            field,
            Summary.of(full[0][:, i], full[1]),
            Summary.of(x[:, i], w),
            Summary.of(x[:, i]),
            beyond[i],
        )
        for i, field in enumerate(fields)
    )
    return Weighting(fields, weights, used, len(full[0]), checks, iterations)


def _reachable(
    fields: tuple[str, ...],
    x: FloatArray,
    sample: FloatArray,
    cuts: list[FloatArray],
    where: str,
) -> None:
    """A target whose 10th or 90th percentile lies beyond every person cannot be met."""
    for i, field in enumerate(fields):
        low, high = float(x[:, i].min()), float(x[:, i].max())
        if cuts[i][0] < low or cuts[i][-1] >= high:
            raise TargetError(
                f"{where}: {field}: the target lies outside the people: its 10th-90th percentiles "
                f"run {cuts[i][0]:.1f}-{cuts[i][-1]:.1f}, the people's values "
                f"{low:.1f}-{high:.1f}; nothing stored",
                where=where,
            )


def _solve(d: FloatArray, fields: tuple[str, ...], where: str) -> tuple[FloatArray, int]:
    """lambda minimising log mean exp(d @ lambda) (d = g(x) - t): Newton's method,
    halving the step until the dual decreases.  Its gradient is the weighted
    mean of d, zero when the calibration is met."""
    lam = np.zeros(d.shape[1])

    def dual(at: FloatArray) -> tuple[float, FloatArray]:
        e = d @ at
        top = float(e.max())
        p = np.exp(e - top)
        total = float(p.sum())
        return top + math.log(total / len(e)), p / total

    value, p = dual(lam)
    for iteration in range(1, MAX_ITERATIONS + 1):
        gradient = p @ d
        if float(np.abs(gradient).max()) < TOLERANCE:
            return lam, iteration - 1
        centred = d - gradient
        hessian = (centred * p[:, None]).T @ centred
        hessian += 1e-10 * np.eye(len(lam))  # ties make cut shares dependent
        step = np.linalg.lstsq(hessian, -gradient, rcond=None)[0]
        size = 1.0
        while size > 1e-8:
            trial = lam + size * step
            trial_value, trial_p = dual(trial)
            if trial_value <= value + 1e-4 * size * float(gradient @ step):
                lam, value, p = trial, trial_value, trial_p
                break
            size /= 2
        else:
            break
    gradient = p @ d
    if float(np.abs(gradient).max()) < 1e3 * TOLERANCE:
        return lam, MAX_ITERATIONS
    raise TargetError(
        f"{where}: the target lies outside the people: no weighting of them reproduces the "
        f"distribution of {', '.join(fields)} in {where}; nothing stored",
        where=where,
    )
