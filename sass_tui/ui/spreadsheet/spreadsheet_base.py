"""What the anthropometric spreadsheet's commands share (report §12.2): the
screen's state and widgets, the figure shown, the workers' messages and the
answers typed on the message line."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from textual.message import Message

from sass_tui.model.body.figure import Figure
from sass_tui.model.errors import SassError
from sass_tui.model.files.popfile import PopulationData
from sass_tui.model.names import (
    GIRTH,
    STRENGTH,
)
from sass_tui.model.session import Session
from sass_tui.ui.base import SassScreen
from sass_tui.ui.spreadsheet.strength_page import StrengthPage
from sass_tui.ui.widgets import (
    CommandMenu,
    DataSheet,
    EditorKeys,
    GlobalPanel,
    GroupBar,
    MessageLine,
)

if TYPE_CHECKING:  # numpy-heavy: imported when first used, after the first screen
    from sass_tui.model.population.prediction import Prediction, Predictor
    from sass_tui.model.strength.strength import StrengthData


# Lines of the screen that are not data rows: group bar 1, global panel and


class AnswerError(ValueError, SassError):
    """An answer typed on the message line that is not what was asked for."""


def parse_percentile(text: str) -> float:
    cleaned = text.strip().removesuffix("%").strip()
    try:
        return float(cleaned)
    except ValueError:
        raise AnswerError(
            f"expected a percentile such as 50 or 95%, got {text.strip()!r}"
        ) from None


# --- what the workers post ------------------------------------------------------------


class PopulationRead(Message):
    def __init__(
        self, group: str, data: PopulationData, stature_and_mass: PopulationData | None = None
    ) -> None:
        super().__init__()
        self.group = group
        self.data = data
        # the people's own stature and mass beside a girth file (NAME-global.dat)
        self.stature_and_mass = stature_and_mass


class StrengthRead(Message):
    def __init__(self, data: StrengthData) -> None:
        super().__init__()
        self.data = data


class SheetScreenBase(SassScreen):
    """The spreadsheet's state and what its commands share: the widgets,
    the figure shown, the message line's answers and the warnings.  The
    commands are in SpreadsheetScreen and the mixins that subclass this
    (spreadsheet_edit.py, spreadsheet_files.py, spreadsheet_people.py)."""

    def __init__(self, session: Session) -> None:
        super().__init__(id="spreadsheet")
        self.session = session
        self.data_group = GIRTH
        self._warning_index = 0
        self._covered = False  # another screen has been pushed over this one
        self._first_screen_shown = False  # the figure panel is drawn from then on
        self._predictor: Predictor | None = None  # opened on the first Predict
        # The prediction shown and its figure (shown while it is session.person).
        self.prediction: tuple[Prediction, Figure] | None = None

    # --- the live figure panel -----------------------------------------
    @property
    def figure_panel(self):
        """The FigureView beside the data, or None (never mounted: narrow terminal)."""
        panels = self.query("#figure-panel")
        return panels.first() if panels else None

    def redraw_figure_panel(self) -> None:
        """Draw the figure shown, with the figure screen's overlay, if the
        panel is on the screen and what it draws has changed."""
        panel = self.figure_panel
        if panel is None or not panel.display or not self._first_screen_shown:
            return
        app = self.sass_app
        try:
            outlines = app.figure_work.outlines(self.session, app.figure_overlay)
        except SassError:
            outlines = ()  # the caption says there is nothing to draw
        if outlines != panel.outlines:
            panel.outlines = outlines

    def show_task_panel(self) -> None:
        """The strength page's Task panel follows the figure (spreadsheet_task.py)."""

    @property
    def sheet(self) -> DataSheet:
        return self.query_one("#sheet", DataSheet)

    @property
    def strength_page(self) -> StrengthPage:
        return self.query_one(StrengthPage)

    @property
    def active_sheet(self) -> DataSheet:
        """The data section on the screen: the group sheet or the strength page."""
        return self.strength_page if self.data_group == STRENGTH else self.sheet

    @property
    def figure(self) -> Figure:
        return self.session.figure

    @property
    def strength_error(self) -> str:
        return self.sass_app.strength_error

    @property
    def strength_percentile(self) -> float | None:
        """The strength page's percentile: the global panel shows it on that page."""
        if self.data_group != STRENGTH:
            return None
        sheet = self.session.strength_sheet
        return sheet.percentile if sheet is not None else None

    def refresh_screen(self) -> None:
        """Hand every widget what it shows now."""
        self.query_one(GroupBar).highlight(self.data_group)
        self.query_one(GlobalPanel).show(self.figure, self.data_group, self.strength_percentile)
        self.query_one(CommandMenu).refresh_labels()
        self.refresh_bindings()
        if self.data_group != STRENGTH:
            self.sheet.show_group(self.figure, self.data_group)
        else:  # hidden on the other pages (and the sheet made after the first screen)
            self.strength_page.show_sheet(
                self.session.strength_sheet, self.session.strength_sheets.missing
            )
            self.show_task_panel()
        self.redraw_figure_panel()

    # --- message line ---------------------------------------------------------
    def on_message_line_answered(self, event: MessageLine.Answered) -> None:
        event.stop()
        self.refresh_screen()

    def _after_edit_request(self, widget: EditorKeys) -> None:
        if not self.message_line.prompting:
            widget.refuse_edit()  # no prompt takes the keys that follow

    def action_next_warning(self) -> None:
        """Show the next warning of the last file read."""
        if not self.session.warnings:
            self.say("No warnings from the last file loaded.")
            return
        self._warning_index = (self._warning_index + 1) % len(self.session.warnings)
        self._show_warning()

    def _show_warning(self) -> None:
        warnings = self.session.warnings
        self.message_line.show(
            f"{warnings[self._warning_index]}  "
            f"[warning {self._warning_index + 1} of {len(warnings)}; w: next]",
            "warning",
        )

    def _pass_to_prompt(self, widget: EditorKeys, initial: str) -> bool:
        """An edit asked for while a prompt is already open (its key was typed
        before the prompt took the focus): the key is the prompt's."""
        if not self.message_line.prompting:
            return False
        if initial:
            self.message_line.type_ahead("paste", None, initial)
        else:
            self.message_line.type_ahead("enter", None)
        widget.typing_done()
        return True

    def action_strength_curve(self) -> None:
        """Strength curves: hip, knee and ankle torque over the joint's range."""
        # deferred: ui.strength_curve_screen — off the first screen, the first screen's next frame (sass_tui/startup.py)
        from sass_tui.ui.spreadsheet.strength_curve_screen import StrengthCurveScreen

        sheet = self.session.strength_sheets.made()
        side = sheet.side if sheet is not None else "right"
        percentile = sheet.percentile if sheet is not None else 50.0
        screen = StrengthCurveScreen(self.session, side, percentile)
        person = self.session.person
        if person is not None and person.person:
            try:  # a real person's own age; a predicted figure has none
                age = self.sass_app.selected_individual(self.session.person_index).age
            except (SassError, OSError):
                age = math.nan
            if 18 <= age <= 100:
                screen.age, screen.person = age, person.person
        self.app.push_screen(screen)
