"""Strength curves: the torque-angle curve of a hip, knee or ankle motion
(Anderson et al. 2007, docs/strength.md) for the figure shown, over the
joint's range (its joint limits), drawn with textual-plotext.

Opened from the spreadsheet (`t`).  The figure's gender, mass, stature and
joint limits are read when the screen opens and at each redraw; the age
(the paper's age group), the percentile and the concentric speed are this
screen's own (`a`, `c`, `v`), `n`/`p` step through the six motions; `l`
asks for a torque and draws percent capable against the torque instead.  The
source of the numbers is on the title line, as on every strength answer.
"""

from __future__ import annotations

from rich.text import Text
from textual.binding import Binding
from textual.widgets import Static
from textual_plotext import PlotextPlot

from sass_tui.model.errors import SassError
from sass_tui.model.population.percentile import check_percentile
from sass_tui.model.strength.published_strength import (
    AGE_GROUPS,
    LOWER_LIMB_MOTIONS,
    MOTION_AXIS,
    PublishedStrengthError,
    Subject,
    age_group,
    lower_limb_curve,
    lower_limb_percent_capable,
    lower_limb_strength,
)
from sass_tui.model.strength.strength import joint_limit_range
from sass_tui.model.units import parse_quantity
from sass_tui.ui.base import SassScreen
from sass_tui.ui.footer import Footer
from sass_tui.ui.widgets import MessageLine


class StrengthCurveScreen(SassScreen):
    DEFAULT_CSS = """
    StrengthCurveScreen #curve-title { padding: 0 1; text-style: bold; color: $text-accent; }
    StrengthCurveScreen #curve-info { padding: 0 1; color: $text-muted; }
    StrengthCurveScreen #curve-plot { height: 1fr; min-height: 8; }
    """
    BINDINGS = [
        Binding("escape", "back", "Back"),
        Binding("n", "next_motion", "Next"),
        Binding("p", "previous_motion", "Prev"),
        Binding("a", "age", "Age"),
        Binding("c", "percentile", "Pctl", tooltip="Percentile"),
        Binding("v", "speed", "Speed"),
        Binding("l", "load", "Load", tooltip="Percent capable of a torque"),
    ]

    def __init__(self, session, side: str = "right", percentile: float = 50.0) -> None:
        super().__init__(id="strength-curve")
        self.session = session
        self.side = side
        self.motion = LOWER_LIMB_MOTIONS.index("knee_extension")
        self.age: float | None = None  # None: the youngest group, said so
        self.percentile = percentile
        self.speed = 0.0  # deg/s, concentric; 0 = isometric
        # A database person shown: their own age is taken, and the curve is
        # marked as predicted for them.
        self.person: str | None = None
        # What was last handed to plotext: (angles, torques), for the tests.
        self.plotted: tuple[list[float], list[float]] = ([], [])
        self.source = ""
        # A torque (N-m) asked about: the plot is then percent capable against
        # the torque at the motion's peak angle within the joint limits.
        self.load: float | None = None
        self.capable: float | None = None

    def compose(self):
        yield Static("", id="curve-title")
        yield Static("", id="curve-info")
        plot = PlotextPlot(id="curve-plot")
        # The plot holds the focus, so keys are this screen's commands and
        # not text for the message line's (idle) answer.
        plot.can_focus = True
        yield plot
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.query_one("#curve-plot", PlotextPlot).focus()
        self.draw()
        self.say("n/p: motion, a: age, c: percentile, v: speed (deg/s, 0 = isometric).")

    def subject(self) -> Subject:
        figure = self.session.figure
        age = self.age if self.age is not None else AGE_GROUPS[0][1]
        return Subject(figure.gender, age, figure.output_mass(), figure.stature / 100.0)

    def draw(self) -> None:
        motion = LOWER_LIMB_MOTIONS[self.motion]
        axis = MOTION_AXIS[motion]
        figure = self.session.figure
        widget = self.query_one("#curve-plot", PlotextPlot)
        plot = widget.plt
        plot.clear_data()
        plot.clear_figure()
        try:
            subject = self.subject()
            lower, upper = joint_limit_range(figure, self.side, axis)
            curve = lower_limb_curve(motion, subject, lower, upper, self.speed, self.percentile)
            peak = lower_limb_strength(motion, subject, None, self.speed, self.percentile)
        except SassError as exc:
            self.plotted = ([], [])
            self.query_one("#curve-title", Static).update(f"{motion.replace('_', ' ')}: {exc}")
            widget.refresh()
            return
        angles = [a for a, _ in curve]
        torques = [t for _, t in curve]
        self.plotted = (angles, torques)
        self.source = peak.source
        if self.person is not None:
            self.source += (
                f"; predicted for {self.person} from their own gender, age, mass and stature"
            )
        top = max(torques)
        at = angles[torques.index(top)]
        if self.load is not None:
            self._plot_capable(plot, motion, subject, at)
        else:
            self.capable = None
            plot.plot(angles, torques, marker="braille")
            plot.xlim(lower, upper)
            plot.ylim(0, max(torques + [1.0]) * 1.05)
            plot.xlabel(f"{axis} (deg of flexion from standing)")
            plot.ylabel("torque (N-m)")
        how = "isometric" if self.speed == 0 else f"concentric at {self.speed:g} deg/s"
        age = "age not given" if self.age is None else f"age {self.age:g}"
        self.query_one("#curve-title", Static).update(
            Text(
                f"{motion.replace('_', ' ').capitalize()} ({self.side}): {self.source}",
                no_wrap=True,
                overflow="ellipsis",
            )
        )
        self.query_one("#curve-info", Static).update(
            Text(
                f"{figure.gender}, {age} (group {peak.group}), {subject.mass:.1f} kg, "
                f"{subject.stature:.3f} m; {how}; highest {top:.1f} N-m at {at:.0f} deg "
                f"within the joint limits {lower:g} to {upper:g} deg",
                no_wrap=True,
                overflow="ellipsis",
            )
        )
        widget.refresh()

    def _plot_capable(self, plot, motion: str, subject: Subject, angle: float) -> None:
        """Percent capable against the torque at `angle` (C1's published spread)."""
        assert self.load is not None
        most = lower_limb_strength(motion, subject, angle, self.speed, 99.5).torque
        torques = [most * i / 60 for i in range(61)]
        shares = [
            lower_limb_percent_capable(motion, subject, x, angle, self.speed) for x in torques
        ]
        self.capable = lower_limb_percent_capable(motion, subject, self.load, angle, self.speed)
        self.plotted = (torques, shares)
        plot.plot(torques, shares, marker="braille")
        plot.vline(self.load)
        plot.ylim(0, 100)
        plot.xlabel(
            f"torque (N-m) at {angle:.0f} deg; {self.load:g} N-m: {self.capable:.1f} % capable"
        )
        plot.ylabel("percent capable (%)")

    def action_load(self) -> None:
        """Percent capable of a torque (N-m; RETURN = the torque curve again)."""

        def answer(text: str) -> None:
            if not text.strip():
                self.load = None
            else:
                value = parse_quantity(text, "N_m")
                if not value >= 0:
                    raise PublishedStrengthError(f"torque {text.strip()!r}: expected 0 or more")
                self.load = value + 0.0  # -0 is 0 N-m, and said so
            self.draw()
            if self.capable is not None:
                self.say(f"{self.capable:.1f} % capable of {self.load:g} N-m at the peak angle.")

        shown = "" if self.load is None else f"{self.load:g}"
        self.ask("Torque to exert (N-m; RETURN = the torque curve):", answer, shown)

    def action_back(self) -> None:
        """Back to the spreadsheet."""
        self.app.pop_screen()

    def action_next_motion(self) -> None:
        """Show the next motion's curve."""
        self.motion = (self.motion + 1) % len(LOWER_LIMB_MOTIONS)
        self.draw()

    def action_previous_motion(self) -> None:
        """Show the previous motion's curve."""
        self.motion = (self.motion - 1) % len(LOWER_LIMB_MOTIONS)
        self.draw()

    def action_age(self) -> None:
        """Set the age (years, 18-100): it picks Anderson et al. 2007's group."""

        def answer(text: str) -> None:
            if not text.strip():
                self.age = None
            else:
                try:
                    age = float(text)
                except ValueError:
                    raise PublishedStrengthError(
                        f"age {text.strip()!r} is not a number of years"
                    ) from None
                age_group(age)  # refuses outside 18-100, naming the groups
                self.age = age
            self.draw()
            self.say(f"Age group {age_group(self.subject().age)}.")

        self.ask("Age (years, 18-100; RETURN = not given):", answer)

    def action_percentile(self) -> None:
        """Set the strength percentile of the curve."""

        def answer(text: str) -> None:
            try:
                value = float(text)
            except ValueError:
                raise PublishedStrengthError(
                    f"percentile {text.strip()!r} is not a number"
                ) from None
            check_percentile(value)
            lower_limb_strength(
                LOWER_LIMB_MOTIONS[self.motion], self.subject(), None, self.speed, value
            )
            self.percentile = value
            self.draw()

        self.ask("Strength percentile (0.5-99.5):", answer, f"{self.percentile:g}")

    def action_speed(self) -> None:
        """Set the concentric speed (deg/s; 0 = isometric)."""

        def answer(text: str) -> None:
            value = parse_quantity(text, "deg/s") if text.strip() else 0.0
            if not value >= 0:
                raise PublishedStrengthError(
                    "the speed is concentric and cannot be negative (eccentric is not offered)"
                )
            self.speed = value
            self.draw()

        self.ask("Concentric speed (deg/s, 0 = isometric):", answer, f"{self.speed:g}")
