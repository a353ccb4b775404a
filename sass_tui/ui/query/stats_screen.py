"""Stats on the query screen: the percentile table (`sass stats`,
db/populations/stats.py) of stature, mass and every ANSUR II measure over the people of
the current query: n, effective n, mean, SD and the 1st/5th/50th/95th/99th
percentiles.  With a target population (`t`, ui/query/target_picker.py) the
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

from sass_tui.db.populations.stats import format_stats
from sass_tui.db.query.lists import DB_ERRORS, QueryLists
from sass_tui.model.errors import error_text
from sass_tui.ui.footer import Footer
from sass_tui.ui.progress import Work, WorkBar
from sass_tui.ui.query.target_picker import weighted_words
from sass_tui.ui.query.weighted_work_screen import WeightedWorkScreen
from sass_tui.ui.widgets import MessageLine


class StatsDone(Message):
    def __init__(self, text: str = "", error: str = "") -> None:
        super().__init__()
        self.text = text
        self.error = error


class StatsScreen(WeightedWorkScreen):
    DEFAULT_CSS = """
    StatsScreen #stats-title { padding: 0 1; text-style: bold; color: $text-accent; }
    StatsScreen #stats-scroll { height: 1fr; }
    StatsScreen #stats-table { padding: 0 1; width: auto; }
    """
    BINDINGS = [
        Binding("escape", "back", "Back to the query"),
        Binding("t", "choose_target", "Target"),
    ]

    TITLE_ID = "stats-title"
    ANSWER_ID = "stats-table"
    WORK_NAME = "Stats"
    BUSY = "The table is being made: wait for it, or Esc."
    WAITING = "Making the table, please wait..."

    def __init__(self, lists: QueryLists, query: str | None, target: str | None = None) -> None:
        super().__init__(lists, target, id="stats-screen")
        self.query_text = query or None  # None: every real person
        self.text = ""  # the table shown

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

    def run_work(self, work: Work) -> None:
        self.make_table(self.lists, self.query_text, self.target, work)

    @work(thread=True, exclusive=True, group="stats", exit_on_error=False)
    def make_table(
        self, lists: QueryLists, query: str | None, target: str | None, work: Work
    ) -> None:
        try:
            table = lists.stats(query, target, work.cancel)
        except DB_ERRORS as exc:
            self.post_message(StatsDone(error=error_text(exc)))
            return
        self.post_message(StatsDone(format_stats(table)))

    def on_stats_done(self, event: StatsDone) -> None:
        event.stop()
        self.work_done()
        shown = self.query_one("#stats-table", Static)
        if event.error:
            shown.update(f"No table: {event.error}")
            self.complain(f"No table: {event.error}")
            return
        self.text = event.text
        shown.update(Text(event.text, no_wrap=True))  # a wide table scrolls sideways
        self.say("Table done: t another target, Esc back to the query, F1 lists the keys.")
