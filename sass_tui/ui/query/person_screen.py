"""The person view: every value the database holds about one person (the
query list's Enter), as `sass person` prints it (db/people/person_text.py): who,
each group's rows, strength, the ANSUR II measures with their units."""

from __future__ import annotations

from rich.text import Text
from textual.binding import Binding
from textual.containers import VerticalScroll
from textual.widgets import Static

from sass_tui.db.people.person_text import person_lines
from sass_tui.ui.base import SassScreen
from sass_tui.ui.footer import Footer
from sass_tui.ui.widgets import MessageLine


class PersonScreen(SassScreen):
    """One person, every value, scrolled with the arrows and the page keys."""

    DEFAULT_CSS = """
    PersonScreen #person { height: 1fr; border: round $accent; padding: 0 1; }
    """
    BINDINGS = [
        Binding("escape", "close", "Back"),
        Binding("e", "close", "Back", show=False),
        Binding("q", "app.quit", "Quit"),
    ]

    def __init__(self, record: dict) -> None:
        super().__init__()
        self.record = record
        self.lines = person_lines(record)

    def compose(self):
        scroll = VerticalScroll(Static(Text("\n".join(self.lines)), id="person-text"), id="person")
        scroll.border_title = f"{self.lines[0].split(' (id ')[0]} — every value"
        scroll.border_subtitle = "↑ ↓ PgUp PgDn scroll; Esc back"
        yield scroll
        yield MessageLine(id="message-line")
        yield Footer(compact=True)

    def on_mount(self) -> None:
        self.query_one("#person", VerticalScroll).focus()
        self.say(self.lines[0])

    def action_close(self) -> None:
        """Back to the query list."""
        self.app.pop_screen()
