"""The standard (global) data of the spreadsheet (report §12.2.2): the
eleven labels, chosen with the mouse or the arrows, edited on the message
line."""

from __future__ import annotations

import math
from dataclasses import dataclass

from rich.text import Text
from textual.message import Message
from textual.widget import Widget

from sass_tui.model.body.figure import Figure
from sass_tui.model.names import GIRTH, STRENGTH
from sass_tui.model.text import printable
from sass_tui.model.vocabulary import FIGURE_TYPES, GENDERS, HANDEDNESS, STRENGTH_TYPES
from sass_tui.ui.widgets.editor import CURSOR_BINDINGS, EDIT_BINDING, EditorKeys
from sass_tui.ui.widgets.formats import (
    format_percentile,
)


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
# The cells whose value is a word, and its words: the first letter of one,
# typed on the cell, starts its value (any other letter is a command).
WORD_FIELDS: dict[str, tuple[str, ...]] = {
    "figure_type": FIGURE_TYPES,
    "gender": GENDERS,
    "strength_type": STRENGTH_TYPES,
    "handedness": HANDEDNESS,
}
# Column widths: left label, value, percentile, gap, right label, right value.
_LABEL_A, _SLOT0, _SLOT1, _GAP = 12, 9, 8, 1
_LABEL_B, _SHORT_LABEL_B = 15, 10
# Below this width the right column's labels are shortened ("Str. type"), so
# that the panel and figure 6's two command columns fit in 80 columns.
_NARROW = _LABEL_A + _SLOT0 + _SLOT1 + _GAP + _LABEL_B + 11


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
    BINDINGS = [*CURSOR_BINDINGS, EDIT_BINDING]

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
                # A terminal narrower than the panel leaves a cell no room.
                width = max(0, span - 1)
                line.append(f"{text:<{width}}"[:width], cell_style)
                line.append(" ")
                column = start + span
            lines.append(line)
        return Text("\n", no_wrap=True).join(lines)

    def cell_at(self, x: int, y: int) -> GlobalCell | None:
        """The cell whose label or value is at (x, y)."""
        for cell in GLOBAL_CELLS:
            start, span = self._slot_span(cell.slot)
            if cell.field == "population":
                span = self.size.width - start
            label_start = (
                0 if cell.slot == 0 else start - self._label_b() if cell.slot == 2 else start
            )
            if cell.row == y and label_start <= x < start + span:
                return cell
        return None

    def chosen(self) -> GlobalCell:
        return self.cursor

    def choose(self, cell: object) -> None:
        assert isinstance(cell, GlobalCell)
        self.cursor = cell

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

    def starts_value(self, character: str) -> bool:
        """On a word cell (figure type, gender, strength type, handedness) the
        first letter of one of its words starts the value: `female` typed on
        Gender is its value, not f's command."""
        words = WORD_FIELDS.get(self.chosen().field, ())
        starts = {word[0] for word in words} | {word[0].upper() for word in words}
        return character in starts or super().starts_value(character)

    def edit_request(self, initial: str) -> Message:
        return self.EditRequested(self.cursor.field, initial)
