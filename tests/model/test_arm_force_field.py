"""The Arm Force Field (model/strength/arm_force_field.py) against the authors' own
script (nladelfa/Arm-Force-Field, AFFinPython - v1.0.py), run by
../shared/reference/arm-force-field/reference.py on postures other than the
authors' example.  The script's numbers are written down here (rounded to
4 decimals), not re-derived by sass's code."""

from __future__ import annotations

import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.model.strength.arm_force_field import (
    POSTURE_JOINTS,
    ArmForceError,
    arm_force,
    check_posture,
    fitted_ranges,
    parse_direction,
    read_coefficients,
)
from tests._paths import SHARED

# Ten points each, in the script's order (POSTURE_JOINTS), metres on HAnim's axes.
POSTURES = {
    "forward_at_shoulder": [
        [0.2, 1.38, 0.55], [0.2, 1.38, 0.47], [0.2, 1.38, 0.2], [0.19, 1.4, -0.05],
        [-0.2, 1.38, 0.55], [-0.2, 1.38, 0.47], [-0.2, 1.38, 0.2], [-0.19, 1.4, -0.05],
        [0.0, 1.45, -0.08], [0.0, 1.0, -0.06],
    ],
    "overhead_and_low": [
        [0.25, 1.95, 0.05], [0.24, 1.87, 0.04], [0.22, 1.65, 0.0], [0.18, 1.42, -0.04],
        [-0.45, 1.05, 0.15], [-0.4, 1.1, 0.12], [-0.32, 1.18, 0.0], [-0.18, 1.42, -0.04],
        [0.0, 1.47, -0.07], [0.0, 1.02, -0.05],
    ],
    "bent_trunk": [
        [0.15, 1.0, 0.62], [0.16, 1.05, 0.56], [0.2, 1.12, 0.35], [0.18, 1.25, 0.15],
        [-0.1, 1.2, 0.7], [-0.12, 1.22, 0.62], [-0.22, 1.18, 0.4], [-0.18, 1.25, 0.15],
        [0.0, 1.3, 0.1], [0.0, 0.98, -0.08],
    ],
}  # fmt: skip

# (posture, left force, right force, left load N, right load N, percent capable,
#  the script's Lmas Rmas Lsd Rsd Lga Rga LMASwG RMASwG LMASprob RMASprob)
SCRIPT_RUNS = [
    ("forward_at_shoulder", (0, 1, 0), (0, 0, -1), 40, 60, 75,
     (104.9639, 223.2, 29.075, 61.8264, -15.3098, 0.5101, 70.0433, 182.0088, 95.6163, 99.595)),
    ("forward_at_shoulder", (0, 0, 1), (1, 0, 0), 80, 30, 90,
     (184.1, 72.3, 50.9957, 20.0271, -0.5101, 0.0141, 118.2363, 46.6483, 97.889, 98.2693)),
    ("overhead_and_low", (0, 1, 0), (0, -1, 0), 30, 100, 50,
     (142.6101, 83.1434, 39.503, 23.0307, -0.7336, 6.7011, 141.8766, 89.8445, 99.7688, 32.9624)),
    ("overhead_and_low", (-0.2, -0.3, 0.9), (0.5, 0.5, -0.7), 70, 70, 25,
     (54.3035, 157.723, 15.0421, 43.6893, 2.1621, 2.4443, 66.6113, 189.6353, 18.4121, 98.0483)),
    ("bent_trunk", (0, -1, 0), (0, 1, 0), 90, 45, 75,
     (86.0733, 81.7112, 23.8423, 22.634, 12.0606, -15.5515, 82.0526, 50.8933, 63.3507, 82.5071)),
    ("bent_trunk", (-1, 0, 0), (0.3, 0.8, 0.2), 50, 120, 95,
     (70.1711, 82.3177, 19.4374, 22.802, 0.0809, -14.5007, 38.2803, 30.3111, 85.1273, 1.1054)),
]  # fmt: skip

# The authors' own example (their script's printed LMASwG and RMASwG).
EXAMPLE = [
    [0.29034, 0.91934, 0.29134], [0.26170, 0.96619, 0.23538], [0.19100, 1.11068, 0.09171],
    [0.09191, 1.30461, -0.06136], [-0.37368, 1.20097, 0.360862], [-0.36905, 1.20173, 0.28260],
    [-0.42676, 1.28636, 0.09280], [-0.21538, 1.32291, -0.06481], [-0.06385, 1.35457, -0.06182],
    [-0.06300, 0.95253, -0.07984],
]  # fmt: skip


def posture(points):
    return check_posture(dict(zip(POSTURE_JOINTS, points)))


@pytest.mark.parametrize("run", SCRIPT_RUNS, ids=lambda r: f"{r[0]}-{r[1]}-{r[2]}")
def test_both_arms_agree_with_the_authors_script(run):
    name, left_force, right_force, left_load, right_load, capable, expected = run
    body = posture(POSTURES[name])
    left = arm_force(body, "left", left_force)
    right = arm_force(body, "right", right_force)
    got = (
        left.mean, right.mean, left.sd, right.sd, left.gravity, right.gravity,
        left.strength(capable), right.strength(capable),
        left.percent_capable(left_load), right.percent_capable(right_load),
    )  # fmt: skip
    for value, want in zip(got, expected):
        assert value == pytest.approx(want, abs=0.5)
    # and much closer than the half newton asked for
    assert max(abs(g - w) for g, w in zip(got, expected)) < 1e-3


def test_the_authors_example_gives_their_printed_strengths():
    body = posture(EXAMPLE)
    assert arm_force(body, "left", (0, 1, 0)).strength(75) == pytest.approx(78.1484, abs=1e-3)
    assert arm_force(body, "right", (0, 1, 0)).strength(75) == pytest.approx(61.8365, abs=1e-3)


def test_men_are_the_worksheets_women_times_1_66_with_88_kg_arms():
    # bent_trunk, left hand pushing down: women 86.0733 N, arm's weight 12.0606 N for 73.5 kg
    body = posture(POSTURES["bent_trunk"])
    men = arm_force(body, "left", (0, -1, 0), gender="male")
    assert men.mean == pytest.approx(86.0733 * 1.66, abs=1e-3)
    assert men.sd == pytest.approx(86.0733 * 1.66 * 0.277, abs=1e-3)
    # the arm's weight scales with body mass: 88.1 kg, the worksheet's man
    assert men.gravity == pytest.approx(12.0606 * 88.1 / 73.5, abs=1e-3)
    assert "La Delfa & Potvin 2017" in men.source and "1.66" in men.source
    own = arm_force(body, "left", (0, -1, 0), body_mass=60.0)
    assert own.gravity == pytest.approx(12.0606 * 60.0 / 73.5, abs=1e-3)


def test_the_coefficients_are_the_published_ones():
    c = read_coefficients()
    assert c.cv == 0.277
    assert c.layer1_weights.shape == (13, 18)
    assert c.bound_min.shape == c.bound_max.shape == (3, 3, 3, 3)
    assert c.output_offset == 44.2451801385399
    assert "CC-BY 4.0" in c.source


def test_percent_capable_and_strength_are_inverse():
    body = posture(POSTURES["forward_at_shoulder"])
    answer = arm_force(body, "left", (0, 1, 0))
    for capable in (5.0, 25.0, 50.0, 75.0, 95.0):
        assert answer.percent_capable(answer.strength(capable)) == pytest.approx(capable)


def test_a_hand_at_the_shoulder_is_refused_naming_the_joint():
    points = [list(p) for p in POSTURES["forward_at_shoulder"]]
    points[0] = list(points[3])  # left knuckle on the left shoulder
    with pytest.raises(ArmForceError, match="l_metacarpophalangeal_3 is within 1 cm of l_shoulder"):
        arm_force(posture(points), "left", (0, 1, 0))


@pytest.mark.parametrize(
    "change, message",
    [
        ({"l_wrist": [0, 0, 0]}, "unknown joint 'l_wrist'"),
        ({"vc7": [0, "1", 0]}, r"vc7: expected \[x, y, z\] in metres"),
        ({"vc7": [0, float("nan"), 0]}, "vc7: .* not three finite numbers"),
        ({"r_elbow": [0, 1]}, r"r_elbow: expected \[x, y, z\]"),
    ],
)
def test_bad_postures_name_the_field(change, message):
    points = dict(zip(POSTURE_JOINTS, POSTURES["bent_trunk"]))
    points.update(change)
    with pytest.raises(ArmForceError, match=message):
        check_posture(points)


def test_a_missing_joint_is_named():
    points = dict(zip(POSTURE_JOINTS, POSTURES["bent_trunk"]))
    del points["vl5"]
    with pytest.raises(ArmForceError, match="no vl5"):
        check_posture(points)


@pytest.mark.parametrize(
    "text, message",
    [
        ("0,0,0", "the zero vector has no direction"),
        ("nan,1,0", "three finite numbers"),
        ("sideways", "expected one of up, down, forward, back, left, right"),
        ("1,2", "expected one of"),
    ],
)
def test_bad_directions_are_refused(text, message):
    with pytest.raises(ArmForceError, match=message):
        parse_direction(text)


def test_direction_words_and_vectors():
    assert parse_direction("Up").tolist() == [0.0, 1.0, 0.0]
    v = parse_direction("-0.2,-0.3,0.9")
    assert math.isclose(float((v * v).sum()), 1.0)


@settings(max_examples=60, deadline=None)
@given(
    st.one_of(
        st.text(max_size=30),
        st.lists(st.floats(), min_size=3, max_size=3).map(lambda v: ",".join(map(repr, v))),
    )
)
def test_any_direction_text_is_a_unit_vector_or_a_clear_refusal(text):
    try:
        v = parse_direction(text, "--direction")
    except ArmForceError as exc:
        assert str(exc).startswith("--direction ")  # the caller's name for it
    else:
        assert math.isclose(float((v * v).sum()), 1.0, rel_tol=1e-9)


# --- where the network was fitted ---------------------------------------------------
# The authors' script scales each input as MATLAB's mapminmax does,
# p = in1gain * (x - in1offset) - 1, so the data it was fitted on ran from
# in1offset to in1offset + 2 / in1gain (read from their script below).
SCRIPT = SHARED / "reference" / "arm-force-field" / "AFFinPython - v1.0.py"


def _script_array(text: str, name: str) -> list[float]:
    found = re.search(rf"^{name} = np\.array\(\[(.*?)\]\)", text, re.S | re.M)
    assert found, name
    return [float(v) for v in found.group(1).replace("\n", " ").split(",")]


def test_the_fitted_region_is_the_authors_scaling():
    if not SCRIPT.is_file():
        pytest.skip("../shared/reference/arm-force-field is absent")
    text = SCRIPT.read_text(encoding="utf-8")
    offset, gain = _script_array(text, "in1offset"), _script_array(text, "in1gain")
    assert re.search(r"^in1min = -1$", text, re.M)
    expected = [(o, o + 2.0 / g) for o, g in zip(offset, gain)]
    got = fitted_ranges(read_coefficients())
    assert len(got) == len(expected) == 18
    for (low, high), (want_low, want_high) in zip(got, expected):
        assert low == pytest.approx(want_low, abs=1e-12)
        assert high == pytest.approx(want_high, abs=1e-12)
    # the hand's place: 0.41 m below to 0.48 m above the shoulder, up to 0.52 m ahead
    assert got[0] == pytest.approx((-0.4145, 0.4768), abs=1e-4)
    assert got[1] == pytest.approx((0.0, 0.5218), abs=1e-4)


def test_the_authors_example_is_inside_and_a_hand_far_ahead_or_below_is_flagged():
    example = posture(EXAMPLE)
    for side in ("left", "right"):
        assert arm_force(example, side, (0, 1, 0)).outside_fitted == "", side
    # forward_at_shoulder holds the hands 0.60 m ahead of the shoulders at their
    # height: past the 0.52 m fitted, the height inside.
    answer = arm_force(posture(POSTURES["forward_at_shoulder"]), "right", (0, 0, 1))
    assert answer.outside_fitted.startswith("the hand 0.60 m forward (fitted 0.00 to 0.52)")
    assert answer.outside_fitted.endswith("extrapolated")
    assert " up " not in answer.outside_fitted
    # the right hand hanging 0.69 m below the shoulder: below the 0.41 m fitted
    low = [list(p) for p in POSTURES["forward_at_shoulder"]]
    low[4], low[5], low[6] = [-0.2, 0.71, -0.05], [-0.2, 0.79, -0.05], [-0.2, 1.1, -0.05]
    hanging = arm_force(posture(low), "right", (0, 1, 0))
    assert "the hand -0.69 m up (fitted -0.41 to 0.48)" in hanging.outside_fitted
