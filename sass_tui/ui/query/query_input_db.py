"""Input DB (report §12.3.3): files imported into the database, asked for
one by one, or an ANSUR II survey file with its source label."""

from __future__ import annotations

from pathlib import Path

from textual import work

from sass_tui.db.people.ansur import DEFAULT_LABEL, looks_like_ansur
from sass_tui.db.people.flatfile import FlatFiles
from sass_tui.db.query.lists import DB_ERRORS, QueryLists
from sass_tui.model.errors import SassError, error_text
from sass_tui.ui.progress import Work
from sass_tui.ui.query.query_base import QueryScreenBase
from sass_tui.ui.query.query_messages import ImportFinished

# Input DB asks for these one by one (report §12.3.3); ESC at Strength
# Parameter skips the three strength files after it.
INPUT_DB_FILES = (
    ("person", "Person"),
    ("girth", "Girth"),
    ("joint_limits", "Joint Limits"),
    ("center_of_mass", "Center of Mass"),
    ("strength_par", "Strength Parameter"),
    ("shoulder", "Shoulder Strength"),
    ("elbow", "Elbow Strength"),
    ("wrist", "Wrist Strength"),
)


CANCELLED_UNCHANGED = "Input DB cancelled; the database is unchanged."


class InputDbCommands(QueryScreenBase):
    def action_input_db(self) -> None:
        """Import person, group and strength files into the database."""
        if self.ready_lists() is None:
            return
        if self.sass_app.read_only:
            self.complain("Input DB is off: this database is served read-only (sass serve).")
            return
        self.converse(self._input_db())

    async def _input_db(self) -> None:
        """Input DB's questions: a file for each of INPUT_DB_FILES in turn, or
        an ANSUR II survey file and its source label.  A refused answer is
        asked again, led by why (the user sees it while answering)."""
        chosen: dict[str, Path] = {}
        problem = ""
        index = 0
        while index < len(INPUT_DB_FILES):
            key, title = INPUT_DB_FILES[index]
            text = await self.answer_to(
                (f"{problem} " if problem else "")
                + f"Enter File Name for {title}"
                + (" (ESC: no strength data)" if index == 4 else "")
                + ":"
            )
            problem = ""
            if text is None:
                if key == "strength_par":
                    break  # no strength data: the person and group files only
                self.say(CANCELLED_UNCHANGED)
                return
            name = text.strip()
            if not name:
                if index == 4:
                    break
                problem = (
                    f"A file name for {title} is needed."
                    if index < 4  # person and the three groups must all be given
                    else "A strength file is needed once Strength Parameter is given."
                )
                continue
            try:
                path = self.sass_app.regular_file(name)
            except SassError as exc:
                problem = f"{exc}."
                continue
            if index == 0:
                if looks_like_ansur(path):  # a survey file holds everything: no group files
                    await self._input_ansur(path)
                    return
            chosen[key] = path
            index += 1
        self._import(chosen)

    async def _input_ansur(self, path: Path) -> None:
        default = path.name.split(".")[0] or DEFAULT_LABEL
        text = await self.answer_to(
            f"{path.name} is an ANSUR II format file. Source label [{default}]:"
        )
        if text is None:
            self.say(CANCELLED_UNCHANGED)
            return
        label = text.strip() or default
        work = self.begin_work("ANSUR import")
        self.say(f"Importing {path.name} as source '{label}' (Esc cancels)...")
        self.import_ansur(self.lists, path, label, work)

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def import_ansur(self, lists: QueryLists, path: Path, label: str, work: Work) -> None:
        try:
            count = lists.import_ansur(path, label, work.report, work.cancel)
        except DB_ERRORS as exc:
            self.post_message(ImportFinished(None, error_text(exc)))
            return
        self.post_message(ImportFinished(count))

    def _import(self, chosen: dict) -> None:
        work = self.begin_work("Input DB")
        self.say("Loading the files into the database (Esc cancels)...")
        self.import_files(self.lists, FlatFiles(**chosen), work)

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def import_files(self, lists: QueryLists, files: FlatFiles, work: Work) -> None:
        try:
            count = lists.import_files(files, work.report, work.cancel)
        except DB_ERRORS as exc:
            self.post_message(ImportFinished(None, error_text(exc)))
            return
        self.post_message(ImportFinished(count))

    def on_import_finished(self, event: ImportFinished) -> None:
        event.stop()
        count, error = event.count, event.error
        if self.end_work() and count is None:
            self.say(CANCELLED_UNCHANGED)
        elif count is None:
            self.complain(f"Input DB failed, the database is unchanged: {error}")
        else:
            self.say(f"Loaded {count:,} people into the database.")
        self.refresh_screen()
