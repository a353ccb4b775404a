"""The data section of the spreadsheet (report figure 4): a group's rows,
value and percentile for x, y and z, a page at a time."""

from __future__ import annotations

import math

from rich.style import Style
from rich.text import Text
from textual import events
from textual.binding import Binding
from textual.message import Message
from textual.reactive import reactive
from textual.widget import Widget

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import AXES, GROUP_TITLES
from sass_tui.model.population.percentile import has_spread
from sass_tui.model.units import DISPLAY, GROUP_UNITS, convert
from sass_tui.ui.widgets.editor import CURSOR_BINDINGS, EDIT_BINDING, EditorKeys
from sass_tui.ui.widgets.formats import (
    format_cell_percentile,
    format_value,
)


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
        *CURSOR_BINDINGS,
        Binding("home", "jump(0)", show=False),
        Binding("end", "jump(-1)", show=False),
        EDIT_BINDING,
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
                # before numpy is imported.
                value, percentile = state.cell(index, column // 2)
                style: str | Style
                if column % 2 == 0:
                    shown = format_value(convert(value, canonical, state.unit), state.unit)
                    text = f"{shown:>{value_w - 1}} "
                    style = ""
                else:
                    if not has_spread(*state.cell_stats(figure.gender, index, column // 2)):
                        percentile = math.nan  # no spread: every percentile is this value
                    text = f"{format_cell_percentile(value, percentile):>{pct_w - 1}} "
                    style = pct_style
                if index == self.cursor_row and column == self.cursor_column:
                    style = cursor_style
                line.append(text, style)
            lines.append(line)
        return Text("\n", no_wrap=True).join(lines)

    # --- input ----------------------------------------------------------
    def cell_at(self, x: int, y: int) -> tuple[int, int] | None:
        """(row, column); a click beside the columns keeps the cursor's column."""
        row = self.page * self.page_size + y - self.HEADER_LINES
        if y < self.HEADER_LINES or row >= min(self.row_count, (self.page + 1) * self.page_size):
            return None
        column = self.cursor_column
        for candidate in range(self.COLUMNS):
            start, width = self._column_start(candidate)
            if start <= x < start + width:
                column = candidate
        return row, column

    def chosen(self) -> tuple[int, int]:
        return self.cursor_row, self.cursor_column

    def choose(self, cell: object) -> None:
        assert isinstance(cell, tuple)
        self.cursor_row, self.cursor_column = cell

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

    def edit_request(self, initial: str) -> Message:
        return self.EditRequested(self.cursor_row, self.cursor_column, initial)

    def on_resize(self) -> None:
        self.refresh()
