"""The data section for strength (report §12.2.3 last paragraphs, figure 5).

Motion impetus (read-only, the limb side under its header), the joint angles
of the configuration (editable), and the strength there, stored or predicted.
The numbers come from the StrengthSheet its screen hands it; edits are asked
for with DataSheet.EditRequested and go through the screen to the Session.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, cast

from rich.text import Text
from textual.message import Message

from sass_tui.model.vocabulary import JOINT_AXES
from sass_tui.ui.widgets import DataSheet

if TYPE_CHECKING:  # numpy-heavy: the page is hidden on the first screen
    from sass_tui.model.strength.strength import StrengthSheet
    from sass_tui.ui.app import SassApp

ANGLE_WIDTH = 6
VALUE_WIDTH = 8
NAME_WIDTH = 26  # "Shoulder lateral rotation" and a space
# Below this the source column shows one letter instead of the word.
SOURCE_WORD_WIDTH = 11
SOURCE_LETTER = {"stored": "s", "predicted": "p", "no data": ""}
JOINT_SPANS = (("Shoulder", 3), ("Elbow", 1), ("Wrist", 3))
# The Task panel under the page (ui/spreadsheet/task_panel.py, T): its border 1, the
# posture and inputs 2, the table's header 1, 12 hands and joints; its notes
# (balance and not covered, limiting, the manual-handling line of
# ui/spreadsheet/task_handling.py), each wrapped on up to 2 lines at 80 columns, 6.
# Fixed: the page's rows follow from the terminal's height (a shorter panel
# scrolls its table and keeps its notes whole).
TASK_PANEL_LINES = 22


def format_angle(degrees: float, width: int = ANGLE_WIDTH - 1) -> str:
    """Whole degrees without decimals, as figure 5; one decimal when it fits."""
    if math.isnan(degrees):
        return ""
    if abs(degrees - round(degrees)) < 0.05:
        return f"{degrees:.0f}"
    text = f"{degrees:.1f}"
    return text if len(text) <= width else f"{degrees:.0f}"


def format_strength(value: float) -> str:
    return "" if math.isnan(value) else f"{value:.2f}"


class StrengthPage(DataSheet):
    """14 motions a page; the cursor moves over the seven angle columns only
    (the names and the strength are read-only: a strength follows its angles).

    A DataSheet for its keys, paging and look; its own rows and columns."""

    COMPONENT_CLASSES = DataSheet.COMPONENT_CLASSES | {"strengthpage--outside"}
    PAGE_ROWS = 14  # report §12.2.4: fixed to 14 lines for strength
    COLUMNS = len(JOINT_AXES)

    class RowChosen(Message):
        """The cursor went to another row (a motion): the Task panel's posture follows."""

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.sheet: StrengthSheet | None = None
        self.missing: str | None = None

    def row_angles(self) -> tuple[str, list[float]] | None:
        """The side shown and the angles of the row under the cursor."""
        if self.sheet is None or not self.row_count:
            return None
        return self.sheet.side, [float(a) for a in self.sheet.angles[self.cursor_row]]

    def _moved_from(self, row: int) -> None:
        if row != self.cursor_row:
            self.post_message(self.RowChosen())

    def action_move(self, rows: int, columns: int) -> None:
        row = self.cursor_row
        super().action_move(rows, columns)
        self._moved_from(row)

    def action_jump(self, row: int) -> None:
        before = self.cursor_row
        super().action_jump(row)
        self._moved_from(before)

    def turn_page(self, pages: int) -> bool:
        row = self.cursor_row
        turned = super().turn_page(pages)
        self._moved_from(row)
        return turned

    def choose(self, cell: object) -> None:
        row = self.cursor_row
        super().choose(cell)
        self._moved_from(row)

    def show_sheet(self, sheet: StrengthSheet | None, missing: str | None = None) -> None:
        """`missing`: why there is no sheet (a person without strength experiments)."""
        self.sheet, self.missing = sheet, missing
        # What the numbers are, on the page's top line: TEST DATA says so there.
        self.border_title = sheet.title if sheet is not None else None
        self.refresh()

    @property
    def row_count(self) -> int:
        return len(self.sheet.angles) if self.sheet is not None else 0

    def column_widths(self) -> tuple[int, int, int]:
        """Name, angle and source widths."""
        width = self.content_size.width
        name = max(12, min(NAME_WIDTH, width - self.COLUMNS * ANGLE_WIDTH - VALUE_WIDTH - 2))
        return name, ANGLE_WIDTH, max(0, width - name - self.COLUMNS * ANGLE_WIDTH - VALUE_WIDTH)

    def _column_start(self, column: int) -> tuple[int, int]:
        name, angle, _ = self.column_widths()
        return name + column * angle, angle

    def render(self) -> Text:
        sheet = self.sheet
        name_w, angle_w, source_w = self.column_widths()
        style = self.get_component_rich_style
        header_style = style("datasheet--header")
        cursor_style = style("datasheet--cursor" if self.has_focus else "datasheet--cursor-blur")

        top = Text(no_wrap=True, overflow="crop")
        top.append(f"{'Motion impetus':<{name_w}}"[:name_w], header_style)
        for joint, span in JOINT_SPANS:
            top.append(f"{joint:^{span * angle_w}}", header_style)
        top.append(f"{'Strength':>{VALUE_WIDTH - 1}}", header_style)
        second = Text(no_wrap=True, overflow="crop")
        if sheet is None:
            return Text("\n").join([top, Text(self.missing or "Strength data is not loaded.")])
        # The strength model (numpy) is the app's once a sheet is shown (ui/spreadsheet/figure_work.py).
        work = cast("SassApp", self.app).figure_work
        rows, problem = work.strength_rows(sheet)  # e.g. no data for this gender in the file
        # Figure 5: the side label sits under "motion impetus".
        second.append(f"{sheet.side:<8}", header_style)
        second.append(
            f"{f'page {self.page + 1}/{self.pages}':<{name_w - 8}}"[: name_w - 8],
            style("datasheet--page"),
        )
        for axis in JOINT_AXES:
            second.append(f"{axis[-1]:>{angle_w - 1}} ", header_style)
        second.append(f"{rows[0].unit if rows else '':>{VALUE_WIDTH - 1}} ", header_style)
        if source_w >= SOURCE_WORD_WIDTH:
            second.append("source", header_style)
        lines = [top, second]
        if not rows:
            lines.append(Text(f"{problem}."))
            return Text("\n").join(lines)
        limits = work.joint_limits(sheet)
        outside_style = style("strengthpage--outside")
        first = self.page * self.page_size
        for row in rows[first : first + self.page_size]:
            line = Text(no_wrap=True, overflow="crop")
            line.append(f"{row.label:<{name_w}}"[:name_w], style("datasheet--name"))
            for column, degrees in enumerate(row.angles):
                lower, upper = limits[column]
                outside = degrees > upper or degrees < lower
                cell_style = outside_style if outside else ""
                if row.index == self.cursor_row and column == self.cursor_column:
                    cell_style = cursor_style
                line.append(f"{format_angle(degrees):>{angle_w - 1}} ", cell_style)
            line.append(f"{format_strength(row.value):>{VALUE_WIDTH - 1}} ")
            source = row.source if source_w >= SOURCE_WORD_WIDTH else SOURCE_LETTER[row.source]
            line.append(source[:source_w], style("datasheet--percentile"))
            lines.append(line)
        return Text("\n", no_wrap=True).join(lines)
