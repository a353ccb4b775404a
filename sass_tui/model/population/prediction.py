"""Predict a person's unmeasured values from the few that are known.

Given any subset of a person's values (stature, mass, any `measure.<name>`,
any girth or center-of-mass cell), every other value is predicted by
conditional regression on the real people of the same gender (ANSUR II in
the default database), with a 90 % prediction interval.

The method: the values of one gender are treated as one multivariate normal
vector on standardized data.  The fit is just the means, standard deviations
and correlation matrix; a prediction conditions it on the known values,

    mean(U | K) = mu_U + S_UK S_KK^-1 (x_K - mu_K),

which is exactly ordinary least squares of every unknown on the known values
(with an intercept) fitted on the same people, but costs one k x k solve
instead of a fit, so any subset of known names can be asked for without
refitting.  The interval's half-width is a residual scale that depends on
the known values (the log squared residuals of the training people
regressed on the known values and their squares: a heavy person's interval
is wider than a slight one's, so the intervals cover 90 % in every BMI
decile, not only on average) times Student's t quantile t(0.95, n - k - 1)
(z(0.95) for many people, wider for a fit on few) and the root mean square of the
training residuals over that scale, widened for degrees of freedom and for
the distance of the known values from the population mean as the OLS
prediction variance s^2 (1 + 1/n + d^2/(n-1)) is (d the Mahalanobis
distance of the known values); see _condition and _spread.  The spread
model of a set of known names is fitted on the first prediction from them
(one pass over the training people) and kept for the next.
Collinear known values (a girth cell and the measurement it is derived from)
are handled by a pseudo-inverse.  docs/accuracy.md measures what this gives
(`scripts/accuracy.py`): error against percentile matching, and the
coverage the intervals reach on held-out people.

The fit holds the standardized people too, for the k nearest real people
(standardized distance over the known values) and for the exact
leave-one-out cross-validation RMSE of a set of known names (PRESS).

numpy only; no database access here (`sass_tui.db` loads the training
values, computes the cache key and calls `Predictor.fit` / `load` / `save`).
"""

from __future__ import annotations

import difflib
import math
import os
import re
import tempfile
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from statistics import NormalDist
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.body_measures import SURFACE_MEASURES
from sass_tui.model.errors import SassError
from sass_tui.model.measures import MEASURE_UNITS, MEASURES
from sass_tui.model.names import (
    AXES,
    CENTER_OF_MASS,
    CENTER_OF_MASS_ROWS,
    GIRTH,
    GIRTH_ROWS,
    JOINT_LIMITS,
    ROWS,
)
from sass_tui.model.population.student_t import t_quantile
from sass_tui.model.units import UnitError, parse_quantity
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure

FloatArray = npt.NDArray[np.float64]

# Bump when the fit's content or file layout changes: old cache files are then rebuilt.
MODEL_VERSION = 1
LEVEL = 0.90
Z = NormalDist().inv_cdf(0.5 + LEVEL / 2)
# A known value this many SD from the population mean is refused; for a
# length or mass below the mean, this many SD on the log scale (see
# Predictor._check_outliers).
MAX_SD = 10.0
MIN_PEOPLE = 30  # fewer complete people of a gender than this: no model
# ANSUR II's own columns for what the person table holds as stature and mass.
ALIASES: dict[str, str] = {"measure.stature": "stature", "measure.weightkg": "mass"}
# Relative eigenvalue below which the known values are taken as collinear.
_RCOND = 1e-10


class PredictionError(ValueError, SassError):
    """A prediction that cannot be made as asked; nothing was computed."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


class UnknownFieldError(PredictionError):
    """A known value's name is not one the model knows."""


class FieldUnitError(PredictionError):
    """A known value is not a number, or carries a unit of the wrong kind."""


class OutlierError(PredictionError):
    """A known value lies MAX_SD or more standard deviations from the population
    (a length or mass below its mean: on the log scale)."""


class NoDataError(PredictionError):
    """No (or too few) people of the gender to predict from."""


class TrainingValues(Protocol):
    """What the fit reads: `sass_tui.db.people.values.Values` has this shape."""

    @property
    def ids(self) -> npt.ArrayLike: ...  # (people,) whole numbers

    @property
    def names(self) -> Sequence[str]: ...

    @property
    def genders(self) -> Sequence[str]: ...

    @property
    def matrix(self) -> npt.NDArray[Any]: ...  # (people, fields), canonical units, NaN = none


# --- names ----------------------------------------------------------------


def predicted_fields() -> tuple[str, ...]:
    """Every value the model can know or predict, named as in the query language."""
    measures = [f"measure.{m}" for m in MEASURES if f"measure.{m}" not in ALIASES]
    cells = [
        f"{group}.{row.name}.{axis}"
        for group, rows in ((GIRTH, GIRTH_ROWS), (CENTER_OF_MASS, CENTER_OF_MASS_ROWS))
        for row in rows
        for axis in AXES
    ]
    return ("stature", "mass", *measures, *cells)


def field_unit(name: str) -> str:
    """The canonical unit of a field ("kg" for mass, "cm" for every length)."""
    name = ALIASES.get(name, name)
    if name == "mass":
        return "kg"
    if name.startswith("measure."):
        return MEASURE_UNITS[name.removeprefix("measure.")]
    return "cm"


def split_known(text: str) -> list[tuple[str, str]]:
    """'stature=180 cm, mass=85kg' -> [("stature", "180 cm"), ("mass", "85kg")]
    (items separated by commas or semicolons; what the TUI's input line takes)."""
    pairs = []
    for item in re.split(r"[;,]", text):
        if not item.strip():
            continue
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise PredictionError(
                f"{item.strip()!r}: expected NAME=VALUE, e.g. stature=175cm", where=item.strip()
            )
        pairs.append((name.strip(), value.strip()))
    return pairs


def _check_gender(gender: str) -> str:
    word = str(gender).strip().lower()
    if word not in GENDERS:
        raise PredictionError(f"gender must be {' or '.join(GENDERS)}, not {gender!r}")
    return word


# --- the fit of one gender ------------------------------------------------


@dataclass(frozen=True)
class GenderModel:
    """Means, SDs and correlations of one gender's fields, and its people standardized.

    `fields` are the fields that vary; `constants` those every person has
    with one value (ANSUR II's clavicle thickness, 1 cm by derivation).
    """

    gender: str
    fields: tuple[str, ...]
    mean: FloatArray  # (p,)
    sd: FloatArray  # (p,)
    corr: FloatArray  # (p, p)
    ids: npt.NDArray[np.int64]  # (n,)
    names: tuple[str, ...]  # (n,)
    scores: npt.NDArray[np.float32]  # (n, p) standardized values
    constants: dict[str, float] = field(default_factory=dict)

    @property
    def n(self) -> int:
        return len(self.ids)

    def index(self) -> dict[str, int]:
        return {name: i for i, name in enumerate(self.fields)}

    @classmethod
    def fit(cls, gender: str, fields: Sequence[str], data: TrainingValues) -> GenderModel:
        rows = np.array([g == gender for g in data.genders], dtype=bool)
        matrix = np.asarray(data.matrix, dtype=float)[rows]
        if not rows.any():
            raise NoDataError(f"no {gender} people in the database to predict from")
        # Fields most people of the gender have; then the people complete in them.
        present = np.isfinite(matrix)
        usable = present.mean(axis=0) >= 0.5
        complete = present[:, usable].all(axis=1)
        matrix = matrix[complete][:, usable]
        kept = [f for f, use in zip(fields, usable) if use]
        if len(matrix) < MIN_PEOPLE:
            raise NoDataError(
                f"only {len(matrix)} {gender} people in the database have every value "
                f"the prediction needs; at least {MIN_PEOPLE} are needed"
            )
        mean = matrix.mean(axis=0)
        sd = matrix.std(axis=0, ddof=1)
        varies = sd > 1e-9 * np.maximum(1.0, np.abs(mean))
        constants = {f: float(m) for f, m, v in zip(kept, mean, varies) if not v}
        mean, sd, matrix = mean[varies], sd[varies], matrix[:, varies]
        scores = (matrix - mean) / sd
        corr = scores.T @ scores / (len(scores) - 1)
        np.fill_diagonal(corr, 1.0)
        ids = np.asarray(data.ids, dtype=np.int64)[rows][complete]
        names = tuple(n for n, r in zip(np.asarray(data.names, dtype=object)[rows], complete) if r)
        return cls(
            gender=gender,
            fields=tuple(f for f, v in zip(kept, varies) if v),
            mean=mean,
            sd=sd,
            corr=corr,
            ids=ids,
            names=tuple(str(n) for n in names),
            scores=scores.astype(np.float32),
            constants=constants,
        )


# --- results ----------------------------------------------------------------


@dataclass(frozen=True)
class Estimate:
    """One field's value with its 90 % prediction interval (canonical unit).

    A known value is returned as given, with low = high = value."""

    value: float
    low: float
    high: float
    unit: str
    known: bool = False


@dataclass(frozen=True)
class Neighbour:
    id: int
    name: str
    distance: float  # root of the summed squared z-differences over the known fields


@dataclass(frozen=True)
class Prediction:
    gender: str
    known: dict[str, float]  # field -> value as given (canonical units)
    values: dict[str, Estimate]  # every field, known ones included
    nearest: list[Neighbour]
    n: int  # people the model was fitted on

    @property
    def predicted(self) -> dict[str, Estimate]:
        return {name: e for name, e in self.values.items() if not e.known}

    def value(self, name: str) -> float:
        estimate = self.values.get(ALIASES.get(name, name))
        return math.nan if estimate is None else estimate.value

    @property
    def stature(self) -> float:
        return self.value("stature")

    @property
    def mass(self) -> float:
        return self.value("mass")

    def group_values(self, group: str, bound: str = "value") -> FloatArray:
        """A girth or center-of-mass group as (rows, 3) for `Figure.for_person`;
        NaN where the model has no value (the figure fills those from the
        population).  `bound` "low" or "high" gives the interval's ends instead
        (a known cell: its value)."""
        rows = {GIRTH: GIRTH_ROWS, CENTER_OF_MASS: CENTER_OF_MASS_ROWS}[group]
        out = np.full((len(rows), 3), np.nan)
        for r, row in enumerate(rows):
            for a, axis in enumerate(AXES):
                estimate = self.values.get(f"{group}.{row.name}.{axis}")
                if estimate is not None:
                    out[r, a] = getattr(estimate, bound)
        return out

    def figure(self, base: Figure) -> Figure:
        """The predicted person as a figure (like Disp. Indv.): girth and center
        of mass from the prediction, percentiles against `base`'s population,
        joint limits and any cell without a prediction from that population at
        output.  `base` is left unchanged, so Disp. Pop. returns to it."""
        figure = base.for_person(
            self.label(),
            self.gender,
            {
                GIRTH: self.group_values(GIRTH),
                JOINT_LIMITS: np.full((len(ROWS[JOINT_LIMITS]), 3), np.nan),
                CENTER_OF_MASS: self.group_values(CENTER_OF_MASS),
            },
            mass=self.mass,
            stature=self.stature,
        )
        # the body's surface goes through the measurements predicted here
        # (model/body/body_measures.py), known ones included
        figure.predicted_measures = {
            name: value
            for name in SURFACE_MEASURES
            if math.isfinite(value := self.value(f"measure.{name}"))
        }
        return figure

    def label(self) -> str:
        """'predicted from stature 180 cm, mass 85 kg' (the population label of the figure)."""
        parts = [f"{name} {value:g} {field_unit(name)}" for name, value in self.known.items()]
        return "predicted from " + ", ".join(parts)


# --- the predictor ------------------------------------------------------------


class Predictor:
    """The fit of every gender with data; `predict` conditions it on known values."""

    def __init__(self, models: Mapping[str, GenderModel], key: str = "") -> None:
        self.models = dict(models)
        self.key = key
        # the residual spread model of each (gender, known fields) asked for
        # (_spread): fitted on the first prediction from those names, reused after
        self._spreads: dict[tuple[str, tuple[int, ...]], Spread] = {}

    @classmethod
    def fit(cls, data: TrainingValues, fields: Sequence[str], key: str = "") -> Predictor:
        """Fit every gender that has at least MIN_PEOPLE complete people."""
        fields = tuple(fields)
        if np.shape(data.matrix)[1:] != (len(fields),):
            raise ValueError(f"matrix has shape {np.shape(data.matrix)}, fields {len(fields)}")
        models: dict[str, GenderModel] = {}
        for gender in GENDERS:
            try:
                models[gender] = GenderModel.fit(gender, fields, data)
            except NoDataError:
                continue
        return cls(models, key)

    # --- the cache file -------------------------------------------------
    def save(self, path: str | Path) -> Path:
        """Write the fit to `path` (.npz) atomically."""
        path = Path(path)
        arrays: dict[str, npt.NDArray[np.generic]] = {
            "version": np.array(MODEL_VERSION),
            "key": np.array(self.key),
            "genders": np.array(sorted(self.models)),
        }
        for gender, m in self.models.items():
            arrays |= {
                f"{gender}.fields": np.array(m.fields),
                f"{gender}.mean": m.mean,
                f"{gender}.sd": m.sd,
                f"{gender}.corr": m.corr,
                f"{gender}.ids": m.ids,
                f"{gender}.names": np.array(m.names),
                f"{gender}.scores": m.scores,
                f"{gender}.constant_fields": np.array(list(m.constants), dtype=str),
                f"{gender}.constant_values": np.array(list(m.constants.values()), dtype=float),
            }
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
        try:
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(tmp, 0o666 & ~umask)  # mkstemp makes it private; a cache need not be
            with os.fdopen(fd, "wb") as handle:
                np.savez(handle, **arrays)  # type: ignore[arg-type]
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(tmp, path)
        except BaseException:
            Path(tmp).unlink(missing_ok=True)
            raise
        return path

    @classmethod
    def load(cls, path: str | Path, key: str) -> Predictor | None:
        """The fit saved at `path` if it was made by this version from data with
        this key; None when the file is absent, stale or unreadable."""
        try:
            with np.load(path, allow_pickle=False) as f:
                if int(f["version"]) != MODEL_VERSION or str(f["key"]) != key:
                    return None
                models = {}
                for gender in (str(g) for g in f["genders"]):
                    models[gender] = GenderModel(
                        gender=gender,
                        fields=tuple(str(s) for s in f[f"{gender}.fields"]),
                        mean=f[f"{gender}.mean"],
                        sd=f[f"{gender}.sd"],
                        corr=f[f"{gender}.corr"],
                        ids=f[f"{gender}.ids"],
                        names=tuple(str(s) for s in f[f"{gender}.names"]),
                        scores=f[f"{gender}.scores"],
                        constants=dict(
                            zip(
                                (str(s) for s in f[f"{gender}.constant_fields"]),
                                (float(v) for v in f[f"{gender}.constant_values"]),
                            )
                        ),
                    )
        except (OSError, KeyError, ValueError):
            return None
        return cls(models, key)

    # --- names and values ---------------------------------------------------
    def model(self, gender: str) -> GenderModel:
        gender = _check_gender(gender)
        if gender not in self.models:
            raise NoDataError(
                f"no {gender} people with measurements in the database to predict from"
            )
        return self.models[gender]

    def fields(self, gender: str) -> tuple[str, ...]:
        """The names a known value may have for this gender (also their completions)."""
        m = self.model(gender)
        return (*m.fields, *m.constants)

    def resolve(self, gender: str, name: str) -> str:
        """The field a typed name stands for, or UnknownFieldError with suggestions."""
        m = self.model(gender)
        key = ALIASES.get(name.strip().lower(), name.strip().lower())
        if key in m.fields or key in m.constants:
            return key
        choices = [*m.fields, *m.constants, *ALIASES]
        close = difflib.get_close_matches(key, choices, n=3, cutoff=0.6)
        if not close and "." not in key:
            close = difflib.get_close_matches(f"measure.{key}", choices, n=3, cutoff=0.6)
        hint = (
            f"; did you mean {', '.join(close)}?"
            if close
            else (
                "; known values are stature, mass, measure.<name>, girth.<segment>.<x|y|z> "
                "or center_of_mass.<segment>.<x|y|z>"
            )
        )
        if key in predicted_fields():
            raise UnknownFieldError(
                f"{name}: the {gender} people in the database have no values for it", where=name
            )
        raise UnknownFieldError(f"unknown name {name!r}{hint}", where=name)

    def parse_known(
        self, gender: str, items: Iterable[tuple[str, str | float]]
    ) -> dict[str, float]:
        """(name, "175.5cm") pairs -> {field: value in its canonical unit}.
        A bare number is in the canonical unit (cm, kg).  A field given twice
        is refused, as a batch file's repeated column is: which value was
        meant is the user's to say."""
        out: dict[str, float] = {}
        typed: dict[str, str] = {}
        for name, text in items:
            key = self.resolve(gender, name)
            given = f"{name}={text.strip() if isinstance(text, str) else text}"
            if key in typed:
                raise PredictionError(
                    f"{given}: {key} is already known ({typed[key]}); give it once", where=name
                )
            typed[key] = given
            unit = field_unit(key)
            if isinstance(text, (int, float)):
                value = float(text)
            else:
                try:
                    value = parse_quantity(text, unit)
                except UnitError as exc:
                    raise FieldUnitError(f"{given}: {exc}", where=name) from None
            out[key] = value
        return out

    # --- prediction ---------------------------------------------------------------
    def predict(self, gender: str, known: Mapping[str, float], nearest: int = 0) -> Prediction:
        """Every field of `gender` given the `known` ones (canonical units)."""
        m = self.model(gender)
        known = {self.resolve(gender, k): float(v) for k, v in known.items()}
        index = m.index()
        k_idx = [index[k] for k in known if k in index]
        z_known = self._standardize(m, known)
        mean, half = _condition(m, k_idx, z_known[None, :], self._spreads)
        values: dict[str, Estimate] = {}
        known_set = set(k_idx)
        for i, name in enumerate(m.fields):
            unit = field_unit(name)
            if name in known:
                v = known[name]
                values[name] = Estimate(v, v, v, unit, known=True)
            elif i not in known_set:
                mu, h = float(mean[0, i]), float(half[0, i])
                values[name] = Estimate(mu, mu - h, mu + h, unit)
        for name, c in m.constants.items():
            v = known.get(name, c)
            values[name] = Estimate(v, v, v, field_unit(name), known=name in known)
        neighbours = self.nearest(gender, known, nearest) if nearest > 0 else []
        return Prediction(gender, dict(known), values, neighbours, m.n)

    def predict_matrix(
        self,
        gender: str,
        names: Sequence[str],
        matrix: FloatArray,
        where: Sequence[str] | None = None,
    ) -> tuple[tuple[str, ...], FloatArray, FloatArray, FloatArray]:
        """Batch prediction: `matrix` (m, len(names)) of known values, NaN where a
        row does not know that name.  Returns (fields, value, low, high), each
        (m, fields); a known cell keeps its value, with low = high = value.
        Rows are grouped by which names they know, one solve per group.
        `where` names each row in error messages (file:line)."""
        m = self.model(gender)
        keys = [self.resolve(gender, n) for n in names]
        matrix = np.asarray(matrix, dtype=float).reshape(-1, len(keys))
        fields = (*m.fields, *m.constants)
        rows = len(matrix)
        value = np.empty((rows, len(fields)))
        value[:, len(m.fields) :] = list(m.constants.values())
        index = m.index()
        cols = np.array([index.get(k, -1) for k in keys])
        known_mask = np.isfinite(matrix)
        # one integer per row for the set of names it knows
        if len(keys) < 63:
            bits = np.int64(1) << np.arange(len(keys), dtype=np.int64)
            codes = known_mask.astype(np.int64) @ bits
        else:
            codes = np.unique(known_mask, axis=0, return_inverse=True)[1].reshape(-1)
        low, high = value.copy(), value.copy()
        for code in np.unique(codes):
            sel = np.flatnonzero(codes == code)
            pattern = known_mask[sel[0]]
            use = pattern & (cols >= 0)
            k_idx = cols[use].tolist()
            # duplicates (an alias and its field) keep the last, as predict does
            order = list(dict.fromkeys(reversed(k_idx)))[::-1]
            take = np.array([np.flatnonzero(use & (cols == c))[-1] for c in order], dtype=np.intp)
            known_values = matrix[np.ix_(sel, take)]
            z = (known_values - m.mean[order]) / m.sd[order]
            self._check_outliers(
                m,
                [m.fields[c] for c in order],
                known_values,
                z,
                None if where is None else [where[int(i)] for i in sel],
            )
            mean, half = _condition(m, order, z, self._spreads)
            value[sel, : len(m.fields)] = mean
            low[sel, : len(m.fields)] = mean - half
            high[sel, : len(m.fields)] = mean + half
            for j, c in zip(take, order):
                value[sel, c] = low[sel, c] = high[sel, c] = matrix[sel, j]
        return fields, value, low, high

    def nearest(self, gender: str, known: Mapping[str, float], k: int) -> list[Neighbour]:
        """The k real people closest to the known values (standardized distance)."""
        m = self.model(gender)
        known = {self.resolve(gender, n): float(v) for n, v in known.items()}
        index = m.index()
        k_idx = [index[n] for n in known if n in index]
        z = self._standardize(m, known)
        if not k_idx or k <= 0:
            return []
        diff = m.scores[:, k_idx].astype(np.float64) - z
        distance = np.sqrt(np.einsum("ij,ij->i", diff, diff))
        k = min(k, m.n)
        best = np.argpartition(distance, k - 1)[:k]
        best = best[np.lexsort((m.ids[best], distance[best]))]
        return [Neighbour(int(m.ids[i]), m.names[i], float(distance[i])) for i in best]

    def cv_rmse(self, gender: str, known_names: Iterable[str]) -> dict[str, float]:
        """Leave-one-out cross-validation RMSE (canonical units) of every field
        predicted from these known names, exact for least squares (PRESS)."""
        m = self.model(gender)
        index = m.index()
        known = [self.resolve(gender, name) for name in known_names]
        k_idx = list(dict.fromkeys(index[n] for n in known if n in index))
        unknown = [i for i in range(len(m.fields)) if i not in set(k_idx)]
        scores = m.scores.astype(np.float64)
        zk = scores[:, k_idx]
        inverse, _ = _pinv(m.corr[np.ix_(k_idx, k_idx)])
        coef = inverse @ m.corr[np.ix_(k_idx, unknown)]
        residual = scores[:, unknown] - zk @ coef
        # The fit has an intercept; scores are centred, so the hat value is
        # 1/n + z_i' S_KK^-1 z_i / (n - 1).
        hat = 1.0 / m.n + np.einsum("ij,jk,ik->i", zk, inverse, zk) / (m.n - 1)
        loo = residual / (1.0 - hat)[:, None]
        rmse = np.sqrt(np.mean(loo**2, axis=0)) * m.sd[unknown]
        out = {m.fields[i]: float(r) for i, r in zip(unknown, rmse)}
        return out | {name: 0.0 for name in m.constants if name not in known}

    # --- internals ----------------------------------------------------------------
    def _standardize(self, m: GenderModel, known: Mapping[str, float]) -> FloatArray:
        index = m.index()
        names = [n for n in known if n in index]
        values = np.array([known[n] for n in names], dtype=float)
        cols = [index[n] for n in names]
        z = (values - m.mean[cols]) / m.sd[cols]
        self._check_outliers(m, names, values[None, :], z[None, :])
        return z

    def _check_outliers(
        self,
        m: GenderModel,
        names: Sequence[str],
        values: FloatArray,
        z: FloatArray,
        where: Sequence[str] | None = None,
    ) -> None:
        # Lengths and masses are positive; a center-of-mass offset may not be.
        signed = np.array([n.startswith(f"{CENTER_OF_MASS}.") for n in names], dtype=bool)
        # Below the mean a positive value can lie at most mean/SD standard
        # deviations away (about 6 for mass), so the linear bound never holds
        # a mass typed in tonnes (0.08 for 80 kg): below the mean, lengths
        # and masses are measured on the log scale, whose SD is about the
        # coefficient of variation SD/mean.
        index = m.index()
        cols = [index[n] for n in names]
        mean, sd = m.mean[cols], m.sd[cols]
        with np.errstate(divide="ignore", invalid="ignore"):
            log_z = np.log(values / mean) * (mean / sd)
        # (a value not above 0 gives NaN or -inf here; "must be more than 0" names it first)
        far_below = ~signed & (log_z <= -MAX_SD)
        bad = ~(np.abs(z) < MAX_SD) | ((values <= 0) & ~signed) | far_below
        if not bad.any():
            return
        row, col = (int(i) for i in np.argwhere(bad)[0])
        name, value, score = names[col], float(values[row, col]), float(z[row, col])
        at = name if where is None else f"{where[row]}: {name}"
        i = index[name]
        unit = field_unit(name)
        if not math.isfinite(value):
            raise FieldUnitError(f"{at}: expected a number, got {value}", where=at)
        if value <= 0 and not signed[col]:
            raise OutlierError(f"{at} = {value:g} {unit}: must be more than 0", where=at)
        if far_below[row, col]:
            raise OutlierError(
                f"{at} = {value:g} {unit} is {100 * value / m.mean[i]:.2g} % of the mean of "
                f"the {m.n} {m.gender} people ({m.mean[i]:.1f} {unit}, SD {m.sd[i]:.1f}); "
                f"check the value and its unit",
                where=at,
            )
        side = "above" if score > 0 else "below"
        raise OutlierError(
            f"{at} = {value:g} {unit} is {abs(score):.1f} SD {side} the mean of the "
            f"{m.n} {m.gender} people ({m.mean[i]:.1f} {unit}, SD {m.sd[i]:.1f}); "
            f"check the value and its unit",
            where=at,
        )


def _quantile(dof: int) -> float:
    """The 90 % interval's multiplier on `dof` residual degrees of freedom:
    Student's t quantile, not the normal z(0.95), which it approaches for
    many people (ANSUR II's 1,986 women: 1.6457 against 1.6449; 30 people:
    1.70)."""
    return t_quantile(0.5 + LEVEL / 2, dof)


def _pinv(matrix: FloatArray) -> tuple[FloatArray, int]:
    """Pseudo-inverse and rank of a symmetric positive semi-definite matrix."""
    if matrix.size == 0:
        return matrix, 0
    w, v = np.linalg.eigh(matrix)
    keep = w > _RCOND * w.max()
    return (v[:, keep] / w[keep]) @ v[:, keep].T, int(keep.sum())


# A residual spread model: the log-scale coefficients on _variance_design's
# terms (terms, p) and each field's calibration, the 90 % multiplier (p,).
Spread = tuple[FloatArray, FloatArray]


def _variance_design(z: FloatArray) -> FloatArray:
    """The terms the residual variance is modelled on: 1, each standardized
    known value and its square (rows, 1 + 2k)."""
    return np.column_stack([np.ones(len(z)), z, z**2])


def _spread(m: GenderModel, k_idx: Sequence[int], coef: FloatArray) -> Spread:
    """How the residuals of the regression on `k_idx` scatter with the known
    values: the log of each training person's squared residual regressed on
    1, the known values and their squares (multiplicative heteroscedasticity,
    Harvey 1976, "Estimating regression models with multiplicative
    heteroscedasticity", Econometrica 44:461-465), and per field the 90 %
    multiplier z(0.95) times the root mean square of the residuals over that
    scale (1 for a residual exactly normal at the modelled scale)."""
    scores = m.scores.astype(np.float64)
    z_train = scores[:, list(k_idx)]
    residual = scores - z_train @ coef  # (n, p); ~0 for the known fields
    squared = residual * residual
    design = _variance_design(z_train)
    # 1e-8: a field the known values determine exactly (a girth cell derived
    # from a known measurement) has residuals at float32 rounding, not 0
    normal = design.T @ np.log(squared + 1e-8)
    # a pseudo-inverse, not a solve: with many known values the terms are
    # dependent (a field the others determine, a known value whose square is
    # a multiple of it), and the normal equations singular
    inverse, _ = _pinv(design.T @ design)
    log_scale = np.asarray(inverse @ normal, dtype=np.float64)
    spread = np.mean(squared / np.exp(design @ log_scale), axis=0, dtype=np.float64)
    calibration: FloatArray = Z * np.sqrt(spread)
    return log_scale, calibration


def _condition(
    m: GenderModel,
    k_idx: Sequence[int],
    z_known: FloatArray,
    spreads: dict[tuple[str, tuple[int, ...]], Spread] | None = None,
) -> tuple[FloatArray, FloatArray]:
    """Conditional mean and 90 % half-width (canonical units) of every field,
    for rows of standardized known values (rows, k).

    The half-width varies with the known values: a heavy person's girths
    scatter more about the regression than a slight one's (ANSUR II: with one
    width for everybody the 90 % intervals covered 86 % of the heaviest tenth
    by BMI and 92 % of the lightest).  It is the residual scale _spread
    models at these known values times the field's calibration, widened for
    degrees of freedom and leverage as the OLS prediction variance is.
    `spreads` keeps each spread model for the next prediction from the same
    known names."""
    k = len(k_idx)
    if k == 0:
        mean = np.broadcast_to(m.mean, (len(z_known), len(m.fields))).copy()
        half = _quantile(m.n - 1) * m.sd * math.sqrt(1.0 + 1.0 / m.n)
        return mean, np.broadcast_to(half, mean.shape).copy()
    cross = m.corr[k_idx]  # (k, p)
    inverse, rank = _pinv(m.corr[np.ix_(k_idx, k_idx)])
    coef = inverse @ cross  # (k, p)
    key = (m.gender, tuple(int(i) for i in k_idx))
    spread = None if spreads is None else spreads.get(key)
    if spread is None:
        spread = _spread(m, k_idx, coef)
        if spreads is not None:
            spreads[key] = spread
    log_scale, calibration = spread
    residual_dof = max(m.n - rank - 1, 1)
    dof = (m.n - 1) / residual_dof
    distance2 = np.einsum("ij,jk,ik->i", z_known, inverse, z_known)
    leverage = 1.0 + 1.0 / m.n + distance2 / (m.n - 1)
    scale = np.exp(_variance_design(z_known) @ log_scale / 2)  # (rows, p)
    # the calibration holds z(0.95); a fit on few people needs t's wider quantile
    widen = _quantile(residual_dof) / Z
    half = np.sqrt(leverage * dof)[:, None] * scale * (calibration * m.sd * widen)
    mean = z_known @ (coef * m.sd)
    mean += m.mean
    return mean, half
