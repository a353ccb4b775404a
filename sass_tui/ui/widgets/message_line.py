"""The report's command/message window: says things, and asks."""

from __future__ import annotations

import asyncio
import os
from collections.abc import AsyncIterator, Callable
from contextlib import asynccontextmanager

from rich.text import Text
from textual import events
from textual.binding import Binding
from textual.containers import Horizontal
from textual.message import Message
from textual.widget import Widget
from textual.widgets import Input, Label
from textual.widgets.input import Selection

from sass_tui.model.errors import SassError, error_text
from sass_tui.ui.textual_api import forward_event
from sass_tui.ui.widgets.editor import run_own_binding
from sass_tui.ui.widgets.formats import printable_lines


class AnswerInput(Input):
    """The answer typed on the message line.

    Its keys apply in the order they came, also when they arrive in one read
    (a paste, a burst): its own bindings (Enter, Escape, the arrows) run as
    the key is handled, not once it has bubbled up to the app, which would be
    after the characters that followed it.  From an Enter or Escape until the
    line has handled that answer (`closing`), the keys that come are not this
    answer's: the line holds them and passes them on, in order, to whatever
    has the keys after the answer (the sheet, a follow-up question)."""

    BINDINGS = [
        Binding("escape", "cancel", "Cancel", show=False),
        Binding("tab", "complete", "Complete", show=False),
    ]

    # An Enter or Escape given; the line has not handled the answer yet.
    closing = False

    class Cancelled(Message):
        pass

    class CompletionAsked(Message):
        pass

    @property
    def line(self) -> MessageLine:
        parent = self.parent
        assert isinstance(parent, MessageLine)
        return parent

    # Textual runs each class's handler in turn (Input's after these) unless
    # one prevents the default.
    async def _on_key(self, event: events.Key) -> None:
        if self.closing or not self.display:
            event.stop()
            event.prevent_default()
            self.line.later(event.key, event.character)
        elif await run_own_binding(self, event.key):
            event.stop()
            event.prevent_default()

    def _on_paste(self, event: events.Paste) -> None:
        if self.closing or not self.display:
            event.stop()
            event.prevent_default()
            self.line.later("paste", None, event.text)

    async def action_submit(self) -> None:
        self.closing = True
        await super().action_submit()

    def action_cancel(self) -> None:
        self.closing = True
        self.post_message(self.Cancelled())

    def action_complete(self) -> None:
        """Tab: complete the answer (a file name, a data set's name)."""
        self.post_message(self.CompletionAsked())

    def submit(self) -> None:
        """Enter, from code that cannot await: what Input.action_submit (a
        coroutine) does for an input without validators."""
        self.closing = True
        self.post_message(self.Submitted(self, self.value))


Handler = Callable[[str], None]
# What a prompt's answer may go on to (Tab), given what is typed so far.
Completer = Callable[[str], list[str]]
# Completions named after the prompt at most.
COMPLETIONS_SHOWN = 6
HISTORY_LENGTH = 200
# What a user may cause in an answer: shown on the message line, never a
# traceback; anything else is a bug and shows as one.
USER_ERRORS = (SassError, OSError)
CANCELLED = "Cancelled; nothing changed."


class MessageLine(Horizontal):
    """The report's command/message window: says things, and asks.

    It owns its prompt: the answer being typed, the handler the answer goes
    to, the handler of a cancel (Escape), and the widget to give the focus
    back to.  A handler may ask again (a follow-up question).  A handler's
    SassError or OSError is shown as an error; after each answer or cancel
    the line posts `Answered` so the screen can redraw.

    A command of several questions is one coroutine (a `@work` method) that
    awaits each answer in turn, inside `conversation()`:
    `name = await line.answer_to("File name:")`, None when cancelled."""

    class Answered(Message):
        pass

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self._on_answer: Handler | None = None
        self._on_cancel: Callable[[], None] | None = None
        self._focus_after: Widget | None = None
        self._prompt = ""
        self._complete: Completer | None = None
        # A conversation's state: the question awaited, and answers given
        # before the next question was asked (an Enter typed ahead).
        self._held = False
        self._future: asyncio.Future[str | None] | None = None
        self._early: list[str | None] = []
        # Keys that came after an Enter or Escape, before its answer was
        # handled: (key, character, pasted text), passed on afterwards.
        self._later: list[tuple[str, str | None, str]] = []
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
        # them may reach the terminal.
        text = printable_lines(text)
        if kind != "prompt" and (not self.history or self.history[-1] != (kind, text)):
            self.history.append((kind, text))
            del self.history[:-HISTORY_LENGTH]
        label = self.query_one("#message", Label)
        label.update(Text(text))
        for name in ("info", "error", "warning", "prompt"):
            label.set_class(name == kind, f"-{name}")

    def showing(self, text: str) -> bool:
        """Whether the line shows `text` now (a question still on the screen)."""
        return str(self.query_one("#message", Label).render()) == printable_lines(text)

    def say(self, text: str) -> None:
        self.show(text, "info")

    def complain(self, text: str) -> None:
        self.show(text, "error")

    @property
    def prompting(self) -> bool:
        """A prompt is open, or a conversation holds the keys for its next
        question."""
        return bool(self.answer.display) or self._held

    def ask(
        self,
        prompt: str,
        on_answer: Handler,
        initial: str = "",
        on_cancel: Callable[[], None] | None = None,
        kind: str = "prompt",
        complete: Completer | None = None,
        cursor: int | None = None,
    ) -> None:
        """`complete`: what Tab completes the answer from (None: nothing).
        `initial` is typed already (the cursor after it); with `cursor`, a
        text offered to edit: selected (-1), so that typing replaces it and
        an arrow keeps it, or with the cursor at that column (an error's)."""
        self._on_answer, self._on_cancel = on_answer, on_cancel
        self._open(prompt, initial, kind, complete)
        answer = self.answer
        if cursor is None or answer.value != initial:
            return  # what was typed ahead stays as typed
        if cursor < 0:
            answer.selection = Selection(0, len(initial))
        else:
            answer.cursor_position = min(cursor, len(initial))

    def _open(
        self, prompt: str, initial: str, kind: str, complete: Completer | None = None
    ) -> None:
        focused = self.screen.focused
        if focused is not None and focused is not self.answer:
            self._focus_after = focused
        self._prompt, self._complete = prompt, complete
        self.show(prompt + " ", kind)
        answer = self.answer
        if not (self._held and answer.value):  # what was typed ahead stays
            answer.value = initial
        answer.display = True
        # Now, not on the next idle: the keys that follow belong to the answer.
        self.screen.set_focus(answer)
        answer.cursor_position = len(answer.value)

    # --- a conversation: questions awaited one after another ----------------------
    def hold(self) -> None:
        """A conversation is about to start (its task runs soon, SassScreen.
        converse): from now the keys typed are its first question's, even
        before the question shows."""
        self._held = True

    @asynccontextmanager
    async def conversation(self) -> AsyncIterator[None]:
        """The questions of one command, asked in turn by `answer_to`.

        From `hold` (or the start) to the end the keys are the questions':
        typed before the next question shows, they are its answer, as
        TypedAhead makes them for a single prompt.  A SassError or OSError
        raised inside ends the conversation on the line, as a handler's
        does; at the end the focus goes back and `Answered` is posted."""
        self._held = True
        try:
            yield
        except USER_ERRORS as exc:
            self.complain(error_text(exc))
        finally:
            self._held = False
            self._early.clear()
            if self.is_attached:
                self._close()
                self.post_message(self.Answered())
                self.release_keys()

    async def answer_to(
        self,
        prompt: str,
        initial: str = "",
        kind: str = "prompt",
        complete: Completer | None = None,
    ) -> str | None:
        """Ask inside `conversation()` and wait: the answer, or None when
        cancelled (Escape).  `complete`: what Tab completes it from."""
        if self._early:  # answered before it was asked
            return self._early.pop(0)
        future: asyncio.Future[str | None] = asyncio.get_running_loop().create_future()
        self._future = future
        self._open(prompt, initial, kind, complete)
        self.release_keys()  # what was typed after the last answer is this one's
        try:
            return await future
        finally:
            self._future = None

    def _settle(self, answer: str | None) -> None:
        """An answer or cancel in a conversation: to the question awaited, or
        kept for the next one.  The answer keeps the focus until the end."""
        self.answer.value = ""
        future = self._future
        if future is not None and not future.done():
            future.set_result(answer)
        else:
            self._early.append(answer)

    def keep_focus(self) -> None:
        """While asking, the answer keeps the focus (a click elsewhere does not
        take the keys away from the prompt)."""
        if self.answer.display and self.screen.focused is not self.answer:
            self.screen.set_focus(self.answer)

    def type_ahead(self, key: str, character: str | None, text: str = "") -> None:
        """A key that reached another widget before the answer had the focus."""
        answer = self.answer
        if answer.closing or not self.prompting:
            self.later(key, character, text)
            return
        if key == "enter":
            answer.submit()
        elif key == "escape":
            answer.action_cancel()
        elif key == "backspace":
            answer.action_delete_left()
        elif text or (character and character.isprintable()):
            typed = text or character or ""
            if answer.selection.is_empty:
                answer.insert_text_at_cursor(typed)
            else:  # typing replaces what is selected, as in the answer itself
                answer.replace(typed, *answer.selection)

    def later(self, key: str, character: str | None, text: str = "") -> None:
        """A key that is not the open answer's: held while an answer is being
        handled, else given now to what has the keys (never dropped)."""
        if self.answer.closing:
            self._later.append((key, character, text))
        else:
            self._pass_on(key, character, text)

    def _pass_on(self, key: str, character: str | None, text: str) -> None:
        target = self.app.focused
        if target is None or (target is self.answer and not self.answer.display):
            target = self.app.screen
        forward_event(target, events.Paste(text) if text else events.Key(key, character))

    def _clear_stale_prompt(self, prompt: str) -> None:
        """The question answered still on the line (its handler said nothing,
        or went to another screen): it is no longer current."""
        if not self.answer.display and self.showing(prompt + " "):
            label = self.query_one("#message", Label)
            label.update("")
            for name in ("info", "error", "warning", "prompt"):
                label.set_class(False, f"-{name}")

    def _answered(self) -> None:
        """An answer or cancel handled: the line says so, and the keys held
        meanwhile go on to what has the keys now.  In a conversation they
        wait for its next question, or its end: the work between two
        questions may take a while (a query, a file)."""
        self.post_message(self.Answered())
        if not self._held:
            self.release_keys()

    def release_keys(self) -> None:
        """The keys held since the last answer, in order, to what has the keys."""
        self.answer.closing = False
        held, self._later = self._later, []
        for key, character, text in held:
            self._pass_on(key, character, text)

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
            self.complain(error_text(exc))

    def on_input_submitted(self, event: Input.Submitted) -> None:
        event.stop()
        if self._held:
            self._settle(event.value)
            self._answered()
            return
        prompt = self._prompt
        on_answer, _ = self._close()
        if on_answer is not None:
            self._run(lambda: on_answer(event.value))
        self._clear_stale_prompt(prompt)
        self._answered()

    def on_answer_input_completion_asked(self, event: AnswerInput.CompletionAsked) -> None:
        """Tab: the answer goes on as far as every completion agrees; the
        completions, when more than one, are named after the prompt."""
        event.stop()
        complete = self._complete
        if complete is None or not self.answer.display:
            return
        answer = self.answer
        found = complete(answer.value)
        start = os.path.commonprefix(found) if found else ""
        if len(start) > len(answer.value):
            answer.value = start
            answer.cursor_position = len(start)
        if len(found) == 1 and found[0] == answer.value:
            self.show(self._prompt + " ", "prompt")
            return
        names = [
            name.rstrip("/").rpartition("/")[2] + ("/" if name.endswith("/") else "")
            for name in found
        ]
        more = " ..." if len(names) > COMPLETIONS_SHOWN else ""
        listed = ", ".join(names[:COMPLETIONS_SHOWN]) + more if names else "no match"
        self.show(f"{self._prompt} [{listed}] ", "prompt")

    def on_answer_input_cancelled(self, event: AnswerInput.Cancelled) -> None:
        event.stop()
        if self._held:
            self._settle(None)
            self._answered()
            return
        _, on_cancel = self._close()
        if on_cancel is not None:
            self._run(on_cancel)
        else:
            self.say(CANCELLED)
        self._answered()
