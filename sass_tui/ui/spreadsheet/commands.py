"""The command menu of the anthropometric spreadsheet (report figure 6).

Each command is a spec: the menu builds its buttons and the screen its key
bindings from COMMANDS, so a later command is one more entry here plus its
`action_` method on the screen.  `label` and `available` are given the screen
(the spreadsheet: its `data_group` and `session`).
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
    available: Callable[[object], bool] = lambda screen: True
    # The footer holds what fits 80 columns (docs/user-guide.md, "The footer");
    # the menu shows every command, and the palette and F1 list them all.
    in_footer: bool = True


def _conversion_label(screen) -> str:
    group = screen.data_group
    if group == STRENGTH:
        # The strength unit is the strength page's, not a Figure group's.
        sheet = screen.session.strength_sheet
        unit = sheet.unit if sheet is not None else GROUP_UNITS[STRENGTH][0]
    else:
        unit = screen.session.figure.groups[group].unit
    return f"{DISPLAY[unit]} → {DISPLAY[other_unit(group, unit)]}"


def _side_label(screen) -> str:
    sheet = screen.session.strength_sheets.made()  # on the first screen: none yet
    side = sheet.side if sheet is not None else "right"
    other = "left" if side == "right" else "right"
    return f"{side.capitalize()} → {other.capitalize()}"


def _showing_person(screen) -> bool:
    return screen.session.person is not None


def _showing_population(screen) -> bool:
    return not _showing_person(screen)


def _showing_prediction(screen) -> bool:
    prediction = getattr(screen, "prediction", None)
    return prediction is not None and screen.session.person is prediction[1]


def _on_strength_page(screen) -> bool:
    return screen.data_group == STRENGTH and screen.session.strength_sheet is not None


COMMANDS: tuple[CommandSpec, ...] = (
    CommandSpec("next_page", "n", "next_page", "Next", lambda screen: "Next Page", row=0),
    CommandSpec(
        "previous_page", "p", "previous_page", "Prev", lambda screen: "Previous Page", row=1
    ),
    CommandSpec(
        "convert_units", "c", "convert_units", "Units", _conversion_label, row=2, in_footer=False
    ),
    CommandSpec(
        "input_data",
        "i",
        "input_data",
        "Input",
        lambda screen: "Input Data",
        row=3,
        in_footer=False,
    ),
    CommandSpec(
        "create_figure", "f", "create_figure", "Figure", lambda screen: "Create Figure", row=4
    ),
    CommandSpec("quit", "q", "quit", "Quit", lambda screen: "Quit", row=5),
    # Figure 6's second column shares slots: "Query or Disp. Pop.", "Disp. Indv. or
    # Disp. More" -- the second of each pair while a person is displayed (§12.2.4).
    CommandSpec(
        "query",
        "d",
        "query",
        "Query",
        lambda screen: "Query",
        column=1,
        row=0,
        available=_showing_population,
    ),
    CommandSpec(
        "display_population",
        "o",
        "display_population",
        "Pop.",
        lambda screen: "Disp. Pop.",
        column=1,
        row=0,
        available=_showing_person,
    ),
    CommandSpec(
        "display_individual",
        "v",
        "display_individual",
        "Disp. Indv.",
        lambda screen: "Disp. Indv.",
        column=1,
        row=1,
        available=_showing_population,
        in_footer=False,
    ),
    CommandSpec(
        "display_more",
        "x",
        "display_more",
        "Disp. More",
        lambda screen: "Disp. More",
        column=1,
        row=1,
        available=_showing_person,
        in_footer=False,
    ),
    # One of figure 6's void slots.
    CommandSpec(
        "export_hanim",
        "e",
        "export_hanim",
        "HAnim",
        lambda screen: "Export HAnim",
        column=1,
        row=2,
        in_footer=False,
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
    # Predict a figure from known values; the interval of a predicted cell.
    CommandSpec(
        "predict",
        "k",
        "predict",
        "Predict",
        lambda screen: "Predict",
        column=1,
        row=3,
        in_footer=False,
    ),
    CommandSpec(
        "interval",
        "a",
        "interval",
        "Interval",
        lambda screen: "Interval",
        column=1,
        row=4,
        available=_showing_prediction,
        in_footer=False,
    ),
    # A manikin family, on a screen of its own; its slot is Interval's
    # while a person or a prediction is shown.
    CommandSpec(
        "family",
        "y",
        "family",
        "Family",
        lambda screen: "Family",
        column=1,
        row=4,
        available=_showing_population,
        in_footer=False,
    ),
)
