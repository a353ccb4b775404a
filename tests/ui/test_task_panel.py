"""The strength page's Task panel (T, ui/spreadsheet/task_panel.py): the posture is the
strength page's row under its cursor, the loads on the hands and the people
are cells edited on the message line, and the answer (moments, percent
capable, the limiting joint, what no model covers) is recomputed in a worker
when an input changes.  The hand's share is checked against the Arm Force
Field run here on the same posture."""

from __future__ import annotations

import pytest
from _screen import message, settle, wait_until
from hypothesis import given, settings
from hypothesis import strategies as st
from textual.widgets import Static

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.body.posed_outline import posed_outline
from sass_tui.model.body.posture import parse_angles
from sass_tui.model.errors import SassError
from sass_tui.model.strength.arm_force_field import arm_force
from sass_tui.model.strength.hands_at import STOOPING_WORDS, HandsAt, Reaching
from sass_tui.model.strength.published_strength import GENDER_WORDS
from sass_tui.model.strength.task import Reference, assess_task, hand_load, load_of, pose_task
from sass_tui.ui.spreadsheet.strength_page import TASK_PANEL_LINES
from sass_tui.ui.spreadsheet.task_panel import TaskPanel
from sass_tui.ui.spreadsheet.task_words import PEOPLE, answer_lines, parse_people, strength_posture
from tests._virtual_task import VIRTUAL, right_hand_sums

SIZE = (110, 44)


def cells_and_answer(panel: TaskPanel) -> str:
    table, notes = (
        panel.query_one(f"#task-{part}", Static).render() for part in ("table", "answer")
    )
    return f"{panel.cells.render()}\n{table}\n{notes}"


async def answer(pilot, text: str) -> None:
    await pilot.press("ctrl+a", "ctrl+k", *text, "enter")


async def answered(pilot, panel: TaskPanel) -> None:
    await wait_until(
        pilot,
        lambda: panel.answer is not None and not panel.computing,
        "panel.answer is not None and not panel.computing",
    )


async def posture_typed(pilot, screen, text: str) -> TaskPanel:
    """The Task panel shown and answered, then `text` typed in its posture cell."""
    await pilot.press("T")
    await wait_until(pilot, lambda: screen.task_panel is not None, "a task panel")
    panel = screen.task_panel
    await answered(pilot, panel)
    await pilot.press("home", "enter")
    await answer(pilot, text)
    return panel


def hand_percent(
    figure: Figure, posture: tuple[str, ...], force: float, way=(0, 1, 0), held: float = 60.0
) -> float:
    """The Arm Force Field's share for the right hand exerting `force` N `way`,
    standing as the task stands (leaning at the ankles)."""
    task_load = hand_load("right", held, way)
    body, _, _, _ = pose_task(figure, parse_angles(list(posture)), [task_load])
    arm = arm_force(body.points, "right", way, figure.gender, body.body_mass)
    return arm.percent_capable(force)


@pytest.mark.parametrize(
    "text, people",
    [("Women  and MEN", "women and men"), ("gender", "gender"), ("Virtual nhanes-2017-2020",
     "virtual nhanes-2017-2020"), ("target civ", "target civ")],
)  # fmt: skip
def test_the_people_cell_takes_its_words(text, people):
    assert parse_people(text) == people


@settings(max_examples=80, deadline=None)
@given(st.text(max_size=30))
def test_any_people_text_is_people_or_a_clear_refusal(text):
    try:
        people = parse_people(text)
    except SassError as exc:
        assert "expected one of gender, figure" in str(exc)
    else:
        kind, _, name = people.partition(" ")
        assert people in PEOPLE or (kind in ("target", "virtual") and name)


@pytest.mark.slow
def test_the_task_panel_follows_the_strength_page_and_its_cells(app_at, drive):
    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            screen = app.screen
            rows_alone = screen.strength_page.page_rows
            await pilot.press("T")  # from the girth page: to the strength page, with the panel
            await wait_until(pilot, lambda: screen.task_panel is not None, "a task panel")
            panel = screen.task_panel
            await answered(pilot, panel)
            assert screen.data_group == "strength" and panel.display and panel.cells.has_focus
            page = screen.strength_page
            side, angles = page.row_angles()
            assert panel.posture == strength_posture(side, angles)
            assert page.page_rows == min(page.PAGE_ROWS, SIZE[1] - 12 - TASK_PANEL_LINES)
            gender = screen.figure.gender
            words = GENDER_WORDS[gender]
            hand = next(c for c in panel.answer.capabilities if c.what == "right hand")
            expected = hand_percent(Figure.default(gender), panel.posture, 60.0)
            assert hand.percent[words] == pytest.approx(expected)
            shown = "\n".join(answer_lines(panel.answer))
            for joint in ("right elbow", "right shoulder", "left hip", "right knee", "left ankle"):
                assert joint in shown
            assert f"Limiting: {words} " in shown
            assert "not covered (N-m): left wrist" in shown
            assert "trunk (L5/S1)" in shown

            # h: the right hand's curve of percent capable against its load
            await pilot.press("h")
            await wait_until(
                pilot,
                lambda: panel.curve_side == "right" and panel.curves and not panel.computing,
                'panel.curve_side == "right" and panel.curves',
            )
            assert panel.query_one("#task-curve").display
            assert not panel.query_one("#task-answer").display
            curve = panel.curves[words]
            assert curve[0] == (
                0.0,
                pytest.approx(hand_percent(Figure.default(gender), panel.posture, 0.0)),
            )
            assert curve[-1][1] < 1.0 and all(a[1] >= b[1] for a, b in zip(curve, curve[1:]))
            force, share = curve[len(curve) // 3]
            assert share == pytest.approx(
                hand_percent(Figure.default(gender), panel.posture, force)
            )
            await pilot.press("h")  # one loaded hand: back to the table
            await wait_until(
                pilot, lambda: panel.query_one("#task-answer").display, "the table again"
            )

            # the people: women and men (the cursor starts on the right hand)
            await pilot.press("right", "enter")
            await answer(pilot, "women and men")
            await wait_until(
                pilot,
                lambda: panel.answer.populations == ["women", "men"],
                'panel.answer.populations == ["women", "men"]',
            )
            # a new load on the right hand: the hand pushes down
            await pilot.press("left", "enter")
            await answer(pilot, "30 N down")
            await wait_until(
                pilot,
                lambda: panel.answer.loads[0].force == 30.0 and not panel.computing,
                "panel.answer.loads[0].force == 30.0",
            )
            hand = next(c for c in panel.answer.capabilities if c.what == "right hand")
            expected = hand_percent(Figure.default("female"), panel.posture, 30.0, (0, -1, 0), 30.0)
            assert hand.percent["women"] == pytest.approx(expected)
            assert "30 N down" in cells_and_answer(panel)
            # a bad load is refused and the load kept
            await pilot.press("enter")
            await answer(pilot, "heavy")
            await wait_until(pilot, lambda: "heavy" in message(app), '"heavy" in message(app)')
            assert panel.loads["right"].force == 30.0

            # T hides it: the strength page has its rows again; T shows it on
            # the row the strength page's cursor moved to
            await pilot.press("T")
            await settle(pilot)
            assert not panel.display and page.has_focus and page.page_rows == rows_alone
            await pilot.press("down", "down")
            await pilot.press("T")
            await answered(pilot, panel)
            side, angles = page.row_angles()
            assert page.cursor_row == 2 and panel.posture == strength_posture(side, angles)
            # the panel shown, the strength page's cursor moved (shift+Tab goes
            # to it): the task's posture follows at once
            await pilot.press("shift+tab")
            await wait_until(pilot, lambda: page.has_focus, "page.has_focus")
            await pilot.press("up")
            await wait_until(
                pilot,
                lambda: panel.posture == strength_posture(*page.row_angles()),
                "panel.posture == strength_posture(*page.row_angles())",
            )
            assert page.cursor_row == 1
            # an angle edited on the strength page: the task's posture follows
            await pilot.press("right", "enter")
            await answer(pilot, "45")
            await wait_until(
                pilot,
                lambda: f"{side}_shoulder_y=45" in panel.posture,
                "f'{side}_shoulder_y=45' in panel.posture",
            )
            await answered(pilot, panel)
            hand = next(c for c in panel.answer.capabilities if c.what == "right hand")
            expected = hand_percent(Figure.default("female"), panel.posture, 30.0, (0, -1, 0), 30.0)
            assert hand.percent["women"] == pytest.approx(expected)

    drive(scenario())


@pytest.mark.slow
def test_the_task_panel_takes_a_virtual_population(app_at, drive, db):
    """`virtual NAME` in the people cell: the shipped virtual population,
    made in the database on first use, each gender and everyone weighted by
    the survey's weights (checked against the stored virtual people); a
    target that does not exist is refused and the people kept."""

    async def scenario():
        async with app_at(SIZE, db=True) as (app, pilot):
            screen = app.screen
            await pilot.press("T")
            await wait_until(pilot, lambda: screen.task_panel is not None, "a task panel")
            panel = screen.task_panel
            await answered(pilot, panel)
            await pilot.press("right", "enter")
            await answer(pilot, "target nosuch")
            await wait_until(pilot, lambda: "nosuch" in message(app), '"nosuch" in message(app)')
            await answered(pilot, panel)
            assert panel.people == "gender" and panel.answered_people == "gender"
            await pilot.press("enter")
            await answer(pilot, f"virtual {VIRTUAL}")
            # making the virtual population takes seconds: wait for the worker itself
            await app.workers.wait_for_complete()
            columns = ["VIRTUAL men", "VIRTUAL women", "VIRTUAL everyone"]
            await wait_until(
                pilot,
                lambda: panel.answer.populations == columns and not panel.computing,
                "panel.answer.populations == columns",
            )
            hand = next(c for c in panel.answer.capabilities if c.what == "right hand")
            pooled = [0.0, 0.0]
            for gender, words in zip(("male", "female"), columns):
                capable, weight = right_hand_sums(str(db), gender, list(panel.posture), 60.0)
                assert hand.percent[words] == pytest.approx(100 * capable / weight, abs=0.05)
                pooled = [pooled[0] + capable, pooled[1] + weight]
            assert hand.percent[columns[2]] == pytest.approx(100 * pooled[0] / pooled[1], abs=0.05)
            shown = cells_and_answer(panel)
            assert "to exert (VIRTUAL)" in shown and "everyone" in shown

    drive(scenario())


@pytest.mark.slow
def test_task_panel_snapshot(snap_compare, new_app):
    async def run_before(pilot):
        await pilot.press("T")
        await wait_until(
            pilot,
            lambda: getattr(pilot.app.screen, "task_panel", None) is not None,
            "a task panel",
        )
        panel = pilot.app.screen.task_panel
        await answered(pilot, panel)

    assert snap_compare(new_app(), run_before=run_before, terminal_size=SIZE)


@pytest.mark.slow
def test_the_task_panels_own_posture_is_kept_for_the_worksheet(app_at, drive):
    """The posture cell: the task's own posture in place of the strength
    page's row (`row` again follows it); the settings go to the session,
    which the worksheet saves (model/files/task_settings.py)."""

    async def scenario():
        async with app_at(SIZE) as (app, pilot):
            screen = app.screen
            panel = await posture_typed(pilot, screen, "trunk_y=30 hip_y=60 shoulder_y=90")
            await wait_until(
                pilot,
                lambda: (
                    panel.posture == ("trunk_y=30", "hip_y=60", "shoulder_y=90")
                    and not panel.computing
                ),
                "the task's own posture",
            )
            assert panel.answer.low_back.moment[0] > 20.0  # a stoop loads the low back
            assert screen.session.task.posture == panel.posture
            assert "trunk (L5/S1)" in cells_and_answer(panel)
            # a bad posture is refused and the posture kept
            await pilot.press("enter")
            await answer(pilot, "trunk_q=3")
            await wait_until(pilot, lambda: "trunk_q" in message(app), '"trunk_q" in message(app)')
            assert panel.posture == ("trunk_y=30", "hip_y=60", "shoulder_y=90")
            # what sass task cautions of a posture, the panel says too: one leg
            # posed shorter stands the figure on the other foot
            await pilot.press("enter")
            await answer(pilot, "left_hip_y=30 left_ankle_y=-30")
            await wait_until(
                pilot,
                lambda: "Cautions: standing on the right foot" in cells_and_answer(panel),
                "the caution in the panel",
            )
            assert panel.answer.stance.bearing == ("right",)
            await pilot.press("enter")
            await answer(pilot, "row")
            await wait_until(pilot, lambda: not panel.own_posture, "the row's posture again")
            assert screen.session.task.posture == ()

    drive(scenario())


def test_the_figure_beside_takes_the_tasks_posture():
    """The posed outline: a stoop (hips flexed 60, trunk 30) puts the head
    forward of the feet, each solid where its joint's turn carries it."""
    figure = Figure.default("female")
    humanoid = build_humanoid(figure)
    standing = posed_outline(humanoid, pose_task(figure, {}, [])[0], "standing", 162.6)
    body = pose_task(figure, parse_angles(["trunk_y=30", "hip_y=60"]), [])[0]
    stoop = posed_outline(humanoid, body, "stoop", 162.6)

    def head(outline):  # the skull: the one ellipse
        return next(s for s in outline.side.shapes if s.kind == "ellipse")

    assert head(stoop).x > head(standing).x + 40.0
    assert head(stoop).y < head(standing).y - 40.0
    assert stoop.height < standing.height


@pytest.mark.slow
def test_the_posture_cell_takes_where_the_hands_grasp(app_at, drive):
    """`hands=40cm,30cm,squat` in the posture cell: each figure answered
    squats to that place (as sass task takes it, model/strength/hands_at.py),
    the figure beside the panel is drawn in its own squat, and the words are
    saved with the worksheet like any posture."""
    from sass_tui.model.strength.hand_position import body_h_v
    from sass_tui.model.strength.hands_at import HandsAt, solve_hands_at, solved_angles

    async def scenario():
        async with app_at((140, 44)) as (app, pilot):  # wide: the figure beside
            screen = app.screen
            panel = await posture_typed(pilot, screen, "hands=40cm,30cm,squat")
            await wait_until(
                pilot,
                lambda: panel.answer is not None and panel.answer.postures and not panel.computing,
                "an answer with each figure's squat",
            )
            assert screen.session.task.posture == ("hands=40cm,30cm,squat",)
            loads = list(panel.loads.values())
            figure = screen.figure
            goal = HandsAt(0.4, 0.3, "squat")
            expected = solve_hands_at(figure, goal, {}, loads)
            assert panel.shown_angles == expected
            # the angles each figure found are said in the panel's notes
            notes = str(panel.query_one("#task-answer", Static).render())
            solved = solved_angles(goal.solved_axes, expected)
            assert set(solved) == {"hip_y", "shoulder_y", "knee_y", "ankle_y"}
            words = " ".join(f"{axis} {deg:.1f}" for axis, deg in solved.items())
            assert f"Squat to the hands' place: {GENDER_WORDS[figure.gender]} {words}" in notes
            body = pose_task(figure, expected, loads)[0]
            assert body_h_v(body) == pytest.approx((0.4, 0.3), abs=0.002)
            drawn = posed_outline(build_humanoid(figure), body, "", float(figure.stature))
            await wait_until(
                pilot,
                lambda: (
                    screen.figure_panel is not None
                    and screen.figure_panel.outlines[0].side == drawn.side
                ),
                "the figure beside drawn in its squat",
            )
            # knee_y is what the squat solves: refused, the posture kept
            await pilot.press("enter")
            await answer(pilot, "hands=40,30,squat knee_y=20")
            await wait_until(pilot, lambda: "leave out knee_y" in message(app), "the refusal")
            assert panel.posture == ("hands=40cm,30cm,squat",)

    drive(scenario())


def test_the_panel_says_which_figure_stoops_when_asked_to_squat():
    """The Task panel's words name the figure whose squat ended with the
    knees all but straight (the woman at H 30 cm, V 10 cm with 10 kg in
    each hand), as `sass task` does, and not the man, who squats."""
    boxes = [load_of("left", "10 kg"), load_of("right", "10 kg")]
    answer = assess_task(
        [
            Reference("women", Figure.default("female"), None),
            Reference("men", Figure.default("male"), None),
        ],
        Reaching(HandsAt(0.3, 0.1, "squat"), {}, tuple(boxes)),
        boxes,
    )
    (note,) = [line for line in answer_lines(answer) if line.startswith("Squat to")]
    women, men = note.split("; men ")
    assert STOOPING_WORDS in women and STOOPING_WORDS not in men
