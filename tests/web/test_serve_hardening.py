"""A served lab stays up (ui/serve/serve.py, ui/serve/serve_session.py): a session whose
process dies closes its WebSocket with a word and frees its slot; the
server's death takes its sessions with it; a terminal size is clamped; every
response carries framing, referrer and content-security headers; the page's
font comes from the package.

Each test starts the real `sass serve` on 127.0.0.1 and a free port and
talks to it as the page does; every wait is bounded, and every process it
started is ended."""

from __future__ import annotations

import asyncio
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from _serve import Served, start_serve, wait_until

aiohttp = pytest.importorskip("aiohttp")

from sass_tui.ui.serve.serve_session import MAX_COLUMNS, MAX_ROWS, clamped_size  # noqa: E402

ESCAPES = re.compile(
    r"\x1b\[[0-9;?<>=]*[ -/]*[@-~]|\x1b\][^\x07\x1b]*(?:\x07|\x1b\\)|\x1b[()][0-9A-B]"
)
READY = "Press left-mouse to select items."


@pytest.fixture
def one_session(tmp_path):
    served = start_serve(
        tmp_path, "--workdir", "work", "--db", str(tmp_path / "none.db"), "--max-sessions", "1"
    )
    yield served
    served.stop()


async def open_session(served: Served, width: int = 120, height: int = 40):
    """The page's WebSocket, once the spreadsheet is on it: (client, socket,
    bytes received so far)."""
    client = aiohttp.ClientSession()
    socket = await client.ws_connect(
        f"ws://localhost:{served.port}/ws?width={width}&height={height}",
        headers={"Origin": served.origin, "Cookie": served.cookie},
        max_msg_size=0,
    )
    received = 0
    text = ""
    async with asyncio.timeout(60):
        while READY not in text:
            message = await socket.receive()
            if message.type == aiohttp.WSMsgType.BINARY:
                received += len(message.data)
                text += ESCAPES.sub("", message.data.decode("utf-8", "replace"))
            elif message.type != aiohttp.WSMsgType.TEXT:
                await client.close()
                raise AssertionError(f"the session ended: {message}; {text[-500:]}")
    return client, socket, received


def session_environment(pid: int) -> dict[str, str]:
    raw = Path(f"/proc/{pid}/environ").read_bytes().split(b"\0")
    return dict(item.decode().split("=", 1) for item in raw if b"=" in item)


@pytest.mark.slow
def test_a_killed_session_closes_its_socket_and_frees_its_slot(one_session):
    served = one_session

    async def scenario() -> None:
        client, socket, _ = await open_session(served)
        try:
            (pid,) = served.children()
            os.kill(pid, signal.SIGKILL)  # a crash, or the OOM killer
            killed = time.monotonic()
            said = b""
            async with asyncio.timeout(20):
                while True:
                    message = await socket.receive()
                    if message.type == aiohttp.WSMsgType.BINARY:
                        said += message.data
                    elif message.type != aiohttp.WSMsgType.TEXT:
                        break
            print(f"the socket closed {time.monotonic() - killed:.2f} s after the kill")
            assert message.type in (aiohttp.WSMsgType.CLOSE, aiohttp.WSMsgType.CLOSED)
            assert socket.close_code == 1011
            assert b"this session's process ended (killed by signal 9)" in said
        finally:
            await client.close()
        # --max-sessions 1: the slot is free again, and a new session runs.
        client, socket, _ = await open_session(served)
        try:
            (new_pid,) = served.children()
            assert new_pid != pid
        finally:
            await client.close()

    asyncio.run(scenario())
    log = served.output.read_text()
    assert re.search(r"session \d+ started", log)
    assert re.search(r"session \d+ ended by itself \(killed by signal 9\)", log)


@pytest.mark.slow
def test_the_sessions_die_with_a_killed_server(tmp_path):
    served = start_serve(tmp_path, "--workdir", "work", "--db", str(tmp_path / "none.db"))
    pids: list[int] = []
    try:

        async def scenario() -> None:
            clients = [await open_session(served) for _ in range(2)]
            pids.extend(served.children())
            assert len(pids) == 2
            served.process.send_signal(signal.SIGKILL)  # no handler runs
            served.process.wait(10)
            killed = time.monotonic()
            await asyncio.to_thread(
                wait_until,
                lambda: not any(Path(f"/proc/{pid}").exists() for pid in pids),
                10,
                "a session's process outlived its server",
            )
            print(f"both sessions gone {time.monotonic() - killed:.2f} s after the server")
            for client, _, _ in clients:
                await client.close()

        asyncio.run(scenario())
    finally:
        for pid in pids:  # only if the test failed
            if Path(f"/proc/{pid}").exists():
                os.kill(pid, signal.SIGKILL)
        if served.process.poll() is None:
            served.stop()


def test_a_terminal_size_is_clamped():
    assert clamped_size("3000", "3000") == (MAX_COLUMNS, MAX_ROWS)
    assert clamped_size(100000, 100000) == (MAX_COLUMNS, MAX_ROWS)
    assert clamped_size("120", "40") == (120, 40)
    assert clamped_size("-5", "0") == (1, 1)
    assert clamped_size("9" * 4000, None) == (MAX_COLUMNS, 24)
    assert clamped_size("wide", 1.5) == (80, 1)


@pytest.mark.slow
def test_a_3000_by_3000_terminal_gets_a_bounded_screen(one_session):
    """Asked for 3000 x 3000 in the URL and in a resize message, the session
    runs at 400 x 150 and pushes what such a screen takes: unclamped, one
    frame of 3000 x 3000 cells is over 9 MB."""
    served = one_session

    async def scenario() -> tuple[int, int]:
        client, socket, first = await open_session(served, 3000, 3000)
        try:
            (pid,) = served.children()
            environment = session_environment(pid)
            assert (environment["COLUMNS"], environment["ROWS"]) == ("400", "150")
            await socket.send_json(["resize", {"width": 3000, "height": 3000}])
            await socket.send_json(["stdin", "j"])  # Joint Limits: the screen is redrawn
            after = 0
            text = ""
            async with asyncio.timeout(30):
                while "Neck ul" not in text:
                    message = await socket.receive()
                    assert message.type in (aiohttp.WSMsgType.BINARY, aiohttp.WSMsgType.TEXT)
                    if message.type == aiohttp.WSMsgType.BINARY:
                        after += len(message.data)
                        text += ESCAPES.sub("", message.data.decode("utf-8", "replace"))
            return first, after
        finally:
            await client.close()

    first, after = asyncio.run(scenario())
    print(f"3000 x 3000 asked: first screen {first:,} bytes, redrawn {after:,} bytes")
    # a 400 x 150 screen of truecolor cells: at most some 40 bytes a cell
    bound = 40 * MAX_COLUMNS * MAX_ROWS
    assert first < bound and after < bound


def fetch(served: Served, path: str, host: str = "localhost") -> tuple[int, dict, bytes]:
    async def go():
        async with aiohttp.ClientSession() as client:
            async with client.get(
                f"http://127.0.0.1:{served.port}{path}",
                headers={"Cookie": served.cookie, "Host": host},
                allow_redirects=False,
            ) as response:
                return response.status, dict(response.headers), await response.read()

    return asyncio.run(go())


@pytest.mark.slow
def test_every_response_forbids_framing_and_referrers(tmp_path):
    served = start_serve(tmp_path, "--workdir", "work", "--db", str(tmp_path / "none.db"))
    try:
        for path in ("/", "/static/js/textual.js", "/download/0123", "/nothing"):
            _, headers, _ = fetch(served, path)
            assert headers["X-Frame-Options"] == "DENY", path
            assert headers["Referrer-Policy"] == "no-referrer", path
            policy = headers["Content-Security-Policy"]
            assert "frame-ancestors 'none'" in policy and "default-src 'self'" in policy
            assert "unsafe-inline" not in policy.split("script-src", 1)[1].split(";")[0]
        # refused requests carry them too
        _, headers, _ = fetch(served, "/", host="evil.example")
        assert headers["X-Frame-Options"] == "DENY"
    finally:
        served.stop()


@pytest.mark.slow
def test_the_page_loads_nothing_from_another_server(tmp_path):
    served = start_serve(tmp_path, "--workdir", "work", "--db", str(tmp_path / "none.db"))
    try:
        status, _, page = fetch(served, "/")
        assert status == 200
        text = page.decode()
        assert "googleapis" not in text and "gstatic" not in text
        loaded = re.findall(r'(?:src|href)="([^"]+)"|url\("([^"]+)"\)', text)
        urls = [a or b for a, b in loaded]
        assert urls and all(url.startswith("/static/") for url in urls), urls
        fonts = [url for url in urls if url.endswith(".ttf")]
        assert len(fonts) == 2
        for font in fonts:
            status, headers, body = fetch(served, font)
            assert status == 200 and body[:4] == b"\x00\x01\x00\x00"  # a TrueType font
    finally:
        served.stop()


@pytest.mark.slow
def test_a_host_with_a_user_part_is_refused(tmp_path):
    """`evil.com@localhost:P` is read by urlsplit as the host localhost;
    `[1.2.3]` made urlsplit raise (a 500 and a traceback on the terminal)."""
    served = start_serve(tmp_path, "--workdir", "work", "--db", str(tmp_path / "none.db"))
    hosts = (f"evil.com@localhost:{served.port}", f"localhost:{served.port}/x", "a b")
    try:
        for host in (*hosts, f"[1.2.3]:{served.port}", "[:::::]"):
            status, _, body = fetch(served, "/", host=host)
            assert status == 403, host
            assert b"is not this server's" in body
        status, _, _ = fetch(served, "/", host=f"localhost:{served.port}")
        assert status == 200
    finally:
        served.stop()


@pytest.mark.slow
def test_port_0_prints_the_port_it_listens_on(tmp_path):
    """`--port 0` lets the system choose: the printed URL names the port
    chosen, not 0."""
    output = tmp_path / "serve.out"
    with output.open("w") as sink:
        process = subprocess.Popen(
            [
                sys.executable,
                "-m",
                "sass_tui",
                "serve",
                "--port",
                "0",
                "--workdir",
                "work",
                "--db",
                str(tmp_path / "n.db"),
            ],
            stdout=sink,
            stderr=subprocess.STDOUT,
            cwd=tmp_path,
        )
    try:
        found = wait_until(
            lambda: re.search(r"open http://localhost:(\d+)/", output.read_text()),
            30,
            f"no URL printed:\n{output.read_text()}",
        )
        assert int(found.group(1)) != 0
    finally:
        process.terminate()
        process.wait(10)
