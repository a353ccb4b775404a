"""The anthropometric spreadsheet (report §12.2, figures 3, 4 and 6): the
app's default screen.

The screen hands its widgets what they show and answers their Messages;
every change to the data goes through the app's Session, so a refused edit
leaves the data as it was and says why on the message line.  Files are read
and written in worker threads that get an immutable input (a path, the
rendered text) and post their result as a Message.

The screen is in pieces, each a class the screen inherits: what its commands
share (spreadsheet_base.py), the edits of cells, angles and global values
(spreadsheet_edit.py), the file commands (spreadsheet_files.py), the people
of the database, Predict and the other screens (spreadsheet_people.py).
"""

from __future__ import annotations

from textual import events
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical

from sass_tui.model.names import (
    CENTER_OF_MASS,
    GIRTH,
    GROUP_TITLES,
    JOINT_LIMITS,
    STRENGTH,
)
from sass_tui.model.units import DISPLAY, other_unit
from sass_tui.ui.footer import Footer
from sass_tui.ui.message_log import MessageLog
from sass_tui.ui.spreadsheet.commands import COMMANDS
from sass_tui.ui.spreadsheet.figure_view import FigureView
from sass_tui.ui.spreadsheet.spreadsheet_edit import EditCommands
from sass_tui.ui.spreadsheet.spreadsheet_people import PeopleCommands
from sass_tui.ui.spreadsheet.spreadsheet_task import TaskCommands
from sass_tui.ui.spreadsheet.spreadsheet_worksheet import WorksheetCommands
from sass_tui.ui.spreadsheet.strength_page import TASK_PANEL_LINES, StrengthPage
from sass_tui.ui.widgets import (
    CommandMenu,
    DataSheet,
    GlobalPanel,
    GroupBar,
    GroupTab,
    MenuItem,
    MessageLine,
)

# The report's first message (§12.2), and the keys that do the same.
FIRST_MESSAGE = "Press left-mouse to select items. The arrows and Enter too; ctrl+p: commands."
GROUP_KEYS = ((GIRTH, "g"), (JOINT_LIMITS, "j"), (CENTER_OF_MASS, "m"), (STRENGTH, "s"))
STRENGTH_NOT_LOADED = (
    "Strength data is not loaded; SASS runs without it (Create Figure leaves strength out)."
)
# Lines of the screen that are not data rows: group bar 1, global panel and
# command menu 6, the data section's border 1 and header 2, message line 1,
# footer 1 (sass.tcss).  The page size follows from the terminal's height.
TOP_LINES = 6
FIXED_LINES = 1 + TOP_LINES + 1 + DataSheet.HEADER_LINES + 1 + 1
# The strength rows kept beside the Task panel on a short terminal.
MIN_STRENGTH_ROWS = 2
# From this many columns the figure is drawn live beside the data, in a panel
# 40 columns wide (sass.tcss) or, on a larger terminal, all the data leave
# (DATA_WIDTH): the figure is drawn as large as the height allows.
FIGURE_PANEL_MIN_WIDTH = 120
FIGURE_PANEL_WIDTH = 40
DATA_WIDTH = 84


class SpreadsheetScreen(EditCommands, WorksheetCommands, PeopleCommands, TaskCommands):
    """Figure 4: group bar, global data | command menu, data section, message line."""

    _group_said = ""  # the last "Girth: 25 rows, 3 pages." said (redone on a resize)

    # The footer at 80 columns (beside ctrl+p): n p f d|o u w b q, and r on
    # the strength page; the menu buttons show the rest.  A short footer label
    # has its full name as the tooltip, which the palette and F1 show.
    BINDINGS = [
        *(
            Binding(spec.key, spec.action, spec.footer, show=spec.in_footer)
            for spec in COMMANDS
            if spec.action != "quit"
        ),
        Binding("pagedown", "next_page", show=False),
        Binding("pageup", "previous_page", show=False),
        Binding("u", "undo", "Undo"),
        Binding("ctrl+z", "undo", show=False),
        Binding("U", "redo", show=False, tooltip="Redo"),
        Binding("ctrl+y", "redo", show=False),
        Binding("ctrl+s", "save", show=False, tooltip="Save worksheet"),
        Binding("S", "save_as", show=False, tooltip="Save worksheet as"),
        Binding("O", "open_worksheet", show=False, tooltip="Open worksheet"),
        Binding("w", "next_warning", "Warn", tooltip="Warnings"),
        Binding("l", "message_log", show=False),
        Binding("b", "see_figure", "Draw", tooltip="See figure"),
        Binding("G", "export_gltf", "glTF", tooltip="Export glTF", show=False),
        Binding("t", "strength_curve", show=False),
        Binding("T", "task", show=False, tooltip="Task panel"),
        Binding(
            "P",
            "population",
            show=False,
            tooltip="Population: virtual U.S. civilians (NHANES), targets, ANSUR II",
        ),
        Binding("M", "assumed_modifiers", show=False),
        *(
            Binding(spec.key, spec.action, spec.footer)
            for spec in COMMANDS
            if spec.action == "quit"
        ),
        *(Binding(key, f"select_group('{group}')", show=False) for group, key in GROUP_KEYS),
    ]

    COMMAND_SPECS = COMMANDS  # the menu's: the palette names these commands by them

    # F1 lists these first (ui/palette.py help_commands): the sheet's own keys,
    # which its widgets take, not the screen's bindings.
    SHEET_KEYS = (
        ("move", "Move", ("↑ ↓ ← →", "Home", "End"), "Move the cursor over the cells."),
        ("edit", "Edit", ("enter",), "Edit the cell under the cursor on the message line."),
        (
            "type",
            "Type a value",
            ("0-9 . - +",),
            "Start a new value for the cell under the cursor (14in, 0.5 rad); Enter keeps it.",
        ),
        ("cancel", "Cancel", ("escape",), "Cancel the value being typed; nothing changes."),
        ("undo", "Undo", ("u", "ctrl+z"), "Undo the newest edit and say what it was."),
        ("redo", "Redo", ("U", "ctrl+y"), "Do again the edit undone last."),
    )

    # --- layout ---------------------------------------------------------------
    def compose(self) -> ComposeResult:
        with Horizontal(id="body"):
            with Vertical(id="data"):
                yield GroupBar(GROUP_KEYS, id="groups")
                with Horizontal(id="top"):
                    yield GlobalPanel(id="global")
                    yield CommandMenu(COMMANDS, self, id="commands")
                yield DataSheet(id="sheet")
                yield StrengthPage(id="strength-sheet")
            # The figure panel (a FigureView) is mounted here on a wide terminal.
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.strength_page.display = False
        self._set_page_rows(self.app.size.height)
        self.refresh_screen()
        self._place_figure_panel(self.app.size.width)
        self.sheet.focus()
        self.say(FIRST_MESSAGE)
        self.call_after_refresh(self._first_screen_drawn)

    def _first_screen_drawn(self) -> None:
        # The figure panel takes its place on the first screen and is drawn
        # one frame after it (the outline and the canvas cost ~25 ms);
        # once, when it is shown.
        self._first_screen_shown = True
        self.redraw_figure_panel()
        self.sass_app.first_screen_drawn()

    def on_resize(self, event: events.Resize) -> None:
        said = self._group_said
        self._set_page_rows(event.size.height)
        self._place_figure_panel(event.size.width)
        if said and self.message_line.showing(said):
            self._say_group_shown()  # its page count is the new size's

    def on_screen_suspend(self) -> None:
        self._covered = True

    def on_screen_resume(self) -> None:
        # The screen that covered this one may have changed the Session (an
        # undo on the figure screen) or the overlay; the first resume (the
        # app's start) follows the drawing made at mount.
        if self._covered:
            self.refresh_screen()

    def _place_figure_panel(self, width: int) -> None:
        panel = self.figure_panel
        wide = width >= FIGURE_PANEL_MIN_WIDTH
        new, shown = False, panel is not None and panel.display
        if panel is None and wide:
            panel = FigureView(canvas_focus=False, canvas_later=True, id="figure-panel")
            new = True
            self.query_one("#body", Horizontal).mount(panel)
        if panel is not None:
            panel.display = wide
            panel.styles.width = max(FIGURE_PANEL_WIDTH, width - DATA_WIDTH)
            if wide and (new or not shown):  # coming on the screen; edits redraw it
                self.redraw_figure_panel()

    def _set_page_rows(self, height: int) -> None:
        self.sheet.page_rows = height - FIXED_LINES
        task_shown = self.task_shown and self.data_group == STRENGTH
        task = TASK_PANEL_LINES if task_shown else 0
        # A terminal too short for the page and the Task panel (80x24): the
        # global data and the menu make room while the panel is shown, so that
        # the page keeps its rows beside the panel's answer.
        short = task_shown and height - FIXED_LINES - task < MIN_STRENGTH_ROWS
        self.query_one("#top").display = not short
        fixed = FIXED_LINES - (TOP_LINES if short else 0)
        panel = self.task_panel
        if panel is not None:  # the panel gives up its last lines (a note) before the page its rows
            task = min(task, height - fixed - MIN_STRENGTH_ROWS) if short else task
            panel.styles.height = task if short else None
        self.strength_page.page_rows = max(1, height - fixed - task)

    # --- the strength page's Task panel (spreadsheet_task.py) --------------------
    async def action_task(self) -> None:
        """Task: show or hide the strength page's panel of who can do a task.

        A posture (the strength page's row), loads on the hands; the joints'
        moments and the percent capable (ui/spreadsheet/task_panel.py)."""
        if self.message_line.prompting:
            return
        if self.task_shown:
            self.task_shown = False
            self._place_task_panel()
            self.set_focus(self.active_sheet)
            self.say("Task panel hidden; T shows it again.")
            return
        if self.data_group != STRENGTH:
            self.action_select_group(STRENGTH)
            if self.data_group != STRENGTH:  # refused: said why
                return
        panel = self.task_panel
        if panel is None:
            # deferred: ui.task_panel — off the first screen, the first screen's next frame (sass_tui/startup.py)
            from sass_tui.ui.spreadsheet.task_panel import TaskPanel

            panel = TaskPanel(id="task-panel")
            await self.query_one("#data", Vertical).mount(panel, after=self.strength_page)
        self.task_shown = True
        self._place_task_panel()
        self.show_task_panel()
        self.set_focus(panel.cells)
        self.say(
            "Task: its posture (its cell, or the strength page's row); ← → Enter: the "
            "posture, the loads and the people; h: curve; shift+Tab: the page."
        )

    def _place_task_panel(self) -> None:
        """Shown on the strength page when asked for; the page's rows make room."""
        panel = self.task_panel
        if panel is not None:
            panel.display = self.task_shown and self.data_group == STRENGTH
            self.redraw_figure_panel()  # in the task's posture, or standing again
        self._set_page_rows(self.app.size.height)

    def check_action(self, action: str, parameters: tuple[object, ...]) -> bool | None:
        spec = next((c for c in COMMANDS if c.action == action), None)
        if spec is not None and not spec.available(self):
            return False  # its slot shows the other command; the key does nothing
        return True

    def why_not(self, action: str) -> str | None:
        if action == "switch_side" and self.session.strength_sheet is None:
            return self.strength_error
        return {
            "switch_side": "Right → Left (r) applies to the Strength group: press s first.",
            "display_more": (
                "Disp. More (x) shows more of the selected list once a person is "
                "shown: Disp. Indv. (v) first."
            ),
            "display_population": (
                "The population is already shown; Disp. Pop. (o) returns to it "
                "after Disp. Indv. (v)."
            ),
            "query": "Query (d) works from the population: Disp. Pop. (o) first.",
            "display_individual": "A person is shown: Disp. More (x) shows another.",
            "family": "Family (y) works from the population: Disp. Pop. (o) first.",
            "interval": "Interval (a) applies to a predicted figure: Predict (k) first.",
        }.get(action)

    # --- groups -----------------------------------------------------------------
    def on_group_tab_chosen(self, event: GroupTab.Chosen) -> None:
        self.action_select_group(event.group)

    def action_select_group(self, group: str) -> None:
        """Show a group: Girth (g), Joint Limits (j), Center of Mass (m), Strength (s)."""
        if self.message_line.prompting:
            return
        session = self.session
        if (
            group == STRENGTH
            and session.strength_sheet is None
            and not session.strength_sheets.missing
        ):
            self.complain(self.strength_error)
            return
        had_focus = self.focused is self.active_sheet
        self.data_group = group
        on_strength = group == STRENGTH
        self.sheet.display = not on_strength
        self.strength_page.display = on_strength
        self._place_task_panel()
        if had_focus or self.focused is None:
            self.set_focus(self.active_sheet)  # now: an edit asked for next keeps its prompt
        self.refresh_screen()
        self._say_group_shown()

    def _say_group_shown(self) -> None:
        sheet = self.active_sheet
        message = (
            f"{GROUP_TITLES[self.data_group]}: {sheet.row_count} rows, "
            f"{sheet.pages} page{'s' if sheet.pages > 1 else ''}."
        )
        strength = self.session.strength_sheet
        if self.data_group == STRENGTH and strength is not None:
            message += f" {strength.side.capitalize()} limb: {strength.data.label}."
        elif self.data_group == STRENGTH and self.session.strength_sheets.missing:
            message += f" {self.session.strength_sheets.missing}"
        self._group_said = message
        self.say(message)

    # --- commands ---------------------------------------------------------------
    async def on_menu_item_pressed(self, event: MenuItem.Pressed) -> None:
        spec = next((c for c in COMMANDS if event.item.id == f"command-{c.name}"), None)
        if spec is not None:
            event.stop()
            await self.run_action(spec.action)

    async def action_quit(self) -> None:
        """Quit SASS (asks again while there are edits that would be lost)."""
        await self.app.action_quit()

    def action_next_page(self) -> None:
        """Show the next page of the data section."""
        self._turn_page(1)

    def action_previous_page(self) -> None:
        """Show the previous page of the data section."""
        self._turn_page(-1)

    def _turn_page(self, pages: int) -> None:
        sheet = self.active_sheet
        if not sheet.turn_page(pages):
            self.say("This is the last page." if pages > 0 else "This is the first page.")
        else:
            self.say(f"Page {sheet.page + 1} of {sheet.pages}.")

    def action_convert_units(self) -> None:
        """Switch the group's display units (cm/in, deg/rad, ft-lb/N-m)."""
        strength = self.session.strength_sheet
        if self.data_group == STRENGTH and strength is not None:
            unit = strength.toggle_unit()
            self.refresh_screen()
            self.say(f"Strength now shown in {unit}.")
            return
        state = self.figure.groups[self.data_group]
        self.session.set_unit(self.data_group, other_unit(self.data_group, state.unit))
        self.refresh_screen()
        self.say(f"{GROUP_TITLES[self.data_group]} now shown in {DISPLAY[state.unit]}.")

    def action_undo(self) -> None:
        """Undo the newest edit, whether of the figure or of a strength angle."""
        what = self.session.undo()
        if what is None:
            self.say("Nothing to undo.")
            return
        self.refresh_screen()
        self.say(f"Undone: {what} (U redoes it).")

    def action_message_log(self) -> None:
        """List the messages shown so far."""
        self.app.push_screen(MessageLog(self.message_line.history))

    # --- Right -> Left -------------------------------------------------------------------
    def action_assumed_modifiers(self) -> None:
        """Strength page: the isokinetic decay and training gain on or off (no published source)."""
        strength = self.session.strength_sheet
        if not (self.data_group == STRENGTH and strength is not None):
            self.say("The assumed modifiers apply to the Strength group (press s).")
            return
        self.say(strength.toggle_assumed_modifiers())
        self.refresh_screen()

    def action_switch_side(self) -> None:
        """Show the other side's strength (right or left limb)."""
        strength = self.session.strength_sheet
        if not (self.data_group == STRENGTH and strength is not None):
            self.say("Right → Left applies to the Strength group (press s).")
            return
        factor = self.sass_app.figure_work.non_dominant_factor
        self.ask(
            f"Scaling factor for the non-dominant limb (RETURN = default {factor:.3f}):",
            lambda text: self.say(strength.switch_side(text) + "."),
        )
