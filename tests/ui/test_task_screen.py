"""The Task panel (T on the spreadsheet, ui/task_screen.py): the posture and
the loads on the hands typed in, the moments and who can do it for the
figure shown, women and men, and the curve of percent capable against the
load of a hand (the Arm Force Field), computed in a worker."""

from __future__ import annotations

import pytest
from _screen import message, settle, wait_until
from textual.widgets import Static

from sass_tui.model.arm_force_field import arm_force
from sass_tui.model.figure import Figure
from sass_tui.model.posture import parse_angles, pose_figure
from sass_tui.ui.task_screen import TaskScreen

SIZE = (110, 44)


def table(screen) -> str:
    return str(screen.query_one("#task-table", Static).render())


async def answer(pilot, text: str) -> None:
    await pilot.press("ctrl+a", "ctrl+k", *text, "enter")


@pytest.mark.slow
def test_the_task_panel_answers_and_follows_new_loads(app_at, drive):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            await pilot.press("T")
            await wait_until(
                pilot,
                lambda: isinstance(app.screen, TaskScreen),
                "isinstance(app.screen, TaskScreen)",
            )
            screen = app.screen
            await wait_until(pilot, lambda: screen.answer is not None, "screen.answer is not None")
            text = table(screen)
            assert "right shoulder" in text and "limiting for women" in text
            assert "not covered: left wrist, right wrist, trunk (L5/S1)" in text
            # the default: 60 N down in the right hand, shoulder_y=60 elbow_y=30
            body = pose_figure(
                Figure.default("male"), parse_angles(["shoulder_y=60", "elbow_y=30"])
            )
            expected = arm_force(body.points, "right", (0, 1, 0), "male", body.body_mass)
            hand = next(c for c in screen.answer.capabilities if c.what == "right hand")
            assert hand.percent["men"] == pytest.approx(expected.percent_capable(60.0))
            curve = screen.curves["men"]
            assert curve[0][0] == 0.0 and curve[0][1] > 99.0 and curve[-1][1] < 1.0
            assert all(a[1] >= b[1] for a, b in zip(curve, curve[1:]))
            # a new posture and a load on the left hand
            await pilot.press("p")
            await answer(pilot, "shoulder_y=90 elbow_y=0")
            await pilot.press("l")
            await answer(pilot, "30 N down")
            await settle(pilot)
            await wait_until(
                pilot,
                lambda: "left hand: force against the load 30.0 N" in table(screen),
                '"left hand: force against the load 30.0 N" in table(screen)',
            )
            assert "posture shoulder_y=90 elbow_y=0" in table(screen)
            # a bad posture is refused and the old one kept
            await pilot.press("p")
            await answer(pilot, "elbow_q=10")
            await wait_until(
                pilot,
                lambda: "unknown joint 'elbow_q'" in message(app),
                "\"unknown joint 'elbow_q'\" in message(app)",
            )
            assert screen.posture == ("shoulder_y=90", "elbow_y=0")
            await pilot.press("escape")
            await wait_until(
                pilot,
                lambda: not isinstance(app.screen, TaskScreen),
                "not isinstance(app.screen, TaskScreen)",
            )

    drive(scenario())


@pytest.mark.slow
def test_task_screen_snapshot(snap_compare, new_app):
    async def run_before(pilot):
        await pilot.press("T")
        await wait_until(
            pilot,
            lambda: getattr(pilot.app.screen, "answer", None) is not None,
            'getattr(pilot.app.screen, "answer", None) is not None',
        )

    assert snap_compare(new_app(), run_before=run_before, terminal_size=SIZE)
