"""Manikin families: the coverage ellipsoid of a few measurements, its
boundary (or distributed) points, and the coverage the family really has.

Geometry (k measurements, 2 <= k <= 6, one gender's people):

- Standardise each measurement (sample mean, sample standard deviation,
  ddof = 1) and take the principal components of the standardised values:
  the eigenvectors v_i and eigenvalues l_i of their correlation matrix.  Each
  component's sign is chosen so its loadings sum to >= 0 ("high" = larger).
- The coverage ellipsoid is z' R^-1 z <= r^2 (z the standardised values, R the
  correlation matrix): the Mahalanobis ball of the sample mean and covariance.
  r^2 is the chi-square quantile of the target with k degrees of freedom, the
  share a multivariate normal population would have inside (the *promise*).
- Boundary family: the center, the 2k axis points z = +-r sqrt(l_i) v_i, and
  for k <= 3 the 2^k diagonal points z = sum_i s_i (r / sqrt k) sqrt(l_i) v_i,
  s_i = +-1 (on the surface too); k = 3 gives 1 + 6 + 8 = 15 manikins.
- Distributed family: the same directions at two radii, r/2 (inner) and r
  (outer), plus the center: a family spread through the ellipsoid rather
  than only on its surface (k = 3: 1 + 14 + 14 = 29 manikins).
- Measured coverage, counted over the real people (never assumed):
  `inside_ellipsoid`, the share with Mahalanobis distance^2 <= r^2; and
  `within_ranges`, the share whose every listed measurement lies between the
  family's smallest and largest value of it.
- A manikin's nearest person: the smallest Mahalanobis distance over the
  listed measurements (in standard deviations of the population).

Chi-square quantiles: the CDF for integer k is the regularised lower gamma
function P(k/2, x/2), which has a closed form: for even k = 2m,
1 - e^-y sum_{j<m} y^j / j!; for odd k = 2m+1, erf(sqrt y) - e^-y
sum_{j<m} y^(j+1/2) / Gamma(j + 3/2), with y = x/2.  The quantile is found by
bisection to 1e-12 (no scipy needed).

People lacking any listed measurement are left out (counted in `missing`).

Whole manikins: each point's listed values are the known values of the
conditional prediction (`sass_tui.model.population.prediction`), which completes every
girth and center-of-mass value; joint limits (not in ANSUR II) come from the
population of the figure, as for any real person.  Numpy; no database.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Final

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.figure import Figure
from sass_tui.model.population.measure_fields import AccommodationError
from sass_tui.model.population.prediction import Prediction, Predictor

FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]

MIN_MEASURES: Final = 2
MAX_MEASURES: Final = 6
MAX_DIAGONAL_MEASURES: Final = 3  # 2^k diagonal points only for k <= 3
KINDS: Final = ("boundary", "distributed")
INNER_RADIUS: Final = 0.5  # the distributed family's inner shell, as a fraction of r


# --- chi-square ------------------------------------------------------------


def chi2_cdf(x: float, k: int) -> float:
    """P(X <= x) for X chi-square with integer k >= 1 degrees of freedom (exact)."""
    if k < 1:
        raise AccommodationError(f"chi-square needs k >= 1 degrees of freedom, not {k}")
    if x <= 0:
        return 0.0
    y = x / 2.0
    if k % 2 == 0:
        term, total = 1.0, 1.0
        for j in range(1, k // 2):
            term *= y / j
            total += term
        return max(0.0, 1.0 - math.exp(-y) * total)
    total = 0.0
    for j in range((k - 1) // 2):
        total += y ** (j + 0.5) / math.gamma(j + 1.5)
    return max(0.0, math.erf(math.sqrt(y)) - math.exp(-y) * total)


def chi2_quantile(p: float, k: int) -> float:
    """The x with chi2_cdf(x, k) = p, 0 < p < 1, by bisection (to 1e-12 relative)."""
    if not 0.0 < p < 1.0:
        raise AccommodationError(f"a chi-square quantile needs 0 < p < 1, not {p}")
    low, high = 0.0, float(k) + 10.0
    while chi2_cdf(high, k) < p:
        high *= 2.0
    while high - low > 1e-12 * max(1.0, high):
        middle = 0.5 * (low + high)
        if chi2_cdf(middle, k) < p:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


# --- the ellipsoid ---------------------------------------------------------


@dataclass(frozen=True)
class CoverageEllipsoid:
    measures: tuple[str, ...]
    mean: FloatArray  # (k,) canonical units
    std: FloatArray  # (k,) sample standard deviation
    correlation: FloatArray  # (k, k)
    eigenvalues: FloatArray  # (k,) of the correlation matrix, largest first
    eigenvectors: FloatArray  # (k, k) columns, sign: loadings sum >= 0
    target: float  # the share promised, 0 < target < 1
    radius: float  # sqrt of the chi-square quantile of target, k dof
    n: int  # people the statistics come from

    @classmethod
    def fit(
        cls,
        measures: tuple[str, ...] | list[str],
        matrix: FloatArray,
        target: float,
        weights: FloatArray | None = None,
    ) -> CoverageEllipsoid:
        """The ellipsoid of `matrix` (people x measures, complete rows only);
        with `weights` (a target population's, per row) the weighted mean, SD
        and correlation (weights as frequencies; the SD's n - 1 is the Kish
        effective size's)."""
        measures = tuple(measures)
        k = len(measures)
        if not MIN_MEASURES <= k <= MAX_MEASURES:
            raise AccommodationError(
                f"a family needs {MIN_MEASURES} to {MAX_MEASURES} measurements, not {k}"
            )
        if len(set(measures)) != k:
            raise AccommodationError(f"a measurement is listed twice: {', '.join(measures)}")
        if not 0.0 < target < 1.0:
            raise AccommodationError(
                f"the coverage target must lie between 0 and 100 %, not {100 * target:g} %"
            )
        complete = ~np.isnan(np.asarray(matrix, dtype=float)).any(axis=1)
        values = complete_rows(matrix)
        if len(values) <= k:
            raise AccommodationError(
                f"{len(values)} people have every one of {', '.join(measures)}; "
                f"a family over {k} measurements needs more than {k}"
            )
        if weights is None:
            mean = values.mean(axis=0)
            std = values.std(axis=0, ddof=1)
        else:
            w = np.asarray(weights, dtype=float)[complete]
            mean = w @ values / w.sum()
            effective = w.sum() ** 2 / float(w @ w)
            variance = w @ (values - mean) ** 2 / w.sum() * effective / (effective - 1)
            std = np.sqrt(variance)
        if np.any(std <= 0):
            flat = [m for m, s in zip(measures, std) if s <= 0]
            raise AccommodationError(f"{', '.join(flat)}: every person has the same value")
        if weights is None:
            correlation: FloatArray = np.asarray(np.corrcoef(values, rowvar=False), dtype=float)
        else:
            centred = values - mean
            covariance = (centred * w[:, None]).T @ centred
            scale = np.sqrt(np.diag(covariance))
            correlation = covariance / np.outer(scale, scale)
        eigenvalues, eigenvectors = np.linalg.eigh(correlation)
        order = np.argsort(eigenvalues)[::-1]
        eigenvalues, eigenvectors = eigenvalues[order], eigenvectors[:, order]
        if eigenvalues[-1] <= 1e-12:
            raise AccommodationError(
                f"{', '.join(measures)}: the measurements are linearly dependent"
            )
        signs = np.where(eigenvectors.sum(axis=0) < 0, -1.0, 1.0)
        eigenvectors = eigenvectors * signs
        return cls(
            measures=measures,
            mean=mean,
            std=std,
            correlation=correlation,
            eigenvalues=eigenvalues,
            eigenvectors=eigenvectors,
            target=float(target),
            radius=math.sqrt(chi2_quantile(target, k)),
            n=len(values),
        )

    @property
    def k(self) -> int:
        return len(self.measures)

    def distance2(self, matrix: FloatArray) -> FloatArray:
        """Squared Mahalanobis distance of each row (NaN where a value is missing)."""
        z = (np.asarray(matrix, dtype=float) - self.mean) / self.std
        scores = z @ self.eigenvectors / np.sqrt(self.eigenvalues)
        result: FloatArray = np.sum(scores**2, axis=1)
        return result

    def contains(self, matrix: FloatArray) -> BoolArray:
        result: BoolArray = self.distance2(matrix) <= self.radius**2 * (1 + 1e-12)
        return result

    def point(self, scores: FloatArray) -> FloatArray:
        """Measurement values at principal-component scores given in units of each
        component's standard deviation (so |scores| = r is on the surface)."""
        z = self.eigenvectors @ (np.asarray(scores, dtype=float) * np.sqrt(self.eigenvalues))
        result: FloatArray = self.mean + z * self.std
        return result


def complete_rows(matrix: FloatArray) -> FloatArray:
    values = np.asarray(matrix, dtype=float)
    result: FloatArray = values[~np.isnan(values).any(axis=1)]
    return result


# --- the family ------------------------------------------------------------


@dataclass(frozen=True)
class ManikinPoint:
    name: str  # center, pc1_high, pc1_low, ..., diag_hhl (high/low along pc1, pc2, pc3)
    scores: FloatArray  # principal-component scores (standard deviations)
    values: FloatArray  # the listed measurements, canonical units


def family_points(ellipsoid: CoverageEllipsoid, kind: str = "boundary") -> list[ManikinPoint]:
    """The family's points, the center first (see the module docstring)."""
    if kind not in KINDS:
        raise AccommodationError(f"unknown family kind {kind!r}; expected {' or '.join(KINDS)}")
    k, r = ellipsoid.k, ellipsoid.radius
    directions: list[tuple[str, FloatArray]] = []
    for i in range(k):
        for sign, word in ((1.0, "high"), (-1.0, "low")):
            unit = np.zeros(k)
            unit[i] = sign
            directions.append((f"pc{i + 1}_{word}", unit))
    if k <= MAX_DIAGONAL_MEASURES:
        for corner in np.ndindex(*([2] * k)):
            signs = np.array([1.0 if c == 0 else -1.0 for c in corner])
            name = "diag_" + "".join("h" if s > 0 else "l" for s in signs)
            directions.append((name, signs / math.sqrt(k)))
    shells = [(1.0, "")] if kind == "boundary" else [(INNER_RADIUS, "_inner"), (1.0, "")]
    points = [ManikinPoint("center", np.zeros(k), ellipsoid.mean.copy())]
    for fraction, suffix in shells:
        for name, direction in directions:
            scores = direction * r * fraction
            points.append(ManikinPoint(name + suffix, scores, ellipsoid.point(scores)))
    return points


@dataclass(frozen=True)
class FamilyCoverage:
    n: int  # people with every listed measurement
    missing: int  # people lacking one (left out)
    inside_ellipsoid: int
    within_ranges: int
    promised_percent: float  # the chi-square promise (= the target)
    # A target population's shares (weighted people), when the family is weighted.
    weighted_inside_percent: float | None = None
    weighted_within_percent: float | None = None

    @property
    def inside_percent(self) -> float:
        if self.weighted_inside_percent is not None:
            return self.weighted_inside_percent
        return 100.0 * self.inside_ellipsoid / self.n

    @property
    def within_ranges_percent(self) -> float:
        if self.weighted_within_percent is not None:
            return self.weighted_within_percent
        return 100.0 * self.within_ranges / self.n


def family_ranges(points: list[ManikinPoint]) -> tuple[FloatArray, FloatArray]:
    """Per listed measurement, the family's smallest and largest value."""
    values = np.array([p.values for p in points])
    return values.min(axis=0), values.max(axis=0)


def family_coverage(
    ellipsoid: CoverageEllipsoid,
    points: list[ManikinPoint],
    matrix: FloatArray,
    weights: FloatArray | None = None,
) -> FamilyCoverage:
    """Count the people of `matrix` (people x the ellipsoid's measures) the family
    covers; with `weights`, also the weighted shares."""
    values = complete_rows(matrix)
    low, high = family_ranges(points)
    within = np.all((values >= low) & (values <= high), axis=1)
    weighted: dict[str, float] = {}
    if weights is not None:
        w = np.asarray(weights, dtype=float)[~np.isnan(np.asarray(matrix, dtype=float)).any(axis=1)]
        weighted = {
            "weighted_inside_percent": 100.0 * float(w[ellipsoid.contains(values)].sum()) / w.sum(),
            "weighted_within_percent": 100.0 * float(w[within].sum()) / w.sum(),
        }
    return FamilyCoverage(
        n=len(values),
        missing=len(matrix) - len(values),
        inside_ellipsoid=int(ellipsoid.contains(values).sum()),
        within_ranges=int(within.sum()),
        promised_percent=100.0 * ellipsoid.target,
        **weighted,
    )


def nearest_person(
    ellipsoid: CoverageEllipsoid, values: FloatArray, matrix: FloatArray
) -> tuple[int, float]:
    """Row of `matrix` nearest to `values` (Mahalanobis), and that distance.
    Rows lacking a listed measurement are never chosen."""
    offsets = np.asarray(matrix, dtype=float) - np.asarray(values, dtype=float)
    distance2 = ellipsoid.distance2(offsets + ellipsoid.mean)
    distance2 = np.where(np.isnan(distance2), np.inf, distance2)
    row = int(np.argmin(distance2))
    if not math.isfinite(distance2[row]):
        raise AccommodationError("nobody has every listed measurement")
    return row, math.sqrt(float(distance2[row]))


# --- whole manikins --------------------------------------------------------


@dataclass(frozen=True)
class Nearest:
    id: int
    name: str
    distance: float  # Mahalanobis, over the listed measurements


@dataclass(frozen=True)
class Manikin:
    name: str
    values: dict[str, float]  # the listed measurements (canonical units)
    nearest: Nearest
    prediction: Prediction  # the whole figure's values, completed from `values`
    files: tuple[str, ...] = ()

    def figure(self, population: Figure) -> Figure:
        """The manikin as a figure (`Prediction.figure`: percentiles against
        `population`'s statistics; joint limits and anything the prediction
        lacks come from the population), named after the manikin."""
        figure = self.prediction.figure(population)
        figure.person = f"manikin {self.name}, {self.prediction.label()}"
        return figure


@dataclass(frozen=True)
class Family:
    gender: str
    kind: str
    ellipsoid: CoverageEllipsoid
    coverage: FamilyCoverage
    manikins: tuple[Manikin, ...]
    target: dict[str, Any] | None = None  # the target population it is weighted to (JSON)
    notes: tuple[str, ...] = ()  # manikins moved inside the people's own ranges
    space: str = "as measured"  # where the ellipsoid was fitted (SPACES)

    @property
    def measures(self) -> tuple[str, ...]:
        return self.ellipsoid.measures

    def to_json(self) -> dict[str, Any]:
        """family.json as docs/accommodation.md shows it: with the counts behind
        the percentages, the chi-square promise and the family's kind and ranges."""
        low, high = family_ranges(list(self.points()))
        return {
            "gender": self.gender,
            "measures": list(self.measures),
            "kind": self.kind,
            "coverage_target": round(100.0 * self.ellipsoid.target, 6),
            "coverage": {
                "inside_ellipsoid": round(self.coverage.inside_percent, 4),
                "within_ranges": round(self.coverage.within_ranges_percent, 4),
                "chi_square_promise": round(self.coverage.promised_percent, 6),
                "people": self.coverage.n,
                "inside_ellipsoid_count": self.coverage.inside_ellipsoid,
                "within_ranges_count": self.coverage.within_ranges,
                "not_measured": self.coverage.missing,
            },
            "ranges": {
                m: [round(float(lo), 4), round(float(hi), 4)]
                for m, lo, hi in zip(self.measures, low, high)
            },
            "manikins": [
                {
                    "name": m.name,
                    "values": {k: round(v, 4) for k, v in m.values.items()},
                    "nearest": {
                        "id": m.nearest.id,
                        "name": m.nearest.name,
                        "distance": round(m.nearest.distance, 4),
                    },
                    "files": list(m.files),
                }
                for m in self.manikins
            ],
            "space": self.space if LOG_MASS in self.measures else SPACES[1],
            "notes": list(self.notes),
        } | ({} if self.target is None else {"target": self.target})

    def points(self) -> list[ManikinPoint]:
        return [
            ManikinPoint(m.name, np.zeros(0), np.array([m.values[f] for f in self.measures]))
            for m in self.manikins
        ]


LOG_MASS: Final = "mass"  # the measure whose logarithm the ellipsoid is fitted on
SPACES: Final = ("log mass", "as measured")  # where the ellipsoid is fitted (build_family)
INSIDE_STEPS: Final = 30  # bisection steps moving a manikin inward (_inside)


def _to_space(
    measures: tuple[str, ...] | list[str], matrix: FloatArray, space: str = SPACES[0]
) -> FloatArray:
    """The values where the population is near normal: mass as its natural
    logarithm (mass is right-skewed; a normal ellipsoid over it runs below
    any living adult), every other measure as it is."""
    out = np.array(matrix, dtype=float, copy=True)
    for k, m in enumerate(measures):
        if m == LOG_MASS and space == SPACES[0]:
            with np.errstate(invalid="ignore", divide="ignore"):
                out[:, k] = np.where(out[:, k] > 0, np.log(out[:, k]), np.nan)
    return out


def _from_space(
    measures: tuple[str, ...] | list[str], values: FloatArray, space: str = SPACES[0]
) -> FloatArray:
    out = np.array(values, dtype=float, copy=True)
    for k, m in enumerate(measures):
        if m == LOG_MASS and space == SPACES[0]:
            out[k] = math.exp(out[k])
    return out


def _body_ranges(body: FloatArray | None) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The population's own range of mass (kg) and BMI (kg/m^2), from its
    people's stature (cm) and mass (columns of `body`)."""
    if body is None:
        return None
    both = body[~np.isnan(body).any(axis=1)]
    if len(both) == 0:
        return None
    bmi = both[:, 1] / (both[:, 0] / 100.0) ** 2
    return (float(both[:, 1].min()), float(both[:, 1].max())), (float(bmi.min()), float(bmi.max()))


def _outside(
    prediction: Prediction, ranges: tuple[tuple[float, float], tuple[float, float]]
) -> str:
    """What of the manikin lies outside the people's own ranges ('' if nothing)."""
    (mass_low, mass_high), (bmi_low, bmi_high) = ranges
    mass, stature = prediction.mass, prediction.stature
    bmi = mass / (stature / 100.0) ** 2
    said = []
    if not mass_low <= mass <= mass_high:
        said.append(f"mass {mass:.1f} kg outside the people's {mass_low:.1f}-{mass_high:.1f} kg")
    if not bmi_low <= bmi <= bmi_high:
        said.append(f"BMI {bmi:.1f} outside the people's {bmi_low:.1f}-{bmi_high:.1f}")
    return "; ".join(said)


def build_family(
    gender: str,
    measures: tuple[str, ...] | list[str],
    ids: npt.NDArray[np.int64],
    names: tuple[str, ...] | list[str],
    matrix: FloatArray,
    target: float,
    predictor: Predictor,
    kind: str = "boundary",
    weights: FloatArray | None = None,
    body: FloatArray | None = None,
    genders: tuple[str, ...] | list[str] | None = None,
    space: str = SPACES[0],
) -> Family:
    """The family of one gender's people (`matrix`: people x `measures`, query-language
    field names as the predictor knows them), each point completed by `predictor`;
    with `weights` (a target population's), the ellipsoid and coverage of the weighted
    people.  The ellipsoid is fitted with mass as its logarithm (`_to_space`).
    With `body` (the same people's stature and mass), a manikin whose mass or BMI
    falls outside the people's own range is moved inward along its direction to
    the last point inside, and a note says so.  `gender` "both" with `genders`
    (each person's): one family of both genders; each manikin is predicted as
    its nearest person's gender."""
    if space not in SPACES:
        raise AccommodationError(f"unknown space {space!r}; expected {' or '.join(SPACES)}")
    fitted_in = space
    space_values = _to_space(measures, matrix, fitted_in)
    ellipsoid = CoverageEllipsoid.fit(measures, space_values, target, weights)
    points = family_points(ellipsoid, kind)
    ranges = _body_ranges(body)
    notes: list[str] = []
    manikins = []
    kept_points = []
    for point in points:
        row, distance = nearest_person(ellipsoid, point.values, space_values)
        sex = gender if genders is None else str(genders[row])

        def predict(values: FloatArray, sex: str = sex) -> tuple[dict[str, float], Prediction]:
            known = {
                m: float(v)
                for m, v in zip(ellipsoid.measures, _from_space(measures, values, fitted_in))
            }
            return known, predictor.predict(sex, known)

        known, prediction = predict(point.values)
        said = "" if ranges is None else _outside(prediction, ranges)
        if said:
            low, high = 0.0, 1.0
            for _ in range(INSIDE_STEPS):
                middle = 0.5 * (low + high)
                if _outside(
                    predict(ellipsoid.point(point.scores * middle))[1], ranges or ((0, 0), (0, 0))
                ):
                    high = middle
                else:
                    low = middle
            point = ManikinPoint(
                point.name, point.scores * low, ellipsoid.point(point.scores * low)
            )
            row, distance = nearest_person(ellipsoid, point.values, space_values)
            known, prediction = predict(point.values)
            notes.append(f"{point.name}: {said}; moved inward to {low:.2f} of its radius")
        kept_points.append(point)
        manikins.append(
            Manikin(
                name=point.name,
                values=known,
                nearest=Nearest(int(ids[row]), str(names[row]), distance),
                prediction=prediction,
            )
        )
    coverage = family_coverage(ellipsoid, kept_points, space_values, weights)
    return Family(
        gender, kind, ellipsoid, coverage, tuple(manikins), notes=tuple(notes), space=fitted_in
    )
