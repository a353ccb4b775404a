"""One browser session of `sass serve`: its `sass` process, from start to end.

textual-serve's `AppService` starts the process through a shell and relays
its output to the browser's WebSocket.  `SessionService` is that service
with what a lab server needs (docs/reliability.md, "sass serve"):

- the process is started without a shell, in the served working directory,
  told the database and whether it is read-only, and is the process stopped;
- its terminal is at most `MAX_COLUMNS` x `MAX_ROWS`, asked for in the URL or
  in a resize message (one 10000 x 10000 request made a child take 1 GB and
  push 408 MB in a minute);
- it dies with the server: Linux's parent-death signal (prctl
  PR_SET_PDEATHSIG) kills it when `sass serve` ends, even by SIGKILL, so no
  session holds its database connection for ever;
- when it ends by itself (a crash, the OOM killer, `kill -9`), the browser
  is told so and its WebSocket closed, which frees the session's
  `--max-sessions` slot (textual-serve's `AppService.run()` returns on the
  output's end and leaves the socket open: the tab froze without a word).

Imported only by ui/serve/serve.py, on `sass serve`'s path.
"""

from __future__ import annotations

import asyncio
import ctypes
import ctypes.util
import logging
import os
import signal
import sys
from collections.abc import Awaitable, Callable
from typing import TYPE_CHECKING

from textual_serve.app_service import AppService

from sass_tui.model.served import READ_ONLY_ENV, WORKDIR_ENV

if TYPE_CHECKING:
    from sass_tui.ui.serve.serve import ServeOptions

log = logging.getLogger("sass.serve")

# A session's process gets this long to quit on textual-serve's "quit"
# message, then as long again to exit once its output has closed; then it is
# killed.  Twice this is under the 5 s promised in docs/user-guide.md.
STOP_WAIT_S = 2.0
# The largest terminal a session gets: a 4K screen at a 9-pixel font is
# about 420 x 120 cells; a larger request is cut to this.
MAX_COLUMNS = 400
MAX_ROWS = 150
# The WebSocket close code for "the server met a condition that kept it
# from going on" (RFC 6455 §7.4.1): the session's process ended by itself.
PROCESS_ENDED = 1011
# Shown in the browser's terminal before its socket closes.
ENDED_NOTICE = (
    "\r\n\x1b[0m\x1b[?1049l\r\nsass serve: this session's process ended ({how}); "
    "nothing more can be done in it. Reload the page (or press Restart) for a new "
    "session.\r\n"
)
# linux/prctl.h
PR_SET_PDEATHSIG = 1


def clamped_size(width: object, height: object) -> tuple[int, int]:
    """A terminal size from a browser (text or numbers, any size) as one a
    session gets: whole numbers from 1 up to MAX_COLUMNS x MAX_ROWS; what is
    not a whole number is the default 80 x 24."""
    return _clamp(width, 80, MAX_COLUMNS), _clamp(height, 24, MAX_ROWS)


def _clamp(value: object, default: int, largest: int) -> int:
    try:
        number = int(value)  # type: ignore[call-overload]
    except (TypeError, ValueError, OverflowError):
        return default
    return min(max(number, 1), largest)


def _libc_prctl() -> Callable[..., int] | None:
    """libc's prctl, on Linux; None elsewhere (macOS has no parent-death
    signal: there a session outlives a killed server until it next writes)."""
    if not sys.platform.startswith("linux"):
        return None
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
    except OSError:
        return None
    prctl: Callable[..., int] = libc.prctl
    return prctl


_PRCTL = _libc_prctl()


def die_with_parent(parent: int) -> Callable[[], None] | None:
    """What the child runs between fork and exec (Popen's preexec_fn): ask
    the kernel for SIGKILL when the server (`parent`) dies, and die at once
    if it died already.  SIGKILL, not SIGTERM: nobody can see or drive the
    session any more, and the databases roll back a killed client's
    unfinished transaction.  It calls one C function, takes no lock and
    imports nothing (Python's warning about preexec_fn and threads is about
    those)."""
    prctl = _PRCTL
    if prctl is None:
        return None

    def in_child() -> None:
        prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        if os.getppid() != parent:  # the server died before prctl
            os.kill(os.getpid(), signal.SIGKILL)

    return in_child


class SessionService(AppService):
    """One browser session's `sass` process: started without a shell in the
    served working directory, surely gone when the session stops or the
    server dies, and said to have ended when it ends by itself."""

    def __init__(
        self,
        options: ServeOptions,
        *,
        close_with: Callable[[int, str], Awaitable[object]],
        **kwargs,
    ) -> None:
        super().__init__(" ".join(options.command()), **kwargs)
        self.options = options
        self.close_with = close_with  # the WebSocket's close(code, reason)
        self.stopping = False
        # The process has ended (or is being stopped): the session no longer
        # holds a slot of --max-sessions, though its socket may still close.
        self.ended = False

    def _build_environment(self, width: int = 80, height: int = 24) -> dict[str, str]:
        environment = super()._build_environment(width, height)
        environment[WORKDIR_ENV] = str(self.options.workdir)
        environment[READ_ONLY_ENV] = "1" if self.options.read_only else ""
        if isinstance(self.options.db, str):  # a PostgreSQL address (its password too)
            environment["SASS_DB"] = self.options.db
        return environment

    async def _open_app_process(self, width: int = 80, height: int = 24):
        # textual-serve starts a shell, which may outlive a killed child;
        # without one the process stopped is the process started.
        pipe = asyncio.subprocess.PIPE
        width, height = clamped_size(width, height)
        self._process = process = await asyncio.create_subprocess_exec(
            *self.options.command(),
            stdin=pipe,
            stdout=pipe,
            stderr=pipe,
            env=self._build_environment(width=width, height=height),
            cwd=self.options.workdir,
            preexec_fn=die_with_parent(os.getpid()),
        )
        assert process.stdin is not None
        self._stdin = process.stdin
        return process

    async def set_terminal_size(self, width: int, height: int) -> None:
        await super().set_terminal_size(*clamped_size(width, height))

    @property
    def pid(self) -> int | None:
        return self._process.pid if self._process is not None else None

    async def run(self) -> None:
        """textual-serve's relay, then: a process that ended without being
        asked to (its output closed) is said to have ended, and the socket
        closed, which ends the session and frees its slot."""
        await super().run()
        process = self._process
        if self.stopping or process is None:
            return
        try:
            status = await asyncio.wait_for(process.wait(), STOP_WAIT_S)
        except TimeoutError:  # its output closed, yet it runs: it is ended here
            process.kill()
            status = await process.wait()
        # The slot is free before the socket closes: a browser reconnecting as
        # soon as it sees the close is let in.
        self.ended = True
        if status == 0:  # the app quit (Ctrl+Q): textual-serve has closed the socket
            await self.close_with(1000, "the session ended")
            return
        how = f"killed by signal {-status}" if status < 0 else f"exit status {status}"
        log.warning("session %s ended by itself (%s)", process.pid, how)
        try:
            await self.remote_write_bytes(ENDED_NOTICE.format(how=how).encode())
        except (ConnectionError, RuntimeError):
            pass  # the browser went first
        await self.close_with(PROCESS_ENDED, f"the session's process ended ({how})")

    async def stop(self) -> None:
        self.stopping = True
        self.ended = True
        process = self._process
        try:
            await asyncio.wait_for(super().stop(), STOP_WAIT_S)
        except (TimeoutError, ConnectionError):
            pass
        if process is None:
            return
        try:
            await asyncio.wait_for(process.wait(), STOP_WAIT_S)
        except TimeoutError:
            log.warning("session process %s did not quit: killed", process.pid)
            process.kill()
            await process.wait()
