"""The figure screen: the current figure drawn front and side, to scale.

Opened from the spreadsheet (`b`, or "See Figure" in the command palette).
It draws `session.figure` each time it is shown and after each edit made
here (undo), and can lay a second figure over it: the population at the
50th, 5th or 95th percentile (`o` cycles), so a person or a tuned figure is
seen against the population it was drawn from.
"""

from __future__ import annotations

import copy

from textual.binding import Binding
from textual.widgets import Footer

from sass_tui.model.errors import SassError
from sass_tui.model.figure import Figure
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.model.outline import Outline, figure_outline
from sass_tui.ui.base import SassScreen
from sass_tui.ui.figure_view import FigureView
from sass_tui.ui.widgets import MessageLine

# The overlays `o` cycles through: None, or the population's percentile.
OVERLAYS: tuple[float | None, ...] = (50.0, 5.0, 95.0, None)


def ordinal(p: float) -> str:
    n = round(p)
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def percentile_figure(population: Figure, p: float) -> Figure:
    """A copy of `population` with every group and global value at percentile `p`."""
    figure = copy.copy(population)
    figure.__dict__.update(population.snapshot())  # groups deep-copied, sources shared
    figure.person = None
    for group in (GIRTH, CENTER_OF_MASS, JOINT_LIMITS):
        figure.set_group_percentile(group, p)
    figure.set_stature_percentile(p)
    figure.set_mass_percentile(p)
    return figure


def figure_label(figure: Figure) -> str:
    if figure.person:
        return figure.person
    return f"{figure.gender} figure"


class FigureScreen(SassScreen):
    """Front and side views of the figure shown, with an optional overlay."""

    BINDINGS = [
        Binding("escape", "close", "Back"),
        Binding("b", "close", "Back", show=False),
        Binding("o", "cycle_overlay", "Overlay"),
        Binding("u", "undo", "Undo"),
        Binding("q", "app.quit", "Quit"),
    ]

    def __init__(self, session) -> None:
        super().__init__()
        self.session = session
        self.overlay_index = len(OVERLAYS) - 1  # no overlay until asked

    def compose(self):
        yield FigureView(id="figure-view")
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    @property
    def view(self) -> FigureView:
        return self.query_one(FigureView)

    @property
    def overlay(self) -> float | None:
        return OVERLAYS[self.overlay_index]

    def on_mount(self) -> None:
        self.redraw()

    def on_screen_resume(self) -> None:
        self.redraw()

    def redraw(self) -> None:
        """Draw the figure shown (and the overlay) as it is now."""
        figure = self.session.figure
        try:
            outlines = [figure_outline(figure, figure_label(figure))]
            if self.overlay is not None:
                outlines.append(self._overlay_outline(self.overlay))
        except SassError as exc:
            self.view.outlines = ()
            self.complain(f"The figure cannot be drawn: {exc}")
            return
        self.view.outlines = tuple(outlines)
        self.say(self.status())

    def _overlay_outline(self, p: float) -> Outline:
        population = self.session.population
        return figure_outline(percentile_figure(population, p), f"population {ordinal(p)}")

    def status(self) -> str:
        overlay = "no overlay" if self.overlay is None else f"over the {ordinal(self.overlay)}"
        return f"Front and side, to scale ({overlay}). o: overlay, Esc: back to the spreadsheet."

    def action_close(self) -> None:
        self.app.pop_screen()
        # An undo here changed what the screen below shows.
        refresh = getattr(self.app.screen, "refresh_screen", None)
        if refresh is not None:
            refresh()

    def action_cycle_overlay(self) -> None:
        self.overlay_index = (self.overlay_index + 1) % len(OVERLAYS)
        self.redraw()

    def action_undo(self) -> None:
        if self.session.undo():
            self.redraw()
        else:
            self.say("Nothing to undo.")
