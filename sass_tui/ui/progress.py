"""Progress of long work on screen: a bar with the count done/total
and "Esc cancels", fed by Messages that a worker posts.

    work = screen.begin_work("Input DB", bar)   # on the UI thread
    ... in the worker: lists.import_files(files, work.report, work.cancel)

`WorkReporter` is the db layer's `progress(done, total)` callback: called in
the worker's thread, it posts `WorkProgressed` to the screen at most
`MAX_UPDATES` times a second (and always the last report).  The screen hands
the message to its `WorkBar`.  `cancel` is a threading.Event that Escape
sets; the db function stops at its next step with `Cancelled`.
"""

from __future__ import annotations

import threading
import time

from textual.containers import Horizontal
from textual.message import Message
from textual.message_pump import MessagePump
from textual.widgets import Label, ProgressBar

MAX_UPDATES = 20  # per second
# A query shows its bar only when it has run this long (a quick one never flickers).
QUERY_BAR_AFTER = 0.2


class WorkProgressed(Message):
    def __init__(self, work: Work, done: int, total: int) -> None:
        super().__init__()
        self.work = work
        self.done = done
        self.total = total


class Work:
    """One piece of long work: its name, its cancel and its throttled reporter."""

    def __init__(self, target: MessagePump, what: str, show_after: float = 0.0) -> None:
        self.target = target
        self.what = what
        self.show_after = show_after
        self.cancel = threading.Event()
        self.started = time.monotonic()
        self._last = -1.0

    def report(self, done: int, total: int) -> None:
        """progress(done, total), from any thread."""
        now = time.monotonic()
        if done < total and now - self._last < 1.0 / MAX_UPDATES:
            return
        self._last = now
        self.target.post_message(WorkProgressed(self, done, total))

    @property
    def due(self) -> bool:
        """Long enough under way to show its bar."""
        return time.monotonic() - self.started >= self.show_after


class WorkBar(Horizontal):
    """`what [#####.....] 12,000/78,000  Esc cancels`; hidden while idle."""

    DEFAULT_CSS = """
    WorkBar { height: 1; display: none; padding: 0 1; }
    WorkBar.-busy { display: block; }
    WorkBar > #work-what { width: auto; padding-right: 1; text-style: bold; }
    WorkBar > ProgressBar { width: auto; }
    WorkBar > #work-count { width: auto; padding: 0 1; }
    WorkBar > #work-hint { width: auto; color: $text-muted; }
    """

    def __init__(self, **kwargs) -> None:
        super().__init__(**kwargs)
        self.work: Work | None = None
        self.done = 0
        self.total = 0

    def compose(self):
        yield Label("", id="work-what")
        yield ProgressBar(total=None, show_eta=False, show_percentage=False, id="work-bar")
        yield Label("", id="work-count")
        yield Label("Esc cancels", id="work-hint")

    def start(self, work: Work) -> None:
        self.work = work
        self.done = self.total = 0
        self.query_one("#work-what", Label).update(work.what)
        self.query_one("#work-count", Label).update("")
        self.query_one(ProgressBar).update(total=None, progress=0)
        self.set_class(work.show_after == 0, "-busy")

    def show(self, event: WorkProgressed) -> None:
        if event.work is not self.work:
            return  # a report of work that has finished or was replaced
        self.done, self.total = event.done, event.total
        self.query_one(ProgressBar).update(total=max(event.total, 1), progress=event.done)
        self.query_one("#work-count", Label).update(f"{event.done:,}/{event.total:,}")
        if event.work.due:
            self.add_class("-busy")

    def cancelling(self) -> None:
        self.query_one("#work-hint", Label).update("cancelling...")

    def stop(self) -> None:
        self.work = None
        self.remove_class("-busy")
        self.query_one("#work-hint", Label).update("Esc cancels")

    @property
    def text(self) -> str:
        """What the bar says (for tests and the palette's status)."""
        return (
            f"{self.work.what if self.work else ''} {self.done:,}/{self.total:,}"
            if self.has_class("-busy")
            else ""
        )
