"""The command menu (report figure 6): commands in two columns, each a
MenuItem clicked like a button."""

from __future__ import annotations

from rich.cells import cell_len
from textual import events
from textual.containers import Horizontal, Vertical
from textual.content import Content
from textual.geometry import Size
from textual.message import Message
from textual.reactive import reactive
from textual.widget import Widget

from sass_tui.ui.spreadsheet.commands import CommandSpec


class MenuItem(Widget, can_focus=False):
    """One command of a CommandMenu: its label, clicked like a button.

    Not Textual's Button: the spreadsheet's 15 Buttons cost ~15 ms of the
    first screen, mostly their large default CSS matched against
    every widget; the menu uses only the label, the click and the look
    (sass.tcss, query.tcss)."""

    ALLOW_SELECT = False
    ACTIVE_SECONDS = 0.2  # the flash after a click, as Button's

    label: reactive[str] = reactive("", layout=True)

    class Pressed(Message):
        def __init__(self, item: MenuItem) -> None:
            super().__init__()
            self.item = item

        @property
        def control(self) -> MenuItem:
            return self.item

    def __init__(self, label: str, *, id: str | None = None, classes: str | None = None) -> None:
        super().__init__(id=id, classes=classes)
        self.set_reactive(MenuItem.label, label)

    def render(self) -> Content:
        return Content(self.label)

    def get_content_width(self, container: Size, viewport: Size) -> int:
        return cell_len(self.label)

    async def _on_click(self, event: events.Click) -> None:
        event.stop()
        self.press()

    def press(self) -> None:
        if self.disabled or not self.display or self.has_class("-active"):
            return
        self.add_class("-active")
        self.set_timer(self.ACTIVE_SECONDS, lambda: self.remove_class("-active"))
        self.post_message(self.Pressed(self))


class CommandMenu(Horizontal):
    """Figure 6: commands in two columns, built from the command specs; the
    labels and availability come from `context` (the screen the menu is on)."""

    def __init__(self, commands: tuple[CommandSpec, ...], context: object, **kwargs) -> None:
        super().__init__(**kwargs)
        self.commands = commands
        self.context = context

    def compose(self):
        for column in sorted({c.column for c in self.commands}):
            with Vertical(classes="command-column"):
                for spec in sorted(
                    (c for c in self.commands if c.column == column), key=lambda c: c.row
                ):
                    yield MenuItem(
                        spec.label(self.context), id=f"command-{spec.name}", classes="command"
                    )

    def item(self, spec: CommandSpec) -> MenuItem:
        return self.query_one(f"#command-{spec.name}", MenuItem)

    def refresh_labels(self) -> None:
        for spec in self.commands:
            item = self.item(spec)
            item.label = spec.label(self.context)
            item.display = spec.available(self.context)
