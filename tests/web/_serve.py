"""Starting `sass serve` for a test: a free port, its printed URL read from
its output, its session processes found in /proc."""

from __future__ import annotations

import os
import re
import socket
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

URL_LINE = re.compile(r"sass serve: open (?P<url>(?P<base>https?://[^/]+/)\?token=(?P<token>\S+))")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_until(condition, timeout: float, what: str):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    raise TimeoutError(what)


@dataclass
class Served:
    process: subprocess.Popen
    port: int
    url: str  # the printed URL, with the token
    base: str  # without it
    token: str
    output: Path  # everything the server printed

    @property
    def origin(self) -> str:
        return self.base.rstrip("/")

    @property
    def cookie(self) -> str:
        return f"sass-token-{self.port}={self.token}"

    def children(self) -> list[int]:
        """The server's live child processes (its sessions), from /proc: a
        killed session the server has not reaped yet (a zombie, state Z) is
        no longer one."""
        found = []
        for entry in Path("/proc").iterdir():
            if not entry.name.isdigit():
                continue
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            state, parent = stat.rsplit(")", 1)[1].split()[:2]
            if int(parent) == self.process.pid and state != "Z":
                found.append(int(entry.name))
        return found

    def stop(self) -> None:
        self.process.terminate()
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


def start_serve(directory: Path, *options: str, env: dict[str, str] | None = None) -> Served:
    """`sass serve --port FREE OPTIONS` in `directory`; returns once it listens."""
    port = free_port()
    output = directory / f"serve-{port}.out"
    with output.open("w") as sink:
        process = subprocess.Popen(
            [sys.executable, "-m", "sass_tui", "serve", "--port", str(port), *options],
            stdout=sink,
            stderr=subprocess.STDOUT,
            cwd=directory,
            env={**os.environ, **(env or {})},
        )
    try:
        found = wait_until(
            lambda: URL_LINE.search(output.read_text()) or process.poll() is not None,
            30,
            f"sass serve printed no URL:\n{output.read_text()}",
        )
        if process.poll() is not None:
            raise AssertionError(f"sass serve exited {process.returncode}:\n{output.read_text()}")

        def listening() -> bool:
            with socket.socket() as s:
                return s.connect_ex(("127.0.0.1", port)) == 0

        wait_until(listening, 30, f"sass serve did not listen on port {port}")
    except BaseException:
        process.kill()
        process.wait()
        raise
    return Served(process, port, found["url"], found["base"], found["token"], output)
