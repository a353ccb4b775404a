"""The Task panel: a posture, the loads on the hands, and who can do it
(model/task.py, docs/strength.md "A task"), for the figure shown on the
spreadsheet and for women and men; and the curve of percent capable against
the load of a loaded hand (the Arm Force Field), drawn with textual-plotext.

Opened with `T` from the spreadsheet (the strength page's task).  `p` the
posture (JOINT=ANGLE ..., as `sass task`), `l`/`r` the load on the left or
right hand ("60 N", "60 N up", "0" for none), `h` which hand's curve.  The
answer is computed in a worker on a copy of the figure, and posted back.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass

from rich.text import Text
from textual import work
from textual.binding import Binding
from textual.message import Message
from textual.widgets import Static
from textual_plotext import PlotextPlot

from sass_tui.model.errors import SassError
from sass_tui.model.figure import Figure
from sass_tui.model.posture import parse_angles, pose_figure
from sass_tui.model.published_strength import GENDER_WORDS
from sass_tui.model.task import (
    HandLoad,
    Reference,
    TaskAnswer,
    TaskError,
    arm_demand,
    assess_task,
    hand_load,
    parse_hand_load,
    task_text,
)
from sass_tui.ui.base import SassScreen
from sass_tui.ui.footer import Footer
from sass_tui.ui.widgets import MessageLine

DEFAULT_POSTURE = ("shoulder_y=60", "elbow_y=30")
DEFAULT_LOAD = 60.0  # N on the right hand, down: a bag held forward
CURVE_POINTS = 41


@dataclass(frozen=True)
class TaskInput:
    """What the worker gets: a copy of the figure shown and the task."""

    figure: Figure
    figure_words: str
    posture: tuple[str, ...]
    loads: tuple[HandLoad, ...]
    curve_side: str


class TaskAssessed(Message):
    def __init__(
        self,
        answer: TaskAnswer | None,
        curves: dict[str, list[tuple[float, float]]],
        error: str = "",
    ) -> None:
        super().__init__()
        self.answer, self.curves, self.error = answer, curves, error


def assess(task: TaskInput) -> tuple[TaskAnswer, dict[str, list[tuple[float, float]]]]:
    """The answer, and percent capable against the load of `curve_side`'s hand
    for each population (the figure shown, women, men)."""
    references = [Reference(task.figure_words, task.figure, None)] + [
        Reference(words, Figure.default(gender), None) for gender, words in GENDER_WORDS.items()
    ]
    angles = parse_angles(list(task.posture))
    answer = assess_task(references, angles, list(task.loads))
    curves: dict[str, list[tuple[float, float]]] = {}
    load = next((x for x in task.loads if x.side == task.curve_side and x.force > 0), None)
    if load is not None:
        for ref in references:
            arm = arm_demand(pose_figure(ref.figure, angles), load, ref.figure.gender)
            top = max(arm.strength(0.5), 1.0)
            curves[ref.words] = [
                (top * i / (CURVE_POINTS - 1), arm.percent_capable(top * i / (CURVE_POINTS - 1)))
                for i in range(CURVE_POINTS)
            ]
    return answer, curves


class TaskScreen(SassScreen):
    DEFAULT_CSS = """
    TaskScreen #task-table { height: auto; max-height: 60%; padding: 0 1; }
    TaskScreen #task-plot { height: 1fr; min-height: 8; }
    """
    BINDINGS = [
        Binding("escape", "back", "Back"),
        Binding("p", "posture", "Posture"),
        Binding("l", "left_load", "Left"),
        Binding("r", "right_load", "Right"),
        Binding("h", "curve_hand", "Hand", tooltip="Which hand's curve"),
    ]

    def __init__(self, figure: Figure) -> None:
        super().__init__(id="task")
        self.figure = figure
        self.posture: tuple[str, ...] = DEFAULT_POSTURE
        self.loads = {"right": hand_load("right", DEFAULT_LOAD, (0.0, -1.0, 0.0))}
        self.curve_side = "right"
        self.answer: TaskAnswer | None = None
        self.curves: dict[str, list[tuple[float, float]]] = {}

    def compose(self):
        yield Static("", id="task-table")
        plot = PlotextPlot(id="task-plot")
        plot.can_focus = True  # the keys are this screen's commands
        yield plot
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.query_one("#task-plot", PlotextPlot).focus()
        self.recompute()
        self.say("p: posture, l/r: load on the left/right hand (e.g. 60 N down), h: hand.")

    # --- the answer ----------------------------------------------------------
    def recompute(self) -> None:
        figure = self.figure
        words = figure.person or "figure shown"
        self.run_task(
            TaskInput(
                copy.deepcopy(figure),
                words,
                self.posture,
                tuple(self.loads.values()),
                self.curve_side,
            )
        )

    @work(thread=True, exclusive=True, group="task", exit_on_error=False)
    def run_task(self, task: TaskInput) -> None:
        try:
            answer, curves = assess(task)
        except SassError as exc:
            self.post_message(TaskAssessed(None, {}, str(exc)))
            return
        self.post_message(TaskAssessed(answer, curves))

    def on_task_assessed(self, event: TaskAssessed) -> None:
        if event.error:
            self.complain(event.error)
            return
        self.answer, self.curves = event.answer, event.curves
        self.draw()

    def draw(self) -> None:
        answer = self.answer
        if answer is None:
            return
        self.query_one("#task-table", Static).update(
            Text("\n".join(task_text(answer, list(self.posture))), no_wrap=True, overflow="crop")
        )
        widget = self.query_one("#task-plot", PlotextPlot)
        plot = widget.plt
        plot.clear_data()
        plot.clear_figure()
        for words, curve in self.curves.items():
            plot.plot([x for x, _ in curve], [y for _, y in curve], marker="braille", label=words)
        load = self.loads.get(self.curve_side)
        if load is not None and self.curves:
            plot.vline(load.force)
        plot.ylim(0, 100)
        plot.xlabel(f"load on the {self.curve_side} hand (N)")
        plot.ylabel("percent capable (%)")
        plot.title(f"{self.curve_side} hand: La Delfa & Potvin 2017 (Arm Force Field)")
        widget.refresh()

    # --- commands ----------------------------------------------------------
    def action_back(self) -> None:
        """Back to the spreadsheet."""
        self.app.pop_screen()

    def action_posture(self) -> None:
        """The posture: JOINT=ANGLE ... (as sass task); RETURN = standing."""

        def answer(text: str) -> None:
            items = tuple(text.split())
            angles = parse_angles(list(items))
            pose_figure(self.figure, angles)  # refuses an angle beyond the joint limits now
            self.posture = items
            self.recompute()

        self.ask(
            "Posture (JOINT=ANGLE ..., e.g. shoulder_y=90 elbow_y=0):",
            answer,
            " ".join(self.posture),
        )

    def _ask_load(self, side: str) -> None:
        def answer(text: str) -> None:
            load = parse_hand_load(side, text)
            loads = {**self.loads, side: load}
            if load.force == 0:
                del loads[side]
            if not loads:
                raise TaskError("a task needs a load on a hand; the loads are unchanged")
            self.loads = loads
            self.recompute()

        current = self.loads.get(side)
        shown = f"{current.force:g} N" if current is not None else "0"
        self.ask(f"Load on the {side} hand (N, then the way it pulls; 0 = none):", answer, shown)

    def action_left_load(self) -> None:
        """The load on the left hand."""
        self._ask_load("left")

    def action_right_load(self) -> None:
        """The load on the right hand."""
        self._ask_load("right")

    def action_curve_hand(self) -> None:
        """Draw the other hand's curve."""
        self.curve_side = "left" if self.curve_side == "right" else "right"
        self.recompute()
