"""Keys of a widget whose cells are edited on the message line, and the
Messages that carry them to the screen (typed ahead of a prompt, or the
screen's commands)."""

from __future__ import annotations

from textual import events
from textual.binding import Binding
from textual.dom import DOMNode
from textual.message import Message
from textual.screen import Screen

from sass_tui.ui.textual_api import bindings_of, event_clock

# Characters that start typing a new number straight into the message line.
NUMBER_START = set("0123456789.-+")

# The keys each editing widget binds: the arrows move its cursor, Enter edits
# the cell under it (a widget adds its own between them: DataSheet's Home/End).
CURSOR_BINDINGS = [
    Binding("up", "move(-1, 0)", show=False),
    Binding("down", "move(1, 0)", show=False),
    Binding("left", "move(0, -1)", show=False),
    Binding("right", "move(0, 1)", show=False),
]
EDIT_BINDING = Binding("enter", "edit", "Edit", show=False)


async def run_own_binding(node: DOMNode, key: str) -> bool:
    """Run `node`'s own binding for `key` at once, in the order the keys
    came; False when it has none that applies (Textual would then look
    further up, as it does for a binding it runs itself)."""
    for binding in bindings_of(node).key_to_bindings.get(key, ()):
        if await node.app.run_action(binding.action, node):
            return True
    return False


def focused_line(screen: Screen) -> list[DOMNode]:
    """The focused widget and the containers it sits in, below `screen`: the
    line a key and the Messages its handlers post travel up."""
    focused = screen.focused
    if focused is None:
        return []
    line = focused.ancestors_with_self
    return line[: line.index(screen)] if screen in line else line


async def run_focused_binding(screen: Screen, key: str) -> bool:
    """Run, at once, the binding for `key` of `screen`'s focused widget or of
    the nearest of its containers below the screen that has one; False when
    none does.  Left to Textual, it would run once the key had bubbled up to
    the app's queue: after the keys that came in the same read (ui/key_order.py)."""
    for node in focused_line(screen):
        if await run_own_binding(node, key):
            return True
    return False


class TypedAhead(Message):
    """Keys typed after an edit was asked for but before its prompt took the
    focus: the app routed them to the widget that asked.  They belong to the
    prompt, in the order typed (a paste arrives as one `text`).  `source`
    and `request`: the widget and the edit they were typed for; when the
    screen refused that edit (no prompt came) they are the value it did not
    take, never commands."""

    def __init__(
        self,
        key: str,
        character: str | None,
        text: str = "",
        source: EditorKeys | None = None,
        request: int = 0,
    ) -> None:
        super().__init__()
        self.key = key
        self.character = character
        self.text = text
        self.source = source
        self.request = request

    def for_refused_edit(self) -> bool:
        return self.source is not None and self.source.refused_request == self.request


class ScreenKey(Message):
    """A key an editing widget does not take, sent to its screen in the order
    typed: the screen's command, or the open prompt's if one opened meanwhile."""

    def __init__(self, key: str, character: str | None) -> None:
        super().__init__()
        self.key = key
        self.character = character


class EditorKeys:
    """Keys of a widget whose cells are edited on the message line.

    A number key (or Enter) asks the screen for a prompt with a Message; from
    then until the widget loses the focus (the prompt took it) or the screen
    says no prompt came (`typing_done`), every key and paste is passed on as
    TypedAhead, never to a binding: `14in` typed fast edits the cell, it does
    not open Input Data on the `i`.

    The widget says what editing its cursor's cell asks for
    (`edit_request`: its EditRequested message); Enter, a click on the chosen
    cell and typing all ask with it.  A click chooses the cell under it
    (`cell_at`, `chosen`, `choose`); a second click on it, or a double
    click, edits it."""

    _typing_ahead = False
    _requests = 0  # the edits asked for
    refused_request = 0  # the last of them the screen refused (no prompt came)
    # When it was refused: a key typed before then (one read of the terminal,
    # handled after the refusal) was typed for that edit, not as a command.
    refused_at = float("-inf")

    def edit_request(self, initial: str) -> Message:
        """The message asking to edit the cell under the cursor, `initial`
        being what was typed so far."""
        raise NotImplementedError

    def cell_at(self, x: int, y: int) -> object | None:
        """The cell at (x, y) of the content; None off the cells."""
        raise NotImplementedError

    def chosen(self) -> object:
        """The cell under the cursor, as `cell_at` names it."""
        raise NotImplementedError

    def choose(self, cell: object) -> None:
        """Put the cursor on `cell` (one that `cell_at` gave)."""
        raise NotImplementedError

    def starts_value(self, character: str) -> bool:
        """Whether typing `character` on the cursor's cell starts its value
        (a number's first character; a word cell's any letter)."""
        return character in NUMBER_START

    def request_edit(self, message: Message) -> None:
        self._requests += 1
        self._typing_ahead = True
        self.post_message(message)  # type: ignore[attr-defined]

    def typing_done(self) -> None:
        self._typing_ahead = False

    def refuse_edit(self) -> None:
        """No prompt came for the edit asked for: the keys typed ahead for it
        are the value the cell did not take (`14in` typed fast on a cell
        without data must not open Input Data on the `i`)."""
        self.refused_request = self._requests
        self.refused_at = event_clock()
        self.typing_done()

    def action_edit(self) -> None:
        self.request_edit(self.edit_request(""))

    def start_typing(self, text: str) -> None:
        self.request_edit(self.edit_request(text))

    def _typed_for_an_edit(self, event: events.Event) -> bool:
        """Whether `event` was typed for the edit asked for last: before its
        prompt took the keys, or before the screen refused it."""
        return self._typing_ahead or event.time < self.refused_at

    async def on_key(self, event: events.Key) -> None:
        if self._typed_for_an_edit(event):
            event.stop()
            event.prevent_default()
            typed = TypedAhead(event.key, event.character, source=self, request=self._requests)
            self.post_message(typed)  # type: ignore[attr-defined]
        elif event.character and self.starts_value(event.character):
            event.stop()
            event.prevent_default()
            self.start_typing(event.character)
        elif event.key == "enter":
            # Here, not by a binding run after the key has bubbled up: the
            # letters typed next must find the edit already asked for.
            event.stop()
            event.prevent_default()
            self.start_typing("")
        elif await run_own_binding(self, event.key):  # type: ignore[arg-type]
            # Its arrows, now: left to the app after the key has bubbled up,
            # the move would land after an Enter or a digit of the same read
            # had asked to edit the cell the cursor was leaving.
            event.stop()
            event.prevent_default()
        elif event.key not in bindings_of(self).key_to_bindings:  # type: ignore[arg-type]
            # Not this widget's: the screen's, in this order.
            event.stop()
            event.prevent_default()
            self.post_message(ScreenKey(event.key, event.character))  # type: ignore[attr-defined]

    def on_paste(self, event: events.Paste) -> None:
        event.stop()
        event.prevent_default()
        if self._typed_for_an_edit(event):
            typed = TypedAhead("paste", None, event.text, self, self._requests)
            self.post_message(typed)  # type: ignore[attr-defined]
        elif event.text.strip():
            self.start_typing(event.text.strip())

    def on_click(self, event: events.Click) -> None:
        offset = event.get_content_offset(self)  # type: ignore[arg-type]
        cell = None if offset is None else self.cell_at(offset.x, offset.y)
        if cell is None:
            return
        # Not while a prompt has the keys: the first click takes the focus back.
        again = self.has_focus and (event.chain > 1 or cell == self.chosen())  # type: ignore[attr-defined]
        self.choose(cell)
        self.focus()  # type: ignore[attr-defined]
        self.refresh()  # type: ignore[attr-defined]
        if again:
            self.action_edit()

    def on_focus(self) -> None:
        self.refresh()  # type: ignore[attr-defined]

    def on_blur(self) -> None:
        self._typing_ahead = False
        self.refresh()  # type: ignore[attr-defined]
