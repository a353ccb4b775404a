"""The query builder's pop-up (report figure 13): its menus (`Menu`, `Item`)
and the widget that shows one at a time, with a filter above a long one
(the 93 measurements) that lists first the items a typed word begins."""

from __future__ import annotations

import re
from dataclasses import dataclass

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.message import Message
from textual.widgets import Input, OptionList
from textual.widgets.option_list import Option

PREVIOUS = "Previous Menu"


@dataclass(frozen=True)
class Item:
    label: str
    text: str  # the piece of query text this choice adds
    next: str  # the menu (or "value", "done", ...) that follows


@dataclass(frozen=True)
class Menu:
    key: str
    title: str
    items: tuple[Item, ...]
    previous: bool = True  # every menu but the Query Menu has Previous Menu
    searchable: bool = False  # too long for a plain menu: typing filters it


def filtered_labels(menu: Menu, typed: str) -> list[str]:
    """The items of `menu` holding every word typed; first those where each
    word begins the label or one of its words ("poplit": poplitealheight
    before buttockpopliteallength), each kind in the menu's order."""
    words = typed.lower().split()
    found = [item.label for item in menu.items if all(w in item.label.lower() for w in words)]

    def begins(label: str) -> bool:
        starts = re.findall(r"\w+", label.lower())
        return all(any(start.startswith(w) for start in starts) for w in words)

    return sorted(found, key=lambda label: not begins(label))


class MenuSearch(Input):
    """The filter above a searchable menu: typing narrows the items, the arrow
    keys move in the menu below, Enter chooses the highlighted item."""

    BINDINGS = [
        Binding("down", "move(1)", show=False),
        Binding("up", "move(-1)", show=False),
    ]

    def action_move(self, rows: int) -> None:
        options = self.screen.query_one("#popup-options", OptionList)
        if options.option_count:
            current = options.highlighted if options.highlighted is not None else -1
            options.highlighted = max(0, min(current + rows, options.option_count - 1))


class QueryPopup(Vertical):
    """One pop-up menu at a time: shows the menu its screen hands it and posts
    `Chosen` for the item picked."""

    class Chosen(Message):
        def __init__(self, label: str, menu: str | None = None) -> None:
            super().__init__()
            self.label = label
            self.menu = menu  # the menu it was chosen in (None: the current one)

    def compose(self) -> ComposeResult:
        search = MenuSearch(placeholder="type to filter", id="popup-search", compact=True)
        search.display = False
        yield search
        yield OptionList(id="popup-options")

    menu: Menu | None = None

    @property
    def menu_key(self) -> str | None:
        return self.menu.key if self.menu is not None else None

    @property
    def options(self) -> OptionList:
        return self.query_one("#popup-options", OptionList)

    @property
    def search(self) -> MenuSearch:
        return self.query_one(MenuSearch)

    def show_menu(self, menu: Menu) -> None:
        self.menu = menu
        self.border_title = menu.title
        search = self.search
        search.display = menu.searchable
        self.set_class(menu.searchable, "-searchable")
        with search.prevent(Input.Changed):
            search.value = ""
        self._fill(menu, "")
        self.display = True
        self.focus_menu()

    def focus_menu(self) -> None:
        """The keys go to the filter of a searchable menu, else to the menu."""
        menu = self.menu
        (self.search if menu is not None and menu.searchable else self.options).focus()

    def _fill(self, menu: Menu, typed: str) -> None:
        labels = filtered_labels(menu, typed) + ([PREVIOUS] if menu.previous else [])
        options = self.options
        options.clear_options()
        options.add_options([Option(label, id=f"opt-{i}") for i, label in enumerate(labels)])
        options.highlighted = 0

    @property
    def labels(self) -> list[str]:
        options = self.options
        return [str(options.get_option_at_index(i).prompt) for i in range(options.option_count)]

    def on_input_changed(self, event: Input.Changed) -> None:
        event.stop()
        if self.menu is not None:
            self._fill(self.menu, event.value)

    def on_input_submitted(self, event: Input.Submitted) -> None:
        event.stop()
        options = self.options
        if options.highlighted is not None and options.option_count:
            prompt = options.get_option_at_index(options.highlighted).prompt
            self.post_message(self.Chosen(str(prompt), self.menu_key))

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        event.stop()
        self.post_message(self.Chosen(str(event.option.prompt), self.menu_key))
