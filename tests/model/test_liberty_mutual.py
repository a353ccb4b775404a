"""The Liberty Mutual manual materials handling equations (Potvin et al. 2021)
against the reference values of ../shared/reference/liberty-mutual/README.md,
the paper's worked example (section 3.4: 12 kg accepted by 81.0 % of women),
and, on other inputs, the 14 equations as the paper prints them, typed again
here (a polynomial per factor, in its printed form)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.strength.liberty_mutual import (
    Inputs,
    acceptable,
    mixed_percent,
    normal_quantile,
)

ln = math.log


def test_readme_women_lift():
    found = acceptable(Inputs("lift", 1.03, 0.51, 1.0, 0.38), "", "female")
    assert found.factors["H"] == pytest.approx(0.76579, abs=5e-5)
    assert found.factors["VRM"] == pytest.approx(0.94788, abs=5e-5)
    assert found.factors["DV"] == pytest.approx(0.90739, abs=5e-5)
    assert found.factors["F"] == pytest.approx(0.6767)
    assert found.mal == pytest.approx(15.556, abs=5e-3)
    assert found.load_for(75) == pytest.approx(12.828, rel=1e-3)
    assert found.load_for(90) == pytest.approx(10.372, rel=1e-3)
    assert found.percent_capable(10) == pytest.approx(91.5, abs=0.05)
    # the paper's own example: 12 kg is acceptable to 81.0 % of women
    assert found.percent_capable(12) == pytest.approx(81.0, abs=0.05)


@pytest.mark.parametrize(
    ("variant", "factors", "mal", "mal75", "mal90"),
    [
        ("initial", (0.68755, 0.76003, 0.6281), 22.91, 19.23, 15.92),
        ("sustained", (0.67250, 0.68569, 0.4896), 13.77, 11.38, 9.236),
    ],
)
def test_readme_men_pull(variant, factors, mal, mal75, mal90):
    found = acceptable(Inputs("pull", 1.2, 20.0, 1.0), variant, "male")
    for name, value in zip(("V", "DH", "F"), factors, strict=True):
        assert found.factors[name] == pytest.approx(value, abs=5e-5)
    assert found.mal == pytest.approx(mal, abs=0.01)
    assert found.load_for(75) == pytest.approx(mal75, abs=0.01)
    assert found.load_for(90) == pytest.approx(mal90, rel=1e-3)


def poly(x, constant, *terms):
    return constant + sum(c * x**p for p, c in terms)


# The paper's equations (sections 3.1-3.3), each factor written out.
def lift_female(h, vrm, dv, f):
    return (
        (1.2602 - h / 0.7686)
        * (0.9877 + vrm / 13.69 - vrm**2 / 9.221)
        * (0.8199 - ln(dv) / 7.696)
        * (0.6767 - ln(f) / 12.59 - ln(f) ** 2 / 228.2)
    )


def lift_male_geometry(h, vrm, dv):
    return (
        (1.3532 - h / 0.7079) * (0.7746 + vrm / 1.912 - vrm**2 / 3.296) * (0.8695 - ln(dv) / 10.62)
    )


REFERENCE = {
    ("lift", "", "female"): (0.260, lambda h, v, d, f: 34.9 * lift_female(h, v, d, f)),
    ("lower", "", "female"): (0.307, lambda h, v, d, f: 37.0 * lift_female(h, v, d, f)),
    ("lift", "", "male"): (
        0.276,
        lambda h, v, d, f: (
            82.6 * lift_male_geometry(h, v, d) * (0.6259 - ln(f) / 9.092 - ln(f) ** 2 / 125.0)
        ),
    ),
    ("lower", "", "male"): (
        0.304,
        lambda h, v, d, f: (
            95.9 * lift_male_geometry(h, v, d) * (0.5773 - ln(f) / 10.80 - ln(f) ** 2 / 255.9)
        ),
    ),
}
PUSH_FEMALE = {
    "initial": lambda v, d, f: (
        36.9
        * (-0.5304 + v / 0.3361 - v**2 / 0.6915)
        * (1.0286 - d / 72.22 + d**2 / 9782)
        * (0.7251 - ln(f) / 13.19 - ln(f) ** 2 / 197.3)
    ),
    "sustained": lambda v, d, f: (
        25.5
        * (-0.6539 + v / 0.2941 - v**2 / 0.5722)
        * (1.0391 - d / 52.91 + d**2 / 7975)
        * (0.6086 - ln(f) / 11.95 - ln(f) ** 2 / 304.4)
    ),
}


def male_initial_df(d, f):
    return (1.0790 - ln(d) / 9.392) * (0.6281 - ln(f) / 13.07 - ln(f) ** 2 / 379.5)


def male_sustained_df(d, f):
    return (1.1035 - ln(d) / 7.170) * (0.4896 - ln(f) / 10.20 - ln(f) ** 2 / 403.9)


SIDEWAYS = {
    ("push", "initial", "female"): (0.214, PUSH_FEMALE["initial"]),
    ("pull", "initial", "female"): (0.234, PUSH_FEMALE["initial"]),
    ("push", "sustained", "female"): (0.286, PUSH_FEMALE["sustained"]),
    ("pull", "sustained", "female"): (0.298, PUSH_FEMALE["sustained"]),
    ("push", "initial", "male"): (
        0.231,
        lambda v, d, f: 70.3 * (1.2737 - v / 1.335 + v**2 / 2.576) * male_initial_df(d, f),
    ),
    ("push", "sustained", "male"): (
        0.267,
        lambda v, d, f: 65.3 * (2.2940 - v / 0.3345 + v**2 / 0.6887) * male_sustained_df(d, f),
    ),
    ("pull", "initial", "male"): (
        0.238,
        lambda v, d, f: 69.8 * (1.7186 - v / 0.6888 + v**2 / 2.025) * male_initial_df(d, f),
    ),
    ("pull", "sustained", "male"): (
        0.257,
        lambda v, d, f: 61.0 * (2.1977 - v / 0.3850 + v**2 / 0.9047) * male_sustained_df(d, f),
    ),
    ("carry", "", "female"): (
        0.231,
        lambda v, d, f: (
            28.6 * (1.1645 - v / 4.437) * (1.0101 - d / 207.8) * (0.6224 - ln(f) / 16.33)
        ),
    ),
    ("carry", "", "male"): (
        0.278,
        lambda v, d, f: (
            74.9
            * (1.5505 - v / 1.417)
            * (1.1172 - ln(d) / 6.332)
            * (0.5149 - ln(f) / 7.958 - ln(f) ** 2 / 131.1)
        ),
    ),
}
V_RANGE = {
    ("push", "female"): (0.58, 1.33),
    ("push", "male"): (0.63, 1.44),
    ("pull", "female"): (0.58, 1.33),
    ("pull", "male"): (0.63, 1.44),
    ("carry", "female"): (0.71, 1.03),
    ("carry", "male"): (0.78, 1.10),
}


def normal_share(z: float) -> float:
    return 50.0 * (1 + math.erf(z / math.sqrt(2)))


@settings(max_examples=30, deadline=None)
@given(
    key=st.sampled_from(sorted(REFERENCE)),
    h=st.floats(0, 1),
    vrm=st.floats(0.3, 1.3),
    dv=st.floats(0.25, 0.9),
    f=st.floats(0.01, 6),
    load=st.floats(1, 40),
)
def test_hidden_lift_and_lower_cases(key, h, vrm, dv, f, load):
    task, variant, sex = key
    low, high = (0.20, 0.68) if sex == "female" else (0.25, 0.73)
    h = low + h * (high - low)
    cv, mal = REFERENCE[key][0], REFERENCE[key][1](h, vrm, dv, f)
    found = acceptable(Inputs(task, vrm, dv, f, h), variant, sex)
    assert found.refused == [] and found.cv == cv
    assert found.mal == pytest.approx(mal, rel=0.01)
    assert found.load_for(75) == pytest.approx(mal * (1 - 0.6745 * cv), rel=0.01)
    assert found.percent_capable(load) == pytest.approx(
        normal_share((1 - load / mal) / cv), abs=0.01
    )


@settings(max_examples=30, deadline=None)
@given(
    key=st.sampled_from(sorted(SIDEWAYS)),
    v=st.floats(0, 1),
    d=st.floats(0, 1),
    f=st.floats(0.01, 1.0),
)
def test_hidden_push_pull_and_carry_cases(key, v, d, f):
    task, variant, sex = key
    low, high = V_RANGE[(task, sex)]
    v = low + v * (high - low)
    d = 2.1 + d * ((10 if task == "carry" else 61) - 2.1)
    f = min(f, 28.0 / d)  # below the paper's velocity limits (29 and 37 m/min)
    cv, mal = SIDEWAYS[key][0], SIDEWAYS[key][1](v, d, f)
    found = acceptable(Inputs(task, v, d, f), variant, sex)
    assert found.refused == [] and found.cv == cv
    assert found.mal == pytest.approx(mal, rel=0.01)
    assert found.load_for(90) == pytest.approx(mal * (1 - 1.2816 * cv), rel=0.01)


@pytest.mark.parametrize(
    ("inputs", "sex", "words"),
    [
        (Inputs("lift", 1.0, 0.5, 1.0, 0.22), "male", "H 0.22 m outside 0.25-0.73 m"),
        (Inputs("lift", 1.0, 0.2, 1.0, 0.4), "female", "DV 0.2 m outside"),
        (Inputs("lower", 1.0, 0.5, 25.0, 0.4), "female", "F 25 per minute outside"),
        (Inputs("lift", 1.0, 0.5, 0.0, 0.4), "male", "F 0 per minute outside 0.00208 (one a day)-"),
        (Inputs("lift", 1.0, 0.6, 19.0, 0.4), "female", "mean velocity"),
        (Inputs("lift", 1.8, 0.6, 1.0, 0.4), "female", "arm reach 1.96 m"),
        (Inputs("push", 0.5, 10.0, 1.0), "female", "V 0.5 m outside 0.58-1.33 m"),
        (Inputs("carry", 0.9, 12.0, 1.0), "male", "DH 12 m outside 2.1-10 m"),
    ],
)
def test_the_papers_ranges_refused(inputs, sex, words):
    variant = "initial" if inputs.task in ("push", "pull") else ""
    found = acceptable(inputs, variant, sex)
    assert any(words in reason for reason in found.refused), found.refused


def test_cautions_and_the_coupling_factor():
    fast = acceptable(Inputs("lift", 1.0, 0.5, 8.0, 0.4), "", "female")
    assert any("caution" in note for note in fast.notes)
    plain = acceptable(Inputs("lift", 1.0, 0.5, 1.0, 0.4), "", "female")
    none = acceptable(Inputs("lift", 1.0, 0.5, 1.0, 0.4, "none"), "", "female")
    assert none.mal == pytest.approx(plain.mal * 0.84)


def test_quantiles_and_the_mix():
    assert normal_quantile(0.75) == pytest.approx(0.6744897502, abs=1e-9)
    assert normal_quantile(0.9) == pytest.approx(1.2815515655, abs=1e-9)
    assert mixed_percent({"female": 80.0, "male": 100.0}, {"female": 3.0, "male": 1.0}) == 85.0
