"""The More Menu of Disp. More (report §12.4): which person of the selected
list the spreadsheet shows next."""

from __future__ import annotations

from textual.app import ComposeResult
from textual.binding import Binding
from textual.containers import Vertical
from textual.widgets import OptionList
from textual.widgets.option_list import Option

from sass_tui.ui.pop_up import PopUpScreen

MORE_CHOICES = ("First", "Last", "Previous", "Next", "Nth Person")


class MoreMenu(PopUpScreen[str | None]):
    """The More Menu: a pop-up menu that looks like the query builder's
    (`.pop-up-menu`, sass.tcss) over the spreadsheet."""

    DEFAULT_CSS = """
    MoreMenu { align: center middle; background: transparent; }
    MoreMenu > #more-popup { width: 24; }
    """
    BINDINGS = [Binding("escape", "dismiss(None)", "Cancel")]

    def compose(self) -> ComposeResult:
        with Vertical(id="more-popup", classes="pop-up-menu") as popup:
            popup.border_title = "More Menu"
            yield OptionList(
                *(Option(choice, id=f"more-{i}") for i, choice in enumerate(MORE_CHOICES)),
                id="more-menu",
            )

    def on_option_list_option_selected(self, event: OptionList.OptionSelected) -> None:
        event.stop()
        if self.app.screen is self:  # not again for an Enter typed twice at once
            self.dismiss(str(event.option.prompt))
