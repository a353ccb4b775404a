"""The command menu of the anthropometric spreadsheet (report figure 6).

Each command is a spec: the menu builds its buttons and the app its key
bindings from COMMANDS, so a later command (Query, Disp. Indv., Disp. More,
Right->Left) is one more entry here plus its `action_` method on the app.
Figure 6 has two columns; `column` and `row` place a command in them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from sass_tui.model.units import DISPLAY, other_unit


@dataclass(frozen=True)
class CommandSpec:
    name: str
    key: str
    action: str
    footer: str
    label: Callable[[object], str]
    column: int = 0
    row: int = 0
    available: Callable[[object], bool] = lambda app: True


def _conversion_label(app) -> str:
    group = app.data_group
    unit = app.figure.groups[group].unit
    return f"{DISPLAY[unit]} → {DISPLAY[other_unit(group, unit)]}"


COMMANDS: tuple[CommandSpec, ...] = (
    CommandSpec("next_page", "n", "next_page", "Next", lambda app: "Next Page", row=0),
    CommandSpec("previous_page", "p", "previous_page", "Prev", lambda app: "Previous Page", row=1),
    CommandSpec("convert_units", "c", "convert_units", "Units", _conversion_label, row=2),
    CommandSpec("input_data", "i", "input_data", "Input", lambda app: "Input Data", row=3),
    CommandSpec("create_figure", "f", "create_figure", "Figure", lambda app: "Create Figure", row=4),
    CommandSpec("quit", "q", "quit", "Quit", lambda app: "Quit", row=5),
)
