"""The database query spreadsheet (report §12.3, figures 9, 10, 11) and the
commands of the anthropometric spreadsheet that reach it: Query, Disp. Indv.,
Disp. More and Disp. Pop. (§12.2, §12.4, §12.5).

The lists are TEMP tables of the database (sass_tui/db/lists.py): a page is
read when it is shown, so a query list of 100,000 people is 25 rows of
widgets' worth of work.  Queries and Input DB run in worker threads; while
one runs, keys are still answered and list commands say so instead of waiting.
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from pathlib import Path

from rich.text import Text
from textual import events, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.message import Message
from textual.reactive import reactive
from textual.screen import ModalScreen
from textual.widget import Widget
from textual.widgets import Footer, OptionList, Static
from textual.widgets.option_list import Option

from sass_tui.db.flatfile import FlatFiles
from sass_tui.db.lists import DB_ERRORS, QUERY_LIST, SELECTED_LIST, DatabaseBusy, QueryLists
from sass_tui.model.errors import SassError
from sass_tui.model.text import printable
from sass_tui.ui.base import SassScreen
from sass_tui.ui.commands import CommandSpec
from sass_tui.ui.progress import QUERY_BAR_AFTER, Work, WorkBar, WorkProgressed
from sass_tui.ui.query_builder import QueryBuilder, QueryBuilderScreen
from sass_tui.ui.widgets import CommandMenu, MenuItem, MessageLine

BUILD_PROMPT = "Press rightmouse to build query."
WAIT = "Query on database, please wait..."
COMPLETE = "Query execution is complete."
NO_DATA = "No data satisfied the query."
LIST_TITLES = {QUERY_LIST: "Query List", SELECTED_LIST: "Selected List"}
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


class Busy(Exception):
    """The database is in use by a running query or import."""


def _on_query_list(screen) -> bool:
    return screen.which == QUERY_LIST


def _void_unless_query_list(label: str):
    return lambda screen: label if _on_query_list(screen) else "void"


# Figure 11: the first label is the one shown with the query list.  The list
# button names the list it will display.
QUERY_COMMANDS: tuple[CommandSpec, ...] = (
    CommandSpec(
        "q_next_page", "n", "next_page", "Next", lambda screen: "Next Page", row=0, in_footer=False
    ),
    CommandSpec(
        "q_previous_page",
        "p",
        "previous_page",
        "Prev",
        lambda screen: "Previous Page",
        row=1,
        in_footer=False,
    ),
    CommandSpec("query_db", "d", "query_db", "Query", lambda screen: "Query DB", row=2),
    CommandSpec(
        "select_all",
        "a",
        "select_all",
        "All",
        _void_unless_query_list("Select All"),
        row=3,
        available=_on_query_list,
    ),
    CommandSpec(
        "select_one",
        "s",
        "select_one",
        "One",
        _void_unless_query_list("Select One"),
        row=4,
        available=_on_query_list,
    ),
    CommandSpec(
        "delete_one",
        "x",
        "delete_one",
        "Delete",
        lambda screen: "Delete One",
        row=5,
        in_footer=False,
    ),
    CommandSpec(
        "display_list",
        "l",
        "display_list",
        "List",
        lambda screen: "Disp. Selected List" if _on_query_list(screen) else "Disp. Query List",
        column=1,
        row=0,
    ),
    CommandSpec(
        "input_db",
        "i",
        "input_db",
        "Input DB",
        lambda screen: "Input DB",
        column=1,
        row=1,
        in_footer=False,
    ),
    CommandSpec(
        "exit_query",
        "e",
        "exit_query",
        "Exit",
        _void_unless_query_list("Exit Query"),
        column=1,
        row=5,
        available=_on_query_list,
    ),
)


class QueryCommandMenu(CommandMenu):
    """Figure 11 keeps its slots: a command that does not apply reads "void"."""

    def refresh_labels(self) -> None:
        for spec in self.commands:
            item = self.item(spec)
            item.label = spec.label(self.context)
            item.disabled = not spec.available(self.context)


class SummaryPanel(Static):
    def show(self, query: str, which: str, query_total: int, selected_total: int) -> None:
        text = Text(no_wrap=True, overflow="ellipsis")
        for label, value in (
            ("Query", query or "(none yet)"),
            ("Current Display List", LIST_TITLES[which]),
            ("Total Data in Query List", f"{query_total:,}"),
            ("Total Data in Selected List", f"{selected_total:,}"),
        ):
            text.append(f"{label}: ", "bold")
            text.append(f"{value}\n")
        text.rstrip()  # in place: no empty line after the last
        self.update(text)


# What a real person has first (age, survey branch), so that 80 columns show
# it; the strength columns, which only the synthetic people fill, after.
LIST_COLUMNS = (
    ("Name", "name", 14, "<"),
    ("Source", "source", 10, "<"),
    ("Gender", "gender", 7, "<"),
    ("Age", "age", 4, ">"),
    ("Mass kg", "mass", 8, ">"),
    ("Stature cm", "stature", 11, ">"),
    ("Branch", "branch", 15, "<"),
    ("Handed", "handedness", 7, "<"),
    ("Strength type", "strength_type", 14, "<"),
    ("Speed °/s", "motion_speed", 10, ">"),
    ("Training", "training_level", 9, ">"),
    ("Fatigue", "fatigue_level", 8, ">"),
)


# How a person's source label reads in the list; an imported file's label is
# shown as stored.
SOURCE_NAMES = {"ansur2": "ANSUR II", "synthetic": "synthetic"}


def _cell(row: dict, key: str) -> str:
    value = row.get(key)
    if key == "source" and isinstance(value, str):
        return printable(SOURCE_NAMES.get(value, value))
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return ""
    if isinstance(value, float):
        return f"{value:.1f}" if key in ("mass", "stature") else f"{value:g}"
    return printable(value)  # names and sources come from files (issue 17)


class ListSheet(Widget, can_focus=True):
    """One page of the query or selected list; only the page's rows are held."""

    COMPONENT_CLASSES = {"listsheet--header", "listsheet--cursor", "listsheet--page"}
    BINDINGS = [Binding("up", "move(-1)", show=False), Binding("down", "move(1)", show=False)]
    HEADER_LINES = 2
    PAGE_ROWS = 25

    class PageTurned(Message):
        """The wheel asks for the next (1) or the previous (-1) page."""

        def __init__(self, pages: int) -> None:
            super().__init__()
            self.pages = pages

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.rows: list[dict] = []
        self.first = 0  # list position of rows[0]
        self.total = 0
        self.cursor = 0

    # Set by the screen from the terminal's height, not from this widget's
    # layout: the page size must not depend on when the layout ran.
    page_rows: reactive[int] = reactive(PAGE_ROWS, init=False)

    def validate_page_rows(self, rows: int) -> int:
        return max(1, min(self.PAGE_ROWS, rows))

    @property
    def page_size(self) -> int:
        return self.page_rows

    def show_rows(self, rows: list[dict], first: int, total: int) -> None:
        self.rows, self.first, self.total = rows, first, total
        self.cursor = min(self.cursor, max(0, len(rows) - 1))
        self.refresh()

    @property
    def highlighted(self) -> dict | None:
        return self.rows[self.cursor] if self.rows else None

    def render(self) -> Text:
        header = self.get_component_rich_style("listsheet--header")
        cursor = self.get_component_rich_style("listsheet--cursor")
        page_style = self.get_component_rich_style("listsheet--page")
        # The name column is as wide as the longest name on the page: a name
        # ("ANSUR II F 11533") is shown whole, never cut.
        longest = max((len(_cell(row, "name")) for row in self.rows), default=0)
        columns = [
            (title, key, max(width, longest + 1) if key == "name" else width, align)
            for title, key, width, align in LIST_COLUMNS
        ]
        top = Text(no_wrap=True, overflow="crop")
        for title, _, width, align in columns:
            top.append(f"{title:{align}{width - 1}} "[:width], header)
        pages = max(1, -(-self.total // self.page_size))
        page = self.first // self.page_size + 1
        lines = [top, Text(f"page {page}/{pages}", page_style)]
        if not self.rows:
            lines.append(Text("(empty)"))
        for index, row in enumerate(self.rows):
            line = Text(no_wrap=True, overflow="crop")
            for _, key, width, align in columns:
                line.append(f"{_cell(row, key)[: width - 1]:{align}{width - 1}} ")
            if index == self.cursor and self.has_focus:
                line.stylize(cursor)
            lines.append(line)
        return Text("\n", no_wrap=True).join(lines)

    def action_move(self, rows: int) -> None:
        if self.rows:
            self.cursor = min(max(self.cursor + rows, 0), len(self.rows) - 1)
            self.refresh()

    def on_click(self, event: events.Click) -> None:
        offset = event.get_content_offset(self)
        if offset is not None and event.button == 1:
            row = offset.y - self.HEADER_LINES
            if 0 <= row < len(self.rows):
                self.cursor = row
                self.focus()
                self.refresh()

    def on_mouse_scroll_down(self, event: events.MouseScrollDown) -> None:
        event.stop()
        self.post_message(self.PageTurned(1))

    def on_mouse_scroll_up(self, event: events.MouseScrollUp) -> None:
        event.stop()
        self.post_message(self.PageTurned(-1))

    def on_focus(self) -> None:
        self.refresh()

    def on_blur(self) -> None:
        self.refresh()


class DatabaseOpened(Message):
    def __init__(self, lists: QueryLists, path: str | Path) -> None:
        super().__init__()
        self.lists = lists
        self.path = path


class DatabaseFailed(Message):
    def __init__(self, text: str) -> None:
        super().__init__()
        self.text = text


class QueryFinished(Message):
    """A query's outcome: the count and first page, or what went wrong."""

    def __init__(
        self,
        count: int = 0,
        rows: list[dict] | None = None,
        error: str = "",
        weighted: str = "",
        hint: str = "",
    ) -> None:
        super().__init__()
        self.count = count
        self.rows = rows or []
        self.error = error
        self.weighted = weighted  # the target's weighted share (ui/target_picker.py)
        self.hint = hint  # no real person found: the demonstration people who would be


class PopulationMade(Message):
    """Make Population's outcome: the population and the files written, or why not."""

    def __init__(self, result=None, paths: dict | None = None, error: str = "") -> None:
        super().__init__()
        self.result = result
        self.paths = paths or {}
        self.error = error


class ImportFinished(Message):
    def __init__(self, count: int | None, error: str = "") -> None:
        super().__init__()
        self.count = count
        self.error = error


# Lines of the query screen that are not list rows: summary and command menu
# 6, the list's border 1 and header 2, message line 1, footer 1 (query.tcss).
LIST_FIXED_LINES = 6 + 1 + ListSheet.HEADER_LINES + 1 + 1


class QueryScreen(SassScreen):
    CSS_PATH = Path(__file__).with_name("query.tcss")
    BINDINGS = [
        # The footer at 80 columns: d a s l e b m f q; the menu shows the rest.
        *(
            Binding(spec.key, spec.action, spec.footer, show=spec.in_footer)
            for spec in QUERY_COMMANDS
        ),
        Binding("b", "build", "Build", tooltip="Build query"),
        Binding("m", "make_population", "Make", tooltip="Make Population"),
        Binding("f", "fit_test", "Fit", tooltip="Fit Test"),
        Binding("G", "export_gltf", "glTF", tooltip="Export glTF", show=False),
        Binding("t", "choose_target", "Target", show=False, tooltip="Target population"),
        Binding("q", "app.quit", "Quit"),
        Binding("escape", "cancel_work", "Cancel work", show=False),
        Binding("pagedown", "next_page", show=False),
        Binding("pageup", "previous_page", show=False),
    ]

    COMMAND_SPECS = QUERY_COMMANDS  # the menu's: the palette names these commands by them

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
        self.work: Work | None = None  # the long work under way (issue 15)
        self.target: str | None = None  # the target population answers are weighted to

    def compose(self):
        with Horizontal(id="query-top"):
            yield SummaryPanel(id="summary")
            yield QueryCommandMenu(QUERY_COMMANDS, self, id="query-commands")
        yield ListSheet(id="list")
        yield WorkBar(id="work")
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.sheet.page_rows = self.app.size.height - LIST_FIXED_LINES
        self.sheet.focus()
        self.refresh_screen()
        if self.lists is None:
            self.say("Opening the database ...")
            self.open_database(self.db_path)
        else:
            self.show_page(0)
            self.say("Query DB (d) to query the database; Exit Query (e) returns.")

    @property
    def sheet(self) -> ListSheet:
        return self.query_one(ListSheet)

    # --- message line -----------------------------------------------------------------
    def on_resize(self, event: events.Resize) -> None:
        self.sheet.page_rows = event.size.height - LIST_FIXED_LINES

    def on_message_line_answered(self, event: MessageLine.Answered) -> None:
        event.stop()
        if not self.message_line.prompting:
            self.set_focus(self.sheet)
        self.refresh_screen()

    # --- long work: progress bar and Escape (issue 15) -----------------------------
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
        from sass_tui.db.addresses import is_url
        from sass_tui.db.database import configured_target
        from sass_tui.db.default import create_default_database, default_needs_building
        from sass_tui.db.progress import Cancelled
        from sass_tui.db.schema import default_db_path

        target = configured_target(db_path)
        if is_url(target):  # a lab's PostgreSQL database (--db or $SASS_DB): never built here
            from sass_tui.db.postgres import shown

            try:
                lists = QueryLists.open(str(target))
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
                self.post_message(DatabaseFailed(f"Creating the default database {path} ..."))
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

    def on_database_failed(self, event: DatabaseFailed) -> None:
        event.stop()
        if not event.text.endswith("..."):
            self._when_open.clear()
            self.end_work()
        (self.say if event.text.endswith("...") else self.complain)(event.text)

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
            self.sheet.show_rows(lists.page(self.which, first, size), first, total)

    def refresh_screen(self) -> None:
        lists = self.lists
        totals = (lists.count(QUERY_LIST), lists.count(SELECTED_LIST)) if lists else (0, 0)
        query = (lists.last_query or "") if lists else ""
        if self.builder is not None and not self.awaiting_build:
            query = f"{self.builder.text}▏ (being built)"
        self.query_one(SummaryPanel).show(query, self.which, *totals)
        self.query_one(QueryCommandMenu).refresh_labels()

    # --- command menu ------------------------------------------------------------------
    async def on_menu_item_pressed(self, event: MenuItem.Pressed) -> None:
        spec = next((c for c in QUERY_COMMANDS if event.item.id == f"command-{c.name}"), None)
        if spec is not None:
            event.stop()
            await self.run_action(spec.action)

    def _turn(self, pages: int) -> None:
        sheet = self.sheet
        target = sheet.first + pages * sheet.page_size
        if not 0 <= target < max(sheet.total, 1):
            self.say("This is the last page." if pages > 0 else "This is the first page.")
            return
        self.show_page(target)
        self.say(
            f"Page {target // sheet.page_size + 1} of {max(1, -(-sheet.total // sheet.page_size))}."
        )

    def action_next_page(self) -> None:
        """Show the next page of the list."""
        self._list_command(lambda: self._turn(1))

    def on_list_sheet_page_turned(self, event: ListSheet.PageTurned) -> None:
        event.stop()
        self._list_command(lambda: self._turn(event.pages))

    def action_previous_page(self) -> None:
        """Show the previous page of the list."""
        self._list_command(lambda: self._turn(-1))

    def action_select_all(self) -> None:
        """Move everyone in the query list to the selected list."""
        if self.which != QUERY_LIST:
            self.say("Select All is void while the selected list is shown.")
            return

        def select_all():
            with self._database() as lists:
                moved = lists.select_all()
                self._selected_from(lists.last_query if moved else None)
            self.show_page(0)
            self.say(f"{moved:,} people moved to the selected list.")

        self._list_command(select_all)

    def _selected_from(self, query: str | None) -> None:
        if query and query not in self.selected_from:
            self.selected_from.append(query)

    def action_select_one(self) -> None:
        """Move the highlighted person to the selected list."""
        if self.which != QUERY_LIST:
            self.say("Select One is void while the selected list is shown.")
            return
        person = self.sheet.highlighted
        if person is None:
            self.say("The query list is empty.")
            return

        def select_one():
            with self._database() as lists:
                if lists.select_one(person["id"]):
                    self._selected_from(lists.last_query)
            self.show_page(self.sheet.first)
            self.say(f"{person['name']} moved to the selected list.")

        self._list_command(select_one)

    def action_delete_one(self) -> None:
        """Delete the highlighted person from the list shown."""
        person = self.sheet.highlighted
        if person is None:
            self.say(f"The {LIST_TITLES[self.which].lower()} is empty.")
            return

        def delete_one():
            with self._database() as lists:
                lists.delete_one(self.which, person["id"])
            self.show_page(self.sheet.first)
            self.say(f"{person['name']} deleted from the {LIST_TITLES[self.which].lower()}.")

        self._list_command(delete_one)

    def action_display_list(self) -> None:
        """Switch between the query list and the selected list."""

        def switch():
            self.which = SELECTED_LIST if self.which == QUERY_LIST else QUERY_LIST
            self.sheet.cursor = 0
            self.show_page(0)
            self.say(f"{LIST_TITLES[self.which]} displayed.")

        self._list_command(switch)

    def action_exit_query(self) -> None:
        """Back to the anthropometric spreadsheet."""
        if self.which != QUERY_LIST:
            self.say("Exit Query is void while the selected list is shown; display the query list.")
            return
        if self.running:
            self.say(WAIT)
            return
        self.app.pop_screen()

    # --- Query DB: the pop-up builder -------------------------------------------------
    def action_query_db(self) -> None:
        """Start a query of the database."""
        if self.running:
            self.say(WAIT)
            return
        if self.lists is None:
            self.say("The database is not open yet.")
            return
        self.awaiting_build = True
        self.builder = QueryBuilder()
        self.say(f"{BUILD_PROMPT} (or press b)")

    def action_build(self, x: int | None = None, y: int | None = None) -> None:
        """Open the pop-up query builder (after Query DB)."""
        builder = self.builder
        if not self.awaiting_build or builder is None:
            self.say("Query DB (d) first, then the right mouse button builds the query.")
            return
        self.awaiting_build = False
        offset = None
        if x is not None and y is not None:
            offset = (
                max(0, min(x, self.size.width - 40)),
                max(0, min(y, self.size.height - 16)),
            )
        last_query = self.lists.last_query if self.lists is not None else None
        self.app.push_screen(
            QueryBuilderScreen(builder, last_query, offset, on_change=self.refresh_screen),
            self._built,
        )

    def on_mouse_down(self, event: events.MouseDown) -> None:
        if event.button == 3 and self.awaiting_build:
            event.stop()
            self.action_build(event.screen_x, event.screen_y)

    def _built(self, query: str | None) -> None:
        """The pop-up builder closed: run its query, or it was aborted."""
        self.builder = None
        self.set_focus(self.sheet)
        self.refresh_screen()
        if query is None:
            self.say("Query aborted; nothing was run.")
        else:
            self.start_query(query)

    # --- running a query --------------------------------------------------------------
    def start_query(self, text: str) -> None:
        work = self.begin_work("Query", show_after=QUERY_BAR_AFTER)
        self.say(WAIT)
        self.run_query(self.lists, text, self.sheet.page_size, work, self.target)

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def run_query(
        self, lists: QueryLists, text: str, page_size: int, work: Work, target: str | None = None
    ) -> None:
        try:
            count, rows = lists.run_first_page(text, page_size, work.report, work.cancel)
            hint = "" if count else lists.demonstration_hint(text) or ""
            weighted = ""
            if target:
                from sass_tui.ui.target_picker import weighted_count_words

                weighted = weighted_count_words(lists, text, target)
        except DB_ERRORS as exc:
            self.post_message(QueryFinished(error=str(exc)))
            return
        self.post_message(QueryFinished(count, rows, weighted=weighted, hint=hint))

    def action_choose_target(self) -> None:
        """Pick a target population: counts, Fit Test and Make Population weighted to it."""
        from sass_tui.ui.target_picker import pick_target

        if self.running or self.lists is None:
            self.say(WAIT if self.running else "The database is not open yet.")
            return

        def chosen(name: str) -> None:
            self.target = name or None
            self.say(
                f"Target {name}: query counts, Fit Test and Make Population are weighted to it."
                if name
                else "No target: the people unweighted."
            )

        pick_target(self, self.lists, self.target, chosen)

    def on_query_finished(self, event: QueryFinished) -> None:
        event.stop()
        if self.end_work() and event.error:
            self.say("Query cancelled; the lists are as they were.")
            self.refresh_screen()
            return
        if event.error:
            self.complain(f"The query was not run: {event.error}")
            self.refresh_screen()
            return
        count, rows = event.count, event.rows
        self.which = QUERY_LIST
        self.sheet.cursor = 0
        self.sheet.show_rows(rows, 0, count)
        self.refresh_screen()
        if count:
            self.say(f"{COMPLETE} {count:,} people found.{event.weighted}")
        else:
            self.say(f"{NO_DATA} {printable(event.hint)}".rstrip())

    # --- Make Population (issue 12) ----------------------------------------------------
    def action_make_population(self) -> None:
        """Write and load population files made of the selected list's people
        (Select One / Select All), not the last query's."""
        if self.running:
            self.say(WAIT)
            return
        try:
            with self._database() as lists:
                ids = lists.selected_ids()
        except Busy as exc:
            self.say(str(exc))
            return
        if not ids:
            self.say(
                "Make Population uses the selected list, which is empty: "
                "Select One (s) or Select All (a) people of a query first."
            )
            return

        def answer(text: str) -> None:
            name = text.strip()
            if not name:
                self.say("Make Population cancelled: no file name given.")
                return
            path = self.sass_app.user_path(name)
            work = self.begin_work("Make Population")
            self.say(f"Making the population of {len(ids):,} selected people (Esc cancels)...")
            sources = " OR ".join(f"({q})" for q in self.selected_from) or "selection"
            title = f"Population of {len(ids):,} selected from {sources}"
            self.make_population(self.lists, tuple(ids), path, title, work, self.target)

        self.ask(
            f"Population of the {len(ids):,} selected people: file name "
            "(girth; the center-of-mass file goes beside it):",
            answer,
            on_cancel=lambda: self.say("Make Population cancelled."),
        )

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def make_population(
        self,
        lists: QueryLists,
        ids: tuple[int, ...],
        target: Path,
        title: str,
        work: Work,
        weighted_to: str | None = None,
    ) -> None:
        from sass_tui.db.population_files import write_population_files
        from sass_tui.db.progress import Steps

        try:
            if weighted_to:
                from sass_tui.ui.target_picker import weighted_words

                title += weighted_words(weighted_to)
            result = lists.population_of(ids, title, work.report, work.cancel, target=weighted_to)
            Steps(cancel=work.cancel, what="making the population").check()  # last chance
            paths = write_population_files(result, target)
        except DB_ERRORS as exc:
            self.post_message(PopulationMade(error=str(exc)))
            return
        self.post_message(PopulationMade(result, paths))

    def on_population_made(self, event: PopulationMade) -> None:
        from dataclasses import replace

        from sass_tui.db.population import people_words
        from sass_tui.model.names import GLOBAL, GROUP_TITLES

        event.stop()
        if self.end_work() and event.error:
            self.say("Make Population cancelled: nothing written or loaded.")
            return
        if event.error:
            self.complain(f"Make Population: nothing written or loaded: {event.error}")
            return
        session = self.sass_app.session
        if session.person is not None:
            session.show_population()  # the population is what the next figure is sized from
        genders = list(event.result.counts)
        if len(genders) == 1 and session.population.gender != genders[0]:
            session.set_gender(genders[0])  # the only gender the population has
        for group, data in event.result.groups.items():
            if group == GLOBAL:  # a weighted population's own stature and mass
                session.load_global(replace(data, path=str(event.paths[group])))
            else:
                session.load_group(group, replace(data, path=str(event.paths[group])))
        files = ", ".join(
            f"{GROUP_TITLES[group].lower()} {path}" for group, path in event.paths.items()
        )
        self.say(
            f"Population of {people_words(event.result.counts)} written ({files}) and loaded: "
            "Create Figure now sizes this subpopulation; joint limits and strength keep "
            "the loaded population."
        )

    # --- Fit Test (issue 14) ------------------------------------------------------------
    def action_fit_test(self) -> None:
        """Test a population against the last query as design limits."""
        from sass_tui.db.fit import DEFAULT_POPULATION
        from sass_tui.ui.fit_screen import FitScreen

        if self.running:
            self.say(WAIT)
            return
        lists = self.lists
        limits = lists.last_query if lists else None
        if lists is None or not limits:
            self.say("Fit Test uses the last query as design limits: run a query first.")
            return

        def answer(text: str) -> None:
            population = text.strip() or DEFAULT_POPULATION
            self.app.push_screen(FitScreen(lists, limits, population, self.target))

        self.ask(
            f"Population to test (Enter: {DEFAULT_POPULATION}):",
            answer,
            on_cancel=lambda: self.say("Fit Test cancelled."),
        )

    def action_export_gltf(self) -> None:
        """Write the highlighted person as a glTF 2.0 body (.glb)."""
        from sass_tui.ui.gltf_export import export_list_person

        self._list_command(lambda: export_list_person(self, self._database, self.sheet.highlighted))

    # --- Input DB ----------------------------------------------------------------------
    def action_input_db(self) -> None:
        """Import person, group and strength files into the database."""
        if self.running:
            self.say(WAIT)
            return
        if self.lists is None:
            self.say("The database is not open yet.")
            return
        if self.sass_app.read_only:
            self.complain("Input DB is off: this database is served read-only (sass serve).")
            return
        self._ask_file({}, 0)

    def _ask_file(self, chosen: dict, index: int, problem: str = "") -> None:
        """Ask for the next file; `problem` (why the last answer was refused)
        leads the prompt, so the user sees it while answering again."""
        if index == len(INPUT_DB_FILES):
            self._import(chosen)
            return
        key, title = INPUT_DB_FILES[index]

        def again(problem: str) -> None:
            # After the answer's prompt has closed, not inside its handler.
            self.call_later(self._ask_file, chosen, index, problem)

        def answer(text: str) -> None:
            name = text.strip()
            if not name:
                if index < 4:  # person and the three groups must all be given
                    again(f"A file name for {title} is needed.")
                    return
                if index == 4:
                    self._import(chosen)
                    return
                again("A strength file is needed once Strength Parameter is given.")
                return
            try:
                path = self.sass_app.regular_file(name)
            except SassError as exc:
                again(f"{exc}.")
                return
            if index == 0:
                from sass_tui.db.ansur import looks_like_ansur

                if looks_like_ansur(path):  # a survey file holds everything: no group files
                    self.call_later(self._ask_ansur_label, path)
                    return
            self._ask_file({**chosen, key: path}, index + 1)

        def cancel() -> None:
            if key == "strength_par":
                self._import(chosen)
            else:
                self.say("Input DB cancelled; the database is unchanged.")

        self.ask(
            (f"{problem} " if problem else "")
            + f"Enter File Name for {title}"
            + (" (ESC: no strength data)" if index == 4 else "")
            + ":",
            answer,
            on_cancel=cancel,
        )

    def _ask_ansur_label(self, path: Path) -> None:
        from sass_tui.db.ansur import DEFAULT_LABEL

        default = path.name.split(".")[0] or DEFAULT_LABEL

        def answer(text: str) -> None:
            label = text.strip() or default
            work = self.begin_work("ANSUR import")
            self.say(f"Importing {path.name} as source '{label}' (Esc cancels)...")
            self.import_ansur(self.lists, path, label, work)

        self.ask(
            f"{path.name} is an ANSUR II format file. Source label [{default}]:",
            answer,
            on_cancel=lambda: self.say("Input DB cancelled; the database is unchanged."),
        )

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def import_ansur(self, lists: QueryLists, path: Path, label: str, work: Work) -> None:
        try:
            count = lists.import_ansur(path, label, work.report, work.cancel)
        except DB_ERRORS as exc:
            self.post_message(ImportFinished(None, str(exc)))
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
            self.post_message(ImportFinished(None, str(exc)))
            return
        self.post_message(ImportFinished(count))

    def on_import_finished(self, event: ImportFinished) -> None:
        event.stop()
        count, error = event.count, event.error
        if self.end_work() and count is None:
            self.say("Input DB cancelled; the database is unchanged.")
        elif count is None:
            self.complain(f"Input DB failed, the database is unchanged: {error}")
        else:
            self.say(f"Loaded {count:,} people into the database.")
        self.refresh_screen()


# --- the More Menu of Disp. More (§12.4) ------------------------------------------------

MORE_CHOICES = ("First", "Last", "Previous", "Next", "Nth Person")


class MoreMenu(ModalScreen[str | None]):
    """The More Menu: a pop-up menu that looks like the query builder's
    (`.pop-up-menu`, sass.tcss) over the spreadsheet."""

    DEFAULT_CSS = """
    MoreMenu { align: center middle; background: transparent; }
    MoreMenu > #more-popup { width: 24; }
    """
    BINDINGS = [Binding("escape", "dismiss(None)", "Cancel")]

    def compose(self) -> ComposeResult:
        with Vertical(id="more-popup", classes="pop-up-menu") as popup:
            popup.border_title = "More Menu"
            yield OptionList(
                *(Option(choice, id=f"more-{i}") for i, choice in enumerate(MORE_CHOICES)),
                id="more-menu",
            )

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        event.stop()
        if self.app.screen is self:  # not again for an Enter typed twice at once
            self.dismiss(str(event.option.prompt))
