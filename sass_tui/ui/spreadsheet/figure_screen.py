"""The figure screen: the current figure drawn front and side, to scale.

Opened from the spreadsheet (`b`, or "See Figure" in the command palette).
It draws `session.figure` each time it is shown and after each edit made
here (undo), and can lay a second figure over it: the population at the
50th, 5th or 95th percentile (`o` cycles), so a person or a tuned figure is
seen against the population it was drawn from.  `r` shows where the right
hand reaches (model/body/reach.py: its fingertip's envelope over the side
view and seen from above); `p` asks for a point and says whether the hand
reaches it and, if not, by how much it misses.  The overlay chosen is the
app's (`SassApp.figure_overlay`): the spreadsheet's figure panel, drawn live
beside the data on a wide terminal, shows the same (`session_outlines`).
"""

from __future__ import annotations

import copy

import numpy as np
from textual.binding import Binding

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.outline import Outline, figure_outline
from sass_tui.model.body.reach import (
    Envelope,
    envelope,
    linkage_of,
    own_travel,
    parse_point,
    point_verdict,
    reach_drawing,
)
from sass_tui.model.errors import SassError
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.ui.base import SassScreen
from sass_tui.ui.footer import Footer
from sass_tui.ui.spreadsheet.figure_view import FigureView
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


def session_outlines(session, overlay: float | None) -> tuple[Outline, ...]:
    """What the figure view draws of `session`: the figure shown, and the
    population at percentile `overlay` over it (None: no overlay).
    Raises SassError when the figure cannot be drawn."""
    figure = session.figure
    outlines = [figure_outline(figure, figure_label(figure))]
    if overlay is not None:
        overlaid = percentile_figure(session.population, overlay)
        outlines.append(figure_outline(overlaid, f"population {ordinal(overlay)}"))
    return tuple(outlines)


class FigureScreen(SassScreen):
    """Front and side views of the figure shown, with an optional overlay."""

    BINDINGS = [
        Binding("escape", "close", "Back"),
        Binding("b", "close", "Back", show=False),
        Binding("o", "cycle_overlay", "Overlay"),
        Binding("g", "switch_gender", "Gender"),
        Binding("r", "toggle_reach", "Reach", show=False),
        Binding("p", "reach_point", "Point", show=False),
        Binding("u", "undo", "Undo"),
        Binding("q", "app.quit", "Quit"),
    ]

    def __init__(self, session) -> None:
        super().__init__()
        self.session = session
        self.reach_shown = False
        self.point: np.ndarray | None = None  # m, the body's frame

    def compose(self):
        yield FigureView(id="figure-view")
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    @property
    def view(self) -> FigureView:
        return self.query_one(FigureView)

    @property
    def overlay(self) -> float | None:
        """The app's overlay: kept when the screen closes, drawn by the panel too."""
        return self.sass_app.figure_overlay

    def on_mount(self) -> None:
        self.redraw()

    def on_screen_resume(self) -> None:
        self.redraw()

    def redraw(self) -> None:
        """Draw the figure shown (and the overlay) as it is now."""
        try:
            outlines = session_outlines(self.session, self.overlay)
        except SassError as exc:
            self.view.outlines = ()
            self.complain(f"The figure cannot be drawn: {exc}")
            return
        self.view.outlines = outlines
        self.view.reach = self.right_reach() if self.reach_shown else None
        self.say(self.status())

    def right_reach(self):
        """The right fingertip's reach of the figure shown (and the point's verdict)."""
        env = self.envelope()
        return None if env is None else reach_drawing(env, self.point)

    def envelope(self) -> Envelope | None:
        figure = self.session.figure
        try:
            return envelope(own_travel(linkage_of(figure, "right"), figure.landmarks or {}))
        except SassError as exc:
            self.complain(f"No reach for this figure: {exc}")
            return None

    def status_overlay(self) -> str:
        return "no overlay" if self.overlay is None else f"over the {ordinal(self.overlay)}"

    def status(self) -> str:
        return (
            f"Front and side, to scale ({self.status_overlay()}). o: overlay, g: gender, Esc: back."
        )

    def action_toggle_reach(self) -> None:
        """Show or hide where the right hand reaches (side and from above)."""
        self.reach_shown = not self.reach_shown
        self.redraw()

    def action_reach_point(self) -> None:
        """Ask for a point (cm, the body's frame) and say whether the right hand reaches it."""

        def answer(text: str) -> None:
            try:
                point = parse_point(text)
            except SassError as exc:
                self.complain(f"The point is unchanged: {exc}")
                return
            env = self.envelope()
            if env is None:
                return
            self.point, self.reach_shown = point, True
            self.redraw()
            verdict = point_verdict(env, point)
            where = ", ".join(f"{v * 100:g}" for v in point)
            if verdict.reached:
                self.say(f"({where}) cm: the right fingertip reaches it. p: another point.")
            else:
                self.say(
                    f"({where}) cm: the right fingertip misses it by {verdict.miss * 100:.1f} cm. "
                    "p: another point."
                )

        shown = "" if self.point is None else ",".join(f"{v * 100:g}" for v in self.point)
        self.ask("Point X,Y,Z (cm; +X the body's left, +Y up, +Z forward):", answer, shown)

    def action_close(self) -> None:
        """Back to the spreadsheet."""
        self.app.pop_screen()  # the spreadsheet shows what an undo here changed as it resumes

    def action_cycle_overlay(self) -> None:
        """Lay the population's 50th, 5th or 95th over the figure, or nothing."""
        index = OVERLAYS.index(self.overlay) if self.overlay in OVERLAYS else len(OVERLAYS) - 1
        self.sass_app.figure_overlay = OVERLAYS[(index + 1) % len(OVERLAYS)]
        self.redraw()

    def action_switch_gender(self) -> None:
        """Switch the figure to the other gender (every group reloaded) and draw it."""
        other = "female" if self.session.figure.gender == "male" else "male"
        try:
            self.session.set_gender(other)
        except SassError as exc:
            self.complain(f"The gender is unchanged: {exc}")
            return
        self.redraw()
        self.say(f"Now a {other} figure ({self.status_overlay()}). u: undo.")

    def action_undo(self) -> None:
        """Undo the newest edit and draw the figure as it is then."""
        what = self.session.undo()
        if what is None:
            self.say("Nothing to undo.")
            return
        self.redraw()
        self.say(f"Undone: {what}.")
