"""The strength page's Task panel on the spreadsheet (ui/spreadsheet/task_panel.py):
`T` shows and hides it, its posture follows the strength page's row, and
its cells are edited on the message line."""

from __future__ import annotations

from typing import TYPE_CHECKING

from sass_tui.model.errors import SassError
from sass_tui.ui.spreadsheet.spreadsheet_base import SheetScreenBase
from sass_tui.ui.spreadsheet.strength_page import StrengthPage

if TYPE_CHECKING:  # numpy-heavy: mounted the first time T is pressed
    from sass_tui.model.files.task_settings import TaskSettings
    from sass_tui.ui.spreadsheet.task_panel import TaskPanel


class TaskCommands(SheetScreenBase):
    task_shown = False  # T: the Task panel is under the strength page

    @property
    def task_panel(self) -> TaskPanel | None:
        panels = self.query("#task-panel")
        return panels.first() if panels else None  # type: ignore[return-value]

    def show_task_panel(self) -> None:
        """Hand the panel the figure shown and the strength page's posture."""
        panel = self.task_panel
        if panel is None or not panel.display:
            return
        kept = self.session.task
        if panel.keep_settings is None:
            panel.keep_settings = self._keep_task
        if kept is not None and kept != panel.settings():
            try:  # a worksheet's settings, opened since
                panel.take_settings(kept)
            except SassError as exc:
                self.complain(f"the worksheet's task: {exc}; the Task panel keeps its own")
        panel.follow_row(self.figure, self.strength_page.row_angles())

    def _keep_task(self, settings: TaskSettings) -> None:
        self.session.task = settings
        self.redraw_figure_panel()

    def redraw_figure_panel(self) -> None:
        """With the Task panel shown, the figure beside it in the task's posture."""
        panel, figure_panel = self.task_panel, self.figure_panel
        if panel is None or not panel.display or figure_panel is None:
            super().redraw_figure_panel()
            return
        try:
            outline = panel.task_outline()
        except SassError:
            outline = None  # a posture the figure cannot take: drawn standing
        if outline is None:
            super().redraw_figure_panel()
        elif (outline,) != figure_panel.outlines:
            figure_panel.outlines = (outline,)

    def on_strength_page_row_chosen(self, event: StrengthPage.RowChosen) -> None:
        event.stop()
        self.show_task_panel()

    def on_task_panel_posed(self, event: TaskPanel.Posed) -> None:
        event.stop()
        self.redraw_figure_panel()

    def on_task_panel_refused(self, event: TaskPanel.Refused) -> None:
        event.stop()
        self.complain(event.text)

    def on_task_panel_edit_requested(self, event: TaskPanel.EditRequested) -> None:
        event.stop()
        panel = self.task_panel
        assert panel is not None  # it asked
        if self._pass_to_prompt(panel.cells, event.initial):
            return
        cell = event.cell

        def answer(text: str) -> None:
            self.say(panel.set_cell(cell, text))

        try:
            self.ask(panel.prompt(cell), answer, event.initial)
        except SassError as exc:
            self.complain(str(exc))
        self._after_edit_request(panel.cells)
