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
  more about the line than a slight one's).

A known value beyond the fitted people is kept and predicted (the line goes
on), unlike `sass predict`, which refuses one 10 SD out; `beyond` counts
them.  numpy only; the random numbers come from the caller's generator, so
the same seed gives the same people.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

# _condition and _pinv are the regression itself: the virtual people must be
# exactly `sass predict`'s prediction plus a residual, so they are shared, not copied.
from sass_tui.model.population.prediction import GenderModel, PredictionError, Z, _condition, _pinv

FloatArray = npt.NDArray[np.float64]
# A conditional variance below this (standardized) is a field the known
# values determine: no residual.
_DETERMINED = 1e-9


@dataclass(frozen=True)
class VirtualPeople:
    gender: str
    fields: tuple[str, ...]  # the model's fields, then its constants
    values: FloatArray  # (people, fields), canonical units
    beyond: int  # people with a known value outside the fitted people's range
    fitted_on: int  # real people the regression was fitted on


def fitted_range(model: GenderModel, name: str) -> tuple[float, float]:
    """The lowest and highest value of `name` among the people `model` was fitted on."""
    i = model.index()[name]
    scores = model.scores[:, i].astype(np.float64)
    return (
        float(scores.min() * model.sd[i] + model.mean[i]),
        float(scores.max() * model.sd[i] + model.mean[i]),
    )


def draw_virtual(
    model: GenderModel,
    names: Sequence[str],
    known: FloatArray,
    rng: np.random.Generator,
) -> VirtualPeople:
    """One virtual person per row of `known` (rows, len(names)): the known
    values kept, every other field of `model` predicted with a residual (see
    the module's docstring).  Every known value must be a positive number."""
    known = np.asarray(known, dtype=float).reshape(-1, len(names))
    index = model.index()
    missing = [n for n in names if n not in index]
    if missing:
        raise PredictionError(f"the prediction model has no field {missing[0]!r}")
    if not (np.isfinite(known) & (known > 0)).all():
        raise PredictionError("every known value of a virtual person must be a number over 0")
    k_idx = [index[n] for n in names]
    z = (known - model.mean[k_idx]) / model.sd[k_idx]
    low = np.array([fitted_range(model, n)[0] for n in names])
    high = np.array([fitted_range(model, n)[1] for n in names])
    spreads: dict[tuple[str, tuple[int, ...]], tuple[FloatArray, FloatArray]] = {}
    mean, _half = _condition(model, k_idx, z, spreads)
    # The scatter is known only where people were measured: beyond them it is
    # held at the edge's (the spread model's squares would grow without end),
    # while the mean goes on along the line.
    edge = (np.clip(known, low, high) - model.mean[k_idx]) / model.sd[k_idx]
    _mean, half = _condition(model, k_idx, edge, spreads)
    # The residuals' correlation given the known fields (standardized).
    cross = model.corr[k_idx]
    inverse, _rank = _pinv(model.corr[np.ix_(k_idx, k_idx)])
    conditional = model.corr - cross.T @ inverse @ cross
    variance = np.diag(conditional)
    free = np.flatnonzero(variance > _DETERMINED)
    # Cholesky of the free fields' block (a tiny ridge for fields the others
    # nearly determine): LAPACK's eigh took 0.3 s on this 93 x 93 matrix here.
    block = conditional[np.ix_(free, free)]
    root = np.linalg.cholesky(block + _DETERMINED * np.eye(len(free)))
    draws = rng.standard_normal((len(known), len(free))) @ root.T
    unit = np.zeros((len(known), len(model.fields)))
    unit[:, free] = draws / np.sqrt(variance[free])
    values = mean + unit * (half / Z)
    values[:, k_idx] = known
    beyond = int(((known < low) | (known > high)).any(axis=1).sum())
    constants = np.broadcast_to(
        np.array(list(model.constants.values()), dtype=float), (len(known), len(model.constants))
    )
    return VirtualPeople(
        gender=model.gender,
        fields=(*model.fields, *model.constants),
        values=np.hstack([values, constants]),
        beyond=beyond,
        fitted_on=model.n,
    )
