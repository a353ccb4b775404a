"""The Task panel's manual-handling line (ui/spreadsheet/task_handling.py):
the task it holds rated as a lift by the NIOSH equation and the Liberty
Mutual equations, checked against the manual's formulas and the paper's
equation written out here, and shown under the panel's table."""

from __future__ import annotations

import math

import pytest
from _screen import wait_until
from textual.widgets import Static

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure
from sass_tui.model.strength.task import hand_load
from sass_tui.ui.spreadsheet.task_handling import handling_line, lifted_kg

POSTURE = ("shoulder_y=30", "elbow_y=60")


def test_the_line_is_the_lift_the_panel_holds():
    figure = Figure.default("female")
    # each hand exerts 60 N up: holds a weight
    loads = [hand_load("right", 60.0, (0, 1, 0)), hand_load("left", 60.0, (0, 1, 0))]
    kg = 120 / 9.80665
    assert lifted_kg(loads) == pytest.approx(kg)
    body = pose_figure(figure, parse_angles(list(POSTURE)))
    grasp = (body.points["l_metacarpophalangeal_3"] + body.points["r_metacarpophalangeal_3"]) / 2
    ankles = (body.centers["l_talocrural"] + body.centers["r_talocrural"]) / 2
    h = math.hypot(grasp[0] - ankles[0], grasp[2] - ankles[2]) * 100
    v = grasp[1] * 100
    # the manual: 23 kg x 25/H x (1 - .003 |V - 75|), D 25 cm (DM 1), A 0, Table 5
    # (0.2/min, long, V >= 75 cm) 0.85, Table 7 (fair, V >= 75 cm) 1
    rwl = 23 * 25 / h * (1 - 0.003 * abs(v - 75)) * 0.85
    # the paper's Lift - Female at VRM = V, DV 0.25 m, F 1/min
    mal = (
        34.9
        * (1.2602 - h / 100 / 0.7686)
        * (0.9877 + v / 100 / 13.69 - (v / 100) ** 2 / 9.221)
        * (0.8199 - math.log(0.25) / 7.696)
        * 0.6767
    )
    women = 50 * (1 + math.erf((1 - kg / mal) / 0.260 / math.sqrt(2)))
    line = handling_line(figure, parse_angles(list(POSTURE)), loads)
    assert f"NIOSH LI {kg / rwl:.2f}" in line
    assert f"accepted by women {women:.0f} %" in line


def test_no_load_held_up_is_no_lift():
    # the hand pushes down: nothing is lifted
    line = handling_line(Figure.default("male"), {}, [hand_load("right", 30.0, (0, -1, 0))])
    assert line.startswith("Lifting: no load held up")


@pytest.mark.slow
def test_the_panel_shows_the_line(app_at, drive):
    async def scenario():
        async with app_at((110, 44)) as (app, pilot):
            screen = app.screen
            await pilot.press("T")
            await wait_until(pilot, lambda: screen.task_panel is not None, "a task panel")
            panel = screen.task_panel
            shown = panel.query_one("#task-answer", Static)
            await wait_until(
                pilot, lambda: "NIOSH LI" in str(shown.render()), "the manual-handling line"
            )
            angles = parse_angles(list(panel.posture))
            expected = handling_line(screen.figure, angles, panel.loads.values())
            assert str(shown.render()).splitlines()[-1] == expected

    drive(scenario())
