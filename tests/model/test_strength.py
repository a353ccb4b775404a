"""Strength: the file, lookup, prediction, modifiers, Right->Left, CLI, .fig."""

from __future__ import annotations

import math

import numpy as np
import pytest

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.fig_reader import read_fig
from sass_tui.model.names import JOINT_LIMITS
from sass_tui.model.strength.strength import (
    DEFAULT_NON_DOMINANT_FACTOR,
    MOTION_NAMES,
    STRENGTH_CV,
    StrengthError,
    StrengthFileError,
    StrengthSheet,
    fatigue_factor,
    fit_summary,
    parse_strength_text,
    read_strength_file,
    strength_percentile,
)

ABDUCTION, ELBOW_FLEXION = 0, MOTION_NAMES.index("elbow_flexion")


@pytest.fixture(scope="module")
def data():
    return read_strength_file()


@pytest.fixture
def male(data):
    return StrengthSheet(data, Figure.default("male"))


def test_default_file_loads_cleanly_with_both_genders_and_every_motion(data):
    assert data.warnings == []
    assert set(data.sections) == {("male", "right"), ("female", "right")}
    for section in data.sections.values():
        assert set(section.motions) == set(range(14))


def test_report_point_comes_back_exactly_in_ft_lb_and_n_m(male):
    row = male.row(ABDUCTION)
    assert row.angles[:4] == (30.0, 45.0, 0.0, 90.0)
    assert (row.value, row.source, row.side, row.unit) == (17.98, "stored", "right", "ft-lb")
    male.toggle_unit()
    row = male.row(ABDUCTION)
    assert row.unit == "N-m" and round(row.value, 2) == 24.38


def test_configuration_between_stored_ones_is_predicted_and_says_so(male):
    at_60 = male.set_angle(ABDUCTION, "shoulder_x", 60).value
    assert male.row(ABDUCTION).source == "stored"
    between = male.set_angle(ABDUCTION, "shoulder_x", "45 deg")
    assert between.source == "predicted"
    assert at_60 < between.value < 17.98
    # An angle in radians that lands on a stored one is the stored value again.
    again = male.set_angle(ABDUCTION, "shoulder_x", f"{math.radians(30)} rad")
    assert again.source == "stored" and again.value == 17.98


def test_elbow_170_refused_for_a_male_at_the_95th_joint_limits(male):
    male.figure.set_group_percentile(JOINT_LIMITS, 95)
    before = male.row(ELBOW_FLEXION)
    with pytest.raises(StrengthError, match=r"right elbow upper limit 159 deg .*95th"):
        male.set_angle(ELBOW_FLEXION, "elbow_y", 170)
    assert male.row(ELBOW_FLEXION) == before
    assert male.set_angle(ELBOW_FLEXION, "elbow_y", 155).angles[3] == 155


def test_male_shoulder_z_lower_limit_is_negative(male):
    male.set_angle(4, "shoulder_z", -90)  # medial rotation within -108.55
    with pytest.raises(StrengthError, match="lower limit -108.55"):
        male.set_angle(4, "shoulder_z", -120)


def _values(sheet):
    return np.array([r.value for r in sheet.rows()])


def test_each_modifier_moves_every_value_by_its_documented_amount(male):
    base = _values(male)
    figure = male.figure
    figure.set_strength_parameter("motion_speed", 50)
    assert np.allclose(_values(male), base)  # isometric ignores speed
    figure.set_strength_parameter("strength_type", "isokinetic")
    # no published source for the decay: off unless asked for, and the title says so
    assert np.allclose(_values(male), base)
    assert "isokinetic decay and training gain off" in male.title
    male.assumed_modifiers = True
    assert "assumed modifiers on" in male.title
    assert np.allclose(_values(male), base * 46.9 / 68.6)
    figure.set_strength_parameter("strength_type", "isotonic")
    assert np.allclose(_values(male), base * 46.9 / 68.6)
    figure.set_strength_parameter("strength_type", "isometric")
    figure.set_strength_parameter("handedness", "left")
    assert np.allclose(_values(male), base / 1.116)
    figure.set_strength_parameter("handedness", "right")
    figure.set_strength_parameter("training_level", 2)
    assert np.allclose(_values(male), base * 1.2)
    figure.set_strength_parameter("training_level", 0)
    figure.set_strength_parameter("fatigue_level", 60)
    tired = _values(male)
    assert np.isclose(tired[ABDUCTION], base[ABDUCTION] * (60 / 14.86) ** (-1 / 1.83))
    assert np.isclose(tired[ELBOW_FLEXION], base[ELBOW_FLEXION] * (60 / 17.98) ** (-1 / 2.21))
    assert fatigue_factor(10, "shoulder") == 1.0  # below b0 nothing is lost yet


def test_percentiles_follow_the_coefficient_of_variation(data, male):
    median = male.row(ELBOW_FLEXION).value
    male.set_percentile(95)
    assert male.row(ELBOW_FLEXION).value == pytest.approx(median * (1 + 1.6448536 * STRENGTH_CV))
    # That row is stored at the 95th: at the 95th it is the file's value exactly.
    section = data.sections[("male", "right")]
    first = np.flatnonzero(section.motions == ELBOW_FLEXION)[0]
    assert male.row(ELBOW_FLEXION).value == section.values[first]
    assert strength_percentile(male.row(ELBOW_FLEXION).value, median) == pytest.approx(95)
    with pytest.raises(ValueError, match="outside 0.5-99.5"):
        male.set_percentile(100)


def test_female_strength_is_lower_by_the_documented_ratios(data):
    male = _values(StrengthSheet(data, Figure.default("male")))
    female = _values(StrengthSheet(data, Figure.default("female")))
    ratio = female / male
    assert np.allclose(ratio[:6], 0.50, atol=0.005)
    assert np.allclose(ratio[6:8], 0.57, atol=0.005)
    assert np.allclose(ratio[8:], 0.641, atol=0.005)


def test_right_to_left_with_a_typed_factor_and_with_return(male):
    right = _values(male)
    message = male.switch_side("0.8")
    assert male.side == "left" and "0.800" in message
    assert np.allclose(_values(male), right * 0.8)
    assert all(r.side == "left" for r in male.rows())
    male.switch_side("")
    assert male.side == "right" and np.allclose(_values(male), right)
    assert "(default)" in male.switch_side("")
    assert np.allclose(_values(male), right * DEFAULT_NON_DOMINANT_FACTOR)
    with pytest.raises(StrengthError, match="not a number"):
        male.switch_side("abc")
    assert male.side == "left"


def test_page_is_fourteen_rows_and_one_page(male):
    assert male.pages == 1 and len(male.page(0)) == 14


def test_fit_errors_are_what_the_equation_gives_back_on_the_stored_points(data):
    summary = fit_summary(data)
    assert len(summary) == 28
    model = data.model("male", "right")
    section = model.section
    median = section.values / (
        1
        + np.array([0 if p == 50 else 1.6448536269514722 for p in section.percentiles])
        * STRENGTH_CV
    )
    predicted = model.predict_median(section.motions, section.angles)
    relative = np.abs(predicted / median - 1) * 100
    for fit in model.fits:
        mask = section.motions == MOTION_NAMES.index(fit.motion)
        assert relative[mask].max() == pytest.approx(fit.max_percent, abs=1e-6)
        assert fit.rms_percent < 25


GOOD = """P test
G MALE
L RIGHT
 30 45 0 90 0 0 0 17.98 50 /* shoulder abduction */
 60 45 0 90 0 0 0 11.24 50 /* shoulder abduction */
"""


@pytest.mark.parametrize(
    "text, expected",
    [
        ("", r"<t>:1: the file is empty"),
        ("P t\nG BOTH\n", r"<t>:2: expected 'G MALE' or 'G FEMALE'"),
        ("P t\nL RIGHT\n", r"<t>:2: 'L RIGHT' before 'G MALE'"),
        ("P t\nG MALE\nL UP\n", r"<t>:3: expected 'L RIGHT' or 'L LEFT'"),
        ("P t\nG MALE\n 1 2 3 4 5 6 7 8 50 /* elbow flexion */\n", r"<t>:3: data before"),
        (GOOD + " 1 2 3 4 5 6 7 8 /* elbow flexion */\n", r"<t>:6: 8 numbers; expected 9"),
        (GOOD + " 1 2 x 4 5 6 7 8 50 /* elbow flexion */\n", r"<t>:6: value 3 is 'x'"),
        (
            GOOD + " 1 2 3 4 5 6 7 8 50 /* knee kicking */\n",
            r"<t>:6: unknown motion 'knee kicking'",
        ),
        (GOOD + " 1 2 3 4 5 6 7 8 50\n", r"<t>:6: no /\* motion \*/ comment"),
        (GOOD + " 1 2 3 4 5 6 7 8 50 /* elbow flexion\n", r"<t>:6: comment '/\*' is not closed"),
        (GOOD + " 1 2 3 4 5 6 7 8 100 /* elbow flexion */\n", r"<t>:6: percentile 100"),
        (GOOD + "L RIGHT\n", r"<t>:6: a second G MALE / L RIGHT section \(first at line 3\)"),
    ],
)
def test_a_broken_file_is_rejected_whole_with_file_and_line(text, expected):
    with pytest.raises(StrengthFileError, match=expected):
        parse_strength_text(text, "<t>")


def test_suspicious_rows_warn_and_loading_goes_on():
    text = GOOD + (
        " 1 2 3 90 5 6 7 20 50 /* elbow flexion */\n"
        " 60 45 0 90 0 0 0 11.50 50 /* shoulder abduction: again */\n"
        " 999 2 3 90 5 6 7 20 50 /* elbow flexion */\n"
        " 1 2 3 80 5 6 7 999 50 /* elbow flexion */\n"
        " 1 2 3 70 5 6 7 -2 50 /* elbow flexion */\n"
    )
    data = parse_strength_text(text, "<t>")
    joined = "\n".join(data.warnings)
    assert "<t>:7: Shoulder abduction: out of display order" in joined
    assert "<t>:7: Shoulder abduction: configuration given again (first at line 5)" in joined
    assert "<t>:8: Elbow flexion: no value for shoulder_x; row not used" in joined
    assert "<t>:9: Elbow flexion: no strength value" in joined
    assert "<t>:10: Elbow flexion: strength -2 is not positive" in joined
    assert "<t>:3: G MALE / L RIGHT has no data for Shoulder adduction" in joined
    section = data.sections[("male", "right")]
    assert len(section.values) == 3 and 11.50 in section.values
    sheet = StrengthSheet(data, Figure.default("male"))
    assert sheet.row(1).source == "no data" and math.isnan(sheet.row(1).value)


def test_cli_strength_prints_stored_and_predicted(capsys):
    assert (
        main(["strength", "shoulder_abduction", "shoulder_x=30", "shoulder_y=45", "elbow_y=90"])
        == 0
    )
    out = capsys.readouterr().out
    assert "right shoulder abduction: 17.98 ft-lb (stored; male, 50th percentile)" in out
    assert main(["strength", "--unit", "N-m", "shoulder_abduction", "shoulder_x=30"]) == 0
    assert "24.38 N-m (stored" in capsys.readouterr().out
    assert main(["strength", "shoulder_abduction", "shoulder_x=45"]) == 0
    assert "(predicted by the least-squares equation" in capsys.readouterr().out


def test_cli_strength_refuses_an_angle_beyond_the_limit(capsys):
    assert main(["strength", "--joint-limit-percentile", "95", "elbow_flexion", "elbow_y=170"]) == 2
    err = capsys.readouterr().err
    assert (
        "sass strength: error: right elbow y 170 deg is above the right elbow upper "
        "limit 159 deg" in err
    )
    assert main(["strength", "elbow_flexion", "elbow=90"]) == 2
    assert "unknown joint axis 'elbow'" in capsys.readouterr().err


def test_fig_carries_no_invented_strength_by_default(tmp_path, capsys):
    plain = tmp_path / "plain.fig"
    assert main(["fig", "-o", str(plain)]) == 0
    text = plain.read_text()
    assert "TEST DATA" not in text and "example data" not in text
    names = [n for n in read_fig(plain).variables if n.endswith("_strength")]
    # only the published hip, knee and ankle (Anderson et al. 2007)
    assert len(names) == 12 and all(n.split("_")[1] in ("hip", "knee", "ankle") for n in names)
    assert "note:" not in capsys.readouterr().err


def test_fig_includes_the_example_strength_only_by_name(tmp_path, capsys):
    out = tmp_path / "with.fig"
    assert main(["fig", "--strength-data", "example", "-o", str(out)]) == 0
    assert (
        "note: the arm's strength variables are example data (invented, for the report's "
        "worked examples), not measured strength" in capsys.readouterr().err
    )
    variables = read_fig(out).variables
    assert variables["right_shoulder_abduction_strength"] == (24.38, "Nm")
    assert variables["left_shoulder_abduction_strength"][0] == pytest.approx(
        24.38 / 1.116, abs=0.01
    )
    # 28 arm (example data) + 12 hip, knee and ankle (Anderson et al. 2007)
    assert sum(name.endswith("_strength") for name in variables) == 28 + 12
    bare = tmp_path / "without.fig"
    assert main(["fig", "--no-strength", "-o", str(bare)]) == 0
    assert not any(name.endswith("_strength") for name in read_fig(bare).variables)
    broken = tmp_path / "broken.dat"
    broken.write_text("P x\nG MALE\n")
    assert main(["fig", "--strength", str(broken), "-o", str(tmp_path / "no.fig")]) == 2
    assert not (tmp_path / "no.fig").exists()


# --- strength answers say what they are -----------------------------------------


def test_every_output_of_the_shipped_test_data_says_so(tmp_path, capsys, data, male):
    assert data.test_data and "TEST DATA" in data.label
    assert "TEST DATA" in male.title  # the strength page's title comes from here
    assert main(["strength", "shoulder_abduction"]) == 0
    assert "test data" in capsys.readouterr().out.lower()
    out = tmp_path / "m.fig"
    assert main(["fig", "-o", str(out), "--strength-data", "example"]) == 0
    assert (
        "/* strength variables: TEST DATA, not measured strength (strength.dat); "
        "source: example data (invented, for the report's worked examples) */"
    ) in out.read_text()
    # a file that does not call itself test data is not labelled so
    mine = parse_strength_text(GOOD, "mine.dat")
    assert not mine.test_data and "TEST DATA" not in mine.label


def test_shoulder_flexion_far_outside_the_data_is_marked_or_refused(male, capsys):
    flexion = MOTION_NAMES.index("shoulder_flexion")
    model = male.data.model("male", "right")
    high = model.high[flexion, 1]
    far = male.set_angle(flexion, "shoulder_y", 180)  # the page marks it
    assert far.extrapolated == (
        "shoulder_y 180 deg is outside the data's 0 to 75 deg, more than 20 deg: not to be trusted"
    )
    assert main(["strength", "shoulder_flexion", "shoulder_y=180"]) == 2  # the CLI refuses
    assert "refuses a prediction more than 20 deg outside the data" in capsys.readouterr().err
    # within the margin: predicted and marked
    row = male.set_angle(flexion, "shoulder_y", high + 10)
    assert row.source == "predicted" and "outside the data's 0 to 75 deg" in row.extrapolated
    inside = male.set_angle(flexion, "shoulder_y", 30)
    assert inside.source == "predicted" and inside.extrapolated == ""


def test_an_angle_the_data_never_vary_says_so(male, capsys):
    flexion = MOTION_NAMES.index("shoulder_flexion")
    before = male.set_angle(flexion, "shoulder_y", 30)  # predicted, inside the data
    row = male.set_angle(flexion, "shoulder_z", -30)
    assert row.extrapolated == (
        "shoulder_z -30 deg: the data hold shoulder_z only at 0 deg, so the prediction "
        "does not vary with it"
    )
    assert row.value == pytest.approx(before.value)
    assert main(["strength", "shoulder_flexion", "shoulder_y=30", "shoulder_z=-30"]) == 0
    assert "EXTRAPOLATED: shoulder_z -30 deg" in capsys.readouterr().out


def _curve(data, motion: str, column: int) -> tuple[np.ndarray, np.ndarray]:
    section = data.sections[("male", "right")]
    rows = section.motions == MOTION_NAMES.index(motion)
    order = np.argsort(section.angles[rows, column])
    return section.angles[rows, column][order], section.values[rows][order]


def test_elbow_flexion_has_the_usual_shape(data):
    """Peak near 90 deg of flexion, about half with the arm straight (it
    peaked at 20 deg and was 53 % at 90 deg)."""
    angles, values = _curve(data, "elbow_flexion", 3)
    assert angles[np.argmax(values)] == 90
    assert 0.5 < values[angles == 5][0] / values.max() < 0.65


def test_forearm_and_wrist_deviation_follow_millards_signs(data):
    """Millard counts supination and ulnar deviation positive; SASS's columns
    count pronation and radial deviation positive: the peaks change sign."""
    angles, values = _curve(data, "forearm_pronation", 6)
    assert angles[np.argmax(values)] > 0  # Millard's peak at -0.21 rad of supination
    angles, values = _curve(data, "wrist_ulnar_deviation", 4)
    assert angles[np.argmax(values)] < 0  # ulnar is negative wrist_x
    angles, values = _curve(data, "wrist_radial_deviation", 4)
    assert angles[np.argmax(values)] > 0


def test_the_report_point_is_kept(data):
    section = data.sections[("male", "right")]
    report = [i for i, note in enumerate(section.notes) if "report figure 5" in note]
    assert len(report) == 1
    assert section.values[report[0]] == 17.98 and section.percentiles[report[0]] == 50


def test_shipped_file_is_what_the_script_writes():
    import runpy

    from _paths import DATASETS, ROOT

    script = runpy.run_path(str(ROOT / "scripts" / "make_strength_dat.py"))
    assert script["render"]() == (DATASETS / "strength.dat").read_text()
