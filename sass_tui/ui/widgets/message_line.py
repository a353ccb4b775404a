"""The report's command/message window: says things, and asks."""

from __future__ import annotations

from collections.abc import Callable

from rich.text import Text
from textual.binding import Binding
from textual.containers import Horizontal
from textual.message import Message
from textual.widget import Widget
from textual.widgets import Input, Label

from sass_tui.model.errors import SassError
from sass_tui.ui.widgets.formats import (
    printable_lines,
)


class AnswerInput(Input):
    BINDINGS = [Binding("escape", "cancel", "Cancel", show=False)]

    class Cancelled(Message):
        pass

    def action_cancel(self) -> None:
        self.post_message(self.Cancelled())

    def submit(self) -> None:
        """Enter, from code that cannot await: what Input.action_submit (a
        coroutine) does for an input without validators."""
        self.post_message(self.Submitted(self, self.value))


Handler = Callable[[str], None]
HISTORY_LENGTH = 200
# What a user may cause in an answer: shown on the message line, never a
# traceback; anything else is a bug and shows as one.
USER_ERRORS = (SassError, OSError)


class MessageLine(Horizontal):
    """The report's command/message window: says things, and asks.

    It owns its prompt: the answer being typed, the handler the answer goes
    to, the handler of a cancel (Escape), and the widget to give the focus
    back to.  A handler may ask again (a follow-up question).  A handler's
    SassError or OSError is shown as an error; after each answer or cancel
    the line posts `Answered` so the screen can redraw."""

    class Answered(Message):
        pass

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self._on_answer: Handler | None = None
        self._on_cancel: Callable[[], None] | None = None
        self._focus_after: Widget | None = None
        # What was said, oldest first: one line is cut at the terminal's width,
        # the message log (`l`) shows it whole.
        self.history: list[tuple[str, str]] = []

    def compose(self):
        yield Label("", id="message")
        yield AnswerInput(id="answer", compact=True, select_on_focus=False)

    def on_mount(self) -> None:
        self.answer.display = False

    @property
    def answer(self) -> AnswerInput:
        return self.query_one("#answer", AnswerInput)

    def show(self, text: str, kind: str = "info") -> None:
        # Messages quote names and titles from files: no escape sequence in
        # them may reach the terminal (issue 17).
        text = printable_lines(text)
        if kind != "prompt" and (not self.history or self.history[-1] != (kind, text)):
            self.history.append((kind, text))
            del self.history[:-HISTORY_LENGTH]
        label = self.query_one("#message", Label)
        label.update(Text(text))
        for name in ("info", "error", "warning", "prompt"):
            label.set_class(name == kind, f"-{name}")

    def say(self, text: str) -> None:
        self.show(text, "info")

    def complain(self, text: str) -> None:
        self.show(text, "error")

    @property
    def prompting(self) -> bool:
        return bool(self.answer.display)

    def ask(
        self,
        prompt: str,
        on_answer: Handler,
        initial: str = "",
        on_cancel: Callable[[], None] | None = None,
        kind: str = "prompt",
    ) -> None:
        focused = self.screen.focused
        if focused is not None and focused is not self.answer:
            self._focus_after = focused
        self._on_answer, self._on_cancel = on_answer, on_cancel
        self.show(prompt + " ", kind)
        answer = self.answer
        answer.value = initial
        answer.display = True
        # Now, not on the next idle: the keys that follow belong to the answer.
        self.screen.set_focus(answer)
        answer.cursor_position = len(initial)

    def keep_focus(self) -> None:
        """While asking, the answer keeps the focus (a click elsewhere does not
        take the keys away from the prompt)."""
        if self.prompting and self.screen.focused is not self.answer:
            self.screen.set_focus(self.answer)

    def type_ahead(self, key: str, character: str | None, text: str = "") -> None:
        """A key that reached another widget before the answer had the focus."""
        if not self.prompting:
            return
        answer = self.answer
        if text:
            answer.insert_text_at_cursor(text)
        elif key == "enter":
            answer.submit()
        elif key == "escape":
            answer.action_cancel()
        elif key == "backspace":
            answer.action_delete_left()
        elif character and character.isprintable():
            answer.insert_text_at_cursor(character)

    def _close(self) -> tuple[Handler | None, Callable[[], None] | None]:
        handlers = self._on_answer, self._on_cancel
        self._on_answer = self._on_cancel = None
        answer = self.answer
        answer.value = ""
        answer.display = False
        focus, self._focus_after = self._focus_after, None
        if focus is not None and focus.is_attached and focus.display:
            # Synchronously, so that a follow-up question keeps the focus.
            self.screen.set_focus(focus)
        return handlers

    def _run(self, handler: Callable[[], None]) -> None:
        try:
            handler()
        except USER_ERRORS as exc:
            self.complain(str(exc))

    def on_input_submitted(self, event: Input.Submitted) -> None:
        event.stop()
        on_answer, _ = self._close()
        if on_answer is not None:
            self._run(lambda: on_answer(event.value))
        self.post_message(self.Answered())

    def on_answer_input_cancelled(self, event: AnswerInput.Cancelled) -> None:
        event.stop()
        _, on_cancel = self._close()
        if on_cancel is not None:
            self._run(on_cancel)
        else:
            self.say("Cancelled; nothing changed.")
        self.post_message(self.Answered())
