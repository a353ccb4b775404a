"""The database query spreadsheet (report §12.3, figures 9, 10, 11): its list
commands and the query run from the pop-up builder.

The screen is in pieces: its database, long work and page (query_base.py),
Input DB (query_input_db.py), Make Population, Fit Test and the target
(query_population.py), the command menu (query_commands.py), the summary and
the list (query_list.py), the workers' messages (query_messages.py).

The lists are TEMP tables of the database (sass_tui/db/query/lists.py): a page is
read when it is shown, so a query list of 100,000 people is 25 rows of
widgets' worth of work.  Queries and Input DB run in worker threads; while
one runs, keys are still answered and list commands say so instead of waiting.
"""

from __future__ import annotations

from pathlib import Path

from textual import events, work
from textual.binding import Binding
from textual.containers import Horizontal

from sass_tui.db.query.lists import DB_ERRORS, QUERY_LIST, SELECTED_LIST, QueryLists
from sass_tui.db.query.lists import sources as database_sources
from sass_tui.model.errors import error_text
from sass_tui.model.text import printable
from sass_tui.ui.footer import Footer
from sass_tui.ui.progress import QUERY_BAR_AFTER, Work, WorkBar
from sass_tui.ui.query.query_base import WAIT, Busy
from sass_tui.ui.query.query_builder import QueryBuilder, QueryBuilderScreen
from sass_tui.ui.query.query_commands import QUERY_COMMANDS, QueryCommandMenu
from sass_tui.ui.query.query_input_db import InputDbCommands
from sass_tui.ui.query.query_list import LIST_TITLES, ListSheet, SummaryPanel
from sass_tui.ui.query.query_messages import QueryFinished
from sass_tui.ui.query.query_people import PeopleCommands
from sass_tui.ui.query.query_population import PopulationCommands
from sass_tui.ui.query.target_picker import weighted_count_words
from sass_tui.ui.spreadsheet.gltf_export import export_list_person
from sass_tui.ui.widgets import MenuItem, MessageLine

BUILD_PROMPT = "Press rightmouse to build query."
COMPLETE = "Query execution is complete."
NO_DATA = "No data satisfied the query."

# Lines of the query screen that are not list rows: summary and command menu
# 6, the list's border 1 and header 2, message line 1, footer 1 (query.tcss).
LIST_FIXED_LINES = 6 + 1 + ListSheet.HEADER_LINES + 1 + 1


class QueryScreen(InputDbCommands, PopulationCommands, PeopleCommands):
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
        Binding(
            "S", "stats", "Stats", show=False, tooltip="Percentile table of the query's people"
        ),
        Binding("G", "export_gltf", "glTF", tooltip="Export glTF", show=False),
        Binding("t", "choose_target", "Target", show=False, tooltip="Target population"),
        Binding(
            "P",
            "pick_population",
            show=False,
            tooltip="Population: virtual U.S. civilians (NHANES), targets, ANSUR II",
        ),
        Binding("q", "app.quit", "Quit"),
        Binding("escape", "cancel_work", "Cancel work", show=False),
        Binding("pagedown", "next_page", show=False),
        Binding("pageup", "previous_page", show=False),
        Binding("enter", "show_person", "Person", show=False, tooltip="Every value of the person"),
        Binding("slash", "free_query", "Query", show=False, tooltip="Type a query"),
        Binding("o", "sort", "Sort", show=False, tooltip="Sort the list"),
        Binding("j", "jump", "Jump", show=False, tooltip="Jump to a person"),
        Binding("L", "message_log", "Log", show=False, tooltip="Message log"),
    ]

    # F1 lists these first (ui/palette.py help_commands): the list's own keys.
    SHEET_KEYS = (
        ("move", "Move", ("↑ ↓",), "Move the cursor over the list."),
        (
            "cancel_work",
            "Cancel",
            ("escape",),
            "Cancel the answer being typed, or the work under way.",
        ),
    )

    COMMAND_SPECS = QUERY_COMMANDS  # the menu's: the palette names these commands by them

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

    # --- message line -----------------------------------------------------------------
    def on_resize(self, event: events.Resize) -> None:
        self.sheet.page_rows = event.size.height - LIST_FIXED_LINES

    def on_message_line_answered(self, event: MessageLine.Answered) -> None:
        event.stop()
        if not self.message_line.prompting:
            self.set_focus(self.sheet)
        self.refresh_screen()

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
        if self.ready_lists() is None:
            return
        self.awaiting_build = True
        sources: tuple[str, ...] = ()
        try:
            with self._database() as lists:
                sources = tuple(lists.read(database_sources))
        except (*DB_ERRORS, Busy):
            pass  # the Source menu then takes a typed source only
        self.builder = QueryBuilder(sources=sources)
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
        self.run_query(self.lists, text, self.sheet.page_size, work, self.target, self.sort)

    @work(thread=True, exclusive=True, group="query-db", exit_on_error=False)
    def run_query(
        self,
        lists: QueryLists,
        text: str,
        page_size: int,
        work: Work,
        target: str | None = None,
        sort: tuple[str, bool] | None = None,
    ) -> None:
        try:
            count, rows = lists.run_first_page(text, page_size, work.report, work.cancel, sort)
            hint = "" if count else lists.demonstration_hint(text) or ""
            weighted = ""
            if target:
                weighted = weighted_count_words(lists, text, target)
        except DB_ERRORS as exc:
            self.post_message(QueryFinished(error=error_text(exc)))
            return
        lost = lists.take_lost() or ""
        self.post_message(QueryFinished(count, rows, weighted=weighted, hint=hint, lost=lost))

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
        lost = f" {event.lost}" if event.lost else ""
        if count:
            self.say(f"{COMPLETE} {count:,} people found.{event.weighted}{lost}")
        else:
            self.say(f"{NO_DATA} {printable(event.hint)}{lost}".rstrip())

    def action_export_gltf(self) -> None:
        """Write the highlighted person as a glTF 2.0 body (.glb)."""
        self._list_command(lambda: export_list_person(self, self._database, self.sheet.highlighted))
