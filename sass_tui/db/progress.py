"""Progress and cancelling for long database work, without Textual.

Long functions (`import_flat_files`, `import_ansur`, `QueryLists.run`,
`population_of`, `fit_test`, `limit_histograms`, `load_family`) take

    progress: Callable[[int, int], None] | None   # called with (done, total)
    cancel:   Cancel | None                        # e.g. a threading.Event

and raise `Cancelled` at the next step after `cancel.is_set()`; they stop only
where nothing is half-written (an import's transaction is rolled back, a
query list is left as it was).  A statement that runs long is interrupted
too: `interruptible(conn, cancel)` installs a SQLite progress handler that
aborts the statement once the cancel is set, or on PostgreSQL watches the
cancel from a thread and asks the server to cancel the statement.
"""

from __future__ import annotations

import sqlite3
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, Protocol

from sass_tui.model.errors import SassError

Progress = Callable[[int, int], None]
# How often a PostgreSQL statement's watcher looks at the cancel, seconds.
CANCEL_POLL_S = 0.05
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
def interruptible(conn: Any, cancel: Cancel | None, what: str = "the work") -> Iterator[None]:
    """Abort a running statement once `cancel` is set; raises Cancelled instead
    of SQLite's "interrupted" or PostgreSQL's "canceling statement" (the
    caller's transaction rolls back).  `conn`: sqlite3's connection or
    db/engine/postgres.py's PostgresConnection (which imports this module)."""
    if cancel is None:
        yield
        return
    if getattr(conn, "dialect", "sqlite") != "sqlite":
        with _postgres_interruptible(conn, cancel, what):
            yield
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


@contextmanager
def _postgres_interruptible(conn: Any, cancel: Cancel, what: str) -> Iterator[None]:
    """A watcher thread asks the PostgreSQL server to cancel the running
    statement once `cancel` is set (db/engine/postgres.py's cancel_statement)."""
    done = threading.Event()

    def watch() -> None:
        while not done.wait(CANCEL_POLL_S):
            if cancel.is_set():
                conn.cancel_statement()
                return

    watcher = threading.Thread(target=watch, name="sass-cancel", daemon=True)
    watcher.start()
    try:
        yield
    except SassError:
        if cancel.is_set():
            raise Cancelled(what) from None
        raise
    finally:
        done.set()
        watcher.join()
    if cancel.is_set():
        raise Cancelled(what)
