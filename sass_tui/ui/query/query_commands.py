"""The query screen's command menu (report figure 11): its slots, and the
labels that read "void" where a command does not apply."""

from __future__ import annotations

from sass_tui.db.query.lists import QUERY_LIST
from sass_tui.ui.spreadsheet.commands import CommandSpec
from sass_tui.ui.widgets import CommandMenu


def _on_query_list(screen) -> bool:
    return screen.which == QUERY_LIST


def _void_unless_query_list(label: str):
    return lambda screen: label if _on_query_list(screen) else "void"


# Figure 11: the first label is the one shown with the query list.  The list
# button names the list it will display.
QUERY_COMMANDS: tuple[CommandSpec, ...] = (
    CommandSpec(
        "q_next_page", "n", "next_page", "Next", lambda screen: "Next Page", row=0, in_footer=False
    ),
    CommandSpec(
        "q_previous_page",
        "p",
        "previous_page",
        "Prev",
        lambda screen: "Previous Page",
        row=1,
        in_footer=False,
    ),
    CommandSpec("query_db", "d", "query_db", "Query", lambda screen: "Query DB", row=2),
    CommandSpec(
        "select_all",
        "a",
        "select_all",
        "All",
        _void_unless_query_list("Select All"),
        row=3,
        available=_on_query_list,
    ),
    CommandSpec(
        "select_one",
        "s",
        "select_one",
        "One",
        _void_unless_query_list("Select One"),
        row=4,
        available=_on_query_list,
    ),
    CommandSpec(
        "delete_one",
        "x",
        "delete_one",
        "Delete",
        lambda screen: "Delete One",
        row=5,
        in_footer=False,
    ),
    CommandSpec(
        "display_list",
        "l",
        "display_list",
        "List",
        lambda screen: "Disp. Selected List" if _on_query_list(screen) else "Disp. Query List",
        column=1,
        row=0,
    ),
    CommandSpec(
        "input_db",
        "i",
        "input_db",
        "Input DB",
        lambda screen: "Input DB",
        column=1,
        row=1,
        in_footer=False,
    ),
    CommandSpec(
        "exit_query",
        "e",
        "exit_query",
        "Exit",
        _void_unless_query_list("Exit Query"),
        column=1,
        row=5,
        available=_on_query_list,
    ),
)


class QueryCommandMenu(CommandMenu):
    """Figure 11 keeps its slots: a command that does not apply reads "void"."""

    def refresh_labels(self) -> None:
        for spec in self.commands:
            item = self.item(spec)
            item.label = spec.label(self.context)
            item.disabled = not spec.available(self.context)
