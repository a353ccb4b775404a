"""The Task panel of the strength page (`T` shows and hides it): can the
people do it?  Four cells, edited on the message line like the page's
angles: the posture (the task's own joint angles as `sass task` takes them,
`trunk_y=40 knee_y=30`, or `row`: the angles of the strength page's row
under its cursor, on the limb it shows), the load on the left hand, on the
right hand (a force, then the way the hand exerts it: `60 N down`, or a
mass held), and the people (the figure's gender, the figure shown, women,
men, women and men, `target NAME` or `virtual NAME`).  The figure beside
the panel takes the posture; the cells are saved with the worksheet
(model/files/task_settings.py).  Below them the answer (model/strength/task.py,
docs/task.md): the moments at the elbows, shoulders, low back, hips, knees
and ankles, the percent capable of each loaded hand (the Arm Force Field)
and each hip, knee and ankle (Anderson et al. 2007), the limiting one, the
balance, the NIOSH lifting index and Liberty Mutual's percent capable; or,
with `h`, the curve of percent capable against the load on a loaded hand,
drawn with textual-plotext.

The answer is computed in a worker (ui/spreadsheet/task_work.py) on a copy
of the figure whenever an input changes, and posted back (the TUI never
blocks).  TaskCells owns the keys
(the arrows, Enter, a number typed, `h`) and asks the screen for a prompt
with TaskPanel.EditRequested, as the strength page does.
"""

from __future__ import annotations

import copy
from collections.abc import Callable

from rich.text import Text
from textual import work
from textual.binding import Binding
from textual.containers import Vertical, VerticalScroll
from textual.message import Message
from textual.widget import Widget
from textual.widgets import Static
from textual_plotext import PlotextPlot

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.hanim import build_humanoid
from sass_tui.model.body.outline import Outline
from sass_tui.model.body.posed_outline import posed_outline
from sass_tui.model.body.posture import Angles, pose_figure
from sass_tui.model.errors import SassError, error_text
from sass_tui.model.files.task_settings import TaskSettings
from sass_tui.model.strength.hands_at import split_posture
from sass_tui.model.strength.published_strength import GENDER_WORDS
from sass_tui.model.strength.task import (
    HandLoad,
    TaskAnswer,
    hand_load,
    parse_hand_load,
    pose_task,
)
from sass_tui.ui.spreadsheet.strength_page import TASK_PANEL_LINES
from sass_tui.ui.spreadsheet.task_handling import handling_line
from sass_tui.ui.spreadsheet.task_words import (
    PEOPLE,
    answer_parts,
    load_words,
    parse_people,
    posture_words,
    strength_posture,
)
from sass_tui.ui.spreadsheet.task_work import Curves, TaskInput, assess
from sass_tui.ui.widgets.editor import CURSOR_BINDINGS, EDIT_BINDING, EditorKeys

CELLS = ("posture", "left", "right", "people")
LABELS = ("Posture", "Left hand", "Right hand", "People")
CELL_WIDTH = 26
FOLLOW_ROW = "row"  # the posture cell's word for the strength page's row
DEFAULT_LOAD = 60.0  # N the right hand exerts up: a bag held out


class TaskCells(EditorKeys, Widget, can_focus=True):
    """The panel's first two lines: the posture, and the three cells the
    arrows move over and Enter (or a number typed) edits; `h` the curve."""

    DEFAULT_CSS = """
    TaskCells { height: 2; text-wrap: nowrap; text-overflow: clip; }
    """
    COMPONENT_CLASSES = {"taskpanel--cursor", "taskpanel--cursor-blur", "taskpanel--header"}
    BINDINGS = [
        *CURSOR_BINDINGS,
        Binding("home", "jump(0)", show=False),
        EDIT_BINDING,
        Binding("h", "curve", "Hand curve", tooltip="The task's hand curve or table"),
    ]

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.cursor = 2  # the right hand's load

    @property
    def panel(self) -> TaskPanel:
        parent = self.parent
        assert isinstance(parent, TaskPanel)
        return parent

    def render(self) -> Text:
        panel = self.panel
        style = self.get_component_rich_style
        cursor = style("taskpanel--cursor" if self.has_focus else "taskpanel--cursor-blur")
        head = Text(no_wrap=True, overflow="crop")
        head.append("Task ", style("taskpanel--header"))
        status = "computing..., " if panel.computing else ""
        whose = "the task's own" if panel.own_posture else "the strength page's"
        head.append(f"({status}T hides, h: curve) {whose} posture: ")
        head.append(" ".join(panel.own_posture) or posture_words(panel.row_posture))
        cells = Text(no_wrap=True, overflow="crop")
        for index, (cell, label) in enumerate(zip(CELLS, LABELS)):
            cells.append(f"{label} ")
            shown = f"{panel.cell_text(cell):<{CELL_WIDTH - len(label) - 2}}"
            cells.append(shown, cursor if index == self.cursor else "")
            cells.append(" ")
        return Text("\n", no_wrap=True).join([head, cells])

    def edit_request(self, initial: str) -> Message:
        return TaskPanel.EditRequested(CELLS[self.cursor], initial)

    def cell_at(self, x: int, y: int) -> int | None:
        if y != 1:
            return None
        return min(x // CELL_WIDTH, len(CELLS) - 1)

    def chosen(self) -> int:
        return self.cursor

    def choose(self, cell: object) -> None:
        assert isinstance(cell, int)
        self.cursor = cell

    def action_move(self, rows: int, columns: int) -> None:
        if rows:  # one row of cells: up and down scroll the table under them
            # At once, not after the next refresh: keys pressed faster than the
            # screen redraws would otherwise each start from the same offset.
            self.panel.query_one("#task-table-scroll").scroll_relative(
                y=rows, animate=False, immediate=True
            )
        self.cursor = min(max(self.cursor + columns, 0), len(CELLS) - 1)
        self.refresh()

    def action_jump(self, cell: int) -> None:
        self.cursor = cell
        self.refresh()

    def action_curve(self) -> None:
        """The task's curve: percent capable against the load on a loaded hand, or the table."""
        self.panel.next_view()


class TaskPanel(Vertical):
    """The task's inputs and its answer (a table, or a hand's curve), under
    the strength page; it holds the task and runs the worker."""

    DEFAULT_CSS = f"""
    TaskPanel {{
        height: {TASK_PANEL_LINES};
        padding: 0 1;
        border-top: solid $panel-lighten-2;
    }}
    TaskPanel #task-table-scroll {{ height: 1fr; overflow-x: hidden; scrollbar-size-vertical: 1; }}
    TaskPanel #task-table {{ text-wrap: nowrap; text-overflow: clip; }}
    TaskPanel #task-answer {{ height: auto; max-height: 75%; }}
    TaskPanel #task-curve {{ height: 1fr; display: none; }}
    """

    class EditRequested(Message):
        """Edit the cell `cell` (left, right, people); `initial` = typed so far."""

        def __init__(self, cell: str, initial: str = "") -> None:
            super().__init__()
            self.cell = cell
            self.initial = initial

    class Assessed(Message):
        def __init__(
            self,
            task: TaskInput,
            answer: TaskAnswer | None,
            curves: Curves,
            error: str = "",
            shown: Angles | None = None,
        ) -> None:
            super().__init__()
            self.task, self.answer, self.curves, self.error = task, answer, curves, error
            self.shown = shown  # the figure shown's angles in the task

    class Posed(Message):
        """An answer came with the figure shown's angles: the figure beside
        the panel is drawn in them."""

    class Refused(Message):
        """The people asked for could not be read: the message line says why."""

        def __init__(self, text: str) -> None:
            super().__init__()
            self.text = text

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.loads: dict[str, HandLoad] = {
            "right": hand_load("right", DEFAULT_LOAD, (0.0, 1.0, 0.0))
        }
        self.people = "gender"
        self.answered_people = "gender"  # the people of the answer shown
        # the screen's keeper of the settings (the session, for the worksheet)
        self.keep_settings: Callable[[TaskSettings], None] | None = None
        self.row_posture: tuple[str, ...] = ()  # the strength page's row
        self.own_posture: tuple[str, ...] = ()  # typed in the posture cell; () follows the row
        self.figure: Figure | None = None
        self.answer: TaskAnswer | None = None
        # the figure shown's angles in the task answered (its own stoop for hands=H,V)
        self.shown_angles: Angles | None = None
        self.error = ""
        self.computing = False
        self.pending: TaskInput | None = None  # the newest task handed to a worker
        self.curve_side = ""  # "": the table; else the hand whose curve is drawn
        self.curves: Curves = {}

    def compose(self):
        yield TaskCells(id="task-cells")
        # The table scrolls (the mouse wheel, ↑ ↓) on a short terminal; the notes
        # under it are wrapped at the panel's width and always shown whole.
        with VerticalScroll(id="task-table-scroll", can_focus=False):
            yield Static("", id="task-table")
        yield Static("", id="task-answer")
        plot = PlotextPlot(id="task-curve")
        plot.can_focus = False  # the keys are the cells'
        yield plot

    @property
    def cells(self) -> TaskCells:
        return self.query_one(TaskCells)

    @property
    def posture(self) -> tuple[str, ...]:
        """The task's posture: its own (the posture cell), or the strength page's row."""
        return self.own_posture or self.row_posture

    # --- what it shows -------------------------------------------------------
    def show_task(self, figure: Figure, posture: tuple[str, ...]) -> None:
        """The figure shown and the strength page's posture: a new answer in
        a worker (on a copy of the figure, which edits change in place)."""
        self.figure, self.row_posture = figure, posture
        self.recompute()

    def follow_row(self, figure: Figure, row: tuple[str, list[float]] | None) -> None:
        """The figure shown and the strength page's row (its side and angles,
        StrengthPage.row_angles; None: no row) as the task's posture."""
        self.show_task(figure, () if row is None else strength_posture(*row))

    def recompute(self) -> None:
        if self.keep_settings is not None:
            self.keep_settings(self.settings())
        if self.figure is None:
            return
        self.computing = True
        self.redraw()
        task = TaskInput(
            copy.deepcopy(self.figure),
            self.posture,
            tuple(self.loads.values()),
            self.people,
            getattr(self.app, "db_path", None),
            self.curve_side,
        )
        self.pending = task
        self.run_task(task)

    @work(thread=True, exclusive=True, group="task", exit_on_error=False)
    def run_task(self, task: TaskInput) -> None:
        try:
            answer, curves, shown = assess(task)
        except (SassError, OSError) as exc:
            self.post_message(self.Assessed(task, None, {}, error_text(exc)))
            return
        self.post_message(self.Assessed(task, answer, curves, shown=shown))

    def on_task_panel_assessed(self, event: TaskPanel.Assessed) -> None:
        event.stop()
        if event.task is not self.pending:
            return  # an older task's answer, finished after a newer one was asked for
        self.computing = False
        if event.error and event.task.people != self.answered_people:
            # people that cannot be read: the answer before stays, for its people
            self.people = self.answered_people
            self.post_message(self.Refused(f"{event.task.people}: {event.error}"))
            self.redraw()
            return
        self.answer, self.error, self.curves = event.answer, event.error, event.curves
        if event.shown != self.shown_angles:
            self.shown_angles = event.shown
            self.post_message(self.Posed())
        if event.answer is not None:
            self.answered_people = event.task.people
        self.redraw()

    def redraw(self) -> None:
        """Draw the cells, the table or the curve from the task held."""
        self.cells.refresh()
        self._draw()

    def next_view(self) -> None:
        """The table, then the curve of each loaded hand in turn, then the table."""
        order = ["", *(side for side in ("right", "left") if side in self.loads)]
        self.curve_side = order[(order.index(self.curve_side) + 1) % len(order)]
        self.recompute()

    def _draw(self) -> None:
        answer_view = self.query_one("#task-answer", Static)
        table = self.query_one("#task-table-scroll", VerticalScroll)
        plot = self.query_one("#task-curve", PlotextPlot)
        curve = bool(self.curve_side) and not self.error
        answer_view.display, plot.display = not curve, curve
        table.display = not curve and not self.error
        if self.error:
            answer_view.update(Text(self.error))
        elif self.answer is not None:
            rows, notes = answer_parts(self.answer)
            if self.figure is not None and self.shown_angles is not None:
                notes.append(handling_line(self.figure, self.shown_angles, self.loads.values()))
            self.query_one("#task-table", Static).update(Text("\n".join(rows), no_wrap=True))
            answer_view.update(Text("\n".join(notes)))
        if not curve:
            return
        chart = plot.plt
        chart.clear_data()
        chart.clear_figure()
        for words, points in self.curves.items():
            chart.plot(
                [x for x, _ in points], [y for _, y in points], marker="braille", label=words
            )
        load = self.loads.get(self.curve_side)
        if load is not None and self.curves:
            chart.vline(load.force)
        chart.ylim(0, 100)
        chart.xlabel(f"load on the {self.curve_side} hand (N), the line at the task's")
        chart.ylabel("percent capable (%)")
        chart.title(f"{self.curve_side} hand: La Delfa & Potvin 2017 (Arm Force Field)")
        plot.refresh()

    # --- the inputs, set from the screen's prompts ----------------------------
    def cell_text(self, cell: str) -> str:
        if cell == "posture":
            return " ".join(self.own_posture) or FOLLOW_ROW
        if cell != "people":
            return load_words(self.loads.get(cell))
        if self.people == "gender" and self.figure is not None:
            return f"gender: {GENDER_WORDS[self.figure.gender]}"
        return self.people

    def prompt(self, cell: str) -> str:
        """What the message line asks for `cell`."""
        if cell == "posture":
            return (
                "The task's posture, JOINT=ANGLE ... (trunk_y=30 hip_y=60 shoulder_y=90; "
                "hands=40cm,30cm: a stoop to where the hands grasp, ,squat after it a squat; "
                f"`{FOLLOW_ROW}`: the strength page's row) [{self.cell_text(cell)}]:"
            )
        if cell == "people":
            return (
                f"People the task is for ({', '.join(PEOPLE)}, target NAME or "
                f"virtual NAME) [{self.people}]:"
            )
        return (
            f"Force the {cell} hand exerts (N, then the way it exerts it: up, down, forward, "
            f"back, left, right or X,Y,Z; or a mass held, kg; 0 = none) [{self.cell_text(cell)}]:"
        )

    def set_cell(self, cell: str, text: str) -> str:
        """Take an answer to `prompt`; what the message line says then."""
        if not text.strip():
            what = cell if cell in ("people", "posture") else f"{cell} hand"
            return f"Task: the {what} unchanged."
        if cell == "posture":
            return f"Task: posture {' '.join(self.set_posture(text)) or 'of the row'}."
        if cell == "people":
            return f"Task: for {self.set_people(text)}."
        return f"Task: {load_words(self.set_load(cell, text))} on the {cell} hand."

    def set_load(self, side: str, text: str) -> HandLoad:
        """`60 N down`, `15 lbf up`, `0` for none; a task keeps one load at least."""
        load = parse_hand_load(side, text)
        loads = {**self.loads, side: load}
        if load.force == 0:
            del loads[side]  # a posture with no hand load is a task too
        self.loads = loads
        if self.curve_side and self.curve_side not in loads:
            self.curve_side = next(iter(loads), "")
        self.recompute()
        return load

    def settings(self) -> TaskSettings:
        return TaskSettings(
            self.own_posture,
            tuple((side, load_words(load)) for side, load in sorted(self.loads.items())),
            self.people,
        )

    def take_settings(self, settings: TaskSettings) -> None:
        """A worksheet's settings: each word checked as when typed (SassError)."""
        split_posture(settings.posture)  # refuse a bad word before taking any
        own = settings.posture
        loads = {side: parse_hand_load(side, text) for side, text in settings.loads}
        people = parse_people(settings.people)
        self.own_posture, self.people = own, people
        self.loads = {side: load for side, load in loads.items() if load.force > 0}
        self.curve_side = ""
        self.recompute()

    def task_outline(self) -> Outline | None:
        """The figure shown in the task's posture, standing as the task stands
        (for the figure panel beside it); None: nothing to pose."""
        if self.figure is None or self.shown_angles is None:
            return None
        figure = self.figure
        angles = self.shown_angles
        loads = list(self.loads.values())
        body, _, _, _ = pose_task(figure, angles, loads)
        label = f"{figure.person or 'figure'} in the task's posture"
        return posed_outline(build_humanoid(figure), body, label, float(figure.stature))

    def set_posture(self, text: str) -> tuple[str, ...]:
        """`trunk_y=30 hip_y=60 ...` (checked as `sass task` checks it, and
        against the figure's joint limits), with `hands=H,V` a stoop to where
        the hands grasp (`hands=H,V,squat` a squat, as `sass task` takes it),
        or `row`: follow the strength page."""
        words = tuple(text.split())
        if words == (FOLLOW_ROW,):
            words = ()
        angles, _ = split_posture(words)
        if self.figure is not None:
            pose_figure(self.figure, angles)  # refuse what the figure cannot take
        self.own_posture = words
        self.recompute()
        return words

    def set_people(self, text: str) -> str:
        self.people = parse_people(text)
        self.recompute()
        return self.people
