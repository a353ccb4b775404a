"""What the Fit Test and Stats screens share: an answer about the query
screen's people made in a worker with a progress bar (ui/progress.py), made
again when `t` picks a target or virtual population (ui/query/target_picker.py),
and Escape back to the query screen, cancelling the work if it runs."""

from __future__ import annotations

from textual.widgets import Static

from sass_tui.db.query.lists import QueryLists
from sass_tui.ui.base import SassScreen
from sass_tui.ui.progress import Work, WorkBar, WorkProgressed
from sass_tui.ui.query.target_picker import pick_target


class WeightedWorkScreen(SassScreen):
    """A screen showing one answer (`#ANSWER_ID`) under its title
    (`#TITLE_ID`), over the people of `lists`, weighted by `target`."""

    TITLE_ID = ""
    ANSWER_ID = ""
    WORK_NAME = ""  # the progress bar's
    BUSY = ""  # said when `t` is pressed while the answer is being made
    WAITING = ""  # shown while the answer is being made again

    def __init__(self, lists: QueryLists, target: str | None, *, id: str) -> None:
        super().__init__(id=id)
        self.lists = lists
        self.target = target or None  # a target population's name: the answer is weighted
        self.work: Work | None = None

    def title_text(self) -> str:
        raise NotImplementedError

    def run_work(self, work: Work) -> None:
        """Start the worker that makes the answer and posts it."""
        raise NotImplementedError

    def on_mount(self) -> None:
        self.start_work()

    def start_work(self) -> None:
        self.work = Work(self, self.WORK_NAME)
        self.query_one(WorkBar).start(self.work)
        self.run_work(self.work)

    def work_done(self) -> None:
        """The worker's answer came: the progress bar goes."""
        self.work = None
        self.query_one(WorkBar).stop()

    def on_work_progressed(self, event: WorkProgressed) -> None:
        event.stop()
        self.query_one(WorkBar).show(event)

    def action_choose_target(self) -> None:
        """Pick a target or virtual population: the answer again on its people, weighted."""
        if self.work is not None:
            self.say(self.BUSY)
            return
        self.converse(self._choose_target())

    async def _choose_target(self) -> None:
        name = await pick_target(self, self.lists, self.target)
        if name is None:
            return
        self.target = name or None
        self.query_one(f"#{self.TITLE_ID}", Static).update(self.title_text())
        self.query_one(f"#{self.ANSWER_ID}", Static).update(self.WAITING)
        self.start_work()

    def action_back(self) -> None:
        """Back to the query screen (cancels the work still running: it stops
        at its next step, with nothing to undo)."""
        if self.work is not None:
            self.work.cancel.set()
        self.app.pop_screen()
