"""Stats on the query screen: the percentile table (`sass stats`,
db/stats.py) of stature, mass and every ANSUR II measure over the people of
the current query: n, effective n, mean, SD and the 1st/5th/50th/95th/99th
percentiles.  With a target population (`t`, ui/target_picker.py) the
people are the target's, weighted, with the share of the target beyond
every person (outside); a virtual population's people are said to be
VIRTUAL in the title and the table.  The table is made in a worker (about
half a second for the virtual NHANES adults), with a progress bar; Escape
returns to the query screen."""

from __future__ import annotations

from rich.text import Text
from textual import work
from textual.binding import Binding
from textual.containers import ScrollableContainer
from textual.message import Message
from textual.widgets import Static

from sass_tui.db.lists import DB_ERRORS, QueryLists
from sass_tui.db.stats import format_stats
from sass_tui.ui.base import SassScreen
from sass_tui.ui.footer import Footer
from sass_tui.ui.progress import Work, WorkBar, WorkProgressed
from sass_tui.ui.target_picker import pick_target, weighted_words
from sass_tui.ui.widgets import MessageLine


class StatsDone(Message):
    def __init__(self, text: str = "", error: str = "") -> None:
        super().__init__()
        self.text = text
        self.error = error


class StatsScreen(SassScreen):
    DEFAULT_CSS = """
    StatsScreen #stats-title { padding: 0 1; text-style: bold; color: $text-accent; }
    StatsScreen #stats-scroll { height: 1fr; }
    StatsScreen #stats-table { padding: 0 1; width: auto; }
    """
    BINDINGS = [
        Binding("escape", "back", "Back to the query"),
        Binding("t", "choose_target", "Target"),
    ]

    def __init__(self, lists: QueryLists, query: str | None, target: str | None = None) -> None:
        super().__init__(id="stats-screen")
        self.lists = lists
        self.query_text = query or None  # None: every real person
        self.target = target or None
        self.text = ""  # the table shown
        self.work: Work | None = None

    def compose(self):
        yield Static(self.title_text(), id="stats-title")
        with ScrollableContainer(id="stats-scroll"):
            yield Static("Making the table, please wait...", id="stats-table")
        yield WorkBar(id="work")
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def title_text(self) -> str:
        people = self.query_text or "every real person"
        return f"Stats of {people}{weighted_words(self.target)}"

    def on_mount(self) -> None:
        self.start_table()

    def start_table(self) -> None:
        self.work = Work(self, "Stats")
        self.query_one(WorkBar).start(self.work)
        self.make_table(self.lists, self.query_text, self.target, self.work)

    @work(thread=True, exclusive=True, group="stats", exit_on_error=False)
    def make_table(
        self, lists: QueryLists, query: str | None, target: str | None, work: Work
    ) -> None:
        try:
            table = lists.stats(query, target, work.cancel)
        except DB_ERRORS as exc:
            self.post_message(StatsDone(error=str(exc)))
            return
        self.post_message(StatsDone(format_stats(table)))

    def on_stats_done(self, event: StatsDone) -> None:
        event.stop()
        self.work = None
        self.query_one(WorkBar).stop()
        shown = self.query_one("#stats-table", Static)
        if event.error:
            shown.update(f"No table: {event.error}")
            self.complain(f"No table: {event.error}")
            return
        self.text = event.text
        shown.update(Text(event.text, no_wrap=True))  # a wide table scrolls sideways
        self.say("Table done: t another target, Esc back to the query, F1 lists the keys.")

    def on_work_progressed(self, event: WorkProgressed) -> None:
        event.stop()
        self.query_one(WorkBar).show(event)

    def action_choose_target(self) -> None:
        """Pick a target or virtual population: the table again on its people, weighted."""
        if self.work is not None:
            self.say("The table is being made: wait for it, or Esc.")
            return
        self.converse(self._choose_target())

    async def _choose_target(self) -> None:
        name = await pick_target(self, self.lists, self.target)
        if name is None:
            return
        self.target = name or None
        self.query_one("#stats-title", Static).update(self.title_text())
        self.query_one("#stats-table", Static).update("Making the table, please wait...")
        self.start_table()

    def action_back(self) -> None:
        """Back to the query screen (cancels a table still being made)."""
        if self.work is not None:
            self.work.cancel.set()
        self.app.pop_screen()
