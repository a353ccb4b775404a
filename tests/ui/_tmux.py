"""`sass` in a real terminal: a tmux pane on a server of the test's own,
read with capture-pane and driven with send-keys (which writes the keys of
one command to the terminal at once)."""

from __future__ import annotations

import contextlib
import os
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

WAIT_S = 30.0
POLL_S = 0.02


class Pane:
    def __init__(self, socket: str, session: str) -> None:
        self.socket, self.session = socket, session

    def tmux(self, *args: str) -> str:
        done = subprocess.run(["tmux", "-L", self.socket, *args], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done.stdout

    def text(self) -> str:
        return self.tmux("capture-pane", "-p", "-t", self.session)

    def send(self, *keys: str) -> None:
        """tmux key names (Down, Enter, C-s) or text, written together."""
        self.tmux("send-keys", "-t", self.session, *keys)

    def wait_for(self, condition: Callable[[str], bool], what: str) -> None:
        """Poll the pane until `condition(text)` holds (no fixed wait)."""
        deadline = time.monotonic() + WAIT_S
        while time.monotonic() < deadline:
            if condition(self.text()):
                return
            time.sleep(POLL_S)  # between two reads of the pane
        raise AssertionError(f"{what}; the pane:\n{self.text()}")

    def wait_for_exit(self, what: str) -> None:
        """Poll until the program has ended (its session with it)."""
        deadline = time.monotonic() + WAIT_S
        while time.monotonic() < deadline:
            alive = subprocess.run(
                ["tmux", "-L", self.socket, "has-session", "-t", self.session],
                capture_output=True,
            )
            if alive.returncode:
                return
            time.sleep(POLL_S)  # between two asks
        raise AssertionError(f"{what}; the pane:\n{self.text()}")


@contextlib.contextmanager
def sass_in_tmux(workdir: Path, *arguments: str, size=(120, 40)) -> Iterator[Pane]:
    """`python -m sass_tui ARGUMENTS` in a detached tmux session; the server
    is killed afterwards."""
    socket = f"sass-test-{os.getpid()}-{time.monotonic_ns()}"
    environment = {**os.environ, "XDG_CONFIG_HOME": str(workdir), "TERM": "xterm-256color"}
    command = [sys.executable, "-m", "sass_tui", *arguments]
    width, height = size
    subprocess.run(
        ["tmux", "-L", socket, "-f", os.devnull, "new-session", "-d", "-s", "sass",
         "-x", str(width), "-y", str(height), *command],
        check=True, env=environment, cwd=workdir,
    )  # fmt: skip
    try:
        yield Pane(socket, "sass")
    finally:
        subprocess.run(["tmux", "-L", socket, "kill-server"], capture_output=True)
