"""Figure.for_person: a real person shown against the population (report §12.4)."""

from __future__ import annotations

import numpy as np
import pytest

from sass_tui.model.body.figure import Figure, FigureError
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GROUPS, JOINT_LIMITS, row_index
from sass_tui.model.population.percentile_arrays import percentile_of
from sass_tui.model.session import Session


def person_groups(figure: Figure, scale: float = 1.1) -> dict[str, np.ndarray]:
    groups = {g: figure.groups[g].values * scale for g in GROUPS}
    groups[GIRTH][row_index(GIRTH, "neck")] = np.nan  # no value in the database
    return groups


def test_person_values_percentiles_and_population_untouched():
    population = Figure.default("male")
    before = {g: population.groups[g].values.copy() for g in GROUPS}
    groups = person_groups(population)
    person = population.for_person(
        "SMITH",
        "male",
        groups,
        mass=90.0,
        stature=185.0,
        handedness="left",
        strength_type="isokinetic",
    )
    assert person.person == "SMITH" and person.population == population.population
    for group in GROUPS:
        np.testing.assert_array_equal(person.groups[group].values, groups[group])
        stats = population.groups[group].source.stats("male")
        np.testing.assert_allclose(
            person.groups[group].percentiles,
            percentile_of(stats, groups[group]).reshape(groups[group].shape),
        )
        np.testing.assert_array_equal(population.groups[group].values, before[group])
    assert np.isnan(person.groups[GIRTH].values[row_index(GIRTH, "neck")]).all()
    assert person.mass == 90.0 and person.mass_percentile > 50
    assert person.handedness == "left" and person.strength_type == "isokinetic"
    assert population.person is None and population.handedness == "right"


def test_person_is_editable_like_population_data():
    population = Figure.default("female")
    person = population.for_person("DOE", "female", person_groups(population, 0.95))
    arm = row_index(GIRTH, "right_upper_arm")
    session = Session(population)
    session.show_person(person, 0)
    session.set_value(GIRTH, arm, 2, 30.0)
    assert person.groups[GIRTH].values[arm, 2] == 30.0
    session.set_cell_percentile(JOINT_LIMITS, 0, 0, 50.0)
    assert session.undo() and session.undo() and not session.undo()
    assert person.groups[GIRTH].values[arm, 2] == pytest.approx(
        population.groups[GIRTH].values[arm, 2] * 0.95
    )


def test_person_refused_without_statistics_or_with_wrong_shape():
    population = Figure.default("male")
    population.groups[CENTER_OF_MASS].source = None
    with pytest.raises(FigureError, match="no male Center of Mass statistics"):
        population.for_person("X", "male", person_groups(Figure.default()))
    with pytest.raises(FigureError, match="shape"):
        Figure.default().for_person("X", "male", {g: np.zeros((2, 3)) for g in GROUPS})


def test_files_for_a_person_with_unmeasured_values_take_the_population_values(tmp_path):
    """Like an ANSUR II soldier: no joint limits at all, no neck in the database."""
    from sass_tui.model.files.fig_reader import read_fig
    from sass_tui.model.files.figfile import render_fig, write_fig
    from sass_tui.model.files.hanim_x3d import export_hanim

    population = Figure.default("male")
    population.set_group_percentile(JOINT_LIMITS, 95)
    groups = person_groups(population)
    groups[JOINT_LIMITS] = np.full_like(groups[JOINT_LIMITS], np.nan)
    person = population.for_person("SMITH", "male", groups)  # mass and stature unknown
    values, filled = person.output_values(JOINT_LIMITS)
    np.testing.assert_array_equal(values, population.groups[JOINT_LIMITS].values)  # 95th, 999 kept
    assert filled.sum() == np.count_nonzero(~np.isnan(population.groups[JOINT_LIMITS].values))
    assert np.isnan(person.groups[JOINT_LIMITS].values).all()  # the display still says "unknown"

    text = render_fig(person)
    assert "nan" not in text.lower()
    assert (
        f"/* not measured for SMITH, so taken from the population ({population.population}): "
        "3 of the 75 girth values (at the girth percentile, 50); "
        f"{filled.sum()} of the {filled.sum()} joint limits values (at the joint limits "
        "percentile, 95); the total mass (the population's median, 82.20 kg) */"
    ) in text
    fig = read_fig(write_fig(person, tmp_path / "smith.fig"))
    assert fig.variables["right_elbow_y_ulimit"] == (159.0, "deg")
    assert fig.variables["neckx"] == (12.3 / 2, "cm")  # population 50th girth, halved
    assert fig.variables["ruparmz"][0] == pytest.approx(36.6 * 1.1, abs=0.005)  # measured
    assert sum(v for v, u in fig.variables.values() if u == "kg") == pytest.approx(82.2, abs=0.05)
    export_hanim(person, tmp_path / "smith.x3d")
    assert "nan" not in (tmp_path / "smith.x3d").read_text().lower()


def test_unmeasured_joint_limits_are_the_populations_on_the_strength_page():
    """An ANSUR II soldier has no joint limits: the strength page checks angles
    against the population's at the group percentile, and says so; it never
    says "no motion about this axis" for an axis that has motion."""
    from sass_tui.model.strength.strength import (
        StrengthError,
        check_angle,
        joint_limit_range,
        limits_source,
    )

    population = Figure.default("male")
    population.set_group_percentile(JOINT_LIMITS, 95)
    groups = person_groups(population)
    groups[JOINT_LIMITS] = np.full_like(groups[JOINT_LIMITS], np.nan)
    person = population.for_person("SMITH", "male", groups)
    assert joint_limit_range(person, "right", "elbow_y") == (0.0, 159.0)
    check_angle(person, "right", "elbow_y", 150)
    with pytest.raises(StrengthError) as refused:
        check_angle(person, "right", "elbow_y", 170)
    message = str(refused.value)
    assert "upper limit 159 deg" in message
    assert "not measured for SMITH: the population's joint limits at the 95th percentile" in message
    assert "no motion" not in message
    # 999 in the population stays no motion
    with pytest.raises(StrengthError, match="no motion about this axis"):
        check_angle(person, "right", "elbow_x", 10)
    assert "not measured for SMITH" in limits_source(person)
    assert limits_source(population) == "joint limits: 95th percentile"
