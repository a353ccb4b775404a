"""The anthropometric spreadsheet (report §12.2, figures 3, 4 and 6).

Every change to the data goes through the Figure's methods; a refused edit
leaves the figure as it was and says why on the message line.  Files are read
and written in worker threads so the screen never freezes.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from textual import work
from textual.app import App, ComposeResult
from textual.binding import Binding
from textual.containers import Horizontal
from textual.widgets import Button, Footer

from sass_tui.model.figfile import (
    FigureIncompleteError,
    FigValueError,
    default_fig_name,
    write_fig,
)
from sass_tui.model.figure import Figure, FigureError
from sass_tui.model.names import (
    AXES,
    CENTER_OF_MASS,
    GIRTH,
    GROUP_TITLES,
    GROUPS,
    JOINT_LIMITS,
    STRENGTH,
)
from sass_tui.model.percentile import PercentileError
from sass_tui.model.popfile import PopulationFileError, read_population_file
from sass_tui.model.strength import (
    DEFAULT_NON_DOMINANT_FACTOR,
    JOINT_AXIS_LABELS,
    MOTIONS,
    StrengthError,
    StrengthFileError,
    StrengthSheet,
    fig_section,
    read_strength_file,
)
from sass_tui.model.units import (
    DISPLAY,
    GROUP_UNITS,
    UnitError,
    convert,
    other_unit,
    parse_quantity,
)
from sass_tui.model.vocabulary import STRENGTH_PARAMETERS
from sass_tui.ui.commands import COMMANDS
from sass_tui.ui.individuals import QueryCommands
from sass_tui.ui.strength_page import StrengthPage, format_angle, format_strength
from sass_tui.ui.widgets import (
    AnswerInput,
    CommandMenu,
    DataSheet,
    GlobalPanel,
    GroupBar,
    GroupTab,
    MessageLine,
    format_percentile,
    format_value,
    global_text,
)

FIRST_MESSAGE = "Press left-mouse to select items."
GROUP_KEYS = ((GIRTH, "g"), (JOINT_LIMITS, "j"), (CENTER_OF_MASS, "m"), (STRENGTH, "s"))
STRENGTH_NOT_LOADED = (
    "Strength data is not loaded; SASS runs without it (Create Figure leaves strength out)."
)
# What the user may type wrongly: shown on the message line, never a traceback.
INPUT_ERRORS = (FigureError, PercentileError, UnitError, ValueError, OSError)


def parse_percentile(text: str) -> float:
    cleaned = text.strip().removesuffix("%").strip()
    try:
        return float(cleaned)
    except ValueError:
        raise ValueError(f"expected a percentile such as 50 or 95%, got {text.strip()!r}") from None


class SassApp(QueryCommands, App):
    # Absolute: the app may be started from any directory.
    CSS_PATH = Path(__file__).with_name("sass.tcss")
    TITLE = "SASS"
    ENABLE_COMMAND_PALETTE = False
    # Letter keys are priority bindings: the app takes them in the order they
    # were typed, before the focused widget sees the next key ("m12" pasted
    # switches to Center of Mass, then types 12).  While the message line takes
    # an answer, check_action turns them off and the letters are typed there.
    BINDINGS = [
        *(Binding(spec.key, spec.action, spec.footer, priority=True) for spec in COMMANDS),
        Binding("pagedown", "next_page", show=False),
        Binding("pageup", "previous_page", show=False),
        Binding("u", "undo", "Undo", priority=True),
        Binding("ctrl+z", "undo", show=False),
        Binding("w", "next_warning", "Warnings", priority=True),
        *(
            Binding(key, f"select_group('{group}')", show=False, priority=True)
            for group, key in GROUP_KEYS
        ),
    ]

    def check_action(self, action: str, parameters) -> bool | None:
        if isinstance(self.focused, AnswerInput):
            return False
        return super().check_action(action, parameters)

    def __init__(
        self,
        figure: Figure | None = None,
        *,
        cursor_blink: bool = True,
        strength_path: str | Path | None = None,
        db_path: str | Path | None = None,
    ) -> None:
        super().__init__()
        self.figure = figure or Figure.default()
        # None = $SASS_DB or the user's data directory, created on first Query.
        self.db_path = Path(db_path).expanduser() if db_path else None
        # None = datasets/strength.dat.  Read at mount: ~25 ms (docs/performance.md).
        self.strength_path = strength_path
        self.strength_sheet: StrengthSheet | None = None
        self.strength_error = STRENGTH_NOT_LOADED
        self.data_group = GIRTH
        self.cursor_blink = cursor_blink
        self.warnings: list[str] = []
        self._warning_index = 0
        self._on_answer: Callable[[str], None] | None = None
        self._focus_after_answer = None

    # --- layout ---------------------------------------------------------------
    def compose(self) -> ComposeResult:
        yield GroupBar(GROUP_KEYS, id="groups")
        with Horizontal(id="top"):
            yield GlobalPanel(id="global")
            yield CommandMenu(COMMANDS, id="commands")
        yield DataSheet(id="sheet")
        yield StrengthPage(id="strength-sheet")
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.query_one(AnswerInput).cursor_blink = self.cursor_blink
        self.strength_page.display = False
        self._load_default_strength()
        self.sheet.show_group(self.data_group)
        self.refresh_screen()
        self.sheet.focus()
        self.say(FIRST_MESSAGE)

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
    def strength_percentile(self) -> float | None:
        return self.strength_sheet.percentile if self.strength_sheet is not None else None

    @property
    def message_line(self) -> MessageLine:
        return self.query_one(MessageLine)

    def refresh_screen(self) -> None:
        self.query_one(GroupBar).highlight(self.data_group)
        self.query_one(GlobalPanel).refresh()
        self.query_one(CommandMenu).refresh_labels()
        self.refresh_bindings()
        self.sheet.refresh()
        if self.strength_sheet is not None:
            # Follow the app's figure should another one be shown (e.g. an individual).
            self.strength_sheet.figure = self.figure
        self.strength_page.refresh()

    # --- message line ---------------------------------------------------------
    def say(self, text: str) -> None:
        self.message_line.show(text, "info")

    def complain(self, text: str) -> None:
        self.message_line.show(text, "error")

    def ask(self, prompt: str, on_answer: Callable[[str], None], initial: str = "") -> None:
        if not isinstance(self.focused, AnswerInput):
            self._focus_after_answer = self.focused
        self._on_answer = on_answer
        self.message_line.ask(prompt, initial)

    def _close_prompt(self) -> Callable[[str], None] | None:
        handler, self._on_answer = self._on_answer, None
        self.message_line.close()
        if self._focus_after_answer is not None:
            # Synchronous, so that a follow-up question (overwrite?) keeps the focus.
            self.screen.set_focus(self._focus_after_answer)
        return handler

    def on_input_submitted(self, event: AnswerInput.Submitted) -> None:
        event.stop()
        handler = self._close_prompt()
        if handler is not None:
            self._guarded(handler, event.value)

    def on_answer_input_cancelled(self, event: AnswerInput.Cancelled) -> None:
        event.stop()
        self._close_prompt()
        self.say("Cancelled; nothing changed.")

    def _guarded(self, handler: Callable[[str], None], text: str) -> None:
        try:
            handler(text)
        except INPUT_ERRORS as exc:
            self.complain(str(exc))
        self.refresh_screen()

    # --- groups -----------------------------------------------------------------
    def on_group_tab_chosen(self, event: GroupTab.Chosen) -> None:
        self.action_select_group(event.group)

    def action_select_group(self, group: str) -> None:
        if self.message_line.prompting:
            return
        if group == STRENGTH and self.strength_sheet is None:
            self.complain(self.strength_error)
            return
        had_focus = self.focused is self.active_sheet
        self.data_group = group
        on_strength = group == STRENGTH
        self.sheet.display = not on_strength
        self.strength_page.display = on_strength
        if not on_strength:
            self.sheet.show_group(group)
        if had_focus or self.focused is None:
            self.active_sheet.focus()
        self.refresh_screen()
        # After the layout: a page just shown has no height yet to page by.
        self.call_after_refresh(self._say_group_shown)

    def _say_group_shown(self) -> None:
        if self.message_line.prompting:  # a cell edit began meanwhile: keep its prompt
            return
        sheet = self.active_sheet
        message = (
            f"{GROUP_TITLES[self.data_group]}: {sheet.row_count} rows, "
            f"{sheet.pages} page{'s' if sheet.pages > 1 else ''}."
        )
        if self.data_group == STRENGTH:
            message += (
                f" {self.strength_sheet.side.capitalize()} limb, "
                f"from {self.strength_sheet.data.title}."
            )
        self.say(message)

    # --- commands ---------------------------------------------------------------
    async def on_button_pressed(self, event: Button.Pressed) -> None:
        spec = next((c for c in COMMANDS if event.button.id == f"command-{c.name}"), None)
        if spec is not None:
            event.stop()
            await self.run_action(spec.action)

    def action_next_page(self) -> None:
        sheet = self.active_sheet
        if not sheet.turn_page(1):
            self.say("This is the last page.")
        else:
            self.say(f"Page {sheet.page + 1} of {sheet.pages}.")

    def action_previous_page(self) -> None:
        sheet = self.active_sheet
        if not sheet.turn_page(-1):
            self.say("This is the first page.")
        else:
            self.say(f"Page {sheet.page + 1} of {sheet.pages}.")

    def action_convert_units(self) -> None:
        if self.data_group == STRENGTH:
            unit = self.strength_sheet.toggle_unit()
            self.refresh_screen()
            self.say(f"Strength now shown in {unit}.")
            return
        state = self.figure.groups[self.data_group]
        self.figure.set_unit(self.data_group, other_unit(self.data_group, state.unit))
        self.refresh_screen()
        self.say(f"{GROUP_TITLES[self.data_group]} now shown in {DISPLAY[state.unit]}.")

    def action_undo(self) -> None:
        """Undo the newest edit, whether of the figure or of a strength angle."""
        sheet = self.strength_sheet
        if sheet is not None and sheet.last_edit > self.figure.last_edit:
            undone = sheet.undo()
        else:
            undone = self.figure.undo()
        if undone:
            self.refresh_screen()
            self.say("Undone.")
        else:
            self.say("Nothing to undo.")

    def action_next_warning(self) -> None:
        if not self.warnings:
            self.say("No warnings from the last file loaded.")
            return
        self._warning_index = (self._warning_index + 1) % len(self.warnings)
        self._show_warning()

    def _show_warning(self) -> None:
        count = len(self.warnings)
        self.message_line.show(
            f"{self.warnings[self._warning_index]}  "
            f"[warning {self._warning_index + 1} of {count}; w: next]",
            "warning",
        )

    # --- Input Data -----------------------------------------------------------------
    def action_input_data(self) -> None:
        if self.data_group == STRENGTH:
            self.ask("Strength data file:", self._input_data_from)
            return
        title = GROUP_TITLES[self.data_group]
        self.ask(f"{title} population file:", self._input_data_from)

    def _input_data_from(self, text: str) -> None:
        if not text.strip():
            self.say("No file given; nothing loaded.")
            return
        self.say(f"Reading {text.strip()} ...")
        path = Path(text.strip()).expanduser()
        if self.data_group == STRENGTH:
            self.load_file(path, read_strength_file, self._apply_strength, "strength data")
        else:
            group = self.data_group
            self.load_file(
                path,
                lambda p: read_population_file(p, group),
                lambda data: self._apply_population(group, data),
                GROUP_TITLES[group],
            )

    @work(thread=True, exclusive=True, group="input-data", exit_on_error=False)
    def load_file(
        self, path: Path, read: Callable[[Path], object], apply: Callable[[object], None], what: str
    ) -> None:
        """Input Data: read in a worker; a file that fails leaves `what` as it was."""
        try:
            data = read(path)
        except (PopulationFileError, StrengthFileError) as exc:
            self.call_from_thread(self.complain, f"{exc}; {what} unchanged.")
            return
        except Exception as exc:  # anything else the file does: report, keep the data
            self.call_from_thread(self.complain, f"{path}: {exc}; {what} unchanged.")
            return
        self.call_from_thread(apply, data)

    # --- strength data ----------------------------------------------------------------
    def _load_default_strength(self) -> None:
        """At start-up, before the first screen: fast enough not to need a worker."""
        try:
            sheet = StrengthSheet(read_strength_file(self.strength_path), self.figure)
        except StrengthFileError as exc:
            self.strength_error = f"Strength data is not loaded ({exc}); SASS runs without it."
            return
        self.strength_sheet = sheet
        try:
            sheet.rows()  # fits the equations now rather than on the first 's'
        except StrengthError:
            pass  # no data for this gender: the page says so when shown

    def _apply_strength(self, data) -> None:
        sheet = StrengthSheet(data, self.figure)
        old = self.strength_sheet
        if old is not None:
            # The view settings survive a new file; the angles are the new file's.
            sheet.side, sheet.unit = old.side, old.unit
            sheet.percentile, sheet.non_dominant_factor = old.percentile, old.non_dominant_factor
        self.strength_sheet = sheet
        self.refresh_screen()
        self.warnings, self._warning_index = list(data.warnings), 0
        self.say(f"Loaded strength from {data.path} ({data.title}).")
        if self.warnings:
            self._show_warning()

    def edit_angle(self, row: int, column: int, initial: str = "") -> None:
        """Prompt for a joint angle of the strength page (column 0-6)."""
        sheet = self.strength_sheet
        name = f"{sheet.side} {MOTIONS[row].label.lower()}, {JOINT_AXIS_LABELS[column].lower()}"
        current = format_angle(sheet.angles[row, column])
        self.ask(
            f"{name} angle [{current} deg]:",
            lambda text: self._edit_angle(row, column, text),
            initial,
        )

    def _edit_angle(self, row: int, column: int, text: str) -> None:
        axis = JOINT_AXIS_LABELS[column].lower()
        if not text.strip():
            self.say(f"{MOTIONS[row].label} {axis} unchanged.")
            return
        result = self.strength_sheet.set_angle(row, column, text)
        self.say(
            f"{result.side.capitalize()} {result.label.lower()} at {axis} "
            f"{format_angle(result.angles[column])} deg: "
            f"{format_strength(result.value)} {result.unit} ({result.source})."
        )

    def action_switch_side(self) -> None:
        if not (self.data_group == STRENGTH and self.strength_sheet is not None):
            self.say("Right → Left applies to the Strength group (press s).")
            return
        self.ask(
            f"Scaling factor for the non-dominant limb "
            f"(RETURN = default {DEFAULT_NON_DOMINANT_FACTOR:.3f}):",
            lambda text: self.say(self.strength_sheet.switch_side(text) + "."),
        )

    def _apply_population(self, group: str, data) -> None:
        gender = self.figure.gender
        if not data.has(gender):
            self.complain(
                f"{data.path}: no 'T {gender.upper()}' section for this {gender} "
                f"figure; {GROUP_TITLES[group]} unchanged."
            )
            return
        self.figure.load_group(group, data)
        self.refresh_screen()
        self.warnings, self._warning_index = list(data.warnings), 0
        loaded = f"Loaded {GROUP_TITLES[group]} from {data.path} ({data.title})."
        if self.warnings:
            self.say(loaded)
            self._show_warning()
        else:
            self.say(loaded)

    # --- Create Figure --------------------------------------------------------------
    def action_create_figure(self) -> None:
        missing = self.figure.missing_groups()
        if missing:
            self.complain(
                f"Cannot create a figure: {', '.join(missing)} not loaded for {self.figure.gender}."
            )
            return
        default = default_fig_name(
            self.figure.gender, self.figure.groups[GIRTH].percentile, self.figure.figure_type
        )
        if self.figure.person:
            default = self.person_fig_name()
        self.ask(
            f"Figure file name [{default}]:",
            lambda text: self._create_figure_named(text.strip() or default),
        )

    def _create_figure_named(self, name: str) -> None:
        path = Path(name).expanduser()
        if self.strength_sheet is None:
            self._write_unless_kept(path, lambda: self.write_figure(path))
            return

        def include(answer: str) -> None:
            word = answer.strip().lower()
            if word in ("n", "no"):
                sections = []
            elif word in ("", "y", "yes"):
                # Computed here, not in the worker: the page may change meanwhile.
                sections = [fig_section(self.strength_sheet)]
            else:
                raise ValueError(f"expected y or n, got {answer.strip()!r}; nothing written")
            self._write_unless_kept(path, lambda: self.write_figure(path, sections))

        self.ask("Include strength in the figure? (Y/n)", include)

    def _write_unless_kept(self, path: Path, write: Callable[[], None]) -> None:
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

    @work(thread=True, exclusive=True, group="create-figure", exit_on_error=False)
    def write_figure(self, path: Path, extra_sections=()) -> None:
        try:
            write_fig(self.figure, path, extra_sections)
        except (FigureIncompleteError, FigValueError) as exc:
            self.call_from_thread(self.complain, str(exc))
            return
        except OSError as exc:
            self.call_from_thread(self.complain, f"{path}: cannot write: {exc.strerror or exc}")
            return
        filled = sum(int(self.figure.output_values(g)[1].sum()) for g in GROUPS)
        note = (
            f" {filled} values not measured for {self.figure.person} came from the population."
            if filled
            else ""
        )
        self.call_from_thread(self.say, f"Wrote {path}.{note}")

    # --- Export HAnim -----------------------------------------------------------------
    def action_export_hanim(self) -> None:
        default = (
            Path(
                default_fig_name(
                    self.figure.gender,
                    self.figure.groups[GIRTH].percentile,
                    self.figure.figure_type,
                )
            )
            .with_suffix(".x3d")
            .name
        )
        self.ask(
            f"HAnim file name [{default}]:",
            lambda text: self._export_hanim_named(Path(text.strip() or default).expanduser()),
        )

    def _export_hanim_named(self, path: Path) -> None:
        self._write_unless_kept(path, lambda: self.export_figure(path))

    @work(thread=True, exclusive=True, group="export-hanim", exit_on_error=False)
    def export_figure(self, path: Path) -> None:
        try:
            from sass_tui.model.hanim import export_hanim

            export_hanim(self.figure, path)
        except ValueError as exc:  # an incomplete figure (HAnimError, FigureIncompleteError)
            self.call_from_thread(self.complain, str(exc))
            return
        except OSError as exc:
            self.call_from_thread(self.complain, f"{path}: cannot write: {exc.strerror or exc}")
            return
        self.call_from_thread(self.say, f"Exported the HAnim humanoid to {path}.")

    # --- editing the data section -------------------------------------------------------
    def edit_cell(self, row: int, column: int, initial: str = "") -> None:
        """Prompt for a data cell (column 0-5: value, percentile of x, y, z)."""
        group = self.data_group
        axis, is_percentile = column // 2, bool(column % 2)
        try:
            self.figure.check_cell(group, row, axis)
        except FigureError as exc:
            self.complain(str(exc))
            return
        state = self.figure.groups[group]
        name = f"{state.rows[row].label} {AXES[axis]}"
        if is_percentile:
            current = format_percentile(state.percentiles[row, axis])
            prompt = f"{name} percentile [{current}]:"
        else:
            shown = convert(state.values[row, axis], GROUP_UNITS[group][0], state.unit)
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
            self.figure.set_cell_percentile(group, row, axis, parse_percentile(text))
        else:
            typed = parse_quantity(text, state.unit)
            self.figure.set_value(
                group, row, axis, convert(typed, state.unit, GROUP_UNITS[group][0])
            )
        shown = convert(state.values[row, axis], GROUP_UNITS[group][0], state.unit)
        self.say(
            f"{name} = {format_value(shown, state.unit)} {DISPLAY[state.unit]} "
            f"({format_percentile(state.percentiles[row, axis])} percentile)."
        )

    # --- editing the global data --------------------------------------------------------
    def edit_global(self, field: str, initial: str = "") -> None:
        if field == "population":
            self.complain("The population is read from the population file; it cannot be edited.")
            return
        if (
            field == "group_percentile"
            and self.data_group == STRENGTH
            and self.strength_sheet is None
        ):
            self.complain(self.strength_error)
            return
        current = global_text(self.figure, self.data_group, field, self.strength_percentile)
        hint = {
            "figure_type": "skinny or polybody",
            "gender": "male or female",
            "mass": "kg, or e.g. 180 lb",
            "stature": "cm, or e.g. 70 in",
            "mass_percentile": "percentile",
            "stature_percentile": "percentile",
            "group_percentile": f"percentile of every {GROUP_TITLES[self.data_group]} row",
            "strength_type": "isometric, isokinetic or isotonic",
            "motion_speed": "deg/s",
            "handedness": "right or left",
            "training_level": "0 = no training",
            "fatigue_level": "0 = not tired",
        }[field]
        label = field.replace("_", " ").capitalize()
        self.ask(
            f"{label} ({hint}) [{current}]:", lambda text: self._edit_global(field, text), initial
        )

    def _edit_global(self, field: str, text: str) -> None:
        label = field.replace("_", " ").capitalize()
        if not text.strip():
            self.say(f"{label} unchanged.")
            return
        figure = self.figure
        if field == "figure_type":
            figure.set_figure_type(text)
        elif field == "gender":
            figure.set_gender(text)
        elif field == "mass":
            figure.set_mass(parse_quantity(text, "kg"))
        elif field == "stature":
            figure.set_stature(parse_quantity(text, "cm"))
        elif field == "mass_percentile":
            figure.set_mass_percentile(parse_percentile(text))
        elif field == "stature_percentile":
            figure.set_stature_percentile(parse_percentile(text))
        elif field == "group_percentile" and self.data_group == STRENGTH:
            self.strength_sheet.set_percentile(parse_percentile(text))
        elif field == "group_percentile":
            figure.set_group_percentile(self.data_group, parse_percentile(text))
        elif field == "motion_speed":
            figure.set_strength_parameter(field, parse_quantity(text, "deg/s"))
        elif field in ("training_level", "fatigue_level"):
            try:
                number = float(text)
            except ValueError:
                raise ValueError(
                    f"{label.lower()} must be a number, got {text.strip()!r}"
                ) from None
            figure.set_strength_parameter(field, number)
        else:
            figure.set_strength_parameter(field, text)
        message = (
            f"{label} = {global_text(figure, self.data_group, field, self.strength_percentile)}."
        )
        if field == "gender":
            message += " Every group reloaded for this gender."
        elif field in STRENGTH_PARAMETERS and self.strength_sheet is None:
            message += " It changes strength only (strength data is not loaded)."
        elif field in STRENGTH_PARAMETERS:
            message += " Strength values recomputed."
        self.say(message)


def run_app(db_path: str | Path | None = None) -> int:
    SassApp(db_path=db_path).run()
    return 0
