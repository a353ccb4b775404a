"""The command menu of the anthropometric spreadsheet (report figure 6).

Each command is a spec: the menu builds its buttons and the app its key
bindings from COMMANDS, so a later command (Query, Disp. Indv., Disp. More,
Right->Left) is one more entry here plus its `action_` method on the app.
Figure 6 has two columns; `column` and `row` place a command in them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from sass_tui.model.names import STRENGTH
from sass_tui.model.units import DISPLAY, GROUP_UNITS, other_unit


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
    if group == STRENGTH:
        # The strength unit is the strength page's, not a Figure group's.
        sheet = app.strength_sheet
        unit = sheet.unit if sheet is not None else GROUP_UNITS[STRENGTH][0]
    else:
        unit = app.figure.groups[group].unit
    return f"{DISPLAY[unit]} → {DISPLAY[other_unit(group, unit)]}"


def _side_label(app) -> str:
    side = app.strength_sheet.side if app.strength_sheet is not None else "right"
    other = "left" if side == "right" else "right"
    return f"{side.capitalize()} → {other.capitalize()}"


def _showing_person(app) -> bool:
    return getattr(app, "population_figure", None) is not None


def _showing_population(app) -> bool:
    return not _showing_person(app)


def _on_strength_page(app) -> bool:
    return app.data_group == STRENGTH and app.strength_sheet is not None


COMMANDS: tuple[CommandSpec, ...] = (
    CommandSpec("next_page", "n", "next_page", "Next", lambda app: "Next Page", row=0),
    CommandSpec("previous_page", "p", "previous_page", "Prev", lambda app: "Previous Page", row=1),
    CommandSpec("convert_units", "c", "convert_units", "Units", _conversion_label, row=2),
    CommandSpec("input_data", "i", "input_data", "Input", lambda app: "Input Data", row=3),
    CommandSpec(
        "create_figure", "f", "create_figure", "Figure", lambda app: "Create Figure", row=4
    ),
    CommandSpec("quit", "q", "quit", "Quit", lambda app: "Quit", row=5),
    # Figure 6's second column shares slots: "Query or Disp. Pop.", "Disp. Indv. or
    # Disp. More" -- the second of each pair while a person is displayed (§12.2.4).
    CommandSpec(
        "query",
        "d",
        "query",
        "Query",
        lambda app: "Query",
        column=1,
        row=0,
        available=_showing_population,
    ),
    CommandSpec(
        "display_population",
        "o",
        "display_population",
        "Disp. Pop.",
        lambda app: "Disp. Pop.",
        column=1,
        row=0,
        available=_showing_person,
    ),
    CommandSpec(
        "display_individual",
        "v",
        "display_individual",
        "Disp. Indv.",
        lambda app: "Disp. Indv.",
        column=1,
        row=1,
        available=_showing_population,
    ),
    CommandSpec(
        "display_more",
        "x",
        "display_more",
        "Disp. More",
        lambda app: "Disp. More",
        column=1,
        row=1,
        available=_showing_person,
    ),
    # One of figure 6's void slots.
    CommandSpec(
        "export_hanim", "e", "export_hanim", "HAnim", lambda app: "Export HAnim", column=1, row=2
    ),
    CommandSpec(
        "switch_side",
        "r",
        "switch_side",
        "Side",
        _side_label,
        column=1,
        row=5,
        available=_on_strength_page,
    ),
)
