"""A sample's survey weights (sass target --weight): read with their file:line
errors, and honoured by the calibration exactly as repeating each row as
many times as its weight says (model/population/target_sample.py, model/population/targets.py)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.files.sample_file import read_sample
from sass_tui.model.population.target_sample import SampleError, is_survey_weight
from sass_tui.model.population.targets import calibrate, outside_share, weighted_percentile

FIELDS = ["stature", "mass"]
HEADER = "id,gender,age,stature[cm],mass[kg],WTMECPRP"


def sample_text(rows: list[str]) -> str:
    return "\n".join([HEADER, *rows]) + "\n"


@pytest.mark.parametrize(
    ("cell", "why"),
    [
        ("-3", "greater than 0"),
        ("0", "greater than 0"),
        ("heavy", "greater than 0"),
        ("", "greater than 0"),
        ("nan", "greater than 0"),
        # weights of 1e308 added up to infinity: numpy's "SVD did not converge"
        ("1e308", "of at most 1e+15"),
        ("inf", "of at most 1e+15"),
    ],
)
def test_a_bad_weight_is_refused_with_its_line_and_column(cell, why):
    text = sample_text(["1,female,30,160,60,2.5", f"2,female,31,161,61,{cell}"])
    with pytest.raises(SampleError) as error:
        read_sample(text, FIELDS, "s.csv", weight="WTMECPRP")
    assert str(error.value) == (
        f"s.csv:3: column 6 'WTMECPRP': {cell!r}: a survey weight must be a number {why}"
    )


def test_a_weight_column_that_is_not_there():
    with pytest.raises(SampleError, match=r"^s.csv:1: --weight 'wt': no such column"):
        read_sample(sample_text(["1,female,30,160,60,2"]), FIELDS, "s.csv", weight="wt")


def test_a_sample_without_gender_for_a_target_of_both():
    text = "stature,mass\n160,60\n"
    with pytest.raises(SampleError, match=r"^s.csv:1: no gender column; a target of both"):
        read_sample(text, FIELDS, "s.csv", need_gender=True)


@pytest.mark.parametrize("age", ["-1", "131", "old"])
def test_an_age_no_person_has(age):
    text = sample_text([f"1,female,{age},160,60,2"])
    with pytest.raises(SampleError, match=r"^s.csv:2: column 3 'age': .*from 0 to 130$"):
        read_sample(text, FIELDS, "s.csv", weight="WTMECPRP")


def test_a_gender_no_one_has():
    with pytest.raises(SampleError, match=r"^s.csv:2: column 2 'gender': 'x': expected male or"):
        read_sample(sample_text(["1,x,30,160,60,2"]), FIELDS, "s.csv")


def test_one_gender_is_kept_and_the_weights_ages_follow_their_rows():
    text = sample_text(["1,female,30,160,60,2", "2,male,40,180,80,3", "3,F,50,,62,4"])
    sample = read_sample(text, FIELDS, "s.csv", weight="WTMECPRP", gender="female")
    assert sample.rows == 2 and sample.incomplete == 1
    assert sample.matrix.tolist() == [[160.0, 60.0]]
    assert sample.weights.tolist() == [2.0] and sample.ages.tolist() == [30.0]
    assert sample.genders == ("female",) and sample.weighted_by == "WTMECPRP"
    everyone = read_sample(text, FIELDS, "s.csv")
    assert everyone.unused_weights == ("WTMECPRP",) and everyone.weights is None


@pytest.mark.parametrize(
    ("name", "survey"),
    [
        ("WTMECPRP", True),
        ("WTINT2YR", True),
        ("survey_weight", True),
        ("final wt", True),
        ("weight", False),  # a body weight as often as not
        ("weightkg", False),
        ("mass", False),
    ],
)
def test_what_looks_like_a_survey_weight(name, survey):
    assert is_survey_weight(name) is survey


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(min_value=1e-3, max_value=1e6), min_size=1, max_size=20))
def test_every_positive_weight_reads_back(weights):
    rows = [f"{i},male,30,{170 + i},{70 + i},{w!r}" for i, w in enumerate(weights)]
    sample = read_sample(sample_text(rows), FIELDS, "s.csv", weight="WTMECPRP")
    assert sample.weights.tolist() == weights


def test_the_weighted_people_have_the_weighted_samples_moments():
    """The calibrated people's weighted means, SDs and correlation are the
    survey-weighted sample's (computed here with numpy), not its rows'."""
    rng = np.random.default_rng(5)
    people = np.column_stack([rng.normal(165, 7, 800), rng.normal(70, 11, 800)])
    sample = np.column_stack([rng.normal(163, 7, 300), rng.normal(74, 13, 300)])
    # an oversampled group: the heavy half counted a quarter as much
    weights = np.where(sample[:, 1] > 74, 1.0, 4.0)
    result = calibrate(FIELDS, people, sample, sample_weights=weights)
    w = result.weights
    goal_mean = np.average(sample, axis=0, weights=weights)
    goal_cov = np.cov(sample.T, aweights=weights, bias=True)
    assert np.allclose(np.average(people, axis=0, weights=w), goal_mean, atol=1e-5)
    assert np.allclose(np.cov(people.T, aweights=w, bias=True), goal_cov, rtol=1e-5)
    assert abs(goal_mean[1] - sample[:, 1].mean()) > 2.0  # the weights mattered
    assert result.sample_rows == 300


def test_outside_share_is_the_weight_beyond_every_person():
    people = np.array([50.0, 60.0, 70.0, np.nan])
    sample = np.array([45.0, 55.0, 70.0, 75.0, np.nan])
    weights = np.array([1.0, 2.0, 3.0, 4.0, 100.0])
    assert outside_share(people, sample, weights) == pytest.approx(5.0 / 10.0)


def test_weighted_percentile_of_a_survey():
    """With integer weights, the weighted percentile of each sorted value's
    position is the repeated values' percentile."""
    values = np.array([1.0, 2.0, 3.0])
    assert weighted_percentile(values, np.array([1.0, 1.0, 1.0]), [50])[0] == 2.0
