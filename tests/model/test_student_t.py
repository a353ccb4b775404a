"""Student's t quantile (model/population/student_t.py) against a published table, and
the prediction intervals of a fit on few people that use it
(model/population/prediction.py): a 90 % interval from 30-odd people is t(0.95, n - 1)
standard deviations wide on each side, not z(0.95)'s."""

from __future__ import annotations

import math
from statistics import NormalDist

import numpy as np
import pytest
from ansur_csv import CsvValues, ansur_values
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.population import prediction
from sass_tui.model.population.prediction import Predictor, Z
from sass_tui.model.population.student_t import t_cdf, t_quantile

# Upper critical values of Student's t: NIST/SEMATECH e-Handbook of
# Statistical Methods, §1.3.6.7.2 (three decimals).
TABLE = {
    (0.95, 1): 6.314,
    (0.95, 2): 2.920,
    (0.95, 5): 2.015,
    (0.95, 10): 1.812,
    (0.95, 29): 1.699,
    (0.95, 30): 1.697,
    (0.95, 100): 1.660,
    (0.975, 1): 12.706,
    (0.975, 10): 2.228,
    (0.99, 20): 2.528,
}


@pytest.mark.parametrize(("p", "df"), list(TABLE))
def test_the_quantile_is_the_tables(p, df):
    assert t_quantile(p, df) == pytest.approx(TABLE[p, df], abs=5e-4)


@settings(max_examples=200, deadline=None)
@given(p=st.floats(min_value=0.001, max_value=0.999), df=st.floats(min_value=0.5, max_value=1e5))
def test_the_quantile_inverts_the_cdf(p, df):
    t = t_quantile(p, df)
    assert t_cdf(t, df) == pytest.approx(p, abs=1e-9)
    assert t_quantile(1 - p, df) == pytest.approx(-t, abs=1e-9 * max(1.0, abs(t)))
    # heavier tails than the normal's, approaching it with many degrees of freedom
    z = NormalDist().inv_cdf(p)
    assert abs(t) >= abs(z) - 1e-9


def test_many_degrees_of_freedom_are_the_normal():
    assert t_quantile(0.95, 1e7) == pytest.approx(Z, abs=1e-6)


@pytest.fixture(scope="module")
def few_women(ansur_dir) -> tuple[CsvValues, Predictor]:
    values = ansur_values(ansur_dir)
    rows = np.flatnonzero(np.array(values.genders) == "female")[:40]
    subset = CsvValues(
        values.fields,
        values.ids[rows],
        [values.names[i] for i in rows],
        [values.genders[i] for i in rows],
        values.matrix[rows],
    )
    return subset, Predictor.fit(subset, subset.fields)


def test_an_interval_from_few_people_is_t_wide(few_women):
    """Nothing known: the prediction interval of a new person, mean ± t(0.95,
    n - 1) s sqrt(1 + 1/n), s the standard deviation of the women the model
    kept (computed here from the CSV)."""
    values, predictor = few_women
    m = predictor.model("female")
    assert 30 <= m.n <= 40
    kept = np.isin(values.ids, m.ids)
    nothing_known = predictor.predict("female", {}).values
    for name in ("stature", "measure.chestcircumference"):
        column = values.matrix[kept, values.fields.index(name)]
        estimate = nothing_known[name]
        half = (estimate.high - estimate.low) / 2
        expected = t_quantile(0.95, m.n - 1) * np.std(column, ddof=1) * math.sqrt(1 + 1 / m.n)
        assert half == pytest.approx(expected, rel=1e-9)
        assert half > Z * np.std(column, ddof=1) * math.sqrt(1 + 1 / m.n) * 1.02


def test_a_regression_on_few_people_widens_by_t_over_z(few_women, monkeypatch):
    """One known value (rank 1): n - 2 residual degrees of freedom."""
    values, predictor = few_women
    m = predictor.model("female")
    known = {"stature": 165.0}
    with_t = predictor.predict("female", known).values["measure.chestcircumference"]
    monkeypatch.setattr(prediction, "t_quantile", lambda p, dof: Z)
    with_z = Predictor.fit(values, values.fields).predict("female", known)
    narrow = with_z.values["measure.chestcircumference"]
    assert with_t.value == pytest.approx(narrow.value, rel=1e-12)
    ratio = (with_t.high - with_t.low) / (narrow.high - narrow.low)
    assert ratio == pytest.approx(t_quantile(0.95, m.n - 2) / Z, rel=1e-9)
