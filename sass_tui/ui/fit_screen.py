"""Fit Test (issue 14) on the query screen: the current query as design limits
over a population (default `source = ansur2`), shown as `sass fit` prints it:
the shares per gender and weighted, the naive estimate, the per-limit table.
The test runs in a worker; Escape returns to the query screen."""

from __future__ import annotations

from rich.text import Text
from textual import work
from textual.binding import Binding
from textual.containers import ScrollableContainer
from textual.message import Message
from textual.screen import Screen
from textual.widgets import Footer, Static

from sass_tui.db.fit_table import format_table
from sass_tui.db.lists import DB_ERRORS, QueryLists


class FitDone(Message):
    def __init__(self, text: str = "", error: str = "") -> None:
        super().__init__()
        self.text = text
        self.error = error


class FitScreen(Screen):
    DEFAULT_CSS = """
    FitScreen #fit-table { padding: 0 1; width: auto; }
    FitScreen #fit-title { padding: 0 1; text-style: bold; color: $text-accent; }
    """
    BINDINGS = [Binding("escape", "app.pop_screen", "Back to the query")]

    def __init__(self, lists: QueryLists, limits: str, population: str) -> None:
        super().__init__(id="fit-screen")
        self.lists = lists
        self.limits = limits
        self.population = population

    def compose(self):
        yield Static(f"Fit Test of {self.limits}", id="fit-title")
        with ScrollableContainer():
            yield Static(f"Testing over {self.population}, please wait...", id="fit-table")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.run_fit(self.lists, self.limits, self.population)

    @work(thread=True, exclusive=True, group="fit", exit_on_error=False)
    def run_fit(self, lists: QueryLists, limits: str, population: str) -> None:
        from sass_tui.db.fit import fit_test

        try:
            with lists.lock:
                result = fit_test(lists.conn, limits, population)
        except DB_ERRORS as exc:
            self.post_message(FitDone(error=str(exc)))
            return
        self.post_message(FitDone(format_table(result)))

    def on_fit_done(self, event: FitDone) -> None:
        event.stop()
        table = self.query_one("#fit-table", Static)
        text = f"The fit test was not run: {event.error}" if event.error else event.text
        table.update(Text(text, no_wrap=True))  # a wide table scrolls sideways
