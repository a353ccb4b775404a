"""The sections of the anthropometric spreadsheet (report figure 4).

Data down, messages up: a widget shows what its screen hands it (a figure, a
group, a page size) and posts a Message for what the user did; it never
reaches into the app.  Every change to the data goes through the screen to
the Session.

The package's modules: `formats` (values, percentiles), `editor` (keys of a
widget edited on the message line), `groups` (the group bar),
`global_panel`, `command_menu`, `data_sheet`, `message_line`.  What screens
and tests use is imported from here.
"""

from sass_tui.ui.widgets.command_menu import CommandMenu, MenuItem
from sass_tui.ui.widgets.data_sheet import DataSheet
from sass_tui.ui.widgets.editor import NUMBER_START, EditorKeys, ScreenKey, TypedAhead
from sass_tui.ui.widgets.formats import (
    DECIMALS,
    NO_PERCENTILE,
    format_cell_percentile,
    format_percentile,
    format_value,
    printable_lines,
)
from sass_tui.ui.widgets.global_panel import GLOBAL_CELLS, GlobalCell, GlobalPanel, global_text
from sass_tui.ui.widgets.groups import GroupBar, GroupTab
from sass_tui.ui.widgets.message_line import USER_ERRORS, AnswerInput, MessageLine

__all__ = [
    "DECIMALS",
    "GLOBAL_CELLS",
    "NO_PERCENTILE",
    "NUMBER_START",
    "USER_ERRORS",
    "AnswerInput",
    "CommandMenu",
    "DataSheet",
    "EditorKeys",
    "GlobalCell",
    "GlobalPanel",
    "GroupBar",
    "GroupTab",
    "MenuItem",
    "MessageLine",
    "ScreenKey",
    "TypedAhead",
    "format_cell_percentile",
    "format_percentile",
    "format_value",
    "global_text",
    "printable_lines",
]
