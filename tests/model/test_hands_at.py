"""A stoop or a squat found from where the hands must be
(model/strength/hands_at.py): the grasp lands where it was asked, measured
by the NIOSH H and V of the posed figure (model/strength/hand_position.py,
not the solver's own measure); each figure finds its own angles; a place
the stoop cannot reach is refused naming a place it does reach; a squat
bends the knees as far as the balance of quiet standing allows."""

from __future__ import annotations

import json
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from sass_tui.cli import main
from sass_tui.model.body.figure import Figure
from sass_tui.model.errors import SassError
from sass_tui.model.strength import hands_at
from sass_tui.model.strength.hand_position import body_h_v
from sass_tui.model.strength.hands_at import (
    STOOPING_WORDS,
    STRAIGHT_KNEES_DEG,
    HandsAt,
    parse_hands_at,
    posture_of,
    solve_hands_at,
    split_posture,
)
from sass_tui.model.strength.strength_conditions import joint_limit_range
from sass_tui.model.strength.task import (
    QUIET_STANCE_COP_M,
    Reference,
    TaskError,
    assess_task,
    load_of,
    pose_task,
)

BOXES = [load_of("left", "10 kg"), load_of("right", "10 kg")]


@pytest.fixture(scope="module")
def figures():
    return {gender: Figure.default(gender) for gender in ("female", "male")}


@pytest.mark.parametrize("gender", ["female", "male"])
@pytest.mark.parametrize("loads", [[], BOXES], ids=["empty-handed", "two 10 kg boxes"])
@pytest.mark.parametrize("h_v", [(0.25, 0.5), (0.4, 0.3), (0.5, 0.75), (0.3, 0.1)])
def test_the_grasp_lands_where_it_was_asked(figures, gender, loads, h_v):
    figure = figures[gender]
    angles = solve_hands_at(figure, HandsAt(*h_v), {}, loads)
    body, stance, *_ = pose_task(figure, angles, loads)
    h, v = body_h_v(body)
    assert h == pytest.approx(h_v[0], abs=0.002)
    assert v == pytest.approx(h_v[1], abs=0.002)
    # a stoop: straight legs, hips and shoulders within the figure's limits
    assert ("left", "knee_y") not in angles
    for side in ("left", "right"):
        for axis in ("hip_y", "shoulder_y"):
            low, high = joint_limit_range(figure, side, axis)
            assert low <= angles[(side, axis)] <= high
    assert angles[("left", "hip_y")] == angles[("right", "hip_y")]


def test_each_figure_stoops_its_own_way(figures):
    """The 50th-percentile woman, shorter, stoops further than the man for one box."""
    goal = HandsAt(0.4, 0.3)
    woman = solve_hands_at(figures["female"], goal, {}, BOXES)
    man = solve_hands_at(figures["male"], goal, {}, BOXES)
    assert woman[("left", "hip_y")] > man[("left", "hip_y")] + 5
    answer = assess_task(
        [Reference("women", figures["female"], None), Reference("men", figures["male"], None)],
        posture_of({}, goal, BOXES),
        BOXES,
    )
    assert answer.postures["women"] == woman and answer.postures["men"] == man
    assert answer.solved_axes == ("hip_y", "shoulder_y")


def test_the_other_angles_are_kept(figures):
    figure = figures["male"]
    angles = solve_hands_at(figure, HandsAt(0.35, 0.6), {("", "neck_y"): 20.0}, [])
    assert angles[("", "neck_y")] == 20.0
    h, v = body_h_v(pose_task(figure, angles, [])[0])
    assert (h, v) == pytest.approx((0.35, 0.6), abs=0.002)


def test_a_place_within_the_straight_arms_reach_is_refused_then_reached_with_bent_elbows(
    figures,
):
    """Hands 30 cm ahead at 1 m: inside the circle a straight arm sweeps from
    the shoulder, so no stoop reaches it until the elbows bend."""
    figure = figures["female"]
    with pytest.raises(TaskError, match=r"nearest is H [\d.]+ cm, V [\d.]+ cm") as refused:
        solve_hands_at(figure, HandsAt(0.3, 1.0), {}, [])
    assert "elbow_y" in str(refused.value)
    bent = {(side, "elbow_y"): 120.0 for side in ("left", "right")}
    angles = solve_hands_at(figure, HandsAt(0.3, 1.0), bent, [])
    assert body_h_v(pose_task(figure, angles, [])[0]) == pytest.approx((0.3, 1.0), abs=0.002)


def test_the_nearest_place_named_is_one_the_stoop_reaches(figures):
    figure = figures["female"]
    with pytest.raises(TaskError) as refused:
        solve_hands_at(figure, HandsAt(0.6, 0.1), {}, BOXES)
    words = str(refused.value).split("nearest is H ")[1]
    h = float(words.split(" cm")[0])
    v = float(words.split("V ")[1].split(" cm")[0])
    angles = solve_hands_at(figure, HandsAt(h / 100, v / 100), {}, BOXES)
    assert body_h_v(pose_task(figure, angles, BOXES)[0]) == pytest.approx(
        (h / 100, v / 100), abs=0.002
    )


def test_sass_task_hands_at_reports_each_figures_posture(capsys):
    assert main(["task", "hands=40cm,30cm", "--left-load", "10 kg", "--right-load",
                 "10 kg", "--format", "json"]) == 0  # fmt: skip
    shown = json.loads(capsys.readouterr().out)
    assert shown["hands_at"]["h"] == {"value": 40.0, "unit": "cm"}
    assert set(shown["hands_at"]["solved"]) == {"women", "men"}
    # the low back of the first figure (the woman) in her own solved stoop
    solved = shown["hands_at"]["solved"]["women"]
    assert solved["hip_y"] > 60 and shown["low_back"]["moment_N_m"] > 60
    assert main(["task", "hands=40,30", "--gender", "female"]) == 0
    text = capsys.readouterr().out
    assert "posture hands=40,30" in text and "note: hands at H 40.0 cm, V 30.0 cm" in text


@pytest.mark.parametrize(
    ("argv", "said"),
    [
        (["hip_y=10", "hands=30,10"], "leave out hip_y"),
        (["hands=30,20", "--seated"], "not with --seated"),
        (["hands=30"], "expected H,V"),
        (["hands=30 kg,20"], "hands=30 kg,20"),
        (["hands=-5,20"], "H from 0 to 200 cm"),
        (["hands=30,20", "hands=40,20"], "one hands=H,V"),
        (["hands=2m,3m", "--gender", "female"], "beyond the arms' reach from a stoop"),
        (["hands=60,10", "--gender", "female"], "a squat, hands=H,V,squat, for one lower"),
        (["hands=40,30,squat", "knee_y=30"], "leave out knee_y"),
        (["hands=40,30,squat", "ankle_y=5"], "leave out ankle_y"),
        (["hands=40,30,kneel"], "40cm,30cm,squat"),
        (["hands=60,10,squat", "--gender", "female"], "by a squat for the female figure"),
    ],
)
def test_what_a_stoop_cannot_take_is_refused(capsys, argv, said):
    assert main(["task", *argv]) == 2
    err = capsys.readouterr().err
    assert said in err and "Traceback" not in err


@given(st.text(max_size=40))
def test_any_text_is_hands_at_or_a_message(text):
    try:
        goal = parse_hands_at(text)
    except SassError as refused:
        assert str(refused)
    else:
        assert 0 <= goal.h <= 2 and 0 <= goal.v <= 3 and goal.by in ("stoop", "squat")


@given(
    st.lists(
        st.sampled_from(
            [
                "hands=",
                "hands=40,30",
                "HANDS=1m,1m",
                "hands=40,30,Squat",
                "hip_y=20",
                "knee_y=9",
                ",",
            ]
        )
        | st.text(max_size=12).map(lambda tail: f"hands={tail}")
        | st.text(max_size=12),
        max_size=4,
    )
)
def test_any_posture_words_are_a_posture_or_a_message(words):
    try:
        angles, goal = split_posture(words)
    except SassError as refused:
        assert str(refused)
    else:
        assert goal is None or not {("left", axis) for axis in goal.solved_axes} & set(angles)


SQUAT_PLACES = [(0.3, 0.5), (0.4, 0.3), (0.25, 0.2), (0.5, 0.6)]


def _trunk_inclination(body):
    """Degrees from upright of the trunk's axis at L5/S1."""
    up = body.turns["vl5"][:, 1]
    return math.degrees(math.acos(float(up[1])))


@pytest.mark.parametrize("gender", ["female", "male"])
@pytest.mark.parametrize("h_v", SQUAT_PLACES)
def test_a_squat_reaches_the_place_balanced_with_the_trunk_more_upright(figures, gender, h_v):
    figure = figures[gender]
    squat = solve_hands_at(figure, HandsAt(*h_v, "squat"), {}, BOXES)
    body, stance, used, _ = pose_task(figure, squat, BOXES)
    assert body_h_v(body) == pytest.approx(h_v, abs=0.002)
    assert stance.stable
    for side in ("left", "right"):
        assert squat[(side, "knee_y")] == pytest.approx(squat[("left", "knee_y")])
        for axis in ("hip_y", "shoulder_y", "knee_y", "ankle_y"):
            low, high = joint_limit_range(figure, side, axis)
            assert low <= squat[(side, axis)] <= high
    assert squat[("left", "knee_y")] > 20.0  # the knees bend
    stoop = solve_hands_at(figure, HandsAt(*h_v), {}, BOXES)
    assert _trunk_inclination(body) < _trunk_inclination(pose_task(figure, stoop, BOXES)[0]) - 5


@pytest.mark.parametrize("gender", ["female", "male"])
def test_the_squat_bends_the_knees_as_far_as_quiet_standing_balance_allows(figures, gender):
    """The criterion, checked from outside the solver: with the knees bent
    5 degrees further (the hips and shoulders found again by the stoop's
    search, the knees given), either the hands no longer reach or the lean
    at the ankles that would put the centre of pressure 5 cm ahead of them
    is past the ankles' range."""
    figure = figures[gender]
    squat = solve_hands_at(figure, HandsAt(0.3, 0.5, "squat"), {}, BOXES)
    body, stance, _, _ = pose_task(figure, squat, BOXES)
    ankles = (body.centers["l_talocrural"][2] + body.centers["r_talocrural"][2]) / 2
    assert stance.center_of_pressure[2] - ankles == pytest.approx(QUIET_STANCE_COP_M, abs=0.002)
    deeper = {(side, "knee_y"): squat[("left", "knee_y")] + 5.0 for side in ("left", "right")}
    try:
        angles = solve_hands_at(figure, HandsAt(0.3, 0.5), deeper, BOXES)
    except TaskError:
        return  # no longer reached
    lean = pose_task(figure, angles, BOXES)[3]
    # the lean stopped at the ankles' dorsiflexion limit, short of that balance
    ankle_high = min(joint_limit_range(figure, side, "ankle_y")[1] for side in ("left", "right"))
    assert lean == pytest.approx(ankle_high)


def test_the_squat_search_stops_at_the_first_start_that_holds_the_hips_at_their_limit(
    figures, monkeypatch
):
    """The 50th-percentile woman at H 40 cm, V 30 cm wants her hips past
    their flexion limit from every start: the first start's 40 poses, not
    each start's (122 before), and the hip-held fallback answers the same."""
    poses = []
    real_pose = hands_at.pose_figure

    def counted(*args, **kwargs):
        poses.append(1)
        return real_pose(*args, **kwargs)

    monkeypatch.setattr(hands_at, "pose_figure", counted)
    angles = solve_hands_at(figures["female"], HandsAt(0.4, 0.3, "squat"), {}, BOXES)
    assert len(poses) <= hands_at.MAX_EVALUATIONS + 2
    hip_limit = joint_limit_range(figures["female"], "left", "hip_y")[1]
    assert angles[("left", "hip_y")] == pytest.approx(hip_limit)
    assert body_h_v(pose_task(figures["female"], angles, BOXES)[0]) == pytest.approx(
        (0.4, 0.3), abs=0.002
    )


def test_sass_task_squat_reports_its_knees_and_ankles(capsys):
    assert main(["task", "hands=30cm,50cm,squat", "--left-load", "10 kg", "--right-load",
                 "10 kg", "--format", "json"]) == 0  # fmt: skip
    shown = json.loads(capsys.readouterr().out)["hands_at"]
    assert shown["by"] == "squat"
    assert set(shown["solved"]["women"]) == {"hip_y", "shoulder_y", "knee_y", "ankle_y"}
    assert main(["task", "hands=30,50,squat", "--gender", "male"]) == 0
    assert "V 50.0 cm by a squat" in capsys.readouterr().out


def test_a_squat_that_ends_with_the_knees_all_but_straight_is_said_to_be_a_stoop(capsys):
    """At V 10 cm with 10 kg in each hand no squat with the heels down
    reaches for the 50th-percentile woman: the fallback folds her hips to
    their limit with the knees 0.6 deg from straight, which the answer says,
    in text and JSON (the Task panel's words: tests/ui/test_task_panel.py);
    the man still squats."""
    argv = ["task", "hands=30cm,10cm,squat", "--left-load", "10 kg", "--right-load", "10 kg"]
    assert main([*argv, "--format", "json"]) == 0
    shown = json.loads(capsys.readouterr().out)["hands_at"]
    assert shown["stooping"] == ["women"]
    assert shown["solved"]["women"]["knee_y"] < STRAIGHT_KNEES_DEG
    assert shown["solved"]["men"]["knee_y"] > STRAIGHT_KNEES_DEG
    assert main(argv) == 0
    (note,) = [line for line in capsys.readouterr().out.splitlines() if "by a squat" in line]
    women, men = note.split("; men ")
    assert STOOPING_WORDS in women and STOOPING_WORDS not in men
    # a squat that bends the knees is a squat
    assert main(["task", "hands=30cm,50cm,squat", *argv[2:], "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["hands_at"]["stooping"] == []


@pytest.mark.parametrize("h_v", [(0.5, 0.6), (0.6, 0.1), (0.2, 0.05), (0.15, 0.4)])
def test_a_squat_is_reached_with_every_angle_it_solves_or_refused_with_a_message(figures, h_v):
    """Places far, low and near: the squat's fallbacks (the hips at their
    limit, the knees straight) still answer with each angle the squat
    solves, on both sides, the grasp at its place, or refuse saying why."""
    figure = figures["female"]
    goal = HandsAt(*h_v, "squat")
    try:
        angles = solve_hands_at(figure, goal, {}, BOXES)
    except TaskError as refused:
        assert "by a squat" in str(refused) and "female figure" in str(refused)
        return
    assert {(side, axis) for side in ("left", "right") for axis in goal.solved_axes} <= set(angles)
    assert body_h_v(pose_task(figure, angles, BOXES)[0]) == pytest.approx(h_v, abs=0.002)


def test_a_squat_to_a_place_above_the_hanging_hands_is_refused(figures, capsys):
    """A squat lowers the hands: a place above where they hang standing
    (the figure's own, about 70 cm for the woman) is left to a stoop."""
    figure = figures["female"]
    hanging = body_h_v(pose_task(figure, {}, BOXES)[0])[1]
    with pytest.raises(TaskError, match="above where the female figure's hands hang"):
        solve_hands_at(figure, HandsAt(0.5, hanging + 0.05, "squat"), {}, BOXES)
    solve_hands_at(figure, HandsAt(0.3, hanging - 0.1, "squat"), {}, BOXES)
    assert main(["task", "hands=50,100,squat", "--gender", "female"]) == 2
    assert "a stoop, hands=H,V, reaches it" in capsys.readouterr().err
