"""Virtual people: civilians' own stature and mass, every other measure
predicted from them with its residual scatter (docs/target-populations.md).

Parkinson & Reed ("Creating virtual user populations by analysis of
anthropometric data", International Journal of Industrial Ergonomics 40(1),
2010, 106-111) keep each person of a large civilian survey that measured a
few dimensions, predict the dimensions it did not measure by regression on a
detailed survey, and add a residual drawn from the regression's own scatter,
so that the virtual people vary about the prediction as real people do.

Here the regression is sass's (model/population/prediction.py: the conditional normal
of one gender's real people, fitted on ANSUR II by default), and the
residual of each virtual person is drawn

- jointly over every predicted field, from the conditional correlation
  R_UU - R_UK R_KK^-1 R_KU of the fields given the known ones (a person with
  a long arm has a long forearm too; independent residuals would lose it),
- at the person's own scale: each field's residual is scaled to the
  heteroscedastic prediction SD at that person's known values (the 90 %
  half-width of `_condition` over z(0.95): a heavy person's girths scatter
  more about the line than a slight one's), with the scatter bounded where
  the data end: the scale is taken at the known values clamped to the
  fitted people's range (the edge's), and never above the scale the model
  gives the fitted people themselves at its 90th percentile (`CAP`;
  Harvey's log-quadratic trend, fitted inside the data, would grow without
  end outside them: civilian women 160-165 cm over 120 kg got popliteal
  heights scattered by 4.2 cm, three times the soldiers').

The known values may differ from row to row (NaN: a value the row lacks; a
civilian survey misses a hip here and there): a missing one is drawn first
from the values the row has (`_fill`: the conditional normal, its scatter
without the spread model), then every row is predicted from every name in
one solve, as a joint draw in two steps.  A known value beyond the fitted people is kept and predicted
(the line goes on), unlike `sass predict`, which refuses one 10 SD out; the
person is flagged (`outside`) and `beyond` counts them.  A `held` field
(age: ANSUR II's soldiers are 17-58) enters the prediction clamped to the
fitted range and flags nobody.  numpy only; the random numbers come from the
caller's generator, so the same seed gives the same people.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

# _condition and _pinv are the regression itself: the virtual people must be
# exactly `sass predict`'s prediction plus a residual, so they are shared, not copied.
from sass_tui.model.population.prediction import GenderModel, PredictionError, Z, _condition, _pinv

FloatArray = npt.NDArray[np.float64]
# A conditional variance below this (standardized) is a field the known
# values determine: no residual.
_DETERMINED = 1e-9
# The residual scale is capped at this quantile of the scales the model
# gives the people it was fitted on (at their own known values).
CAP = 0.90


@dataclass(frozen=True)
class VirtualPeople:
    gender: str
    fields: tuple[str, ...]  # the model's fields, then its constants
    values: FloatArray  # (people, fields), canonical units
    beyond: int  # people with a known value outside the fitted people's range
    fitted_on: int  # real people the regression was fitted on
    # per person: a known value (not a held one) outside the fitted people's range
    outside: npt.NDArray[np.bool_] = field(default_factory=lambda: np.zeros(0, dtype=bool))


def fitted_range(model: GenderModel, name: str) -> tuple[float, float]:
    """The lowest and highest value of `name` among the people `model` was fitted on."""
    i = model.index()[name]
    scores = model.scores[:, i].astype(np.float64)
    # rounded: the scores are float32, and a civilian exactly as tall as the
    # tallest soldier is not beyond him (measures are printed to 0.1 mm)
    return (
        round(float(scores.min() * model.sd[i] + model.mean[i]), 4),
        round(float(scores.max() * model.sd[i] + model.mean[i]), 4),
    )


def draw_virtual(
    model: GenderModel,
    names: Sequence[str],
    known: FloatArray,
    rng: np.random.Generator,
    *,
    held: Sequence[str] = (),
) -> VirtualPeople:
    """One virtual person per row of `known` (rows, len(names)): the known
    values kept, every other field of `model` predicted with a residual (see
    the module's docstring).  A known value is a number over 0, or NaN where
    the row lacks it (predicted then); `held` names known fields that enter
    the prediction clamped to the fitted people's range."""
    known = np.asarray(known, dtype=float).reshape(-1, len(names))
    index = model.index()
    missing = [n for n in names if n not in index]
    if missing:
        raise PredictionError(f"the prediction model has no field {missing[0]!r}")
    present = ~np.isnan(known)
    if not (np.isfinite(known[present]) & (known[present] > 0)).all():
        raise PredictionError("every known value of a virtual person must be a number over 0")
    k_all = [index[n] for n in names]
    ranges = np.array([fitted_range(model, n) for n in names]).reshape(len(names), 2)
    is_held = np.array([n in held for n in names], dtype=bool)
    outside = ((known < ranges[:, 0]) | (known > ranges[:, 1])) & present & ~is_held
    # A value a row lacks is drawn first, from the values it has (the
    # regression's mean and its conditional scatter); then every row is one
    # solve from every name (a joint draw, done in two steps).
    filled = _fill(model, k_all, np.where(is_held, np.clip(known, *ranges.T), known), rng)
    edge = np.clip(filled, ranges[:, 0], ranges[:, 1])
    given = np.where(is_held, edge, filled)
    spreads: dict[tuple[str, tuple[int, ...]], tuple[FloatArray, FloatArray]] = {}
    values = _draw(model, k_all, given, edge, rng, spreads)
    for c, k in enumerate(k_all):
        values[:, k] = np.where(present[:, c], known[:, c], filled[:, c])
    constants = np.broadcast_to(
        np.array(list(model.constants.values()), dtype=float), (len(known), len(model.constants))
    )
    flagged = outside.any(axis=1)
    return VirtualPeople(
        gender=model.gender,
        fields=(*model.fields, *model.constants),
        values=np.hstack([values, constants]),
        beyond=int(flagged.sum()),
        fitted_on=model.n,
        outside=flagged,
    )


def _fill(
    model: GenderModel, k_idx: list[int], known: FloatArray, rng: np.random.Generator
) -> FloatArray:
    """`known` (rows, k) with each NaN drawn from the values its row has:
    the conditional normal of the model's correlation (its mean, and its
    conditional SD, without the spread model: these are a survey's few
    missing cells).  A row lacking every value is refused."""
    out = known.copy()
    present = ~np.isnan(known)
    codes = present.astype(np.int64) @ (np.int64(1) << np.arange(len(k_idx), dtype=np.int64))
    for code in np.unique(codes[~present.all(axis=1)]):
        rows = np.flatnonzero(codes == code)
        has = np.flatnonzero(present[rows[0]])
        lacks = np.flatnonzero(~present[rows[0]])
        if len(has) == 0:
            raise PredictionError("a virtual person needs at least one known value")
        h = [k_idx[c] for c in has]
        m = [k_idx[c] for c in lacks]
        inverse, _rank = _pinv(model.corr[np.ix_(h, h)])
        coef = inverse @ model.corr[np.ix_(h, m)]
        z = (known[np.ix_(rows, has)] - model.mean[h]) / model.sd[h]
        scatter = model.corr[np.ix_(m, m)] - model.corr[np.ix_(m, h)] @ coef
        root = np.linalg.cholesky(scatter + _DETERMINED * np.eye(len(m)))
        drawn = z @ coef + rng.standard_normal((len(rows), len(m))) @ root.T
        out[np.ix_(rows, lacks)] = drawn * model.sd[m] + model.mean[m]
    return out


def _draw(
    model: GenderModel,
    k_idx: list[int],
    given: FloatArray,
    edge: FloatArray,
    rng: np.random.Generator,
    spreads: dict[tuple[str, tuple[int, ...]], tuple[FloatArray, FloatArray]],
) -> FloatArray:
    """Rows of every field predicted from the known fields `k_idx` at values
    `given` (canonical units), plus a residual drawn at the scale of `edge`
    (the known values clamped to the fitted range), capped at CAP."""
    mean_k, sd_k = model.mean[k_idx], model.sd[k_idx]
    cross = model.corr[k_idx]
    inverse, _rank = _pinv(model.corr[np.ix_(k_idx, k_idx)])
    # the regression's mean at the given values (_condition's, without its spread)
    mean = ((given - mean_k) / sd_k) @ (inverse @ cross * model.sd) + model.mean
    # The scatter is known only where people were measured: beyond them it is
    # held at the edge's, while the mean goes on along the line; and the
    # trend is capped at the scale most fitted people have.
    _mean, half = _condition(model, k_idx, (edge - mean_k) / sd_k, spreads)
    _fitted, own = _condition(model, k_idx, model.scores[:, k_idx].astype(np.float64), spreads)
    half = np.minimum(half, np.quantile(np.ascontiguousarray(own.T), CAP, axis=1))
    # The residuals' correlation given the known fields (standardized).
    conditional = model.corr - cross.T @ inverse @ cross
    variance = np.diag(conditional)
    free = np.flatnonzero(variance > _DETERMINED)
    # Cholesky of the free fields' block (a tiny ridge for fields the others
    # nearly determine): LAPACK's eigh took 0.3 s on this 93 x 93 matrix here.
    block = conditional[np.ix_(free, free)]
    root = np.linalg.cholesky(block + _DETERMINED * np.eye(len(free)))
    draws = rng.standard_normal((len(given), len(free))) @ root.T
    unit = np.zeros((len(given), len(model.fields)))
    unit[:, free] = draws / np.sqrt(variance[free])
    out: FloatArray = mean + unit * (half / Z)
    return out
