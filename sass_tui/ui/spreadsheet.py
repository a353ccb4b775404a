"""The anthropometric spreadsheet (report §12.2, figures 3, 4 and 6): the
app's default screen.

The screen hands its widgets what they show and answers their Messages;
every change to the data goes through the app's Session, so a refused edit
leaves the data as it was and says why on the message line.  Files are read
and written in worker threads that get an immutable input (a path, the
rendered text) and post their result as a Message.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from textual import events, work
from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.message import Message
from textual.widgets import Footer

from sass_tui.model.errors import SassError
from sass_tui.model.figure import Figure
from sass_tui.model.names import (
    AXES,
    CENTER_OF_MASS,
    GIRTH,
    GROUP_TITLES,
    GROUPS,
    JOINT_LIMITS,
    STRENGTH,
)
from sass_tui.model.popfile import PopulationData, read_population_file
from sass_tui.model.session import Session
from sass_tui.model.units import DISPLAY, GROUP_UNITS, convert, other_unit, parse_quantity
from sass_tui.model.vocabulary import STRENGTH_PARAMETERS
from sass_tui.ui.base import SassScreen
from sass_tui.ui.commands import COMMANDS
from sass_tui.ui.predict import (
    KNOWN_PROMPT,
    KnownSuggester,
    PredictorOpened,
    interval_text,
    open_predictor_at,
)
from sass_tui.ui.strength_page import StrengthPage, format_angle, format_strength
from sass_tui.ui.widgets import (
    CommandMenu,
    DataSheet,
    EditorKeys,
    GlobalPanel,
    GroupBar,
    GroupTab,
    MenuItem,
    MessageLine,
    format_percentile,
    format_value,
    global_text,
)

if TYPE_CHECKING:  # numpy-heavy: imported when first used, after the first screen (issue 16)
    from sass_tui.model.prediction import Prediction, Predictor
    from sass_tui.model.strength import StrengthData

FIRST_MESSAGE = "Press left-mouse to select items."
GROUP_KEYS = ((GIRTH, "g"), (JOINT_LIMITS, "j"), (CENTER_OF_MASS, "m"), (STRENGTH, "s"))
STRENGTH_NOT_LOADED = (
    "Strength data is not loaded; SASS runs without it (Create Figure leaves strength out)."
)
# Lines of the screen that are not data rows: group bar 1, global panel and
# command menu 6, the data section's border 1 and header 2, message line 1,
# footer 1 (sass.tcss).  The page size follows from the terminal's height.
FIXED_LINES = 1 + 6 + 1 + DataSheet.HEADER_LINES + 1 + 1
# From this many columns the figure is drawn live beside the data, in a panel
# FIGURE_PANEL_WIDTH wide (sass.tcss): the data keep their 80 columns.
FIGURE_PANEL_MIN_WIDTH = 120
GLOBAL_HINTS = {
    "figure_type": "skinny or polybody",
    "gender": "male or female",
    "mass": "kg, or e.g. 180 lb",
    "stature": "cm, or e.g. 70 in",
    "mass_percentile": "percentile",
    "stature_percentile": "percentile",
    "strength_type": "isometric, isokinetic or isotonic",
    "motion_speed": "deg/s",
    "handedness": "right or left",
    "training_level": "0 = no training",
    "fatigue_level": "0 = not tired",
}


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


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name).strip("_") or "person"


# --- what the workers post ------------------------------------------------------------


class PopulationRead(Message):
    def __init__(self, group: str, data: PopulationData) -> None:
        super().__init__()
        self.group = group
        self.data = data


class StrengthRead(Message):
    def __init__(self, data: StrengthData) -> None:
        super().__init__()
        self.data = data


class WorkerSaid(Message):
    """A worker's outcome for the message line: kind is "info" or "error"."""

    def __init__(self, text: str, kind: str = "info") -> None:
        super().__init__()
        self.text = text
        self.kind = kind


class SpreadsheetScreen(SassScreen):
    """Figure 4: group bar, global data | command menu, data section, message line."""

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
        Binding("w", "next_warning", "Warn", tooltip="Warnings"),
        Binding("l", "message_log", show=False),
        Binding("b", "see_figure", "Draw", tooltip="See figure"),
        Binding("G", "export_gltf", "glTF", tooltip="Export glTF", show=False),
        Binding("t", "strength_curve", show=False),
        *(
            Binding(spec.key, spec.action, spec.footer)
            for spec in COMMANDS
            if spec.action == "quit"
        ),
        *(Binding(key, f"select_group('{group}')", show=False) for group, key in GROUP_KEYS),
    ]

    COMMAND_SPECS = COMMANDS  # the menu's: the palette names these commands by them

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
        # one frame after it (issue 16: the outline and the canvas cost ~25 ms);
        # once, when it is shown.
        self._first_screen_shown = True
        self.redraw_figure_panel()
        self.sass_app.first_screen_drawn()

    def on_resize(self, event: events.Resize) -> None:
        self._set_page_rows(event.size.height)
        self._place_figure_panel(event.size.width)

    def on_screen_suspend(self) -> None:
        self._covered = True

    def on_screen_resume(self) -> None:
        # The screen that covered this one may have changed the Session (an
        # undo on the figure screen) or the overlay; the first resume (the
        # app's start) follows the drawing made at mount.
        if self._covered:
            self.refresh_screen()

    # --- the live figure panel (issue 15) -----------------------------------------
    @property
    def figure_panel(self):
        """The FigureView beside the data, or None (never mounted: narrow terminal)."""
        panels = self.query("#figure-panel")
        return panels.first() if panels else None

    def _place_figure_panel(self, width: int) -> None:
        panel = self.figure_panel
        wide = width >= FIGURE_PANEL_MIN_WIDTH
        new, shown = False, panel is not None and panel.display
        if panel is None and wide:
            from sass_tui.ui.figure_view import FigureView

            panel = FigureView(canvas_focus=False, canvas_later=True, id="figure-panel")
            new = True
            self.query_one("#body", Horizontal).mount(panel)
        if panel is not None:
            panel.display = wide
            if wide and (new or not shown):  # coming on the screen; edits redraw it
                self.redraw_figure_panel()

    def redraw_figure_panel(self) -> None:
        """Draw the figure shown, with the figure screen's overlay, if the
        panel is on the screen and what it draws has changed."""
        panel = self.figure_panel
        if panel is None or not panel.display or not self._first_screen_shown:
            return
        from sass_tui.ui.figure_screen import session_outlines

        try:
            outlines = session_outlines(self.session, self.sass_app.figure_overlay)
        except SassError:
            outlines = ()  # the caption says there is nothing to draw
        if outlines != panel.outlines:
            panel.outlines = outlines

    def _set_page_rows(self, height: int) -> None:
        self.sheet.page_rows = height - FIXED_LINES
        self.strength_page.page_rows = height - FIXED_LINES

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
                self.session.strength_sheet, self.session.strength_missing
            )
        self.redraw_figure_panel()

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

    # --- message line ---------------------------------------------------------
    def on_message_line_answered(self, event: MessageLine.Answered) -> None:
        event.stop()
        self.refresh_screen()

    def on_worker_said(self, event: WorkerSaid) -> None:
        self.message_line.show(event.text, event.kind)

    def _after_edit_request(self, widget: EditorKeys) -> None:
        if not self.message_line.prompting:
            widget.typing_done()  # refused: no prompt takes the keys that follow

    # --- groups -----------------------------------------------------------------
    def on_group_tab_chosen(self, event: GroupTab.Chosen) -> None:
        self.action_select_group(event.group)

    def action_select_group(self, group: str) -> None:
        """Show a group: Girth (g), Joint Limits (j), Center of Mass (m), Strength (s)."""
        if self.message_line.prompting:
            return
        session = self.session
        if group == STRENGTH and session.strength_sheet is None and not session.strength_missing:
            self.complain(self.strength_error)
            return
        had_focus = self.focused is self.active_sheet
        self.data_group = group
        on_strength = group == STRENGTH
        self.sheet.display = not on_strength
        self.strength_page.display = on_strength
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
        elif self.data_group == STRENGTH and self.session.strength_missing:
            message += f" {self.session.strength_missing}"
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
        if self.session.undo():
            self.refresh_screen()
            self.say("Undone.")
        else:
            self.say("Nothing to undo.")

    def action_message_log(self) -> None:
        """List the messages shown so far."""
        from sass_tui.ui.message_log import MessageLog

        self.app.push_screen(MessageLog(self.message_line.history))

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

    # --- Input Data -----------------------------------------------------------------
    def action_input_data(self) -> None:
        """Read a population (or strength) file into the group shown."""
        if self.data_group == STRENGTH:
            self.ask(
                "Strength data file: (or a data set: example, anderson2007)", self._input_data_from
            )
            return
        self.ask(f"{GROUP_TITLES[self.data_group]} population file:", self._input_data_from)

    def _input_data_from(self, text: str) -> None:
        if not text.strip():
            self.say("No file given; nothing loaded.")
            return
        if self.data_group == STRENGTH and self._strength_data_set(text.strip().lower()):
            return
        # Refused here, before any worker opens it: a FIFO would block it forever.
        path = self.sass_app.regular_file(text.strip())
        self.say(f"Reading {text.strip()} ...")
        self.read_data_file(path, self.data_group)

    def _strength_data_set(self, name: str) -> bool:
        """A strength data set named instead of a file (docs/strength.md): the
        example data read again, or Anderson et al. 2007's curves shown."""
        from sass_tui.model.published_strength import DATA_SET, EXAMPLE_DATA_SET

        if name == EXAMPLE_DATA_SET:
            from sass_tui.model.strength import default_path

            self.say(f"Reading the example data ({default_path().name}) ...")
            self.read_data_file(default_path(), STRENGTH)
            return True
        if name == DATA_SET:
            self.action_strength_curve()
            return True
        return False

    @work(thread=True, exclusive=True, group="input-data", exit_on_error=False)
    def read_data_file(self, path: Path, group: str) -> None:
        """Input Data: read in a worker; a file that fails changes nothing."""
        what = "strength data" if group == STRENGTH else GROUP_TITLES[group]
        try:
            if group == STRENGTH:
                from sass_tui.model.strength import read_strength_file

                self.post_message(StrengthRead(read_strength_file(path)))
            else:
                self.post_message(PopulationRead(group, read_population_file(path, group)))
        except SassError as exc:
            self.post_message(WorkerSaid(f"{exc}; {what} unchanged.", "error"))
        except OSError as exc:
            self.post_message(
                WorkerSaid(f"{path}: {exc.strerror or exc}; {what} unchanged.", "error")
            )

    def on_strength_read(self, event: StrengthRead) -> None:
        data = event.data
        self.session.load_strength(data)
        self._warning_index = 0
        self.refresh_screen()
        self.say(f"Loaded strength from {data.path} ({data.title}).")
        if self.session.warnings:
            self._show_warning()

    def on_population_read(self, event: PopulationRead) -> None:
        group, data = event.group, event.data
        gender = self.figure.gender
        if not data.has(gender):
            self.complain(
                f"{data.path}: no 'T {gender.upper()}' section for this {gender} "
                f"figure; {GROUP_TITLES[group]} unchanged."
            )
            return
        try:
            self.session.load_group(group, data)
        except SassError as exc:
            self.complain(f"{exc}; {GROUP_TITLES[group]} unchanged.")
            return
        self._warning_index = 0
        self.refresh_screen()
        self.say(f"Loaded {GROUP_TITLES[group]} from {data.path} ({data.title}).")
        if self.session.warnings:
            self._show_warning()

    # --- Right -> Left -------------------------------------------------------------------
    def action_switch_side(self) -> None:
        """Show the other side's strength (right or left limb)."""
        strength = self.session.strength_sheet
        if not (self.data_group == STRENGTH and strength is not None):
            self.say("Right → Left applies to the Strength group (press s).")
            return
        from sass_tui.model.strength import DEFAULT_NON_DOMINANT_FACTOR

        self.ask(
            f"Scaling factor for the non-dominant limb "
            f"(RETURN = default {DEFAULT_NON_DOMINANT_FACTOR:.3f}):",
            lambda text: self.say(strength.switch_side(text) + "."),
        )

    # --- Create Figure --------------------------------------------------------------
    def _default_name(self, suffix: str) -> str:
        """Create Figure's and Export HAnim's file name: the person's shown,
        else the figure's gender and girth percentile (MALE50.FIG)."""
        from sass_tui.model.figfile import default_fig_name

        figure = self.figure
        if figure.person:
            return f"{_slug(figure.person)}{suffix}"
        name = default_fig_name(figure.gender, figure.groups[GIRTH].percentile, figure.figure_type)
        return name if suffix == ".fig" else Path(name).with_suffix(suffix).name

    def action_create_figure(self) -> None:
        """Write the figure shown as a .fig file."""
        missing = self.figure.missing_groups()
        if missing:
            self.complain(
                f"Cannot create a figure: {', '.join(missing)} not loaded for {self.figure.gender}."
            )
            return
        default = self._default_name(".fig")
        self.ask(
            f"Figure file name [{default}]:",
            lambda text: self._create_figure_named(text.strip() or default),
        )

    def _create_figure_named(self, name: str) -> None:
        path = self.sass_app.user_path(name)
        strength = self.session.strength_sheet
        if strength is None:
            self._write_unless_kept(path, lambda: self._write_figure(path, []))
            return

        def include(answer: str) -> None:
            word = answer.strip().lower()
            if word in ("n", "no"):
                sections = []
            elif word in ("", "y", "yes"):
                from sass_tui.model.strength import fig_section, lower_limb_fig_section

                sections = [fig_section(strength), lower_limb_fig_section(self.figure)]
            else:
                raise AnswerError(f"expected y or n, got {answer.strip()!r}; nothing written")
            self._write_unless_kept(path, lambda: self._write_figure(path, sections))

        self.ask("Include strength in the figure? (Y/n)", include)

    def _write_unless_kept(self, path: Path, write: Callable[[], object]) -> None:
        """Write, but an existing file only after the user says y."""
        if not path.exists():
            write()
            return

        def overwrite(answer: str) -> None:
            if answer.strip().lower() in ("y", "yes"):
                write()
            else:
                self.say(f"Not written; {path} kept as it was.")

        self.ask(f"{path} exists. Overwrite it? (y/N)", overwrite)

    def _write_figure(self, path: Path, sections: list) -> None:
        """Rendered here, on the UI thread: the worker gets the text, never the
        figure the user may be editing meanwhile."""
        from sass_tui.model.figfile import render_fig

        figure = self.figure
        text = render_fig(figure, sections)
        filled = sum(int(figure.output_values(g)[1].sum()) for g in GROUPS)
        note = (
            f" {filled} values not measured for {figure.person} came from the population."
            if filled
            else ""
        )
        self.write_text(path, text, f"Wrote {path}.{note}")

    @work(thread=True, group="write", exit_on_error=False)
    def write_text(self, path: Path, text: str, done: str) -> None:
        from sass_tui.model.atomic import write_text_atomic

        try:
            write_text_atomic(path, text)
        except (SassError, OSError) as exc:
            reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else exc
            self.post_message(WorkerSaid(f"{path}: cannot write: {reason}", "error"))
            return
        self.post_message(WorkerSaid(done))

    # --- Export HAnim -----------------------------------------------------------------
    def action_export_hanim(self) -> None:
        """Write the figure shown as an HAnim X3D humanoid."""
        default = self._default_name(".x3d")
        self.ask(
            f"HAnim file name [{default}]:",
            lambda text: self._export_hanim_named(self.sass_app.user_path(text.strip() or default)),
        )

    def _export_hanim_named(self, path: Path) -> None:
        from sass_tui.model.hanim import not_in_humanoid_note, render_hanim

        text = render_hanim(self.figure)  # on the UI thread: see _write_figure
        done = f"Exported the HAnim humanoid to {path}.{not_in_humanoid_note(self.figure)}"
        self._write_unless_kept(path, lambda: self.write_text(path, text, done))

    def action_export_gltf(self) -> None:
        """Write the figure shown as a glTF 2.0 body (.glb)."""
        from sass_tui.ui.gltf_export import ask_gltf_export

        ask_gltf_export(self, self.figure, self._default_name(".glb"))

    # --- editing the data section -------------------------------------------------------
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

    def on_data_sheet_edit_requested(self, event: DataSheet.EditRequested) -> None:
        event.stop()
        if self._pass_to_prompt(self.active_sheet, event.initial):
            return
        try:
            if self.data_group == STRENGTH:
                self.edit_angle(event.row, event.column, event.initial)
            else:
                self.edit_cell(event.row, event.column, event.initial)
        except SassError as exc:
            self.complain(str(exc))
        self._after_edit_request(self.active_sheet)

    def edit_cell(self, row: int, column: int, initial: str = "") -> None:
        """Prompt for a data cell (column 0-5: value, percentile of x, y, z)."""
        group = self.data_group
        axis, is_percentile = column // 2, bool(column % 2)
        self.figure.check_cell(group, row, axis)
        state = self.figure.groups[group]
        value, percentile = state.cell(row, axis)
        name = f"{state.rows[row].label} {AXES[axis]}"
        if is_percentile:
            current = format_percentile(percentile)
            prompt = f"{name} percentile [{current}]:"
        else:
            shown = convert(value, GROUP_UNITS[group][0], state.unit)
            current = format_value(shown, state.unit)
            prompt = f"{name} value [{current} {DISPLAY[state.unit]}]:"
        self.ask(
            prompt, lambda text: self._edit_cell(group, row, axis, is_percentile, text), initial
        )

    def _edit_cell(self, group: str, row: int, axis: int, is_percentile: bool, text: str) -> None:
        state = self.figure.groups[group]
        name = f"{state.rows[row].label} {AXES[axis]}"
        if not text.strip():
            self.say(f"{name} unchanged.")
            return
        if is_percentile:
            self.session.set_cell_percentile(group, row, axis, parse_percentile(text))
        else:
            typed = parse_quantity(text, state.unit)
            self.session.set_value(
                group, row, axis, convert(typed, state.unit, GROUP_UNITS[group][0])
            )
        state = self.figure.groups[group]
        source = state.source
        assert source is not None  # a loaded group has its population
        canonical = GROUP_UNITS[group][0]
        value, percentile = state.cell(row, axis)
        shown = convert(value, canonical, state.unit)
        if math.isnan(percentile):
            stats = source.cell(self.figure.gender, row, axis)
            if stats[0] == stats[1] == stats[2]:
                flat = convert(stats[1], canonical, state.unit)
                where = (
                    f"no percentile: the population's 5th, 50th and 95th are all "
                    f"{format_value(flat, state.unit)} {DISPLAY[state.unit]}"
                )
            else:
                where = "no percentile: the population's statistics give none for this value"
        else:
            where = f"{format_percentile(percentile)} percentile"
        said = f"{name} = {format_value(shown, state.unit)} {DISPLAY[state.unit]} ({where})."
        from sass_tui.model.hanim import NOT_IN_HUMANOID

        if group == GIRTH and (state.rows[row].name, axis) in NOT_IN_HUMANOID:
            # The figure view does not move: say why, and where the value goes.
            said += (
                " It goes to a .fig; the figure view and Export HAnim stand the joints "
                "at the stature's landmarks."
            )
        self.say(said)

    def edit_angle(self, row: int, column: int, initial: str = "") -> None:
        """Prompt for a joint angle of the strength page (column 0-6)."""
        sheet = self.session.strength_sheet
        if sheet is None:
            self.complain(self.strength_error)
            return
        from sass_tui.model.strength import JOINT_AXIS_LABELS, MOTIONS

        name = f"{sheet.side} {MOTIONS[row].label.lower()}, {JOINT_AXIS_LABELS[column].lower()}"
        current = format_angle(sheet.angles[row, column])
        self.ask(
            f"{name} angle [{current} deg]:",
            lambda text: self._edit_angle(row, column, text),
            initial,
        )

    def _edit_angle(self, row: int, column: int, text: str) -> None:
        from sass_tui.model.strength import JOINT_AXIS_LABELS, MOTIONS

        axis = JOINT_AXIS_LABELS[column].lower()
        if not text.strip():
            self.say(f"{MOTIONS[row].label} {axis} unchanged.")
            return
        result = self.session.set_angle(row, column, text)
        self.say(
            f"{result.side.capitalize()} {result.label.lower()} at {axis} "
            f"{format_angle(result.angles[column])} deg: "
            f"{format_strength(result.value)} {result.unit} ({result.source})."
        )

    # --- editing the global data --------------------------------------------------------
    def on_global_panel_edit_requested(self, event: GlobalPanel.EditRequested) -> None:
        event.stop()
        if self._pass_to_prompt(self.query_one(GlobalPanel), event.initial):
            return
        self.edit_global(event.field, event.initial)
        self._after_edit_request(self.query_one(GlobalPanel))

    def edit_global(self, field: str, initial: str = "") -> None:
        if field == "population":
            self.complain("The population is read from the population file; it cannot be edited.")
            return
        if field == "group_percentile" and self.data_group == STRENGTH:
            if self.session.strength_sheet is None:
                self.complain(self.strength_error)
                return
        current = global_text(self.figure, self.data_group, field, self.strength_percentile)
        hint = GLOBAL_HINTS.get(field, f"percentile of every {GROUP_TITLES[self.data_group]} row")
        label = field.replace("_", " ").capitalize()
        self.ask(
            f"{label} ({hint}) [{current}]:", lambda text: self._edit_global(field, text), initial
        )

    def _edit_global(self, field: str, text: str) -> None:
        label = field.replace("_", " ").capitalize()
        if not text.strip():
            self.say(f"{label} unchanged.")
            return
        session = self.session
        strength = session.strength_sheet
        if field == "figure_type":
            session.set_figure_type(text)
        elif field == "gender":
            session.set_gender(text)
        elif field == "mass":
            session.set_mass(parse_quantity(text, "kg"))
        elif field == "stature":
            session.set_stature(parse_quantity(text, "cm"))
        elif field == "mass_percentile":
            session.set_mass_percentile(parse_percentile(text))
        elif field == "stature_percentile":
            session.set_stature_percentile(parse_percentile(text))
        elif field == "group_percentile" and self.data_group == STRENGTH and strength is not None:
            strength.set_percentile(parse_percentile(text))
        elif field == "group_percentile":
            session.set_group_percentile(self.data_group, parse_percentile(text))
        elif field == "motion_speed":
            session.set_strength_parameter(field, parse_quantity(text, "deg/s"))
        elif field in ("training_level", "fatigue_level"):
            try:
                number = float(text)
            except ValueError:
                raise AnswerError(
                    f"{label.lower()} must be a number, got {text.strip()!r}"
                ) from None
            session.set_strength_parameter(field, number)
        else:
            session.set_strength_parameter(field, text)
        shown = global_text(self.figure, self.data_group, field, self.strength_percentile)
        message = f"{label} = {shown}."
        if field == "gender":
            message += " Every group reloaded for this gender."
        elif field in STRENGTH_PARAMETERS and strength is None:
            message += " It changes strength only (strength data is not loaded)."
        elif field in STRENGTH_PARAMETERS:
            message += " Strength values recomputed."
        self.say(message)

    # --- Query, Disp. Indv., Disp. More, Disp. Pop. (§12.2.4, §12.4) ----------------------
    def action_query(self) -> None:
        """Open the database query spreadsheet."""
        self.sass_app.open_query_screen()

    def action_see_figure(self) -> None:
        """Open the figure view: the figure drawn front and side, to scale."""
        self.sass_app.open_figure_screen()

    def action_strength_curve(self) -> None:
        """Strength curves: hip, knee and ankle torque over the joint's range."""
        from sass_tui.ui.strength_curve_screen import StrengthCurveScreen

        sheet = self.session.made_strength_sheet()
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

    def action_display_individual(self) -> None:
        """Show the first person of the selected list."""
        self.show_person(0)

    def action_display_more(self) -> None:
        """Show another person of the selected list (first, next, Nth ...)."""
        if self.session.person is None:
            self.complain("Disp. Indv. first: Disp. More shows more of the selected list.")
            return
        from sass_tui.ui.query_screen import MoreMenu

        def chosen(choice: str | None) -> None:
            if choice is None:
                self.say("Disp. More cancelled.")
            elif choice == "Nth Person":
                self.ask("Enter the number:", self._nth_person)
            else:
                total = self.sass_app.selected_count()
                index = {
                    "First": 0,
                    "Last": total - 1,
                    "Previous": self.session.person_index - 1,
                    "Next": self.session.person_index + 1,
                }[choice]
                self.show_person(index)

        self.app.push_screen(MoreMenu(), chosen)

    def _nth_person(self, text: str) -> None:
        try:
            number = int(text.strip())
        except ValueError:
            raise AnswerError(f"expected a whole number such as 3, got {text.strip()!r}") from None
        self.show_person(number - 1)

    def show_person(self, index: int) -> None:
        total = self.sass_app.selected_count()
        if total == 0:
            self.complain("The selected list is empty: Query, then Select One or Select All.")
            return
        if not 0 <= index < total:
            self.complain(f"There is no person {index + 1}: the selected list holds {total}.")
            return
        try:
            person = self.sass_app.person_figure(index, self.session.population)
        except (SassError, OSError) as exc:
            self.complain(f"Cannot display person {index + 1}: {exc}")
            return
        self.session.show_person(person, index, self._own_strength(index, person))
        self.refresh_screen()
        self.say(f"Person {index + 1} of {total} in the selected list: {person.person}.")

    def _own_strength(self, index: int, person: Figure) -> StrengthData | str:
        """The person's own strength experiments (issue 11), or why there are none."""
        from sass_tui.db.individual import strength_measurements
        from sass_tui.model.strength import person_strength_data

        try:
            individual = self.sass_app.selected_individual(index)
        except (SassError, OSError) as exc:
            return f"{person.person}: strength not read ({exc})."
        measurements = strength_measurements(individual)
        if not measurements:
            return (
                f"{person.person} has no strength experiments in the database: "
                "no strength is shown for them."
            )
        # The experiments at the person's own conditions (the global panel's).
        conditions = (
            person.strength_type,
            person.motion_speed,
            person.training_level,
            person.fatigue_level,
        )
        name = person.person or f"person {index + 1}"  # a person's figure is always named
        return person_strength_data(name, person.gender, measurements, conditions)

    def action_display_population(self) -> None:
        """Go back to the population figure."""
        self.prediction = None
        if self.session.person is None:
            self.say("The population is already shown.")
            return
        self.session.show_population()
        self.refresh_screen()
        self.say(f"Population {self.figure.population} displayed.")

    # --- Family (issue 14) ----------------------------------------------------------------
    def action_family(self) -> None:
        """Build a manikin family covering the population."""
        from sass_tui.ui.family_screen import FamilyScreen

        self.app.push_screen(FamilyScreen(self.sass_app.db_path, self.session.population.gender))

    # --- Predict (issue 13) ---------------------------------------------------------------
    def action_predict(self) -> None:
        """Predict a whole figure from a few known measurements."""
        if self._predictor is not None:
            self._ask_known()
            return
        self.say("Opening the prediction model (fitting it the first time takes a second) ...")
        self.open_predictor(self.sass_app.db_path)

    @work(thread=True, exclusive=True, group="predictor", exit_on_error=False)
    def open_predictor(self, db_path: str | Path | None) -> None:
        try:
            self.post_message(PredictorOpened(open_predictor_at(db_path)))
        except (SassError, OSError) as exc:
            self.post_message(WorkerSaid(f"Cannot open the prediction model: {exc}", "error"))

    def on_predictor_opened(self, event: PredictorOpened) -> None:
        self._predictor = event.predictor
        self._ask_known()

    def _ask_known(self) -> None:
        predictor = self._predictor
        if predictor is None:
            return  # asked only once the model is open
        gender = self.session.population.gender
        try:
            fields = predictor.fields(gender)
        except SassError as exc:  # no people of this gender in the database
            self.complain(f"Cannot predict: {exc}")
            return
        answer = self.message_line.answer
        answer.suggester = KnownSuggester(fields)

        def done(text: str) -> None:
            answer.suggester = None
            self._predict_from(text)

        def cancelled() -> None:
            answer.suggester = None
            self.say("Predict cancelled; nothing changed.")

        self.ask(KNOWN_PROMPT.format(gender=gender), done, on_cancel=cancelled)

    def _predict_from(self, text: str) -> None:
        from sass_tui.model.prediction import split_known

        if not text.strip():
            self.say("No known values given; nothing predicted.")
            return
        gender = self.session.population.gender
        predictor = self._predictor
        if predictor is None:
            return  # asked only once the model is open
        known = predictor.parse_known(gender, split_known(text))
        prediction = predictor.predict(gender, known, nearest=1)
        figure = prediction.figure(self.session.population)
        self.session.show_person(figure, -1)
        self.prediction = (prediction, figure)
        self.refresh_screen()
        nearest = (
            f" Nearest real person: {prediction.nearest[0].name}." if prediction.nearest else ""
        )
        self.say(
            f"Figure {prediction.label()}.{nearest} a: a cell's 90 % interval; "
            "o: back to the population."
        )

    def action_interval(self) -> None:
        """Show the 90 % interval of the predicted cell under the cursor."""
        if self.prediction is None or self.session.person is not self.prediction[1]:
            self.complain(self.why_not("interval") or "Predict (k) first.")
            return
        group = self.data_group
        if group not in (GIRTH, CENTER_OF_MASS):
            self.say(
                f"{GROUP_TITLES[group]} is not predicted: it is the population's at the "
                "group percentile."
            )
            return
        sheet = self.sheet
        state = self.figure.groups[group]
        axis = sheet.cursor_column // 2
        field = f"{group}.{state.rows[sheet.cursor_row].name}.{AXES[axis]}"
        self.say(interval_text(self.prediction[0], field, state.unit, convert))
