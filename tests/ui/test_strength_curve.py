"""Strength curves (t on the spreadsheet): Anderson et al. 2007's hip, knee
and ankle torque over the joint's range, with its source on the title line."""

from __future__ import annotations

import math
from statistics import NormalDist

import pytest
from textual.widgets import Static

from sass_tui.model.body.figure import Figure
from sass_tui.ui.spreadsheet.strength_curve_screen import StrengthCurveScreen


def young_man() -> Figure:
    figure = Figure.default("male")
    figure.set_mass(75)
    figure.set_stature(175)
    return figure


async def type_answer(pilot, text: str) -> None:
    await pilot.press("ctrl+a", "ctrl+k", *text, "enter")
    await pilot.pause()


def test_t_draws_the_knee_extension_curve_with_its_source(app_at, drive):
    async def scenario():
        async with app_at((100, 30), young_man()) as (app, pilot):
            await pilot.press("t")
            await pilot.pause()
            screen = app.screen
            assert isinstance(screen, StrengthCurveScreen)
            angles, torques = screen.plotted
            # over the knee's joint limits (50th percentile: 0 to 132 deg)
            assert (angles[0], angles[-1]) == (0.0, 132.0)
            # the curve's top is C1 m g h (Table 3, young men: C1 0.163, C3 1.133 rad)
            assert max(torques) == pytest.approx(0.163 * 75 * 9.81 * 1.75, rel=0.005)
            title = str(screen.query_one("#curve-title", Static).render())
            assert "Anderson et al. 2007, young men, mean" in title
            await pilot.press("n")
            await pilot.pause()
            assert "Ankle plantarflexion" in str(screen.query_one("#curve-title", Static).render())
            await pilot.press("escape")
            await pilot.pause()
            assert not isinstance(app.screen, StrengthCurveScreen)

    drive(scenario())


def test_age_percentile_and_speed_change_the_curve(app_at, drive):
    async def scenario():
        async with app_at((100, 30), young_man()) as (app, pilot):
            await pilot.press("t")
            await pilot.pause()
            screen = app.screen
            await pilot.press("a")
            await type_answer(pilot, "70")
            assert "older men" in screen.source
            # C1 of men over 65 (Table 3): 0.137
            assert max(screen.plotted[1]) == pytest.approx(0.137 * 75 * 9.81 * 1.75, rel=0.005)
            await pilot.press("c")
            await type_answer(pilot, "5")
            assert screen.source == "Anderson et al. 2007, older men, 5th percentile"
            await pilot.press("v")
            await type_answer(pilot, "90")
            c4, c5, w = 1.141, 3.152, math.radians(90)
            tv = (2 * c4 * c5 + w * (c5 - 3 * c4)) / (2 * c4 * c5 + w * (2 * c5 - 4 * c4))
            # the 5th percentile of C1: Table 3's over-65 SD 0.017 is below the pooled
            # CV of the 18-25 and 55-65 groups (0.040/0.163, 0.031/0.156), which sets it
            sd = 0.137 * math.sqrt(((0.040 / 0.163) ** 2 + (0.031 / 0.156) ** 2) / 2)
            c1 = 0.137 - 1.6448536 * sd
            assert max(screen.plotted[1]) == pytest.approx(c1 * 75 * 9.81 * 1.75 * tv, rel=0.005)
            await pilot.press("a")
            await type_answer(pilot, "17")
            assert "18-25, 55-65, over-65" in screen.message_line.history[-1][1]
            assert "older men" in screen.source  # nothing changed

    drive(scenario())


def test_the_strength_group_selects_a_data_set_by_name(app_at, drive):
    async def scenario():
        async with app_at((100, 30), young_man()) as (app, pilot):
            await pilot.press("s")
            await pilot.pause()
            await pilot.press("i")
            await pilot.pause()
            await type_answer(pilot, "anderson2007")
            assert isinstance(app.screen, StrengthCurveScreen)
            assert "Anderson et al. 2007" in app.screen.source

    drive(scenario())


@pytest.mark.slow
def test_a_real_persons_curve_uses_their_own_age_and_is_marked_predicted(app_at, db, drive):
    from sass_tui.db.engine.schema import connect
    from sass_tui.db.people.individual import fetch_individual
    from tests.ui.test_person_strength_page import show_first_person_of

    async def scenario():
        async with app_at((100, 37), db=db) as (app, pilot):
            await show_first_person_of(pilot, "source = ansur2 AND gender = female AND age > 55")
            with connect(db) as conn:
                person = fetch_individual(conn, app.query_lists.selected_id(0))
            await pilot.press("t")
            await pilot.pause()
            screen = app.screen
            assert isinstance(screen, StrengthCurveScreen)
            assert screen.age == person.age
            assert screen.source == (
                "Anderson et al. 2007, middle-aged women, mean; predicted for "
                f"{person.name} from their own gender, age, mass and stature"
            )
            # Table 3, knee extension, women 55-65: C1 0.128 (peak C3 = 65.4 deg)
            expected = 0.128 * person.mass * 9.81 * person.stature / 100
            assert max(screen.plotted[1]) == pytest.approx(expected, rel=0.005)

    drive(scenario())


def test_l_draws_percent_capable_against_the_torque(app_at, drive):
    async def scenario():
        async with app_at((100, 30), young_man()) as (app, pilot):
            await pilot.press("t")
            await pilot.pause()
            screen = app.screen
            angles, torques = screen.plotted
            peak = angles[torques.index(max(torques))]
            await pilot.press("l")
            await type_answer(pilot, "150")
            # Table 3, knee extension, young men: C1 0.163, SD 0.040, C2 1.258, C3 1.133
            shape = 75 * 9.81 * 1.75 * math.cos(1.258 * (math.radians(peak) - 1.133))
            expected = 100 * (1 - NormalDist().cdf((150 / shape - 0.163) / 0.040))
            assert screen.capable == pytest.approx(expected, abs=0.01)
            load, shares = screen.plotted
            assert load[0] == 0.0 and shares[0] == pytest.approx(100.0, abs=0.01)
            assert all(a >= b for a, b in zip(shares, shares[1:]))
            await pilot.press("l")
            await type_answer(pilot, "-0")  # was said "capable of -0 N-m"
            assert screen.message_line.history[-1][1].endswith(
                "capable of 0 N-m at the peak angle."
            )
            await pilot.press("l")
            await type_answer(pilot, "")
            assert screen.load is None and screen.plotted[0][0] == 0.0  # angles again

    drive(scenario())
