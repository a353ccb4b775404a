"""The anthropometric group status line of the spreadsheet (report figure 4):
one tab per group, the selected one highlighted."""

from __future__ import annotations

from textual import events
from textual.containers import Horizontal
from textual.message import Message
from textual.widgets import Static

from sass_tui.model.names import GROUP_TITLES


class GroupTab(Static):
    """One group's cell; the selected group's is highlighted."""

    class Chosen(Message):
        def __init__(self, group: str) -> None:
            super().__init__()
            self.group = group

    def __init__(self, group: str, key: str) -> None:
        super().__init__(f"{GROUP_TITLES[group]} ({key})", id=f"group-{group}", classes="group-tab")
        self.group = group

    def on_click(self, event: events.Click) -> None:
        event.stop()
        self.post_message(self.Chosen(self.group))


class GroupBar(Horizontal):
    def __init__(self, groups: tuple[tuple[str, str], ...], **kwargs) -> None:
        super().__init__(**kwargs)
        self._groups = groups

    def compose(self):
        for group, key in self._groups:
            yield GroupTab(group, key)

    def highlight(self, group: str) -> None:
        for tab in self.query(GroupTab):
            tab.set_class(tab.group == group, "-selected")
