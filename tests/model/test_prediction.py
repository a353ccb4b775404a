"""Conditional prediction (sass_tui/model/population/prediction.py) on ANSUR II, checked
against direct least squares with numpy and against held-out people."""

from __future__ import annotations

import math

import numpy as np
import pytest
from ansur_csv import CsvValues, ansur_values
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.errors import SassError
from sass_tui.model.population.prediction import (
    MAX_SD,
    FieldUnitError,
    NoDataError,
    OutlierError,
    PredictionError,
    Predictor,
    UnknownFieldError,
    split_known,
)
from sass_tui.model.population.student_t import t_quantile


@pytest.fixture(scope="session")
def values(ansur_dir) -> CsvValues:
    return ansur_values(ansur_dir)


@pytest.fixture(scope="session")
def predictor(values) -> Predictor:
    return Predictor.fit(values, values.fields, key="test")


def _rows(values: CsvValues, gender: str) -> np.ndarray:
    return np.flatnonzero(np.array(values.genders) == gender)


def _subset(values: CsvValues, rows) -> CsvValues:
    return CsvValues(
        values.fields,
        values.ids[rows],
        [values.names[i] for i in rows],
        [values.genders[i] for i in rows],
        values.matrix[rows],
    )


def test_the_fit_covers_every_measured_value(predictor):
    male = predictor.model("male")
    assert male.n == 4082 and predictor.model("female").n == 1986
    assert "measure.sittingheight" in male.fields and "girth.right_upper_arm.z" in male.fields
    # ANSUR II derives no head length (z) and no hand thickness (x): no value to predict
    assert "girth.bottom_head.z" not in predictor.fields("male")
    assert male.constants == {
        "girth.right_clavicle.x": 1.0,
        "girth.right_clavicle.y": 1.0,
        "girth.left_clavicle.x": 1.0,
        "girth.left_clavicle.y": 1.0,
    }


@pytest.mark.parametrize(
    "known", [("stature", "mass"), ("stature", "mass", "measure.sittingheight")]
)
def test_the_prediction_is_least_squares_with_its_prediction_interval(values, predictor, known):
    """The conditional mean equals OLS with an intercept computed directly with
    numpy (x0'b); the half-width is the residual scale modelled on the known
    values (log r^2 regressed on 1, x, x^2), times z(0.95) and the root mean
    square of the residuals over their scale, times sqrt((1 + x0'(X'X)^-1 x0) dof)."""
    rows = _rows(values, "male")
    col = {f: i for i, f in enumerate(values.fields)}
    given = values.matrix[np.ix_(rows, [col[k] for k in known])]
    x = np.column_stack([np.ones(len(rows)), given])
    design = np.column_stack([x, given**2])
    given_values = {"stature": 181.0, "mass": 95.0, "measure.sittingheight": 96.0}
    x0 = np.array([1.0] + [given_values[k] for k in known])
    design0 = np.concatenate([x0, x0[1:] ** 2])
    prediction = predictor.predict("male", {k: given_values[k] for k in known})
    n, k = len(rows), len(known)
    for target in ("measure.headcircumference", "girth.right_upper_arm.z", "measure.footlength"):
        y = values.matrix[rows, col[target]]
        b, *_ = np.linalg.lstsq(x, y, rcond=None)
        residual = y - x @ b
        floor = 1e-8 * y.var(ddof=1)  # the model's floor, in this value's unit
        g, *_ = np.linalg.lstsq(design, np.log(residual**2 + floor), rcond=None)
        quantile = t_quantile(0.95, n - k - 1)
        spread = quantile * math.sqrt(np.mean(residual**2 / np.exp(design @ g)))
        leverage = 1.0 + x0 @ np.linalg.inv(x.T @ x) @ x0
        half = math.exp(design0 @ g / 2) * spread * math.sqrt(leverage * (n - 1) / (n - k - 1))
        estimate = prediction.values[target]
        assert estimate.value == pytest.approx(x0 @ b, abs=1e-9)
        assert estimate.high - estimate.value == pytest.approx(half, rel=1e-4)
        assert estimate.value - estimate.low == pytest.approx(half, rel=1e-4)
        assert not estimate.known


@pytest.mark.slow
@pytest.mark.parametrize("gender", ["male", "female"])
def test_90_percent_intervals_cover_85_to_95_percent_of_held_out_people(values, gender):
    rows = _rows(values, gender)
    fold = np.random.default_rng(7).permutation(len(rows)) % 10
    inside, total = 0, 0
    known = ["stature", "mass", "measure.sittingheight"]
    col = {f: i for i, f in enumerate(values.fields)}
    for f in range(10):
        train, test = rows[fold != f], rows[fold == f]
        model = Predictor.fit(_subset(values, train), values.fields)
        known_matrix = values.matrix[np.ix_(test, [col[k] for k in known])]
        fields, _, low, high = model.predict_matrix(gender, known, known_matrix)
        predicted = [i for i, name in enumerate(fields) if name not in known]
        truth = values.matrix[np.ix_(test, [col[fields[i]] for i in predicted])]
        ok = np.isfinite(truth)
        inside += int(((truth >= low[:, predicted]) & (truth <= high[:, predicted]))[ok].sum())
        total += int(ok.sum())
    assert 0.85 <= inside / total <= 0.95


def test_a_persons_complete_measurements_give_back_their_girth(values, predictor):
    col = {f: i for i, f in enumerate(values.fields)}
    person = _rows(values, "female")[123]
    raw = [f for f in values.fields if f in ("stature", "mass") or f.startswith("measure.")]
    known = {f: float(values.matrix[person, col[f]]) for f in raw}
    prediction = predictor.predict("female", known)
    girth = [f for f in prediction.predicted if f.startswith("girth.")]
    assert len(girth) > 50
    for f in girth:
        assert prediction.values[f].value == pytest.approx(values.matrix[person, col[f]], abs=1e-6)
        assert prediction.values[f].high - prediction.values[f].low < 1e-3


def test_known_values_come_back_unchanged(predictor):
    known = {"measure.stature": 175.5, "mass": 82.2, "girth.right_upper_arm.z": 33.3}
    prediction = predictor.predict("male", known)
    assert prediction.known == {"stature": 175.5, "mass": 82.2, "girth.right_upper_arm.z": 33.3}
    for name, value in prediction.known.items():
        estimate = prediction.values[name]
        assert (estimate.value, estimate.low, estimate.high, estimate.known) == (
            value,
            value,
            value,
            True,
        )
    assert prediction.stature == 175.5 and prediction.mass == 82.2
    # the other arm's length is derived from the same measurement: it follows
    assert prediction.values["girth.left_upper_arm.z"].value == pytest.approx(33.3, abs=1e-6)
    assert prediction.label() == (
        "predicted from stature 175.5 cm, mass 82.2 kg, girth.right_upper_arm.z 33.3 cm"
    )


def test_batch_prediction_matches_one_by_one(predictor):
    names = ["stature", "mass", "measure.sittingheight"]
    matrix = np.array(
        [[170.0, 70.0, np.nan], [185.0, np.nan, 95.0], [178.0, 90.0, 92.0], [160.0, 60.0, np.nan]]
    )
    fields, value, low, high = predictor.predict_matrix("male", names, matrix)
    for r, row in enumerate(matrix):
        known = {n: v for n, v in zip(names, row) if not math.isnan(v)}
        one = predictor.predict("male", known)
        for i, f in enumerate(fields):
            e = one.values[f]
            assert (value[r, i], low[r, i], high[r, i]) == pytest.approx((e.value, e.low, e.high))


def test_nearest_people_are_ranked_by_standardized_distance(values, predictor):
    col = {f: i for i, f in enumerate(values.fields)}
    person = _rows(values, "male")[42]
    known = {f: float(values.matrix[person, col[f]]) for f in ("stature", "mass", "measure.span")}
    nearest = predictor.nearest("male", known, 5)
    assert nearest[0].id == values.ids[person] and nearest[0].distance < 1e-4
    assert [n.distance for n in nearest] == sorted(n.distance for n in nearest)
    m = predictor.model("male")
    i = list(m.ids).index(nearest[3].id)
    z = [(values.matrix[person, col[f]] - m.mean[m.index()[f]]) / m.sd[m.index()[f]] for f in known]
    direct = math.dist(z, [float(m.scores[i, m.index()[f]]) for f in known])
    assert nearest[3].distance == pytest.approx(direct, rel=1e-5)
    assert predictor.predict("male", known, nearest=3).nearest == nearest[:3]


def test_cv_rmse_is_the_leave_one_out_error(values):
    rows = _rows(values, "female")[:60]
    small = Predictor.fit(_subset(values, rows), values.fields)
    col = {f: i for i, f in enumerate(values.fields)}
    target = "measure.chestcircumference"
    errors = []
    for left_out in range(len(rows)):
        keep = np.delete(rows, left_out)
        model = Predictor.fit(_subset(values, keep), values.fields)
        person = rows[left_out]
        known = {"stature": values.matrix[person, col["stature"]]}
        known["mass"] = values.matrix[person, col["mass"]]
        errors.append(
            model.predict("female", known).value(target) - values.matrix[person, col[target]]
        )
    loo = math.sqrt(np.mean(np.square(errors)))
    assert small.cv_rmse("female", ["stature", "mass"])[target] == pytest.approx(loo, rel=1e-6)


def test_the_cache_file_round_trips_and_knows_its_key(predictor, tmp_path):
    path = predictor.save(tmp_path / "sass.db.predict.npz")
    again = Predictor.load(path, "test")
    assert again is not None
    known = {"stature": 165.0, "mass": 61.0}
    a, b = predictor.predict("female", known), again.predict("female", known)
    assert a.values == b.values
    assert Predictor.load(path, "other data") is None
    assert Predictor.load(tmp_path / "absent.npz", "test") is None
    (tmp_path / "junk.npz").write_bytes(b"not a zip file")
    assert Predictor.load(tmp_path / "junk.npz", "test") is None


# --- errors a user can cause --------------------------------------------------


def test_an_unknown_name_suggests_the_close_ones(predictor):
    with pytest.raises(UnknownFieldError, match=r"did you mean measure\.sittingheight"):
        predictor.parse_known("male", [("measure.sitingheight", "90")])
    with pytest.raises(UnknownFieldError, match=r"did you mean measure\.sittingheight"):
        predictor.parse_known("male", [("sittingheight", "90")])
    with pytest.raises(UnknownFieldError, match=r"did you mean girth\.right_upper_arm\.z"):
        predictor.predict("male", {"girth.right_uper_arm.z": 30.0})
    with pytest.raises(UnknownFieldError, match="no values for it"):
        predictor.predict("male", {"girth.bottom_head.z": 20.0})


def test_a_unit_of_the_wrong_kind_names_the_value(predictor):
    with pytest.raises(FieldUnitError, match=r"mass=80 cm: cm is not a unit of mass"):
        predictor.parse_known("male", [("mass", "80 cm")])
    with pytest.raises(FieldUnitError, match=r"stature=tall: expected a number"):
        predictor.parse_known("male", [("stature", "tall")])
    with pytest.raises(
        PredictionError,
        match=r"stature=70 in: stature is already known "
        r"\(measure\.stature=180cm\); give it once",
    ):
        predictor.parse_known("male", [("measure.stature", "180cm"), ("stature", "70 in")])
    assert predictor.parse_known("male", [("stature", "70 in"), ("mass", "176.37 lb")]) == {
        "stature": pytest.approx(177.8),
        "mass": pytest.approx(80.0, abs=1e-3),
    }


def test_a_value_10_sd_from_the_population_is_refused(predictor):
    m = predictor.model("male")
    sd = m.sd[m.index()["stature"]]
    mean = m.mean[m.index()["stature"]]
    predictor.predict("male", {"stature": mean + (MAX_SD - 0.1) * sd})
    with pytest.raises(OutlierError, match=r"stature = 1755 cm is \d+\.\d SD above the mean"):
        predictor.predict("male", {"stature": 1755.0})  # mm typed as cm
    with pytest.raises(OutlierError, match=r"known.csv:3: mass = 822 kg is .* SD above"):
        predictor.predict_matrix(
            "male", ["mass"], np.array([[80.0], [822.0]]), where=["known.csv:2", "known.csv:3"]
        )
    with pytest.raises(OutlierError, match=r"mass = 0 kg: must be more than 0"):
        predictor.predict("male", {"mass": 0.0})
    with pytest.raises(FieldUnitError, match="expected a number"):
        predictor.predict("male", {"stature": float("nan")})


def test_a_length_or_mass_far_below_the_mean_is_refused_on_the_log_scale(predictor):
    # Below the mean a positive value lies at most mean/SD linear SDs away
    # (about 6 for mass), so 10 SD alone let a mass typed in tonnes through.
    m = predictor.model("male")
    i = m.index()["mass"]
    mean, sd = float(m.mean[i]), float(m.sd[i])
    assert (mean - 0.08) / sd < MAX_SD  # what the linear bound alone says of 0.08
    with pytest.raises(OutlierError, match=r"mass = 0\.08 kg is 0\.094 % of the mean of the"):
        predictor.predict("male", {"mass": 0.08})  # 80 kg typed in tonnes
    with pytest.raises(OutlierError, match=r"known\.csv:3: mass = 0\.0001 kg is"):
        predictor.predict_matrix(
            "male", ["mass"], np.array([[80.0], [0.0001]]), where=["known.csv:2", "known.csv:3"]
        )
    # The bound itself, computed here: MAX_SD on the log scale, whose SD is SD/mean.
    edge = mean * math.exp(-MAX_SD * sd / mean)
    predictor.predict("male", {"mass": edge * 1.01})
    with pytest.raises(OutlierError, match="% of the mean"):
        predictor.predict("male", {"mass": edge * 0.99})


@pytest.mark.parametrize("gender", ["female", "male"])
def test_every_real_persons_smallest_and_largest_value_is_accepted(predictor, values, gender):
    # The bounds refuse typing mistakes, never a soldier ANSUR II measured:
    # each field's smallest and largest value among the people is predicted from.
    rows = _rows(values, gender)
    for c, name in enumerate(values.fields):
        column = values.matrix[rows, c]
        column = column[np.isfinite(column)]
        if name not in predictor.model(gender).index() or not len(column):
            continue
        for value in (column.min(), column.max()):
            if value > 0 or name.startswith("center_of_mass."):
                predictor.predict(gender, {name: float(value)})


def test_a_gender_without_data_says_so(values):
    males = Predictor.fit(_subset(values, _rows(values, "male")), values.fields)
    with pytest.raises(NoDataError, match="no female people"):
        males.predict("female", {"stature": 160.0})
    with pytest.raises(SassError, match="gender must be male or female"):
        males.predict("other", {"stature": 160.0})
    few = Predictor.fit(_subset(values, _rows(values, "female")[:10]), values.fields)
    assert "female" not in few.models


@settings(max_examples=50, deadline=None)
@given(
    number=st.floats(min_value=100, max_value=230, allow_nan=False),
    unit=st.sampled_from(["", "cm", " cm", "in", "mm", " m"]),
)
def test_known_values_parse_with_any_length_unit(predictor, number, unit):
    factor = {"": 1.0, "cm": 1.0, " cm": 1.0, "in": 2.54, "mm": 0.1, " m": 100.0}[unit]
    text = f"{number / factor!r}{unit}"
    parsed = predictor.parse_known("male", [("stature", text)])
    assert parsed["stature"] == pytest.approx(number, rel=1e-9)


def test_batch_with_every_measurement_known_matches_one_by_one(values, predictor):
    """More known names than fit in one integer's bits (the row grouping's other path)."""
    names = [f for f in values.fields if f in ("stature", "mass") or f.startswith("measure.")]
    col = {f: i for i, f in enumerate(values.fields)}
    rows = _rows(values, "male")[:4]
    matrix = values.matrix[np.ix_(rows, [col[n] for n in names])].copy()
    matrix[1, 5] = matrix[3, 7] = np.nan
    assert len(names) > 63
    fields, value, _, high = predictor.predict_matrix("male", names, matrix)
    for r, row in enumerate(matrix):
        one = predictor.predict("male", {n: v for n, v in zip(names, row) if not math.isnan(v)})
        for i, f in enumerate(fields):
            assert value[r, i] == pytest.approx(one.values[f].value, abs=1e-7)
            assert high[r, i] == pytest.approx(one.values[f].high, abs=1e-7)


def test_the_prediction_as_a_figure_leaves_the_population_figure_alone(predictor):
    from sass_tui.model.body.figure import Figure
    from sass_tui.model.names import GIRTH, row_index

    prediction = predictor.predict("male", {"stature": 180.0, "mass": 85.0})
    base = Figure.default("male")
    before = base.groups[GIRTH].values.copy()
    figure = prediction.figure(base)
    arm = row_index(GIRTH, "right_upper_arm")
    assert figure.person == "predicted from stature 180 cm, mass 85 kg"
    assert figure.stature == 180.0 and figure.mass == 85.0
    expected = prediction.values["girth.right_upper_arm.z"]
    assert figure.groups[GIRTH].values[arm, 2] == expected.value
    low, high = prediction.group_values(GIRTH, "low"), prediction.group_values(GIRTH, "high")
    assert (low[arm, 2], high[arm, 2]) == (expected.low, expected.high)
    values = prediction.group_values(GIRTH)
    finite = np.isfinite(values)
    assert (low[finite] <= values[finite]).all() and (values[finite] <= high[finite]).all()
    assert base.person is None and np.array_equal(base.groups[GIRTH].values, before)


def test_known_values_split_from_one_line():
    assert split_known("stature=180 cm, mass = 85kg;measure.span=185") == [
        ("stature", "180 cm"),
        ("mass", "85kg"),
        ("measure.span", "185"),
    ]
    assert split_known(" ") == []
    with pytest.raises(PredictionError, match="'stature': expected NAME=VALUE"):
        split_known("stature, mass=80")


@settings(max_examples=100, deadline=None)
@given(
    st.lists(
        st.tuples(
            st.sampled_from(["stature", "mass", "measure.span", "girth.neck.x"]),
            st.floats(min_value=0.01, max_value=500, allow_nan=False),
            st.sampled_from(["", "cm", " in", " kg", "lb"]),
            st.sampled_from([",", ";", " , ", "; "]),
        ),
        max_size=5,
    )
)
def test_split_known_takes_back_what_was_joined(items):
    text = "".join(f"{name} = {number!r}{unit}{sep}" for name, number, unit, sep in items)
    assert split_known(text) == [(name, f"{number!r}{unit}") for name, number, unit, _ in items]
