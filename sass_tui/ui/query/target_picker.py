"""The target picker: a pop-up menu (`.pop-up-menu`, as the More Menu) of the
target populations stored in the database (`sass target`), for the query
screen and the Fit Test screen.  Its first choice is no target (the people
unweighted).  Dismissed with the chosen name, "" for no target, None when
cancelled."""

from __future__ import annotations

from typing import TYPE_CHECKING

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import OptionList
from textual.widgets.option_list import Option

from sass_tui.db.query.lists import DB_ERRORS, QueryLists
from sass_tui.db.query.lists import target_names as stored_target_names
from sass_tui.db.query.scope import VIRTUAL_PREFIX
from sass_tui.ui.pop_up import PopUpScreen

if TYPE_CHECKING:  # for the annotation only
    from sass_tui.ui.base import SassScreen

NO_TARGET = "No target (unweighted)"


def target_names(lists: QueryLists) -> list[str]:
    """The stored targets' names (a short read)."""
    return lists.read(stored_target_names)


def weighted_words(name: str | None) -> str:
    """What a screen shows of its target: nothing, or that its answers are
    weighted (a virtual population's people said to be VIRTUAL)."""
    if name and name.startswith(VIRTUAL_PREFIX):
        return f", VIRTUAL people of {name.removeprefix(VIRTUAL_PREFIX)}, weighted"
    return f", weighted to target {name}" if name else ""


def _shown(name: str) -> str:
    """A target's name in the menu; a virtual population's labelled."""
    return f"{name} (VIRTUAL people)" if name.startswith(VIRTUAL_PREFIX) else name


class TargetPicker(PopUpScreen[str | None]):
    DEFAULT_CSS = """
    TargetPicker { align: center middle; background: transparent; }
    TargetPicker > #target-popup { width: 40; max-height: 80%; }
    """
    BINDINGS = [Binding("escape", "dismiss(None)", "Cancel")]

    def __init__(self, names: list[str], current: str | None) -> None:
        super().__init__()
        self.names = names
        self.current = current

    def compose(self) -> ComposeResult:
        with Vertical(id="target-popup", classes="pop-up-menu") as popup:
            popup.border_title = "Target population"
            menu = OptionList(
                Option(NO_TARGET, id="target-none"),
                *(Option(_shown(name), id=f"target-{i}") for i, name in enumerate(self.names)),
                id="target-menu",
            )
            if self.current in self.names:
                menu.highlighted = self.names.index(self.current) + 1
            yield menu

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        event.stop()
        if self.app.screen is self:  # not again for an Enter typed twice at once
            index = event.option_index
            self.dismiss("" if index == 0 else self.names[index - 1])


async def pick_target(screen: SassScreen, lists: QueryLists, current: str | None) -> str | None:
    """The picker over `screen`, in its `converse`: the name taken, "" for no
    target; None when none was (said on the message line)."""
    try:
        names = target_names(lists)
    except DB_ERRORS as exc:
        screen.complain(f"Cannot read the targets: {exc}")
        return None
    if not names:
        screen.say(
            "No target populations in the database: make one with "
            "`sass target NAME --gender G --sample FILE.csv`."
        )
        return None
    name = await screen.choose(TargetPicker(names, current))
    if name is None:
        screen.say("Target unchanged.")
    return name


def weighted_count_words(lists: QueryLists, query: str, name: str) -> str:
    """The query's weighted share of a target (in a worker)."""
    counted = lists.weighted_count(query, name)
    return (
        f" Weighted to target {name}: {counted.weighted:,.1f} of {counted.total:,.0f} "
        f"({counted.percent:.1f} %)."
    )
