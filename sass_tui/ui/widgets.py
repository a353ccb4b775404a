"""The sections of the anthropometric spreadsheet (report figure 4).

Data down, messages up: a widget shows what its screen hands it (a figure, a
group, a page size) and posts a Message for what the user did; it never
reaches into the app.  Every change to the data goes through the screen to
the Session.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from rich.cells import cell_len
from rich.style import Style
from rich.text import Text
from textual import events
from textual.binding import Binding
from textual.containers import Horizontal, Vertical
from textual.content import Content
from textual.geometry import Size
from textual.message import Message
from textual.reactive import reactive
from textual.widget import Widget
from textual.widgets import Input, Label, Static

from sass_tui.model.errors import SassError
from sass_tui.model.figure import Figure
from sass_tui.model.names import AXES, GIRTH, GROUP_TITLES, STRENGTH
from sass_tui.model.text import printable
from sass_tui.model.units import DISPLAY, GROUP_UNITS, convert
from sass_tui.ui.commands import CommandSpec
from sass_tui.ui.textual_api import bindings_of

# Characters that start typing a new number straight into the message line.
NUMBER_START = set("0123456789.-+")
DECIMALS = {"cm": 2, "in": 2, "deg": 1, "rad": 3}


def format_value(value: float, unit: str) -> str:
    """999 (NaN) is shown blank, as SASS did."""
    if value is None or math.isnan(value):
        return ""
    return f"{value:.{DECIMALS.get(unit, 2)}f}"


def format_percentile(p: float) -> str:
    if p is None or math.isnan(p):
        return ""
    return f"{p:.1f}"


NO_PERCENTILE = "—"


def format_cell_percentile(value: float, p: float) -> str:
    """A value without a percentile (its row has no spread: 5th, 50th and
    95th equal, and the value is another) shows "—", not a blank that looks
    like a missing value."""
    if not math.isnan(value) and math.isnan(p):
        return NO_PERCENTILE
    return format_percentile(p)


class TypedAhead(Message):
    """Keys typed after an edit was asked for but before its prompt took the
    focus: the app routed them to the widget that asked.  They belong to the
    prompt, in the order typed (a paste arrives as one `text`)."""

    def __init__(self, key: str, character: str | None, text: str = "") -> None:
        super().__init__()
        self.key = key
        self.character = character
        self.text = text


class ScreenKey(Message):
    """A key an editing widget does not take, sent to its screen in the order
    typed: the screen's command, or the open prompt's if one opened meanwhile."""

    def __init__(self, key: str, character: str | None) -> None:
        super().__init__()
        self.key = key
        self.character = character


class EditorKeys:
    """Keys of a widget whose cells are edited on the message line.

    A number key (or Enter) asks the screen for a prompt with a Message; from
    then until the widget loses the focus (the prompt took it) or the screen
    says no prompt came (`typing_done`), every key and paste is passed on as
    TypedAhead, never to a binding: `14in` typed fast edits the cell, it does
    not open Input Data on the `i`."""

    _typing_ahead = False

    def request_edit(self, message: Message) -> None:
        self._typing_ahead = True
        self.post_message(message)  # type: ignore[attr-defined]

    def typing_done(self) -> None:
        self._typing_ahead = False

    def start_typing(self, text: str) -> None:
        raise NotImplementedError

    def on_key(self, event: events.Key) -> None:
        if self._typing_ahead:
            event.stop()
            event.prevent_default()
            self.post_message(TypedAhead(event.key, event.character))  # type: ignore[attr-defined]
        elif event.character and event.character in NUMBER_START:
            event.stop()
            event.prevent_default()
            self.start_typing(event.character)
        elif event.key == "enter":
            # Here, not by a binding run after the key has bubbled up: the
            # letters typed next must find the edit already asked for.
            event.stop()
            event.prevent_default()
            self.start_typing("")
        elif event.key not in bindings_of(self).key_to_bindings:  # type: ignore[arg-type]
            # Not this widget's (its arrows are): the screen's, in this order.
            event.stop()
            event.prevent_default()
            self.post_message(ScreenKey(event.key, event.character))  # type: ignore[attr-defined]

    def on_paste(self, event: events.Paste) -> None:
        event.stop()
        event.prevent_default()
        if self._typing_ahead:
            self.post_message(TypedAhead("paste", None, event.text))  # type: ignore[attr-defined]
        elif event.text.strip():
            self.start_typing(event.text.strip())

    def on_blur(self) -> None:
        self._typing_ahead = False
        self.refresh()  # type: ignore[attr-defined]


# --- anthropometric group status line ------------------------------------


class GroupTab(Static):
    """One group's cell; the selected group's is highlighted."""

    class Chosen(Message):
        def __init__(self, group: str) -> None:
            super().__init__()
            self.group = group

    def __init__(self, group: str, key: str) -> None:
        super().__init__(f"{GROUP_TITLES[group]} ({key})", id=f"group-{group}", classes="group-tab")
        self.group = group

    def on_click(self, event: events.Click) -> None:
        event.stop()
        self.post_message(self.Chosen(self.group))


class GroupBar(Horizontal):
    def __init__(self, groups: tuple[tuple[str, str], ...], **kwargs) -> None:
        super().__init__(**kwargs)
        self._groups = groups

    def compose(self):
        for group, key in self._groups:
            yield GroupTab(group, key)

    def highlight(self, group: str) -> None:
        for tab in self.query(GroupTab):
            tab.set_class(tab.group == group, "-selected")


# --- standard (global) data --------------------------------------------------


@dataclass(frozen=True)
class GlobalCell:
    field: str
    label: str
    row: int
    slot: int  # 0 = value, 1 = its percentile (mass, stature), 2 = right column
    short_label: str = ""  # for narrow terminals (80 columns)


GLOBAL_CELLS: tuple[GlobalCell, ...] = (
    GlobalCell("population", "Population", 0, 0),
    GlobalCell("figure_type", "Figure type", 1, 0),
    GlobalCell("gender", "Gender", 2, 0),
    GlobalCell("mass", "Mass", 3, 0),
    GlobalCell("mass_percentile", "", 3, 1),
    GlobalCell("stature", "Stature", 4, 0),
    GlobalCell("stature_percentile", "", 4, 1),
    GlobalCell("group_percentile", "Group pct.", 5, 0),
    GlobalCell("strength_type", "Strength type", 1, 2, "Str. type"),
    GlobalCell("motion_speed", "Motion speed", 2, 2, "Speed"),
    GlobalCell("handedness", "Handedness", 3, 2, "Handed"),
    GlobalCell("training_level", "Training level", 4, 2, "Training"),
    GlobalCell("fatigue_level", "Fatigue level", 5, 2, "Fatigue"),
)
GLOBAL_ROWS = 6
# Column widths: left label, value, percentile, gap, right label, right value.
_LABEL_A, _SLOT0, _SLOT1, _GAP = 12, 9, 8, 1
_LABEL_B, _SHORT_LABEL_B = 15, 10
# Below this width the right column's labels are shortened ("Str. type"), so
# that the panel and figure 6's two command columns fit in 80 columns.
_NARROW = _LABEL_A + _SLOT0 + _SLOT1 + _GAP + _LABEL_B + 11


def printable_lines(text: str) -> str:
    """`printable` line by line: a message may span lines, and keeps them."""
    return "\n".join(printable(line) for line in text.split("\n"))


def global_text(figure, group: str, field: str, strength_percentile: float | None = None) -> str:
    if field == "population":
        return printable(figure.person or figure.population)
    if field in ("mass", "stature"):
        value = getattr(figure, field)
        return "" if math.isnan(value) else f"{value:.1f} {'kg' if field == 'mass' else 'cm'}"
    if field in ("mass_percentile", "stature_percentile"):
        return f"{format_percentile(getattr(figure, field))} %".strip(" ")
    if field == "group_percentile":
        if group == STRENGTH:
            return "" if strength_percentile is None else format_percentile(strength_percentile)
        return format_percentile(figure.groups[group].percentile)
    if field == "motion_speed":
        return f"{figure.motion_speed:g} deg/s"
    value = getattr(figure, field)
    return f"{value:g}" if isinstance(value, float) else str(value)


class GlobalPanel(EditorKeys, Widget, can_focus=True):
    """The eleven labels of §12.2.2; a cell is chosen with the mouse or arrows.
    Shows the figure, group and strength percentile its screen gives it."""

    COMPONENT_CLASSES = {
        "globalpanel--label",
        "globalpanel--cursor",
        "globalpanel--cursor-blur",
        "globalpanel--readonly",
    }
    BINDINGS = [
        Binding("up", "move(-1, 0)", show=False),
        Binding("down", "move(1, 0)", show=False),
        Binding("left", "move(0, -1)", show=False),
        Binding("right", "move(0, 1)", show=False),
        Binding("enter", "edit", "Edit", show=False),
    ]

    class EditRequested(Message):
        def __init__(self, field: str, initial: str = "") -> None:
            super().__init__()
            self.field = field
            self.initial = initial

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.cursor = GLOBAL_CELLS[1]
        self.figure: Figure | None = None
        self.group = GIRTH
        self.strength_percentile: float | None = None

    def show(self, figure: Figure, group: str, strength_percentile: float | None) -> None:
        self.figure, self.group, self.strength_percentile = figure, group, strength_percentile
        self.refresh()

    def select(self, field: str) -> None:
        self.cursor = next(c for c in GLOBAL_CELLS if c.field == field)
        self.refresh()

    @property
    def _narrow(self) -> bool:
        return self.size.width < _NARROW

    def _label_b(self) -> int:
        return _SHORT_LABEL_B if self._narrow else _LABEL_B

    def _label(self, cell: GlobalCell) -> str:
        return cell.short_label if self._narrow and cell.short_label else cell.label

    def _slot_span(self, slot: int) -> tuple[int, int]:
        starts = (_LABEL_A, _LABEL_A + _SLOT0, _LABEL_A + _SLOT0 + _SLOT1 + _GAP + self._label_b())
        widths = (_SLOT0, _SLOT1, max(6, self.size.width - starts[2]))
        return starts[slot], widths[slot]

    def render(self) -> Text:
        figure, group = self.figure, self.group
        if figure is None:
            return Text()
        label_style = self.get_component_rich_style("globalpanel--label")
        cursor_style = self.get_component_rich_style(
            "globalpanel--cursor" if self.has_focus else "globalpanel--cursor-blur"
        )
        width = self.size.width
        lines = []
        for row in range(GLOBAL_ROWS):
            line = Text(no_wrap=True, overflow="crop")
            cells = sorted((c for c in GLOBAL_CELLS if c.row == row), key=lambda c: c.slot)
            column = 0
            for cell in cells:
                start, span = self._slot_span(cell.slot)
                if cell.field == "population":
                    span = width - start
                if cell.label:
                    label_start = 0 if cell.slot == 0 else start - self._label_b()
                    line.append(" " * max(0, label_start - column))
                    line.append(
                        f"{self._label(cell):<{start - label_start}}"[: start - label_start],
                        label_style,
                    )
                    column = start
                line.append(" " * max(0, start - column))
                text = global_text(figure, group, cell.field, self.strength_percentile)
                cell_style = cursor_style if cell == self.cursor else ""
                # A terminal narrower than the panel leaves a cell no room (issue 17).
                width = max(0, span - 1)
                line.append(f"{text:<{width}}"[:width], cell_style)
                line.append(" ")
                column = start + span
            lines.append(line)
        return Text("\n", no_wrap=True).join(lines)

    def on_click(self, event: events.Click) -> None:
        offset = event.get_content_offset(self)
        if offset is None:
            return
        for cell in GLOBAL_CELLS:
            start, span = self._slot_span(cell.slot)
            if cell.field == "population":
                span = self.size.width - start
            label_start = (
                0 if cell.slot == 0 else start - self._label_b() if cell.slot == 2 else start
            )
            if cell.row == offset.y and label_start <= offset.x < start + span:
                again = self.has_focus and (event.chain > 1 or self.cursor == cell)
                self.cursor = cell
                self.focus()
                self.refresh()
                if again:  # a second click on the chosen value edits it
                    self.action_edit()
                return

    def action_move(self, rows: int, slots: int) -> None:
        here = self.cursor
        if rows:
            target = here.row + rows
            candidates = [c for c in GLOBAL_CELLS if c.row == target]
            if not candidates:
                return
            self.cursor = min(candidates, key=lambda c: abs(c.slot - here.slot))
        else:
            same_row = sorted((c for c in GLOBAL_CELLS if c.row == here.row), key=lambda c: c.slot)
            index = same_row.index(here) + slots
            if 0 <= index < len(same_row):
                self.cursor = same_row[index]
        self.refresh()

    def action_edit(self) -> None:
        self.request_edit(self.EditRequested(self.cursor.field))

    def start_typing(self, text: str) -> None:
        self.request_edit(self.EditRequested(self.cursor.field, text))

    def on_focus(self) -> None:
        self.refresh()


# --- command menu --------------------------------------------------------------


class MenuItem(Widget, can_focus=False):
    """One command of a CommandMenu: its label, clicked like a button.

    Not Textual's Button: the spreadsheet's 15 Buttons cost ~15 ms of the
    first screen (issue 16), mostly their large default CSS matched against
    every widget; the menu uses only the label, the click and the look
    (sass.tcss, query.tcss)."""

    ALLOW_SELECT = False
    ACTIVE_SECONDS = 0.2  # the flash after a click, as Button's

    label: reactive[str] = reactive("", layout=True)

    class Pressed(Message):
        def __init__(self, item: MenuItem) -> None:
            super().__init__()
            self.item = item

        @property
        def control(self) -> MenuItem:
            return self.item

    def __init__(self, label: str, *, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.set_reactive(MenuItem.label, label)

    def render(self) -> Content:
        return Content(self.label)

    def get_content_width(self, container: Size, viewport: Size) -> int:
        return cell_len(self.label)

    async def _on_click(self, event: events.Click) -> None:
        event.stop()
        self.press()

    def press(self) -> None:
        if self.disabled or not self.display or self.has_class("-active"):
            return
        self.add_class("-active")
        self.set_timer(self.ACTIVE_SECONDS, lambda: self.remove_class("-active"))
        self.post_message(self.Pressed(self))


class CommandMenu(Horizontal):
    """Figure 6: commands in two columns, built from the command specs; the
    labels and availability come from `context` (the screen the menu is on)."""

    def __init__(self, commands: tuple[CommandSpec, ...], context: object, **kwargs) -> None:
        super().__init__(**kwargs)
        self.commands = commands
        self.context = context

    def compose(self):
        for column in sorted({c.column for c in self.commands}):
            with Vertical(classes="command-column"):
                for spec in sorted(
                    (c for c in self.commands if c.column == column), key=lambda c: c.row
                ):
                    yield MenuItem(
                        spec.label(self.context), id=f"command-{spec.name}", classes="command"
                    )

    def item(self, spec: CommandSpec) -> MenuItem:
        return self.query_one(f"#command-{spec.name}", MenuItem)

    def refresh_labels(self) -> None:
        for spec in self.commands:
            item = self.item(spec)
            item.label = spec.label(self.context)
            item.display = spec.available(self.context)


# --- data section ----------------------------------------------------------------


class DataSheet(EditorKeys, Widget, can_focus=True):
    """Names column, then value and percentile for x, y and z; 25 rows a page,
    fewer when the terminal is too short (paging still reaches every row).

    The screen hands it the figure and the rows a page may hold
    (`page_rows`, from the terminal's height, not from this widget's layout:
    the page size must not depend on when the layout ran)."""

    COMPONENT_CLASSES = {
        "datasheet--header",
        "datasheet--name",
        "datasheet--percentile",
        "datasheet--cursor",
        "datasheet--cursor-blur",
        "datasheet--page",
    }
    BINDINGS = [
        Binding("up", "move(-1, 0)", show=False),
        Binding("down", "move(1, 0)", show=False),
        Binding("left", "move(0, -1)", show=False),
        Binding("right", "move(0, 1)", show=False),
        Binding("home", "jump(0)", show=False),
        Binding("end", "jump(-1)", show=False),
        Binding("enter", "edit", "Edit", show=False),
    ]
    HEADER_LINES = 2
    PAGE_ROWS = 25  # the report's fixed page
    COLUMNS = 6  # value and percentile for x, y, z

    class EditRequested(Message):
        """Edit the cell at (row, column); `initial` = what was typed so far."""

        def __init__(self, row: int, column: int, initial: str = "") -> None:
            super().__init__()
            self.row = row
            self.column = column
            self.initial = initial

    page_rows: reactive[int] = reactive(PAGE_ROWS, init=False)

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.cursor_row = 0
        self.cursor_column = 0
        self._cursors: dict[str, tuple[int, int]] = {}
        self._group = ""
        self.figure: Figure | None = None

    def validate_page_rows(self, rows: int) -> int:
        return max(1, min(self.PAGE_ROWS, rows))

    def watch_page_rows(self) -> None:
        if self.row_count:
            self.cursor_row = min(self.cursor_row, self.row_count - 1)
        self.refresh()

    # --- paging ---------------------------------------------------------
    @property
    def page_size(self) -> int:
        return self.page_rows

    @property
    def row_count(self) -> int:
        if not self._group or self.figure is None:
            return 0
        return len(self.figure.groups[self._group].rows)

    @property
    def page(self) -> int:
        return self.cursor_row // self.page_size

    @property
    def pages(self) -> int:
        return max(1, -(-self.row_count // self.page_size))

    def show_group(self, figure: Figure, group: str) -> None:
        self.figure = figure
        if group == self._group:
            self.refresh()
            return
        if self._group:
            self._cursors[self._group] = (self.cursor_row, self.cursor_column)
        self._group = group
        self.cursor_row, self.cursor_column = self._cursors.get(group, (0, 0))
        self.refresh()

    def turn_page(self, pages: int) -> bool:
        """Keep the cursor's place on the page; False at the first/last page."""
        target = self.page + pages
        if not 0 <= target < self.pages:
            return False
        offset = self.cursor_row % self.page_size
        self.cursor_row = min(target * self.page_size + offset, self.row_count - 1)
        self.refresh()
        return True

    # --- layout ---------------------------------------------------------
    def column_widths(self) -> tuple[int, int, int]:
        """Name, value and percentile widths; a wide terminal widens them."""
        width = self.content_size.width
        name, value, percentile = 18, 9, 7
        spare = max(0, width - (name + 3 * (value + percentile)))
        name += min(spare, 6)
        spare -= min(spare, 6)
        value += min(spare // 6, 4)
        percentile += min(spare // 6, 3)
        return name, value, percentile

    def _column_start(self, column: int) -> tuple[int, int]:
        name, value, percentile = self.column_widths()
        start = name + (column // 2) * (value + percentile) + (value if column % 2 else 0)
        return start, value if column % 2 == 0 else percentile

    def render(self) -> Text:
        figure = self.figure
        if figure is None or not self._group:
            return Text()
        state = figure.groups[self._group]
        unit = DISPLAY[state.unit]
        name_w, value_w, pct_w = self.column_widths()
        header_style = self.get_component_rich_style("datasheet--header")
        name_style = self.get_component_rich_style("datasheet--name")
        pct_style = self.get_component_rich_style("datasheet--percentile")
        cursor_style = self.get_component_rich_style(
            "datasheet--cursor" if self.has_focus else "datasheet--cursor-blur"
        )
        page_style = self.get_component_rich_style("datasheet--page")

        top = Text(no_wrap=True, overflow="crop")
        top.append(f"{GROUP_TITLES[self._group]:<{name_w}}"[:name_w], header_style)
        for axis in AXES:
            top.append(f"{axis:^{value_w + pct_w}}", header_style)
        second = Text(no_wrap=True, overflow="crop")
        second.append(f"{f'page {self.page + 1}/{self.pages}':<{name_w}}", page_style)
        for _ in AXES:
            second.append(f"{unit:>{value_w - 1}} ", header_style)
            second.append(f"{'%':>{pct_w - 1}} ", header_style)
        lines = [top, second]

        if not state.loaded:
            lines.append(Text(f"No {figure.gender} data loaded for {GROUP_TITLES[self._group]}."))
            return Text("\n").join(lines)
        first = self.page * self.page_size
        canonical = GROUP_UNITS[self._group][0]
        for index in range(first, min(first + self.page_size, self.row_count)):
            line = Text(no_wrap=True, overflow="crop")
            line.append(f"{state.rows[index].label:<{name_w}}"[:name_w], name_style)
            for column in range(self.COLUMNS):
                # Cell by cell in plain floats: the first screen is drawn
                # before numpy is imported (issue 16).
                value, percentile = state.cell(index, column // 2)
                style: str | Style
                if column % 2 == 0:
                    shown = format_value(convert(value, canonical, state.unit), state.unit)
                    text = f"{shown:>{value_w - 1}} "
                    style = ""
                else:
                    text = f"{format_cell_percentile(value, percentile):>{pct_w - 1}} "
                    style = pct_style
                if index == self.cursor_row and column == self.cursor_column:
                    style = cursor_style
                line.append(text, style)
            lines.append(line)
        return Text("\n", no_wrap=True).join(lines)

    # --- input ----------------------------------------------------------
    def on_click(self, event: events.Click) -> None:
        offset = event.get_content_offset(self)
        if offset is None:
            return
        row = self.page * self.page_size + offset.y - self.HEADER_LINES
        if offset.y < self.HEADER_LINES or row >= min(
            self.row_count, (self.page + 1) * self.page_size
        ):
            return
        chosen = (self.cursor_row, self.cursor_column)
        was_focused = self.has_focus  # not while a prompt has the keys
        self.cursor_row = row
        for column in range(self.COLUMNS):
            start, width = self._column_start(column)
            if start <= offset.x < start + width:
                self.cursor_column = column
        self.focus()
        self.refresh()
        # A click chooses the cell; a second click on it (or a double click) edits it.
        if was_focused and (event.chain > 1 or chosen == (self.cursor_row, self.cursor_column)):
            self.action_edit()

    def on_mouse_scroll_down(self, event: events.MouseScrollDown) -> None:
        event.stop()
        self.turn_page(1)

    def on_mouse_scroll_up(self, event: events.MouseScrollUp) -> None:
        event.stop()
        self.turn_page(-1)

    def action_move(self, rows: int, columns: int) -> None:
        self.cursor_row = min(max(self.cursor_row + rows, 0), self.row_count - 1)
        self.cursor_column = min(max(self.cursor_column + columns, 0), self.COLUMNS - 1)
        self.refresh()

    def action_jump(self, row: int) -> None:
        if self.row_count:
            self.cursor_row = row % self.row_count
            self.refresh()

    def action_edit(self) -> None:
        self.request_edit(self.EditRequested(self.cursor_row, self.cursor_column))

    def start_typing(self, text: str) -> None:
        self.request_edit(self.EditRequested(self.cursor_row, self.cursor_column, text))

    def on_resize(self) -> None:
        self.refresh()

    def on_focus(self) -> None:
        self.refresh()


# --- command/message line ------------------------------------------------------------


class AnswerInput(Input):
    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]

    class Cancelled(Message):
        pass

    def action_cancel(self) -> None:
        self.post_message(self.Cancelled())

    def submit(self) -> None:
        """Enter, from code that cannot await: what Input.action_submit (a
        coroutine) does for an input without validators."""
        self.post_message(self.Submitted(self, self.value))


Handler = Callable[[str], None]
HISTORY_LENGTH = 200
# What a user may cause in an answer: shown on the message line, never a
# traceback; anything else is a bug and shows as one.
USER_ERRORS = (SassError, OSError)


class MessageLine(Horizontal):
    """The report's command/message window: says things, and asks.

    It owns its prompt: the answer being typed, the handler the answer goes
    to, the handler of a cancel (Escape), and the widget to give the focus
    back to.  A handler may ask again (a follow-up question).  A handler's
    SassError or OSError is shown as an error; after each answer or cancel
    the line posts `Answered` so the screen can redraw."""

    class Answered(Message):
        pass

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self._on_answer: Handler | None = None
        self._on_cancel: Callable[[], None] | None = None
        self._focus_after: Widget | None = None
        # What was said, oldest first: one line is cut at the terminal's width,
        # the message log (`l`) shows it whole.
        self.history: list[tuple[str, str]] = []

    def compose(self):
        yield Label("", id="message")
        yield AnswerInput(id="answer", compact=True, select_on_focus=False)

    def on_mount(self) -> None:
        self.answer.display = False

    @property
    def answer(self) -> AnswerInput:
        return self.query_one("#answer", AnswerInput)

    def show(self, text: str, kind: str = "info") -> None:
        # Messages quote names and titles from files: no escape sequence in
        # them may reach the terminal (issue 17).
        text = printable_lines(text)
        if kind != "prompt" and (not self.history or self.history[-1] != (kind, text)):
            self.history.append((kind, text))
            del self.history[:-HISTORY_LENGTH]
        label = self.query_one("#message", Label)
        label.update(Text(text))
        for name in ("info", "error", "warning", "prompt"):
            label.set_class(name == kind, f"-{name}")

    def say(self, text: str) -> None:
        self.show(text, "info")

    def complain(self, text: str) -> None:
        self.show(text, "error")

    @property
    def prompting(self) -> bool:
        return bool(self.answer.display)

    def ask(
        self,
        prompt: str,
        on_answer: Handler,
        initial: str = "",
        on_cancel: Callable[[], None] | None = None,
        kind: str = "prompt",
    ) -> None:
        focused = self.screen.focused
        if focused is not None and focused is not self.answer:
            self._focus_after = focused
        self._on_answer, self._on_cancel = on_answer, on_cancel
        self.show(prompt + " ", kind)
        answer = self.answer
        answer.value = initial
        answer.display = True
        # Now, not on the next idle: the keys that follow belong to the answer.
        self.screen.set_focus(answer)
        answer.cursor_position = len(initial)

    def keep_focus(self) -> None:
        """While asking, the answer keeps the focus (a click elsewhere does not
        take the keys away from the prompt)."""
        if self.prompting and self.screen.focused is not self.answer:
            self.screen.set_focus(self.answer)

    def type_ahead(self, key: str, character: str | None, text: str = "") -> None:
        """A key that reached another widget before the answer had the focus."""
        if not self.prompting:
            return
        answer = self.answer
        if text:
            answer.insert_text_at_cursor(text)
        elif key == "enter":
            answer.submit()
        elif key == "escape":
            answer.action_cancel()
        elif key == "backspace":
            answer.action_delete_left()
        elif character and character.isprintable():
            answer.insert_text_at_cursor(character)

    def _close(self) -> tuple[Handler | None, Callable[[], None] | None]:
        handlers = self._on_answer, self._on_cancel
        self._on_answer = self._on_cancel = None
        answer = self.answer
        answer.value = ""
        answer.display = False
        focus, self._focus_after = self._focus_after, None
        if focus is not None and focus.is_attached and focus.display:
            # Synchronously, so that a follow-up question keeps the focus.
            self.screen.set_focus(focus)
        return handlers

    def _run(self, handler: Callable[[], None]) -> None:
        try:
            handler()
        except USER_ERRORS as exc:
            self.complain(str(exc))

    def on_input_submitted(self, event: Input.Submitted) -> None:
        event.stop()
        on_answer, _ = self._close()
        if on_answer is not None:
            self._run(lambda: on_answer(event.value))
        self.post_message(self.Answered())

    def on_answer_input_cancelled(self, event: AnswerInput.Cancelled) -> None:
        event.stop()
        _, on_cancel = self._close()
        if on_cancel is not None:
            self._run(on_cancel)
        else:
            self.say("Cancelled; nothing changed.")
        self.post_message(self.Answered())
