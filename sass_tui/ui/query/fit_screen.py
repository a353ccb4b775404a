"""Fit Test on the query screen: the current query as design limits
over a population (default `source = ansur2`), shown as `sass fit` prints it:
the shares per gender and weighted, the naive estimate, the per-limit table;
below it a histogram (textual-plotext) of one limited measurement for the
population, per gender, with its limit(s) drawn as vertical lines; `l` shows
the next limited measurement.  The test runs in a worker, with a progress
bar; Escape returns to the query screen (cancelling the test if it runs).
`t` picks a target population (ui/query/target_picker.py): the test is run again
on its people, weighted, and the title says so.  `e` edits the design limits
on the screen (Enter runs them): a `?` is an unknown, solved for the share
typed beside (default 95 %) as `sass design` solves it
(db/populations/design.py), and the solved limits are then fit-tested."""

from __future__ import annotations

from rich.text import Text
from textual import work
from textual.binding import Binding
from textual.containers import Horizontal, ScrollableContainer
from textual.message import Message
from textual.widgets import Input, Static
from textual_plotext import PlotextPlot
from textual_plotext.plot import Plot

from sass_tui.db.populations.design import format_design
from sass_tui.db.populations.fit import LimitHistogram
from sass_tui.db.populations.fit_table import format_table
from sass_tui.db.query.lists import DB_ERRORS, QueryLists
from sass_tui.model.errors import error_text
from sass_tui.ui.footer import Footer
from sass_tui.ui.progress import Work, WorkBar
from sass_tui.ui.query.target_picker import weighted_words
from sass_tui.ui.query.weighted_work_screen import WeightedWorkScreen
from sass_tui.ui.widgets import MessageLine

GENDER_COLORS = {"male": "blue", "female": "magenta"}


class FitDone(Message):
    def __init__(
        self, text: str = "", histograms: tuple[LimitHistogram, ...] = (), error: str = ""
    ) -> None:
        super().__init__()
        self.text = text
        self.histograms = histograms
        self.error = error


def draw_gender_bars(plot: Plot, edges: list[float], counts: dict[str, list[int]]) -> None:
    """Each gender's bars side by side in its bin, its colour named in the
    legend.  Stacked, a bin's one column of cells takes one colour: the
    women's bar hid the men's wherever both were counted."""
    genders = list(counts)
    if not genders or len(edges) < 2:
        return
    share = 1 / len(genders)
    for index, gender in enumerate(genders):
        shift = (index + 0.5) * share - 0.5  # this gender's slot in the bin
        plot.bar(
            [a + (b - a) * (0.5 + shift) for a, b in zip(edges, edges[1:])],
            counts[gender],
            label=gender,
            color=GENDER_COLORS.get(gender, "green"),
            width=share,
        )


def _short(field: str) -> str:
    return field.removeprefix("measure.")


class FitScreen(WeightedWorkScreen):
    DEFAULT_CSS = """
    FitScreen #fit-scroll { height: auto; max-height: 50%; }
    FitScreen #fit-table { padding: 0 1; width: auto; }
    FitScreen #fit-title { padding: 0 1; text-style: bold; color: $text-accent; }
    FitScreen #fit-plot-title { padding: 0 1; color: $text-muted; }
    FitScreen #fit-plot { height: 1fr; min-height: 6; }
    FitScreen #fit-edit { height: auto; }
    FitScreen #fit-limits { width: 1fr; }
    FitScreen #fit-accommodate { width: 12; }
    """
    BINDINGS = [
        Binding("escape", "back", "Back to the query"),
        Binding("l", "next_limit", "Next limit"),
        Binding("t", "choose_target", "Target", show=False),  # F1 lists it; the footer as it was
        Binding("e", "edit_limits", "Edit limits", show=False),
    ]
    AUTO_FOCUS = "#fit-scroll"  # the keys above, not the limits' input, until e

    TITLE_ID = "fit-title"
    ANSWER_ID = "fit-table"
    WORK_NAME = "Fit Test"
    BUSY = "The fit test is running: wait for it, or Esc."
    WAITING = "Testing, please wait..."

    def __init__(
        self, lists: QueryLists, limits: str, population: str, target: str | None = None
    ) -> None:
        super().__init__(lists, target, id="fit-screen")
        self.limits = limits
        self.population = population
        self.percent = 95.0  # the share a `?` is solved for
        self.histograms: tuple[LimitHistogram, ...] = ()
        self.shown = 0  # which histogram is drawn
        # What was last handed to plotext: bin centers and, per gender, the counts.
        self.plotted: tuple[list[float], dict[str, list[int]]] = ([], {})

    def compose(self):
        yield Static(self.title_text(), id="fit-title")
        with Horizontal(id="fit-edit"):
            yield Input(
                self.limits,
                placeholder="design limits; ? to solve, e.g. stature <= ?",
                id="fit-limits",
                compact=True,
            )
            yield Input("95", placeholder="share %", id="fit-accommodate", compact=True)
        with ScrollableContainer(id="fit-scroll"):
            yield Static(f"Testing over {self.population}, please wait...", id="fit-table")
        yield Static("", id="fit-plot-title")
        yield PlotextPlot(id="fit-plot")
        yield WorkBar(id="work")
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def title_text(self) -> str:
        return f"Fit Test of {self.limits}{weighted_words(self.target)}"

    def run_work(self, work: Work) -> None:
        self.run_fit(self.lists, self.limits, self.population, work, self.target)

    def action_edit_limits(self) -> None:
        """Type design limits here (a ? is solved, as sass design does) instead of the last query's."""
        self.query_one("#fit-limits", Input).focus()

    def on_input_submitted(self, event: Input.Submitted) -> None:
        """Enter in either input: test (or solve) the limits typed."""
        event.stop()
        limits = self.query_one("#fit-limits", Input).value.strip()
        if not limits:
            self.complain("Type design limits, e.g. stature <= 190 cm or stature <= ?")
            return
        share = self.query_one("#fit-accommodate", Input).value.strip().removesuffix("%")
        try:
            self.percent = float(share)
        except ValueError:
            self.complain(f"The share {share!r} is no percentage; type e.g. 95")
            return
        self.limits = limits
        self.query_one("#fit-title", Static).update(self.title_text())
        self.query_one("#fit-scroll").focus()
        self.start_work()

    @work(thread=True, exclusive=True, group="fit", exit_on_error=False)
    def run_fit(
        self, lists: QueryLists, limits: str, population: str, work: Work, target: str | None
    ) -> None:
        try:
            if "?" in limits:
                designed, histograms = lists.design(
                    limits, self.percent, population, work.cancel, target=target
                )
                text = format_design(designed) + "\n" + format_table(designed.fit)
            else:
                result, histograms = lists.fit_test(
                    limits, population, work.report, work.cancel, target=target
                )
                text = format_table(result)
        except DB_ERRORS as exc:
            self.post_message(FitDone(error=error_text(exc)))
            return
        self.post_message(FitDone(text, histograms))

    def on_fit_done(self, event: FitDone) -> None:
        event.stop()
        self.work_done()
        table = self.query_one("#fit-table", Static)
        text = f"The fit test was not run: {event.error}" if event.error else event.text
        table.update(Text(text, no_wrap=True))  # a wide table scrolls sideways
        if event.error:
            self.complain(f"The fit test was not run: {event.error}")
        else:
            more = ", l the next limit" if len(event.histograms) > 1 else ""
            self.say(f"Fit test done: Esc back to the query{more}, F1 lists the keys.")
        self.histograms = event.histograms
        self.shown = 0
        self.draw_histogram()

    def action_next_limit(self) -> None:
        """Show the histogram of the next limited measurement."""
        if len(self.histograms) > 1:
            self.shown = (self.shown + 1) % len(self.histograms)
            self.draw_histogram()

    def draw_histogram(self) -> None:
        title = self.query_one("#fit-plot-title", Static)
        widget = self.query_one("#fit-plot", PlotextPlot)
        plot = widget.plt
        plot.clear_data()
        plot.clear_figure()
        if not self.histograms:
            title.update("No limit on a number to draw." if self.limits else "")
            self.plotted = ([], {})
            widget.refresh()
            return
        hist = self.histograms[self.shown]
        edges = [float(e) for e in hist.edges]
        centers = [(a + b) / 2 for a, b in zip(edges, edges[1:])]
        counts = {g: [int(c) for c in hist.counts[g]] for g in hist.counts}
        self.plotted = (centers, counts)
        draw_gender_bars(plot, edges, counts)
        top = max((max(column) for column in counts.values() if column), default=0)
        for line in hist.lines:
            # A line series, not plotext's vline: it is drawn over the bars.
            plot.plot([line.value, line.value], [0, top], color="red", marker="braille")
        plot.xlim(edges[0], edges[-1])
        ticks = [edges[0] + (edges[-1] - edges[0]) * k / 4 for k in range(5)]
        plot.xticks(ticks, [f"{t:.4g}" for t in ticks])
        unit = f" ({hist.unit})" if hist.unit else ""
        plot.xlabel(f"{_short(hist.field)}{unit}")
        plot.ylabel("people")
        limits = ", ".join(f"{_short(x.field)} {x.op} {x.value:g}" for x in hist.lines)
        more = f"  (l: {self.shown + 1}/{len(self.histograms)})" if len(self.histograms) > 1 else ""
        missing = f"; {hist.missing} not measured" if hist.missing else ""
        title.update(
            Text(
                f"{_short(hist.field)}{unit} of {self.population}, red: {limits}{missing}{more}",
                no_wrap=True,
                overflow="ellipsis",
            )
        )
        widget.refresh()
