"""What every SASS screen shares: its message line, and keys taken in the
order they were typed.

A key the focused widget does not take bubbles to the screen.  The screen
runs its own BINDINGS for it there, at once, rather than leaving them to the
app after the bubbling: a burst such as `m12` (Center of Mass, then 12) then
switches the group before the edit that the `1` asks for (a Message sent
after the `m` reached the screen) begins.  Nothing here is app-wide: each
screen's bindings are its own.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable, Coroutine
from typing import TYPE_CHECKING, Any, TypeVar, cast

from textual import events
from textual.binding import Binding
from textual.message import Message
from textual.screen import Screen

from sass_tui.model.files.paths import complete_path
from sass_tui.ui.palette import HelpScreen, help_commands
from sass_tui.ui.textual_api import bindings_of, run_bindings_now
from sass_tui.ui.widgets import MessageLine, ScreenKey, TypedAhead
from sass_tui.ui.widgets.editor import run_focused_binding
from sass_tui.ui.widgets.message_line import Completer

if TYPE_CHECKING:  # app.py imports the screens: at run time this would be a cycle
    from sass_tui.ui.app import SassApp


T = TypeVar("T")


class WorkerSaid(Message):
    """A worker's outcome for its screen's message line: kind is "info" or
    "error" (SassScreen.on_worker_said shows it)."""

    def __init__(self, text: str, kind: str = "info") -> None:
        super().__init__()
        self.text = text
        self.kind = kind


class SassScreen(Screen):
    # Every screen's help (bindings merge down the class hierarchy).
    BINDINGS = [
        Binding("f1", "help", "Help", show=False),
        Binding("question_mark", "help", "Help", show=False),
    ]

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        # The commands asking their questions now (converse).
        self._conversations: set[asyncio.Task[None]] = set()
        # The keys typed for the last edit refused: (its widget and request, why, the keys).
        self._refused_typing: tuple[tuple[int, int], str, str] = ((0, 0), "", "")

    @property
    def sass_app(self) -> SassApp:
        """The app, typed: what a screen reads of it (the Session, the database
        lists, the screens it opens) is checked by mypy."""
        return cast("SassApp", self.app)

    @property
    def message_line(self) -> MessageLine:
        return self.query_one(MessageLine)

    def say(self, text: str) -> None:
        self.message_line.say(text)

    def complain(self, text: str) -> None:
        self.message_line.complain(text)

    def on_worker_said(self, event: WorkerSaid) -> None:
        self.message_line.show(event.text, event.kind)

    def ask(
        self,
        prompt: str,
        on_answer: Callable[[str], None],
        initial: str = "",
        on_cancel: Callable[[], None] | None = None,
        kind: str = "prompt",
        complete: Completer | None = None,
        cursor: int | None = None,
    ) -> None:
        self.message_line.ask(prompt, on_answer, initial, on_cancel, kind, complete, cursor)

    def converse(self, questions: Coroutine[Any, Any, None]) -> None:
        """Run a command that asks several questions in turn: `questions` is
        one coroutine that awaits each answer (`answer_to`, `choose`) and
        reads top to bottom.  The keys typed from now on are its answers.

        It runs as a task of this screen, not as a worker: a worker is work
        under way (`app.workers.wait_for_complete()` waits for it, the palette
        calls its screen busy), a question waits for the user.  A bug in it
        is raised on the screen's message loop, as a handler's would be."""
        line = self.message_line
        line.hold()

        async def run() -> None:
            async with line.conversation():
                await questions

        task = asyncio.get_running_loop().create_task(run())
        self._conversations.add(task)  # the loop keeps only a weak reference
        task.add_done_callback(self._conversation_done)

    def _conversation_done(self, task: asyncio.Task[None]) -> None:
        self._conversations.discard(task)
        error = None if task.cancelled() else task.exception()
        if error is None:
            return

        def raise_it() -> None:
            raise error

        self.call_next(raise_it)

    async def choose(self, screen: Screen[T]) -> T | None:
        """Push a modal screen and wait, in `converse`, for what it is
        dismissed with."""
        chosen: asyncio.Future[T | None] = asyncio.get_running_loop().create_future()
        self.app.push_screen(screen, chosen.set_result)
        # The keys typed after the last answer are the pop-up's, once it has the focus.
        self.call_after_refresh(self.message_line.release_keys)
        return await chosen

    async def answer_to(
        self, prompt: str, initial: str = "", complete: Completer | None = None
    ) -> str | None:
        """Ask and wait, in `converse`: the answer, None when cancelled (Escape)."""
        return await self.message_line.answer_to(prompt, initial, complete=complete)

    def complete_file(self, text: str) -> list[str]:
        """Tab at a file name's prompt: the names it may go on to (inside a
        served session's directory, as `user_path` takes them)."""
        return complete_path(text, self.sass_app.workdir)

    async def on_key(self, event: events.Key) -> None:
        event.stop()
        event.prevent_default()
        line = self.message_line
        if line.prompting:
            if not line.answer.display:
                # A conversation whose first question is not shown yet: the
                # key is its answer's, never a command (converse).
                line.type_ahead(event.key, event.character)
            else:
                # The prompt's own keys (Enter, Escape) ran as the answer's
                # bindings; another is looked up now, as the app would.
                await run_bindings_now(self.app, event.key)
            return
        # A widget's own binding comes first, run here and now rather than by
        # the app after the key has bubbled up: "Down Enter" in one read must
        # move the list's cursor before the screen's Enter.  Nor is a key
        # left to the app: it would look it up after the next key's work.
        if not (await run_focused_binding(self, event.key) or await self._run_binding(event.key)):
            await run_bindings_now(self.app, event.key)

    async def on_screen_key(self, event: ScreenKey) -> None:
        event.stop()
        if self.message_line.prompting:
            # A prompt opened after the key was typed: it is the prompt's.
            self.message_line.type_ahead(event.key, event.character)
        elif not await self._run_binding(event.key) and (event.character or "").isprintable():
            self.say(
                f"{event.character!r} is neither part of this cell's value nor a command's "
                "key: type a value, or Enter to edit; F1 lists the keys."
            )

    async def _run_binding(self, key: str) -> bool:
        """Run this screen's binding for `key`, or say why it does nothing
        here.  False when the screen has nothing to do with the key."""
        for binding in bindings_of(self).key_to_bindings.get(key, ()):
            if self.check_action(binding.action, ()):
                await self.run_action(binding.action)
                return True
            reason = self.why_not(binding.action)
            if reason:
                self.say(reason)
                return True
        return False

    async def run_command(self, action: str) -> None:
        """Run a command chosen in the palette, as its key would."""
        if self.check_action(action, ()):
            await self.run_action(action)
        else:
            self.say(self.why_not(action) or "That command does not apply here.")

    def run_when_ready(self, action: str) -> None:
        """Run a command chosen in the palette on another screen, which has
        just brought this one up, once it can take it (after its mount)."""
        self.call_later(self.run_command, action)

    def action_help(self) -> None:
        """List every key of this screen, what it runs and what that does."""
        title = f"Keys of {type(self).__name__.removesuffix('Screen') or 'this'} screen"
        self.app.push_screen(HelpScreen(help_commands(self), title))

    def why_not(self, action: str) -> str | None:
        """Why a command's key does nothing here (its slot shows another
        command), for the message line; None: say nothing."""
        return None

    def on_typed_ahead(self, event: TypedAhead) -> None:
        event.stop()
        if event.for_refused_edit():
            self._not_a_command(event)
        else:
            self.message_line.type_ahead(event.key, event.character, event.text)

    def _not_a_command(self, event: TypedAhead) -> None:
        """A key typed for an edit that was refused: part of the value the
        cell did not take, said after why it was refused, never a command."""
        typed = event.text or (event.character if (event.character or "").isprintable() else "")
        if not typed:
            return  # its Enter, Escape or Backspace: nothing more to do
        edit = (id(event.source), event.request)
        if self._refused_typing[0] != edit:
            history = self.message_line.history
            self._refused_typing = (edit, history[-1][1] if history else "", "")
        _, why, keys = self._refused_typing
        said = f"{why.rstrip('.')}; typed for it, not run as commands: "
        history = self.message_line.history
        if keys and history and history[-1][1] == said + keys:
            history.pop()  # the log keeps the whole of it once
        keys += typed
        self._refused_typing = (edit, why, keys)
        self.complain(said + keys)

    def on_descendant_focus(self, event: events.DescendantFocus) -> None:
        # While a prompt is open the keys are its own, wherever the user clicks.
        self.message_line.keep_focus()
