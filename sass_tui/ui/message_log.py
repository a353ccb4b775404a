"""The message log: every message of a screen's message line, whole (the
line itself is cut at the terminal's width)."""

from __future__ import annotations

from rich.text import Text
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.widgets import Static

from sass_tui.ui.pop_up import PopUpScreen

KIND_STYLE = {"error": "bold red", "warning": "yellow", "info": ""}


class MessageLog(PopUpScreen[None]):
    DEFAULT_CSS = """
    MessageLog { align: center middle; background: $background 40%; }
    MessageLog > VerticalScroll { width: 90%; height: 80%; border: round $accent;
                                  border-title-style: bold; background: $surface;
                                  padding: 0 1; }
    """
    BINDINGS = [
        Binding("escape", "dismiss(None)", "Close"),
        Binding("l", "dismiss(None)", "Close", show=False),
        Binding("q", "dismiss(None)", "Close", show=False),
    ]

    def __init__(self, history: list[tuple[str, str]]) -> None:
        super().__init__()
        self.history = list(history)

    def compose(self):
        text = Text()
        for kind, message in self.history or [("info", "No messages yet.")]:
            text.append(message + "\n", KIND_STYLE.get(kind, ""))
        scroll = VerticalScroll(Static(text, id="log-text"), id="log")
        scroll.border_title = "Messages (Escape closes)"
        yield scroll

    def on_mount(self) -> None:
        self.query_one(VerticalScroll).scroll_end(animate=False)
