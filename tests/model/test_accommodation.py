"""Manikin-family geometry, checked against textbook chi-square quantiles and an
independent count over the ANSUR II CSV."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
from ansur_csv import ansur_values
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.family_files import write_family
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.population.accommodation import (
    AccommodationError,
    CoverageEllipsoid,
    build_family,
    chi2_cdf,
    chi2_quantile,
    family_coverage,
    family_points,
    family_ranges,
    nearest_person,
)
from sass_tui.model.population.prediction import Predictor

# chi-square quantiles (NIST/SEMATECH e-Handbook, table 1.3.6.7.4, and the
# closed form -2 ln(1 - p) for k = 2)
TABLE = [
    (0.90, 1, 2.706),
    (0.95, 1, 3.841),
    (0.90, 2, 4.605),
    (0.95, 2, 5.991),
    (0.90, 3, 6.251),
    (0.99, 3, 11.345),
    (0.90, 4, 7.779),
    (0.95, 5, 11.070),
    (0.90, 6, 10.645),
    (0.99, 6, 16.812),
    (0.50, 4, 3.357),
]


@pytest.mark.parametrize("p,k,expected", TABLE)
def test_chi2_quantile_matches_the_table(p, k, expected):
    assert chi2_quantile(p, k) == pytest.approx(expected, abs=6e-4)


@given(st.floats(0.001, 0.999), st.integers(1, 8))
def test_chi2_quantile_inverts_the_cdf(p, k):
    assert chi2_cdf(chi2_quantile(p, k), k) == pytest.approx(p, abs=1e-10)


@given(st.floats(0.001, 0.999))
def test_chi2_two_degrees_is_closed_form(p):
    assert chi2_quantile(p, 2) == pytest.approx(-2 * math.log(1 - p), rel=1e-9)


def _csv_matrix(ansur_dir, gender: str, columns: list[str]) -> np.ndarray:
    name = "MALE" if gender == "male" else "FEMALE"
    with open(ansur_dir / f"ANSUR_II_{name}_Public.csv", encoding="cp1252", newline="") as f:
        rows = [{k.lower(): v for k, v in row.items()} for row in csv.DictReader(f)]
    scale = {"weightkg": 0.1}
    return np.array([[float(r[c]) * scale.get(c, 0.1) for c in columns] for r in rows])


MEASURES = ["stature", "weightkg", "sittingheight"]


@pytest.fixture(scope="module")
def women(ansur_dir):
    return _csv_matrix(ansur_dir, "female", MEASURES)


def test_boundary_family_of_three_has_fifteen_points_on_the_surface(women):
    ellipsoid = CoverageEllipsoid.fit(MEASURES, women, 0.9)
    points = family_points(ellipsoid, "boundary")
    assert len(points) == 15
    assert points[0].name == "center"
    np.testing.assert_allclose(points[0].values, women.mean(axis=0))
    d2 = ellipsoid.distance2(np.array([p.values for p in points[1:]]))
    np.testing.assert_allclose(d2, chi2_quantile(0.9, 3), rtol=1e-9)
    names = [p.name for p in points]
    assert len(set(names)) == len(names)
    assert "pc1_high" in names and "diag_hll" in names
    # PC1 "high" is the larger person: every measurement above the mean
    high = next(p for p in points if p.name == "pc1_high")
    assert np.all(high.values > women.mean(axis=0))


def test_distributed_family_fills_the_inside(women):
    ellipsoid = CoverageEllipsoid.fit(MEASURES, women, 0.9)
    points = family_points(ellipsoid, "distributed")
    assert len(points) == 29
    d2 = ellipsoid.distance2(np.array([p.values for p in points]))
    radius2 = chi2_quantile(0.9, 3)
    inner = [p.name.endswith("_inner") for p in points]
    np.testing.assert_allclose(d2[np.array(inner)], radius2 / 4, rtol=1e-9)
    assert sum(inner) == 14


@pytest.mark.parametrize("k,count", [(2, 9), (4, 9), (6, 13)])
def test_family_sizes(ansur_dir, k, count):
    measures = ["stature", "weightkg", "sittingheight", "hipbreadthsitting", "footlength",
                "handlength"][:k]  # fmt: skip
    matrix = _csv_matrix(ansur_dir, "male", measures)
    points = family_points(CoverageEllipsoid.fit(measures, matrix, 0.95))
    assert len(points) == count


@pytest.mark.parametrize("gender", ["male", "female"])
@pytest.mark.parametrize("target", [0.90, 0.95])
def test_coverage_equals_an_independent_count(ansur_dir, gender, target):
    matrix = _csv_matrix(ansur_dir, gender, MEASURES)
    ellipsoid = CoverageEllipsoid.fit(MEASURES, matrix, target)
    points = family_points(ellipsoid)
    coverage = family_coverage(ellipsoid, points, matrix)
    # independent: covariance inverse (not the PCA), the table's quantile
    mean = matrix.mean(axis=0)
    cov = np.cov(matrix, rowvar=False)
    offsets = matrix - mean
    d2 = np.einsum("ij,ij->i", offsets, np.linalg.solve(cov, offsets.T).T)
    quantile = {0.90: 6.251389, 0.95: 7.814728}[target]
    assert coverage.n == len(matrix)
    assert coverage.inside_ellipsoid == int((d2 <= quantile).sum())
    assert coverage.promised_percent == pytest.approx(100 * target)
    # real people are not multivariate normal: the count is near, not equal to, the promise
    assert abs(coverage.inside_percent - 100 * target) < 3
    low = np.min([p.values for p in points], axis=0)
    high = np.max([p.values for p in points], axis=0)
    within = np.all((matrix >= low) & (matrix <= high), axis=1)
    assert coverage.within_ranges == int(within.sum())
    np.testing.assert_array_equal(np.array([low, high]), np.array(family_ranges(points)))


def test_nearest_person_is_the_smallest_mahalanobis_distance(women):
    ellipsoid = CoverageEllipsoid.fit(MEASURES, women, 0.9)
    target = family_points(ellipsoid)[1].values
    row, distance = nearest_person(ellipsoid, target, women)
    cov = np.cov(women, rowvar=False)
    offsets = women - target
    d2 = np.einsum("ij,ij->i", offsets, np.linalg.solve(cov, offsets.T).T)
    assert row == int(np.argmin(d2))
    assert distance == pytest.approx(math.sqrt(d2.min()))


def test_people_lacking_a_measurement_are_left_out(women):
    holed = women.copy()
    holed[:10, 1] = np.nan
    ellipsoid = CoverageEllipsoid.fit(MEASURES, holed, 0.9)
    assert ellipsoid.n == len(women) - 10
    coverage = family_coverage(ellipsoid, family_points(ellipsoid), holed)
    assert coverage.missing == 10 and coverage.n == len(women) - 10
    row, _ = nearest_person(ellipsoid, women[0], holed)
    assert row >= 10


@pytest.mark.parametrize(
    "measures,target,message",
    [
        (["stature"], 0.9, "2 to 6"),
        (["stature", "stature"], 0.9, "twice"),
        (["stature", "weightkg"], 1.0, "between 0 and 100"),
    ],
)
def test_bad_families_are_refused(women, measures, target, message):
    with pytest.raises(AccommodationError, match=message):
        CoverageEllipsoid.fit(measures, women[:, : len(measures)], target)


def test_unknown_kind_is_refused(women):
    ellipsoid = CoverageEllipsoid.fit(MEASURES, women, 0.9)
    with pytest.raises(AccommodationError, match="boundary or distributed"):
        family_points(ellipsoid, "random")


@pytest.fixture(scope="module")
def csv_values(ansur_dir):
    return ansur_values(ansur_dir)


@pytest.fixture(scope="module")
def predictor(csv_values):
    return Predictor.fit(csv_values, csv_values.fields)


FIELDS = ["stature", "mass", "measure.sittingheight"]


@pytest.mark.slow
def test_a_written_family_reads_back_and_counts_right(csv_values, predictor, ansur_dir, tmp_path):
    women = np.array([g == "female" for g in csv_values.genders])
    columns = [csv_values.fields.index(f) for f in FIELDS]
    matrix = csv_values.matrix[women][:, columns]
    names = [n for n, w in zip(csv_values.names, women) if w]
    family = build_family(
        "female", FIELDS, csv_values.ids[women], names, matrix, 0.9, predictor, space="as measured"
    )
    written = write_family(family, tmp_path / "family", Figure.default("female"))
    data = json.loads((tmp_path / "family" / "family.json").read_text())
    assert data["gender"] == "female" and data["measures"] == FIELDS
    assert data["coverage_target"] == 90
    assert len(data["manikins"]) == 15
    # the reported coverage equals an independent count over the CSV itself
    independent = _csv_matrix(ansur_dir, "female", ["stature", "weightkg", "sittingheight"])
    cov = np.cov(independent, rowvar=False)
    offsets = independent - independent.mean(axis=0)
    d2 = np.einsum("ij,ij->i", offsets, np.linalg.solve(cov, offsets.T).T)
    inside = 100 * np.mean(d2 <= 6.251389)
    assert data["coverage"]["inside_ellipsoid"] == pytest.approx(inside, abs=1e-3)
    values = np.array([[m.values[f] for f in FIELDS] for m in written.manikins])
    low, high = values.min(axis=0), values.max(axis=0)
    within = 100 * np.mean(np.all((independent >= low) & (independent <= high), axis=1))
    assert data["coverage"]["within_ranges"] == pytest.approx(within, abs=1e-3)
    for manikin, entry in zip(written.manikins, data["manikins"]):
        assert entry["files"] == [f"female_{manikin.name}.fig", f"female_{manikin.name}.x3d"]
        fig = read_fig(tmp_path / "family" / entry["files"][0])
        assert fig.variables  # a whole figure
        x3d = (tmp_path / "family" / entry["files"][1]).read_text()
        assert "<HAnimHumanoid" in x3d
        # the nearest person is real and named
        row = list(csv_values.ids).index(entry["nearest"]["id"])
        assert csv_values.names[row] == entry["nearest"]["name"]
        # the manikin's known values are the ellipsoid point, kept by the prediction
        for f in FIELDS:
            assert manikin.prediction.value(f) == pytest.approx(entry["values"][f], abs=1e-3)
    center = written.manikins[0]
    assert center.values["stature"] == pytest.approx(independent[:, 0].mean())
