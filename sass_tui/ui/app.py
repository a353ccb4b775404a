"""The SASS application: holds the Session and wires the screens.

The anthropometric spreadsheet is the default screen (spreadsheet.py); Query
pushes the query spreadsheet (query_screen.py), Disp. More the More menu.
Each screen has its own BINDINGS; the app has none a screen must switch off.
See docs/architecture.md.
"""

from __future__ import annotations

import gc
import time
from pathlib import Path
from typing import TYPE_CHECKING

from textual import events
from textual.app import App

from sass_tui.model.body.figure import Figure
from sass_tui.model.files.paths import regular_file, user_path
from sass_tui.model.served import served_read_only, served_workdir
from sass_tui.model.session import Session
from sass_tui.ui.key_order import screen_settled
from sass_tui.ui.palette import ScreenCommands
from sass_tui.ui.settings import load_settings, save_setting
from sass_tui.ui.spreadsheet.spreadsheet import STRENGTH_NOT_LOADED, SpreadsheetScreen
from sass_tui.ui.widgets import MessageLine

if TYPE_CHECKING:  # the database costs start-up time: imported when first used
    from sass_tui.db.people.individual import Individual
    from sass_tui.db.query.lists import QueryLists
    from sass_tui.model.files.worksheet import StrengthSettings
    from sass_tui.model.strength.strength import StrengthSheet
    from sass_tui.ui.query.people_work import PeopleWork
    from sass_tui.ui.query.query_messages import DatabaseOpened
    from sass_tui.ui.spreadsheet.figure_work import FigureWork


class SassApp(App):
    # Absolute: the app may be started from any directory.
    CSS_PATH = Path(__file__).with_name("sass.tcss")
    TITLE = "SASS"
    # ctrl+p: the active screen's commands (sass_tui/ui/palette.py) and
    # Textual's own (themes, keys, screenshot, quit).
    COMMANDS = App.COMMANDS | {ScreenCommands}

    def __init__(
        self,
        figure: Figure | None = None,
        *,
        strength_path: str | Path | None = None,
        db_path: str | Path | None = None,
        workdir: Path | None = None,
        read_only: bool = False,
        worksheet: str | Path | None = None,
    ) -> None:
        """`worksheet`: a worksheet file to open (`sass --open FILE`), read
        now: WorksheetError (a SassError) when it cannot be opened."""
        super().__init__()
        # None = $SASS_DB or the user's data directory, created on first Query;
        # a PostgreSQL address (postgresql://...) stays text.
        self.db_path: str | Path | None = None
        if db_path:
            # deferred: db.addresses — the db package is off the first screen (sass_tui/startup.py) unless --db is given; addresses imports nothing
            from sass_tui.db.engine.addresses import is_url

            self.db_path = db_path if is_url(db_path) else user_path(db_path)
        # A session served to a browser (model/served.py): the directory every
        # file name typed at a prompt stays in, and a database it must not change.
        self.workdir = workdir
        self.read_only = read_only
        # The worksheet file Save writes (None: Save asks for a name).
        self.worksheet_path: Path | None = None
        self._opened_strength: StrengthSettings | None = None
        if worksheet is not None:
            figure, strength_path = self._read_worksheet(worksheet)
        figure = figure or Figure.default()
        self._strength_error = STRENGTH_NOT_LOADED
        # The strength sheet (numpy, ~10 ms) is made once the first screen is
        # drawn (first_screen_drawn), or earlier if something asks for it.
        self.session = Session(
            figure, strength_later=lambda: self._make_strength_sheet(figure, strength_path)
        )
        self.query_lists: QueryLists | None = None  # opened by the query screen
        # The population percentile laid over the figure view (None: none);
        # chosen on the figure screen, drawn there and by the spreadsheet's panel.
        self.figure_overlay: float | None = None
        self._quit_asked_at = float("-inf")
        self._restore_theme()

    async def on_event(self, event: events.Event) -> None:
        if isinstance(event, (events.Key, events.Paste)) and not event.is_forwarded:
            # The keys of one read of the terminal, one at a time (ui/key_order.py).
            await screen_settled(self)
            if not self.screen_stack:
                return  # the app closed meanwhile: no screen takes the key
        await super().on_event(event)

    # --- the theme, chosen in the palette ("Change theme"), remembered -----------
    def _restore_theme(self) -> None:
        theme = load_settings().get("theme")
        if isinstance(theme, str) and theme in self.available_themes:
            self.theme = theme
        self._theme_restored = True

    def watch_theme(self, theme: str) -> None:
        if not getattr(self, "_theme_restored", False):
            return  # the default, or the one just read back

        problem = save_setting("theme", theme)
        if problem:
            self.notify(f"The theme is not remembered: {problem}", severity="warning")

    @property
    def strength_error(self) -> str:
        """What to say when the strength sheet is asked for and there is none."""
        self.session.strength_sheets.make()
        return self._strength_error

    @property
    def figure_work(self) -> FigureWork:
        """The work on the figure's model past the first screen (ui/spreadsheet/figure_work.py:
        the strength sheet, the worksheet file, the .fig file, the outlines),
        imported when first needed: once the first screen is drawn, or by
        `sass --open`."""
        # deferred: ui.figure_work (model.strength, model.worksheet, numpy) — off the first screen (sass_tui/startup.py)
        from sass_tui.ui.spreadsheet.figure_work import FigureWork

        return FigureWork()

    def _make_strength_sheet(self, figure: Figure, path: str | Path | None) -> StrengthSheet | None:
        """The population's strength sheet from `path` (None =
        datasets/strength.dat), or None and why in strength_error."""
        sheet, problem = self.figure_work.strength_sheet(
            path, figure, self._opened_strength, self.workdir
        )
        if sheet is None:
            self._strength_error = problem
        return sheet

    def _read_worksheet(self, name: str | Path) -> tuple[Figure, str | None]:
        """The figure of the worksheet `sass --open` names, and its strength
        file (its settings are set on the sheet when it is made)."""
        path = self.regular_file(str(name))
        worksheet = self.figure_work.read_worksheet(path)
        self.worksheet_path = path
        self._opened_strength = worksheet.strength
        strength = worksheet.strength
        return worksheet.figure, None if strength is None else strength.path

    # --- quitting -------------------------------------------------------------
    QUIT_AGAIN = "There are edits since the last save (ctrl+s saves): press q again to quit."
    QUIT_AGAIN_S = 5.0  # where no message line shows the question: the notice's time

    async def action_quit(self) -> None:
        """Quit; with edits since the last save, only on a second q while the
        question is still shown."""
        now = time.monotonic()
        line = self.screen.query(MessageLine).first() if self.screen.query(MessageLine) else None
        asked = (
            line.showing(self.QUIT_AGAIN)
            if line is not None
            else now - self._quit_asked_at < self.QUIT_AGAIN_S
        )
        if not self.session.unsaved_edits() or asked:
            self.exit()
            return
        self._quit_asked_at = now
        if line is not None:
            line.say(self.QUIT_AGAIN)
        else:
            self.notify(self.QUIT_AGAIN, timeout=self.QUIT_AGAIN_S)

    def get_default_screen(self) -> SpreadsheetScreen:
        return SpreadsheetScreen(self.session)

    def first_screen_drawn(self) -> None:
        """The spreadsheet is on the terminal: the strength sheet is made (if
        nothing has asked for it yet); the collector, held off while starting
        (cli.run_tui), runs again; what the start made is frozen out of its
        walks, since it lives as long as the app."""
        self.session.strength_sheets.make()
        if not gc.isenabled():
            gc.freeze()
            gc.enable()

    # --- what tests and screens read ------------------------------------------------
    def user_path(self, text: str) -> Path:
        """A file name typed at a prompt: the user's own, or inside a served
        session's working directory (model/files/paths.py's `inside`)."""
        return user_path(text, self.workdir)

    def regular_file(self, text: str) -> Path:
        """An existing regular file named at a prompt, as `user_path` finds it."""
        return regular_file(text, self.workdir)

    @property
    def spreadsheet(self) -> SpreadsheetScreen:
        return next(s for s in self.screen_stack if isinstance(s, SpreadsheetScreen))

    @property
    def figure(self) -> Figure:
        return self.session.figure

    @property
    def strength_sheet(self) -> StrengthSheet | None:
        return self.session.strength_sheet

    @property
    def data_group(self) -> str:
        return self.spreadsheet.data_group

    @property
    def message_line(self):
        return self.spreadsheet.message_line

    @property
    def strength_page(self):
        return self.spreadsheet.strength_page

    # --- the query screen and the selected list -------------------------------------
    @property
    def people_work(self) -> PeopleWork:
        """The work on the database's people (ui/query/people_work.py: the query
        screen, the selected list, a person's figure and strength, Family,
        Predict's model), imported when a command first needs it: the
        database costs ~60 ms of start-up that a user who never queries
        should not pay."""
        # deferred: ui.people_work (the db package, ui.query_screen, model.prediction) — off the first screen, the first screen's next frame (sass_tui/startup.py)
        from sass_tui.ui.query.people_work import PeopleWork

        return PeopleWork()

    def open_query_screen(self) -> None:
        self.push_screen(self.people_work.query_screen(self.query_lists, self.db_path))

    def open_figure_screen(self) -> None:
        self.push_screen(self.figure_work.figure_screen(self.session))

    def on_database_opened(self, event: DatabaseOpened) -> None:
        self.query_lists = event.lists

    def selected_count(self) -> int:
        lists = self.query_lists
        return self.people_work.selected_count(lists) if lists is not None else 0

    def selected_individual(self, index: int) -> Individual:
        """Person `index` of the selected list, read from the database; OSError
        when it cannot be read, DatabaseError when there is no such person."""
        lists = self.query_lists
        if lists is None:
            raise OSError("the database is not open")
        return lists.fetch_selected(index)

    def person_figure(self, index: int, population: Figure) -> Figure:
        """The figure of person `index` of the selected list (report §12.4)."""
        return self.people_work.person_figure(self.selected_individual(index), population)


def make_app(db_path: str | Path | None = None, worksheet: str | None = None) -> SassApp:
    """The app `sass` runs: a served session's (`sass serve`) when its
    environment says so (model/served.py)."""
    return SassApp(
        db_path=db_path,
        workdir=served_workdir(),
        read_only=served_read_only(),
        worksheet=worksheet,
    )


def run_app(db_path: str | Path | None = None, worksheet: str | None = None, **run_options) -> int:
    """Run the TUI (`worksheet`: `sass --open FILE`); the exit status is the
    app's (non-zero after a crash)."""
    app = make_app(db_path, worksheet)
    app.run(**run_options)
    return app.return_code or 0
