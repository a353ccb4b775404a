"""The query screen's base (report §12.3): the database it opens, the lock
that keeps one worker on it at a time, the long work's bar and cancel, and
the page of the list shown."""

from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path

from textual import work

from sass_tui.db.engine.addresses import is_url, shown
from sass_tui.db.engine.database import configured_target
from sass_tui.db.engine.schema import default_db_path
from sass_tui.db.people.default import create_default_database, default_needs_building
from sass_tui.db.progress import Cancelled
from sass_tui.db.query.lists import DB_ERRORS, QUERY_LIST, SELECTED_LIST, DatabaseBusy, QueryLists
from sass_tui.ui.base import SassScreen
from sass_tui.ui.progress import Work, WorkBar, WorkProgressed
from sass_tui.ui.query.query_builder import QueryBuilder
from sass_tui.ui.query.query_commands import QueryCommandMenu
from sass_tui.ui.query.query_list import ListSheet, SummaryPanel
from sass_tui.ui.query.query_messages import (
    DatabaseFailed,
    DatabaseOpened,
    DatabaseProgress,
)

WAIT = "Query on database, please wait..."


class Busy(Exception):
    """The database is in use by a running query or import."""


class QueryScreenBase(SassScreen):
    """The query screen's state, its database and its long work; the
    commands are in QueryScreen and the command mixins (query_input_db.py,
    query_population.py) that subclass this."""

    def __init__(self, lists: QueryLists | None, db_path: str | Path | None = None) -> None:
        super().__init__(id="query-screen")
        self._when_open: list[str] = []  # palette commands waiting for the database
        self.lists = lists
        self.db_path = db_path
        self.which = QUERY_LIST
        self.builder: QueryBuilder | None = None
        self.awaiting_build = False
        self.running = False
        # The queries whose people were moved to the selected list (the
        # population's title says them).
        self.selected_from: list[str] = []
        self.work: Work | None = None  # the long work under way
        self.target: str | None = None  # the target population answers are weighted to
        # The list's sort (a SORT_COLUMNS key, largest first); None: its own order.
        self.sort: tuple[str, bool] | None = None

    @property
    def sheet(self) -> ListSheet:
        return self.query_one(ListSheet)

    # --- long work: progress bar and Escape -----------------------------
    def begin_work(self, what: str, show_after: float = 0.0, busy: bool = True) -> Work:
        """Start long work: the bar (at once, or after `show_after` s) and its
        cancel; `busy`: list commands wait for it (not while the database opens)."""
        self.running = busy
        work = self.work = Work(self, what, show_after)
        self.query_one(WorkBar).start(work)
        return work

    def end_work(self) -> bool:
        """The work is over (its result message arrived); True if a cancel was
        asked for (whether it came in time is the result's to say)."""
        work, self.work = self.work, None
        self.running = False
        self.query_one(WorkBar).stop()
        return work is not None and work.cancel.is_set()

    def on_work_progressed(self, event: WorkProgressed) -> None:
        event.stop()
        self.query_one(WorkBar).show(event)

    def action_cancel_work(self) -> None:
        work = self.work
        if work is None or work.cancel.is_set():
            return
        work.cancel.set()  # the db function stops at its next step, nothing written
        self.query_one(WorkBar).cancelling()
        self.say(f"Cancelling {work.what} ...")

    # --- database ------------------------------------------------------------------
    def open_database(self, db_path: str | Path | None) -> None:
        self._open_database(db_path, self.begin_work("Building the database", busy=False))

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def _open_database(self, db_path: str | Path | None, work: Work) -> None:
        target = configured_target(db_path)
        if is_url(target):  # a lab's PostgreSQL database (--db or $SASS_DB): never built here
            try:
                lists = QueryLists.open(str(target), read_only=self.sass_app.read_only)
            except DB_ERRORS as exc:
                self.post_message(DatabaseFailed(f"Cannot open the database: {exc}"))
                return
            self.post_message(DatabaseOpened(lists, shown(str(target))))
            return
        path = Path(db_path) if db_path else default_db_path()
        read_only = self.sass_app.read_only  # served --read-only: never built nor changed
        building = db_path is None and not read_only and default_needs_building(path)
        try:
            if building:
                self.post_message(DatabaseProgress(f"Creating the default database {path} ..."))
                create_default_database(path, work.report, cancel=work.cancel)
            lists = QueryLists.open(path, read_only=read_only)
        except Cancelled as exc:
            if building:  # rolled back: the empty file must not pass for the database
                for leftover in (path, Path(f"{path}-journal"), Path(f"{path}-wal")):
                    leftover.unlink(missing_ok=True)
            self.post_message(DatabaseFailed(f"Cannot open the database: {exc}"))
            return
        except DB_ERRORS as exc:
            self.post_message(DatabaseFailed(f"Cannot open the database: {exc}"))
            return
        self.post_message(DatabaseOpened(lists, path))

    def run_when_ready(self, action: str) -> None:
        if self.lists is None:
            self._when_open.append(action)  # run by on_database_opened
        else:
            super().run_when_ready(action)

    def on_database_progress(self, event: DatabaseProgress) -> None:
        event.stop()
        self.say(event.text)

    def on_database_failed(self, event: DatabaseFailed) -> None:
        event.stop()
        self._when_open.clear()
        self.end_work()
        self.complain(event.text)

    def on_database_opened(self, event: DatabaseOpened) -> None:
        # Not stopped: the app keeps the lists for Disp. Indv.
        lists, path = event.lists, event.path
        self.end_work()
        self.lists = lists
        self.refresh_screen()
        self.show_page(0)
        self.say(f"Database {path} open. Query DB (d) to query it; Exit Query (e) returns.")
        for action in self._when_open:
            super().run_when_ready(action)
        self._when_open.clear()

    def ready_lists(self) -> QueryLists | None:
        """The open database's lists for a command that starts work on them;
        None, saying why, while a query or an import runs or before the
        database is open."""
        if self.running:
            self.say(WAIT)
            return None
        if self.lists is None:
            self.say("The database is not open yet.")
            return None
        return self.lists

    @contextmanager
    def _database(self):
        """The lists, if no query or import is using the connection."""
        if self.lists is None:
            raise Busy("The database is not open yet.")
        try:
            with self.lists.exclusive(wait=False) as lists:
                yield lists
        except DatabaseBusy:
            raise Busy(WAIT) from None

    def _list_command(self, func) -> None:
        try:
            func()
        except Busy as exc:
            self.say(str(exc))
        except DB_ERRORS as exc:
            self.complain(f"Database error: {exc}")
        self.refresh_screen()

    def show_page(self, first: int) -> None:
        if self.lists is None:
            return
        with self._database() as lists:
            total = lists.count(self.which)
            size = self.sheet.page_size
            first = max(0, min(first, (max(total, 1) - 1) // size * size))
            self.sheet.show_rows(lists.page(self.which, first, size, self.sort), first, total)

    def refresh_screen(self) -> None:
        lists = self.lists
        totals = (lists.count(QUERY_LIST), lists.count(SELECTED_LIST)) if lists else (0, 0)
        query = (lists.last_query or "") if lists else ""
        if self.builder is not None and not self.awaiting_build:
            query = f"{self.builder.text}▏ (being built)"
        self.query_one(SummaryPanel).show(query, self.which, *totals)
        self.query_one(QueryCommandMenu).refresh_labels()
