"""Progress and cancelling for long database work (issue 15), without Textual.

Long functions (`import_flat_files`, `import_ansur`, `QueryLists.run`,
`population_of`, `fit_test`, `limit_histograms`, `load_family`) take

    progress: Callable[[int, int], None] | None   # called with (done, total)
    cancel:   Cancel | None                        # e.g. a threading.Event

and raise `Cancelled` at the next step after `cancel.is_set()`; they stop only
where nothing is half-written (an import's transaction is rolled back, a
query list is left as it was).  A SQLite statement that runs long is
interrupted too: `interruptible(conn, cancel)` installs a progress handler
that aborts the statement once the cancel is set.
"""

from __future__ import annotations

import sqlite3
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Protocol

from sass_tui.model.errors import SassError

Progress = Callable[[int, int], None]
# SQLite calls the progress handler every this many virtual-machine instructions.
HANDLER_INSTRUCTIONS = 20_000


class Cancel(Protocol):
    def is_set(self) -> bool: ...


class Cancelled(ValueError, SassError):
    """The user cancelled the work; nothing was written."""

    def __init__(self, what: str = "the work") -> None:
        super().__init__(f"{what} was cancelled; nothing was written or changed")


class Steps:
    """`(done, total)` reports that also check for a cancel: call it as a
    progress callback (it can be handed to functions that take one)."""

    def __init__(
        self, progress: Progress | None = None, cancel: Cancel | None = None, what: str = "the work"
    ) -> None:
        self.progress = progress
        self.cancel = cancel
        self.what = what

    def check(self) -> None:
        if self.cancel is not None and self.cancel.is_set():
            raise Cancelled(self.what)

    def __call__(self, done: int, total: int) -> None:
        self.check()
        if self.progress is not None:
            self.progress(done, total)


@contextmanager
def interruptible(
    conn: sqlite3.Connection, cancel: Cancel | None, what: str = "the work"
) -> Iterator[None]:
    """Abort a running statement once `cancel` is set; raises Cancelled instead
    of SQLite's "interrupted" (the caller's transaction rolls back)."""
    if cancel is None or getattr(conn, "dialect", "sqlite") != "sqlite":
        # PostgreSQL: the cancel is seen between statements (the Steps around them).
        yield
        if cancel is not None and cancel.is_set():
            raise Cancelled(what)
        return
    conn.set_progress_handler(lambda: 1 if cancel.is_set() else 0, HANDLER_INSTRUCTIONS)
    try:
        yield
    except sqlite3.OperationalError as exc:
        if cancel.is_set() and "interrupt" in str(exc):
            raise Cancelled(what) from None
        raise
    finally:
        conn.set_progress_handler(None, HANDLER_INSTRUCTIONS)
    if cancel.is_set():
        raise Cancelled(what)
