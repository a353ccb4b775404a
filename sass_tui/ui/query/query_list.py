"""What the query screen shows (report figure 10): the summary of the query
and the lists, and one page of the query or selected list."""

from __future__ import annotations

import math

from rich.text import Text
from textual import events
from textual.binding import Binding
from textual.message import Message
from textual.reactive import reactive
from textual.widget import Widget
from textual.widgets import Static

from sass_tui.db.query.lists import QUERY_LIST, SELECTED_LIST
from sass_tui.db.query.query import field_column
from sass_tui.model.text import printable

LIST_TITLES = {QUERY_LIST: "Query List", SELECTED_LIST: "Selected List"}


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
    return printable(value)  # names and sources come from files


def query_field_columns(rows: list[dict]) -> list[tuple[str, str]]:
    """(title, key) of each field a page's rows carry beyond the list's own
    columns: the fields the last query compared (dotted names), titled by
    their name without the group and their stored unit (`poplitealheight
    mm`, `neck.x cm`)."""
    if not rows:
        return []
    columns = []
    for key in rows[0]:
        if "." in key:
            unit = field_column(key)[2]
            name = key.partition(".")[2]
            shown = unit.replace("N_m", "N·m") if unit else ""
            columns.append((f"{name} {shown}".rstrip(), key))
    return columns


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
        # The sort shown in the header (a column key, largest first); None: none.
        self.sort: tuple[str, bool] | None = None

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
        # The name and source columns are as wide as the longest on the page:
        # a name ("ANSUR II F 11533") or a source ("virtual:nhanes-2017-2020")
        # is shown whole, never cut.
        longest = {
            key: max((len(_cell(row, key)) for row in self.rows), default=0)
            for key in ("name", "source")
        }
        columns = [
            (title, key, max(width, longest[key] + 1) if key in longest else width, align)
            for title, key, width, align in LIST_COLUMNS
        ]
        # The fields the query compared (measure.poplitealheight), after the source.
        columns[2:2] = [
            (title, key, len(title) + 1, ">") for title, key in query_field_columns(self.rows)
        ]
        top = Text(no_wrap=True, overflow="crop")
        for title, key, width, align in columns:
            if self.sort is not None and self.sort[0] == key:
                # The column's first word and the way: "Stature ▼" fits its width.
                title = f"{title.split()[0]} {'▼' if self.sort[1] else '▲'}"
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
