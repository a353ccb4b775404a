"""Anderson et al. 2007's lower-limb torque model, recomputed independently.

The coefficients below are typed from Table 3 of D. E. Anderson, M. L.
Madigan, M. A. Nussbaum, J. Biomech. 40(14):3105-3113 (2007) (mean, and the
standard deviation of C1), and the torque from the paper's equations:

    T = C1 m g h cos(C2 (theta - C3)) (2 C4 C5 + w (C5 - 3 C4)) / (2 C4 C5 + w (2 C5 - 4 C4))

with g = 9.81, theta in rad, w the concentric speed in rad/s.  Nothing here
reads sass's data file: sass must agree within 0.5 %.
"""

from __future__ import annotations

import json
import math
from statistics import NormalDist

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles
from sass_tui.model.names import JOINT_LIMITS
from sass_tui.model.strength.percent_capable import lower_limb_capable
from sass_tui.model.strength.published_strength import (
    PublishedStrengthError,
    Subject,
    age_group,
    beyond_curve,
    curve_region,
    lower_limb_percent_capable,
    lower_limb_strength,
    parse_strength_limit,
    read_anderson2007,
)
from sass_tui.model.strength.task import Reference, assess_task

# Table 3 as printed: (motion, gender, age group) -> C1, C2, C3, C4, C5, SD of C1.
TABLE3 = {
    ("knee_extension", "male", "18-25"): (0.163, 1.258, 1.133, 1.517, 3.952, 0.040),
    ("knee_flexion", "female", "18-25"): (0.080, 0.873, 0.635, 1.698, 4.412, 0.015),
    ("hip_flexion", "female", "55-65"): (0.091, 0.812, -0.196, 2.145, 4.366, 0.016),
    ("hip_extension", "male", "55-65"): (0.171, 0.922, 1.176, 1.601, 3.236, 0.043),
    ("ankle_plantarflexion", "male", "over-65"): (0.106, 1.465, 0.498, 0.490, 1.767, 0.035),
    ("ankle_dorsiflexion", "female", "over-65"): (0.022, 1.096, -0.369, 0.458, 1.242, 0.003),
}
AGE_OF = {"18-25": 21, "55-65": 60, "over-65": 72}


def paper_torque(key, mass, stature, angle_deg, speed_deg_s, percentile=50.0):
    c1, c2, c3, c4, c5, sd1 = TABLE3[key]
    c1 += NormalDist().inv_cdf(percentile / 100) * sd1
    theta, w = math.radians(angle_deg), math.radians(speed_deg_s)
    tv = (2 * c4 * c5 + w * (c5 - 3 * c4)) / (2 * c4 * c5 + w * (2 * c5 - 4 * c4))
    return c1 * mass * 9.81 * stature * math.cos(c2 * (theta - c3)) * tv


@pytest.mark.parametrize("key", sorted(TABLE3))
@pytest.mark.parametrize("angle", [-10.0, 20.0, 45.0, 70.0])
@pytest.mark.parametrize("speed", [0.0, 60.0, 180.0])
def test_sass_matches_the_paper_within_half_a_percent(key, angle, speed):
    motion, gender, group = key
    subject = Subject(gender, AGE_OF[group], 71.5, 1.69)
    expected = paper_torque(key, 71.5, 1.69, angle, speed)
    if expected <= 0:  # beyond the active curve's range: sass says no torque
        expected = 0.0
    got = lower_limb_strength(motion, subject, angle, speed).torque
    assert got == pytest.approx(expected, rel=0.005, abs=1e-9)


@pytest.mark.parametrize("percentile", [5.0, 25.0, 95.0])
def test_percentiles_take_c1_from_the_published_spread(percentile):
    key = ("knee_extension", "male", "18-25")
    got = lower_limb_strength("knee_extension", Subject("male", 20, 80, 1.8), 60, 30, percentile)
    assert got.torque == pytest.approx(paper_torque(key, 80, 1.8, 60, 30, percentile), rel=0.005)
    assert got.source == f"Anderson et al. 2007, young men, {percentile:g}th percentile"


def test_peak_isometric_knee_extension_of_a_young_man_is_c1_m_g_h():
    got = lower_limb_strength("knee_extension", Subject("male", 21, 75, 1.75))
    assert got.angle == pytest.approx(math.degrees(1.133))  # the paper's C3
    assert got.torque == pytest.approx(0.163 * 75 * 9.81 * 1.75, rel=1e-9)  # 209.87 N-m
    assert got.source == "Anderson et al. 2007, young men, mean"


def test_the_shipped_file_has_every_block_of_table_3():
    data = read_anderson2007()
    assert len(data.mean) == len(data.sd) == 36
    c = data.mean[("ankle_dorsiflexion", "female", "over-65")]
    assert (c.c1, c.c2, c.c3, c.c4, c.c5, c.c6) == (0.022, 1.096, -0.369, 0.458, 1.242, 1.401)


@pytest.mark.parametrize(
    ("age", "group"),
    [(18, "18-25"), (25, "18-25"), (40, "18-25"), (41, "55-65"), (65, "55-65"), (66, "over-65")],
)
def test_age_picks_the_papers_group(age, group):
    assert age_group(age) == group


@pytest.mark.parametrize("age", [17.9, 100.5, float("nan")])
def test_ages_outside_18_to_100_are_refused_with_the_groups_listed(age):
    with pytest.raises(PublishedStrengthError, match="18-25, 55-65, over-65"):
        age_group(age)


def test_cli_answers_name_their_source(capsys):
    assert main(["strength", "knee_extension", "--mass", "75", "--stature", "175"]) == 0
    out = capsys.readouterr().out
    assert "209.87 N-m" in out  # in the source's unit: N-m
    assert main(["strength", "knee_extension", "--unit", "ft-lb", "--mass", "75"]) == 0
    assert " ft-lb " in capsys.readouterr().out
    assert "source: Anderson et al. 2007, young men, mean" in out
    assert main(["strength", "knee_extension", "--unit", "N-m", "--mass", "75"]) == 0
    assert main(["strength", "--format", "json", "--unit", "N-m", "knee_extension"]) == 0
    answer = json.loads(capsys.readouterr().out.splitlines()[-1])
    assert answer["source"] == "Anderson et al. 2007, young men, mean"
    assert answer["value"] == pytest.approx(
        0.163 * answer["mass_kg"] * 9.81 * answer["stature_m"], abs=0.01
    )
    # to the data's precision
    assert answer["angles"]["knee_y"] == 64.9 and answer["peak_angle"] == 64.9
    assert answer["value"] == round(answer["value"], 2)
    assert main(["strength", "shoulder_abduction", "shoulder_x=30"]) == 0
    assert "source: example data (invented, for the report's worked examples)" in (
        capsys.readouterr().out
    )


def test_cli_isokinetic_and_age_and_plot(capsys):
    argv = ["strength", "--unit", "N-m", "--gender", "female", "--age", "70", "--mass", "60"]
    argv += ["--stature", "160", "--strength-type", "isokinetic", "--motion-speed", "120"]
    assert main([*argv, "ankle_plantarflexion", "ankle_y=10", "--plot"]) == 0
    out = capsys.readouterr().out
    c1, c2, c3, c4, c5 = 0.125, 1.299, 0.58, 0.587, 1.819  # women over 65, Table 3
    w = math.radians(120)
    tv = (2 * c4 * c5 + w * (c5 - 3 * c4)) / (2 * c4 * c5 + w * (2 * c5 - 4 * c4))
    expected = c1 * 60 * 9.81 * 1.6 * math.cos(c2 * (math.radians(10) - c3)) * tv
    assert f"{expected:.2f} N-m" in out
    assert "source: Anderson et al. 2007, older women, mean" in out
    assert "torque (N-m)" in out and "*" in out  # the curve


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["knee_extension", "--age", "17"], "outside 18-100 years"),
        (["knee_extension", "hip_y=10"], "about knee_y only"),
        (["knee_extension", "knee_y=150"], "upper limit"),
        (["knee_extension", "--strength-data", "example"], "no hip, knee or ankle"),
        (["elbow_flexion", "--strength-data", "anderson2007"], "covers hip_flexion"),
        (["knee_extension", "--fatigue-level", "10"], "no training or fatigue"),
        (["elbow_flexion", "--person", "17"], "no model of a person"),
    ],
)
def test_cli_refusals_say_why(capsys, argv, message):
    assert main(["strength", *argv]) == 2
    assert message in capsys.readouterr().err


@settings(max_examples=60, deadline=None)
@given(st.lists(st.text(max_size=40), max_size=4))
def test_a_damaged_coefficient_file_is_refused_not_crashed(tmp_path_factory, lines):
    path = tmp_path_factory.mktemp("anderson") / "a.csv"
    good = read_anderson2007().path
    with open(good, encoding="utf-8") as handle:
        text = handle.read().splitlines()
    path.write_text("\n".join(text[:20] + lines + text[20:]) + "\n", encoding="utf-8")
    try:
        read_anderson2007(str(path))
    except PublishedStrengthError as exc:
        assert str(path) in str(exc)


def test_fig_names_the_source_of_every_strength_section(tmp_path):
    from sass_tui.model.files.fig_reader import read_fig

    out = tmp_path / "m.fig"
    argv = ["fig", "-o", str(out), "--mass", "75", "--stature", "175"]
    assert main([*argv, "--strength-data", "example"]) == 0
    text = out.read_text()
    assert "source: example data (invented, for the report's worked examples) */" in text
    assert (
        "/* hip, knee and ankle strength variables: Anderson et al. 2007, young men, mean" in text
    )
    variables = read_fig(out).variables
    # knee extension peaks at C3 = 64.9 deg, inside the knee's limits: C1 m g h
    expected = 0.163 * 75 * 9.81 * 1.75
    assert variables["right_knee_extension_strength"] == (round(expected, 2), "Nm")
    assert variables["left_knee_extension_strength"] == (round(expected, 2), "Nm")


@pytest.mark.parametrize(
    ("text", "torque", "angle"),
    [
        ("strength.knee_extension >= 150 N-m at knee_y=60", 150.0, 60.0),
        ("knee_extension>=100 ft-lb", 100 * 1.3558179483314004, None),
        ("ankle_dorsiflexion < 40 at ankle_y=0.1 rad", 40.0, math.degrees(0.1)),
    ],
)
def test_strength_limits_parse(text, torque, angle):
    limit = parse_strength_limit(text)
    assert limit.torque == pytest.approx(torque)
    assert limit.angle == (None if angle is None else pytest.approx(angle))


def test_a_strength_limit_passes_fails_or_cannot_say():
    limit = parse_strength_limit("knee_extension >= 200 N-m")  # at the peak: C1 m g h
    assert limit.passes("male", 21, 75, 175) == 1.0  # 209.87 N-m
    assert limit.passes("male", 21, 70, 175) == 0.0  # 195.88 N-m
    assert math.isnan(limit.passes("male", 17, 75, 175))  # the paper starts at 18
    assert math.isnan(limit.passes("male", 21, math.nan, 175))


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=60))
def test_any_strength_limit_text_parses_or_is_refused(text):
    try:
        limit = parse_strength_limit(text)
    except PublishedStrengthError as exc:
        assert "strength limit" in str(exc)
    else:
        squeezed = "".join(text.lower().replace("_", " ").split())
        assert limit.motion.replace("_", "") in squeezed and math.isfinite(limit.torque)


def test_cli_plot_as_json_gives_the_curve_over_the_joint_limits(capsys):
    argv = ["strength", "knee_flexion", "--plot", "--format", "json", "--unit", "N-m"]
    assert main([*argv, "--mass", "70", "--stature", "170", "--gender", "female"]) == 0
    curve = json.loads(capsys.readouterr().out)["curve"]
    assert (curve[0][0], curve[-1][0]) == (0.0, 135.2)  # female knee y limits, 50th percentile
    c1, c2, c3 = 0.080, 0.873, 0.635  # Table 3, knee flexion, women 18-25
    for angle, torque in curve[::10]:
        expected = c1 * 70 * 9.81 * 1.7 * max(0.0, math.cos(c2 * (math.radians(angle) - c3)))
        assert torque == pytest.approx(expected, rel=0.005, abs=1e-3)


@pytest.mark.parametrize("torque", [60.0, 120.0, 150.0, 200.0])
def test_knee_extension_percent_capable_at_the_peak_is_one_minus_phi(torque):
    # Table 3, knee extension, women 18-25: C1 mean 0.159, SD 0.028; C3 1.274 rad.
    mass, stature = 62.0, 1.64
    expected = 100 * (1 - NormalDist().cdf((torque / (mass * 9.81 * stature) - 0.159) / 0.028))
    subject = Subject("female", 22, mass, stature)
    got = lower_limb_percent_capable("knee_extension", subject, torque)
    assert got == pytest.approx(expected, abs=1e-6)
    # and at the peak angle given in degrees, as the CLI gives it
    at_peak = lower_limb_percent_capable("knee_extension", subject, torque, math.degrees(1.274))
    assert at_peak == pytest.approx(expected, abs=1e-6)


def test_percent_capable_is_the_percentile_read_backwards():
    subject = Subject("male", 60, 80.0, 1.78)
    for percentile in (5.0, 50.0, 90.0):
        torque = lower_limb_strength("hip_extension", subject, 30, 0, percentile).torque
        share = lower_limb_percent_capable("hip_extension", subject, torque, 30)
        assert share == pytest.approx(100 - percentile, abs=1e-6)


def test_cli_load_gives_percent_capable(capsys):
    argv = ["strength", "knee_extension", "--gender", "female", "--mass", "62", "--stature"]
    assert main([*argv, "164", "--age", "22", "--load", "120 N-m", "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    expected = 100 * (1 - NormalDist().cdf((120 / (62 * 9.81 * 1.64) - 0.159) / 0.028))
    assert answer["percent_capable"] == pytest.approx(expected, abs=0.05)
    assert answer["load_N_m"] == 120.0
    assert main(["strength", "elbow_flexion", "--load", "20"]) == 2
    assert "the example data have no spread of people" in capsys.readouterr().err


def test_many_people_at_once_agree_with_one_at_a_time():
    people = [("female", 22, 62.0, 1.64), ("male", 60, 85.0, 1.80), ("female", 80, 58.0, 1.55)]
    genders, ages, masses, statures = zip(*people)
    many = lower_limb_capable("knee_extension", genders, ages, masses, statures, 120.0, 60.0)
    for (gender, age, mass, stature), got in zip(people, many):
        one = lower_limb_percent_capable(
            "knee_extension", Subject(gender, age, mass, stature), 120.0, 60.0
        )
        assert 100 * got == pytest.approx(one, abs=1e-9)
    unknown = lower_limb_capable("knee_extension", ["male"] * 3, [17, 30, 30], [80, 0, 80],
                                 [1.8, 1.8, float("nan")], 100.0)  # fmt: skip
    assert np.isnan(unknown).all()


def test_cli_plot_with_a_load_gives_the_curve_of_percent_capable(capsys):
    argv = ["strength", "knee_extension", "--gender", "female", "--load", "120 N-m", "--plot"]
    assert main([*argv, "--format", "json"]) == 0
    answer = json.loads(capsys.readouterr().out)
    curve = answer["capable_curve"]
    assert curve[0] == [0.0, 100.0] and curve[-1][1] == pytest.approx(0.5, abs=0.05)
    assert all(a[1] >= b[1] for a, b in zip(curve, curve[1:]))
    # the load's share lies on the curve
    below = max(p for p in curve if p[0] <= 120.0)
    above = min(p for p in curve if p[0] >= 120.0)
    assert below[1] >= answer["percent_capable"] >= above[1]
    assert main(argv) == 0
    assert "percent capable against the torque" in capsys.readouterr().out


@pytest.mark.parametrize("key", sorted(TABLE3))
def test_the_fitted_curve_gives_torque_only_within_c3_plus_or_minus_90_deg_over_c2(key):
    """Beyond C3 +/- 90 deg / C2 (Table 3's typed C2, C3) the cosine term is
    not positive: the model has no torque there, and sass says so."""
    motion, gender, group = key
    _, c2, c3, *_ = TABLE3[key]
    low, high = math.degrees(c3) - 90 / c2, math.degrees(c3) + 90 / c2
    assert curve_region(motion, gender, group) == pytest.approx((low, high), abs=0.05)
    subject = Subject(gender, AGE_OF[group], 70.0, 1.70)
    for inside in (low + 0.5, high - 0.5):
        assert lower_limb_strength(motion, subject, inside).torque > 0
        assert beyond_curve(motion, gender, [group], inside) == ""
    for outside in (low - 0.5, high + 0.5):
        assert lower_limb_strength(motion, subject, outside).torque == 0
        note = beyond_curve(motion, gender, [group], outside)
        assert f"outside {low:.0f} to {high:.0f} deg" in note and "extrapolated" in note


def test_sass_strength_says_when_the_angle_is_beyond_the_fitted_curve(capsys):
    # knee extension, women over 65: the curve ends at 132 deg; the 50th
    # percentile woman's knee bends to 135.2 deg
    argv = ["strength", "knee_extension", "knee_y=134", "--gender", "female", "--age", "70"]
    assert main([*argv, "--mass", "70", "--stature", "160"]) == 0
    out = capsys.readouterr().out
    assert "0.00 N-m" in out
    assert "note: knee extension at 134 deg lies outside -1 to 132 deg" in out
    assert main([*argv, "--format", "json"]) == 0
    assert "outside -1 to 132 deg" in json.loads(capsys.readouterr().out)["outside_fitted"]
    assert main(["strength", "knee_extension", "knee_y=90", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["outside_fitted"] is None


def test_a_tasks_knee_beyond_the_curve_is_marked_extrapolated():
    """A deep squat a 99th-percentile knee range allows (134 deg): for men
    over 65 knee extension's curve ends at 130 deg, for men of 18-25 at 136."""
    figure = Figure.default("male")
    figure.set_group_percentile(JOINT_LIMITS, 99)
    squat = parse_angles(["hip_y=110", "knee_y=134", "ankle_y=20", "trunk_y=45", "shoulder_y=90"])
    older = assess_task([Reference("men", figure, 70.0)], squat, [])
    knees = [c for c in older.capabilities if c.what.endswith("knee")]
    assert [c.motion for c in knees] == ["knee_extension"] * 2
    assert all("outside -8 to 130 deg" in c.extrapolated for c in knees)
    young = assess_task([Reference("men", figure, 20.0)], squat, [])
    assert all(c.extrapolated == "" for c in young.capabilities if c.what.endswith("knee"))
