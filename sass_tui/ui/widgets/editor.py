"""Keys of a widget whose cells are edited on the message line, and the
Messages that carry them to the screen (typed ahead of a prompt, or the
screen's commands)."""

from __future__ import annotations

from textual import events
from textual.message import Message

from sass_tui.ui.textual_api import bindings_of

# Characters that start typing a new number straight into the message line.
NUMBER_START = set("0123456789.-+")


class TypedAhead(Message):
    """Keys typed after an edit was asked for but before its prompt took the
    focus: the app routed them to the widget that asked.  They belong to the
    prompt, in the order typed (a paste arrives as one `text`)."""

    def __init__(self, key: str, character: str | None, text: str = "") -> None:
        super().__init__()
        self.key = key
        self.character = character
        self.text = text


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
    not open Input Data on the `i`."""

    _typing_ahead = False

    def request_edit(self, message: Message) -> None:
        self._typing_ahead = True
        self.post_message(message)  # type: ignore[attr-defined]

    def typing_done(self) -> None:
        self._typing_ahead = False

    def start_typing(self, text: str) -> None:
        raise NotImplementedError

    def on_key(self, event: events.Key) -> None:
        if self._typing_ahead:
            event.stop()
            event.prevent_default()
            self.post_message(TypedAhead(event.key, event.character))  # type: ignore[attr-defined]
        elif event.character and event.character in NUMBER_START:
            event.stop()
            event.prevent_default()
            self.start_typing(event.character)
        elif event.key == "enter":
            # Here, not by a binding run after the key has bubbled up: the
            # letters typed next must find the edit already asked for.
            event.stop()
            event.prevent_default()
            self.start_typing("")
        elif event.key not in bindings_of(self).key_to_bindings:  # type: ignore[arg-type]
            # Not this widget's (its arrows are): the screen's, in this order.
            event.stop()
            event.prevent_default()
            self.post_message(ScreenKey(event.key, event.character))  # type: ignore[attr-defined]

    def on_paste(self, event: events.Paste) -> None:
        event.stop()
        event.prevent_default()
        if self._typing_ahead:
            self.post_message(TypedAhead("paste", None, event.text))  # type: ignore[attr-defined]
        elif event.text.strip():
            self.start_typing(event.text.strip())

    def on_blur(self) -> None:
        self._typing_ahead = False
        self.refresh()  # type: ignore[attr-defined]
