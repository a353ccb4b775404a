"""`sass serve`'s own memory over many sessions: is it bounded, or does each
session leave something behind?

Starts `sass serve` on a free port (an empty work folder, a database that
does not exist yet, one session at a time), then opens sessions one after
another as a browser would (the page's WebSocket with the printed token and
the page's Origin), waits for each spreadsheet to be drawn, closes it and
waits for its process to go.  After every `--every` sessions it reads the
server's resident memory (VmRSS, /proc) and the number of its open file
descriptors.  A leak grows without end; a heap that settles grows at first
and then stays.

    python benchmarks/serve_memory.py [--sessions 300] [--every 25]

Needs aiohttp (the `serve` extra brings it).
"""

from __future__ import annotations

import argparse
import asyncio
import datetime
import os
import re
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import aiohttp

URL_LINE = re.compile(r"sass serve: open (?P<base>https?://[^/]+/)\?token=(?P<token>\S+)")
READY = "Press left-mouse to select items."  # the spreadsheet's footer, drawn
# The terminal's escape sequences, taken out before looking for READY (a
# redraw may put one inside the footer's text).
ESCAPES = re.compile(
    r"\x1b\[[0-9;?<>=]*[ -/]*[@-~]|\x1b\][^\x07\x1b]*(?:\x07|\x1b\\)|\x1b[()][0-9A-B]"
)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def resident_kib(pid: int) -> int:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1])
    raise RuntimeError(f"no VmRSS for {pid}")


def open_descriptors(pid: int) -> int:
    return len(os.listdir(f"/proc/{pid}/fd"))


def children(pid: int) -> int:
    """Live (not zombie) child processes of `pid`."""
    count = 0
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            state, parent = (entry / "stat").read_text().rsplit(")", 1)[1].split()[:2]
        except OSError:
            continue
        count += int(parent) == pid and state != "Z"
    return count


async def one_session(port: int, origin: str, cookie: str) -> None:
    async with aiohttp.ClientSession() as client:
        ws = await client.ws_connect(
            f"ws://localhost:{port}/ws?width=120&height=40",
            headers={"Origin": origin, "Cookie": cookie},
            max_msg_size=0,
        )
        text = ""
        async with asyncio.timeout(60):
            while READY not in text:
                message = await ws.receive()
                if message.type == aiohttp.WSMsgType.BINARY:
                    text += ESCAPES.sub("", message.data.decode("utf-8", "replace"))
                elif message.type != aiohttp.WSMsgType.TEXT:
                    raise RuntimeError(f"the session ended: {message}")
        await ws.close()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sessions", type=int, default=300)
    parser.add_argument("--every", type=int, default=25)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        port = free_port()
        output = Path(folder) / "serve.out"
        with output.open("w") as sink:
            server = subprocess.Popen(
                [sys.executable, "-m", "sass_tui", "serve", "--port", str(port),
                 "--workdir", "work", "--db", str(Path(folder) / "none.db"),
                 "--max-sessions", "1"],
                stdout=sink, stderr=subprocess.STDOUT, cwd=folder,
            )  # fmt: skip
        try:
            found = None
            for _ in range(600):
                found = URL_LINE.search(output.read_text())
                if found or server.poll() is not None:
                    break
                time.sleep(0.05)
            if not found:
                raise SystemExit(f"sass serve printed no URL:\n{output.read_text()}")
            origin = found["base"].rstrip("/")
            cookie = f"sass-token-{port}={found['token']}"
            started = time.monotonic()
            print(
                f"{datetime.datetime.now(datetime.UTC):%Y-%m-%d %H:%M} UTC, {os.cpu_count()} cores, "
                f"Python {sys.version.split()[0]}, load average {os.getloadavg()[0]:.1f}"
            )
            print("| sessions | server RSS (MB) | open descriptors | seconds |")
            print("| ---: | ---: | ---: | ---: |")
            print(
                f"| 0 | {resident_kib(server.pid) / 1024:.1f} | {open_descriptors(server.pid)} | 0 |"
            )
            for done in range(1, args.sessions + 1):
                asyncio.run(one_session(port, origin, cookie))
                while children(server.pid):  # the session's process gone before the next
                    time.sleep(0.02)
                if done % args.every == 0:
                    print(
                        f"| {done} | {resident_kib(server.pid) / 1024:.1f} "
                        f"| {open_descriptors(server.pid)} | {time.monotonic() - started:.0f} |",
                        flush=True,
                    )
        finally:
            server.terminate()
            server.wait(10)
    return 0


if __name__ == "__main__":
    sys.exit(main())
