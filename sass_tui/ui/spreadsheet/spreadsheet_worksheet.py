"""The spreadsheet's worksheet commands: Save (ctrl+s), Save As (S) and Open
(O) of the worksheet file (model/files/worksheet.py), and redo.  The file is
rendered on the UI thread and written in a worker; one opened is read, with
its strength file, in a worker, and shown only once both were read, so a
file that fails changes nothing."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from textual import work
from textual.message import Message

from sass_tui.model.errors import SassError, reason_text
from sass_tui.model.files.atomic import write_text_atomic
from sass_tui.ui.base import WorkerSaid
from sass_tui.ui.spreadsheet.spreadsheet_files import FileCommands
from sass_tui.ui.widgets.message_line import CANCELLED

if TYPE_CHECKING:  # numpy and the strength model: off the first screen
    from sass_tui.model.files.worksheet import Worksheet
    from sass_tui.model.strength.strength import StrengthData


class WorksheetSaved(Message):
    def __init__(self, path: Path, state: frozenset[int]) -> None:
        super().__init__()
        self.path = path
        self.state = state


class WorksheetRead(Message):
    """A worksheet read; `strength` its strength file read again (None: it
    names none, or `strength_problem` says why it could not be read)."""

    def __init__(
        self,
        path: Path,
        worksheet: Worksheet,
        strength: StrengthData | None,
        strength_problem: str = "",
    ) -> None:
        super().__init__()
        self.path = path
        self.worksheet = worksheet
        self.strength = strength
        self.strength_problem = strength_problem


class WorksheetCommands(FileCommands):
    # --- Save, Save As ----------------------------------------------------------
    def action_save(self) -> None:
        """Save the worksheet (every group, global data, strength) to its file."""
        path = self.sass_app.worksheet_path
        if path is None:
            self.converse(self._save_as())
        else:
            self._save_to(path)

    def action_save_as(self) -> None:
        """Save the worksheet to a file named now."""
        self.converse(self._save_as())

    async def _save_as(self) -> None:
        current = self.sass_app.worksheet_path
        default = str(current) if current is not None else self.sass_app.figure_work.worksheet_name
        name = await self.answer_to(f"Save worksheet as [{default}]:", complete=self.complete_file)
        if name is None:
            self.say(CANCELLED)
            return
        path = self.sass_app.user_path(name.strip() or default)
        if path == current or await self._may_write(path):
            self._save_to(path)

    def _save_to(self, path: Path) -> None:
        # Rendered here: the worker gets the text, not the figure being edited.
        text = self.sass_app.figure_work.worksheet_text(self.session)
        self.say(f"Saving the worksheet to {path} ...")
        self.write_worksheet(path, text, self.session.edit_state())

    @work(thread=True, group="write", exit_on_error=False)
    def write_worksheet(self, path: Path, text: str, state: frozenset[int]) -> None:
        try:
            write_text_atomic(path, text)
        except (SassError, OSError) as exc:
            self.post_message(
                WorkerSaid(
                    f"{path}: cannot write: {reason_text(exc)}; the worksheet is not saved",
                    "error",
                )
            )
            return
        self.post_message(WorksheetSaved(path, state))

    def on_worksheet_saved(self, event: WorksheetSaved) -> None:
        self.session.mark_saved(event.state)
        self.sass_app.worksheet_path = event.path
        self.say(f"Saved the worksheet to {event.path}.")

    # --- Open -------------------------------------------------------------------
    def action_open_worksheet(self) -> None:
        """Open a saved worksheet in place of the sheet shown."""
        unsaved = " (the edits since the last save are replaced)"
        prompt = "Open worksheet file" + (unsaved if self.session.unsaved_edits() else "") + ":"
        self.ask(prompt, self._open_from, complete=self.complete_file)

    def _open_from(self, text: str) -> None:
        if not text.strip():
            self.say("No file given; nothing opened.")
            return
        path = self.sass_app.regular_file(text.strip())
        self.say(f"Opening {path} ...")
        self.read_worksheet_file(path)

    @work(thread=True, exclusive=True, group="input-data", exit_on_error=False)
    def read_worksheet_file(self, path: Path) -> None:
        figure_work = self.sass_app.figure_work
        try:
            worksheet, strength, unread = figure_work.read_worksheet_and_strength(
                path, self.sass_app.workdir
            )
        except (SassError, OSError) as exc:
            self.post_message(WorkerSaid(f"{exc}; the sheet is unchanged.", "error"))
            return
        # The strength file is named, not held, by the worksheet: one moved
        # since leaves the strength page as it is, and the sheet opens.
        problem = ""
        if unread is not None:
            problem = f" Its strength file is not read ({unread}); the strength page is unchanged."
        self.post_message(WorksheetRead(path, worksheet, strength, problem))

    def on_worksheet_read(self, event: WorksheetRead) -> None:
        self.sass_app.figure_work.open_worksheet(self.session, event.worksheet, event.strength)
        self.sass_app.worksheet_path = event.path
        self._warning_index = 0
        self.refresh_screen()
        opened = (
            f"Opened the worksheet {event.path} (saved by sass {event.worksheet.sass_version})."
        )
        if event.strength_problem:
            self.complain(opened + event.strength_problem)
        else:
            self.say(opened)

    # --- redo ---------------------------------------------------------------------
    def action_redo(self) -> None:
        """Do again the edit undone last."""
        what = self.session.redo()
        if what is None:
            self.say("Nothing to redo.")
            return
        self.refresh_screen()
        self.say(f"Redone: {what}.")
