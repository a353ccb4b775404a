"""`sass serve` refuses whoever lacks this run's token, and pages of other
sites, before any session process starts (ui/serve/serve.py); remote listening is
a choice; a session's process is gone soon after its tab closes.

Each test starts the real server on a free port and talks HTTP and
WebSocket to it as a browser (or another site's page) would."""

from __future__ import annotations

import asyncio
import http.client
import re
import shutil
import socket
import ssl
import subprocess
import sys
import time
from pathlib import Path

import pytest
from _serve import Served, start_serve, wait_until

aiohttp = pytest.importorskip("aiohttp")

ESCAPES = re.compile(
    r"\x1b\[[0-9;?<>=]*[ -/]*[@-~]|\x1b\][^\x07\x1b]*(?:\x07|\x1b\\)|\x1b[()][0-9A-B]"
)
READY = "Press left-mouse to select items."
PATHS = ["/", "/ws", "/static/js/textual.js", "/download/0123456789abcdef"]
# What a browser sends to open a WebSocket (RFC 6455 §4.1).
UPGRADE = {
    "Connection": "Upgrade",
    "Upgrade": "websocket",
    "Sec-WebSocket-Version": "13",
    "Sec-WebSocket-Key": "dGhlIHNhbXBsZSBub25jZQ==",
}


@pytest.fixture
def server(tmp_path):
    served = start_serve(tmp_path, "--workdir", "work", "--db", str(tmp_path / "none.db"))
    yield served
    served.stop()


def get(served: Served, path: str, headers: dict[str, str] | None = None, host: str = "localhost"):
    connection = http.client.HTTPConnection(host, served.port, timeout=10)
    try:
        connection.request("GET", path, headers=headers or {})
        response = connection.getresponse()
        return response.status, dict(response.getheaders()), response.read().decode()
    finally:
        connection.close()


def test_without_the_token_every_request_is_refused(server):
    for path in PATHS:
        headers = {**UPGRADE, "Origin": server.origin} if path == "/ws" else {}
        status, _, body = get(server, path, headers)
        assert status == 403, path
        assert "open the URL `sass serve` printed" in body
    assert server.children() == []


def test_a_wrong_token_is_refused_in_the_url_and_in_the_cookie(server):
    wrong = server.token[:-1] + ("A" if server.token[-1] != "A" else "B")
    for path in PATHS:
        status, _, _ = get(server, f"{path}?token={wrong}")
        assert status == 403, path
        status, _, _ = get(server, path, {"Cookie": f"sass-token-{server.port}={wrong}"})
        assert status == 403, path
    assert server.children() == []
    assert server.token not in server.output.read_text().replace(server.url, "")


def test_the_token_once_in_the_url_then_a_strict_http_only_cookie(server):
    status, headers, _ = get(server, f"/?token={server.token}&fontsize=18")
    assert status == 303
    assert headers["Location"] == "/?fontsize=18"  # the token leaves the address bar
    cookie = headers["Set-Cookie"]
    assert cookie.startswith(f"sass-token-{server.port}={server.token};")
    assert "HttpOnly" in cookie
    assert "SameSite=Strict" in cookie
    assert "Path=/" in cookie
    for path in ("/", "/static/js/textual.js"):
        status, _, body = get(server, path, {"Cookie": server.cookie})
        assert status == 200, path
    status, _, page = get(server, "/", {"Cookie": server.cookie})
    assert f'data-session-websocket-url="ws://localhost:{server.port}/ws"' in page
    # Undelivered key: past the checks, textual-serve's own 404.
    status, _, _ = get(server, "/download/0123456789abcdef", {"Cookie": server.cookie})
    assert status == 404


def test_another_sites_page_is_refused_before_a_process_starts(server):
    for path, headers in (
        ("/ws", {**UPGRADE, "Origin": "http://evil.example"}),
        ("/ws", {**UPGRADE, "Origin": f"http://localhost:{server.port + 1}"}),
        ("/ws", {**UPGRADE, "Origin": server.origin, "Sec-Fetch-Site": "cross-site"}),
        ("/ws", UPGRADE),  # no Origin: no browser's page (it was accepted with the token)
        ("/download/0123456789abcdef", {"Origin": "http://evil.example"}),
        ("/download/0123456789abcdef", {"Sec-Fetch-Site": "cross-site"}),
    ):
        status, _, body = get(server, path, {**headers, "Cookie": server.cookie})
        assert status == 403, (path, headers)
    assert server.children() == []
    # A name that only resolves here (DNS rebinding): its own origin, still refused.
    rebound = {**UPGRADE, "Host": f"evil.example:{server.port}"}
    rebound["Origin"] = f"http://evil.example:{server.port}"
    status, _, body = get(server, f"/ws?token={server.token}", rebound)
    assert status == 403
    assert "not this server's" in body
    assert server.children() == []


async def session(served: Served, origin: str):
    """A WebSocket session as the page opens it; returns it once the
    spreadsheet is on it, with the text received."""
    client = aiohttp.ClientSession()
    socket = await client.ws_connect(
        f"ws://localhost:{served.port}/ws?width=120&height=40",
        headers={"Origin": origin, "Cookie": served.cookie},
    )
    await socket.send_json(["resize", {"width": 120, "height": 40}])
    text = ""
    async with asyncio.timeout(60):
        while READY not in text:
            message = await socket.receive()
            if message.type == aiohttp.WSMsgType.BINARY:
                text += ESCAPES.sub("", message.data.decode("utf-8", "replace"))
            elif message.type != aiohttp.WSMsgType.TEXT:
                raise AssertionError(f"the session ended: {message}; {text[-500:]}")
    return client, socket


def test_a_session_runs_and_its_process_is_gone_within_5_s_of_closing(tmp_path):
    served = start_serve(
        tmp_path, "--workdir", "work", "--db", str(tmp_path / "none.db"), "--max-sessions", "1"
    )
    try:

        async def scenario() -> float:
            client, socket = await session(served, served.origin)
            try:
                (pid,) = served.children()
                # One session is the most: the next is refused, and starts nothing.
                with pytest.raises(aiohttp.WSServerHandshakeError) as refused:
                    await client.ws_connect(
                        f"ws://localhost:{served.port}/ws",
                        headers={"Origin": served.origin, "Cookie": served.cookie},
                    )
                assert refused.value.status == 503
                assert served.children() == [pid]
                await socket.close()  # the tab closes
                closed = time.monotonic()
                await asyncio.to_thread(
                    wait_until,
                    lambda: not Path(f"/proc/{pid}").exists(),
                    10,
                    "the session's process outlived its tab",
                )
                return time.monotonic() - closed
            finally:
                await client.close()

        gone_after = asyncio.run(scenario())
        print(f"session process gone {gone_after:.2f} s after its tab closed")
        assert gone_after < 5.0
    finally:
        served.stop()


def test_a_served_session_starts_in_the_working_directory(tmp_path):
    """Without --workdir, a new directory under the user's data directory,
    printed; the session's process runs there and is told it."""
    data = tmp_path / "data"
    served = start_serve(
        tmp_path, "--db", str(tmp_path / "none.db"), env={"XDG_DATA_HOME": str(data)}
    )
    try:
        printed = re.search(r"read and write files in (\S+)", served.output.read_text())
        assert printed, served.output.read_text()
        workdir = Path(printed[1])
        assert workdir.parent == data / "sass" / "serve"
        assert workdir.is_dir()

        async def scenario() -> None:
            client, socket = await session(served, served.origin)
            try:
                (pid,) = served.children()
                assert Path(f"/proc/{pid}/cwd").resolve() == workdir
                environ = Path(f"/proc/{pid}/environ").read_bytes().split(b"\0")
                assert f"SASS_WORKDIR={workdir}".encode() in environ
            finally:
                await socket.close()
                await client.close()

        asyncio.run(scenario())
    finally:
        served.stop()
    # Nothing saved in it: the folder this run made goes with it (every run left one).
    assert not workdir.exists()


def sass_serve(*options: str, cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "sass_tui", "serve", *options],
        capture_output=True,
        text=True,
        timeout=60,
        cwd=cwd,
    )


def test_listening_beyond_this_machine_needs_allow_remote(tmp_path):
    done = sass_serve("--host", "0.0.0.0", "--port", "1", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr.startswith("sass serve: error: --host 0.0.0.0 is reachable from other")
    assert "Add --allow-remote if you mean it" in done.stderr
    assert "Traceback" not in done.stderr
    assert done.stdout == ""


def test_remote_without_tls_is_served_with_a_warning(tmp_path):
    served = start_serve(
        tmp_path, "--host", "0.0.0.0", "--allow-remote", "--workdir", "w", "--db", "none.db"
    )
    try:
        out = served.output.read_text()
        assert "warning: 0.0.0.0 serves plain HTTP" in out
        assert "--certfile/--keyfile" in out
        # Reached by this machine's address: the page's socket goes back to it.
        status, _, page = get(served, "/", {"Cookie": served.cookie}, host="127.0.0.1")
        assert status == 200
        assert f'"ws://127.0.0.1:{served.port}/ws"' in page
        status, _, _ = get(served, "/", host="127.0.0.1")
        assert status == 403
    finally:
        served.stop()


@pytest.mark.skipif(not shutil.which("openssl"), reason="the openssl command is not installed")
def test_tls_serves_https_with_a_secure_cookie(tmp_path):
    cert, key = tmp_path / "cert.pem", tmp_path / "key.pem"
    subprocess.run(
        ["openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1"]
        + ["-subj", "/CN=localhost", "-keyout", str(key), "-out", str(cert)],
        check=True,
        capture_output=True,
    )
    served = start_serve(
        tmp_path,
        "--workdir",
        "w",
        "--db",
        "none.db",
        "--certfile",
        str(cert),
        "--keyfile",
        str(key),
    )
    try:
        assert served.url.startswith(f"https://localhost:{served.port}/?token=")
        context = ssl.create_default_context(cafile=str(cert))
        connection = http.client.HTTPSConnection("localhost", served.port, context=context)
        connection.request("GET", f"/?token={served.token}")
        response = connection.getresponse()
        assert response.status == 303
        assert "Secure" in response.getheader("Set-Cookie")
        response.read()
        connection.request("GET", "/", headers={"Cookie": served.cookie})
        page = connection.getresponse().read().decode()
        assert f'"wss://localhost:{served.port}/ws"' in page
        connection.close()
    finally:
        served.stop()


@pytest.mark.parametrize(
    "content, why",
    [("short\n", "5 characters"), ("a" * 30 + "%$\n", "characters '$%' are not allowed")],
)
def test_a_token_file_must_hold_128_bits(tmp_path, content, why):
    (tmp_path / "token").write_text(content)
    done = sass_serve("--token-file", "token", "--port", "1", cwd=tmp_path)
    assert done.returncode == 2
    assert "token:1: the token must be at least 22 characters" in done.stderr
    assert why in done.stderr


def test_a_token_file_gives_the_token(tmp_path):
    token = "Scripted-token_0123456789abcdefXYZ"
    (tmp_path / "token").write_text(token + "\n")
    served = start_serve(tmp_path, "--workdir", "w", "--db", "none.db", "--token-file", "token")
    try:
        assert served.token == token
        assert get(served, f"/?token={token}")[0] == 303
    finally:
        served.stop()


def test_behind_a_reverse_proxy_its_public_url_is_this_servers(tmp_path):
    public = "https://sass.example.org"
    served = start_serve(
        tmp_path, "--workdir", "w", "--db", "none.db", "--public-url", public + "/"
    )
    try:
        assert served.url == f"{public}/?token={served.token}"
        proxied = {"Host": "sass.example.org"}  # nginx: proxy_set_header Host $host
        status, headers, _ = get(served, f"/?token={served.token}", proxied)
        assert status == 303
        assert "Secure" in headers["Set-Cookie"]  # the browser's side is https
        status, _, page = get(served, "/", {**proxied, "Cookie": served.cookie})
        assert status == 200
        assert 'data-session-websocket-url="wss://sass.example.org/ws"' in page
        evil = {**proxied, **UPGRADE, "Cookie": served.cookie, "Origin": "https://evil.example"}
        assert get(served, "/ws", evil)[0] == 403
        assert get(served, "/", {"Host": "other.example.org", "Cookie": served.cookie})[0] == 403
        assert served.children() == []
    finally:
        served.stop()


def test_without_the_serve_extra_sass_serve_says_what_to_install(monkeypatch, capsys):
    import importlib.util

    from sass_tui.cli import main

    real = importlib.util.find_spec
    monkeypatch.setattr(
        importlib.util,
        "find_spec",
        lambda name, *a: None if name == "textual_serve" else real(name, *a),
    )
    assert main(["serve", "--port", "1"]) == 2
    assert capsys.readouterr().err == (
        "sass serve: error: sass serve needs textual-serve: pip install 'sass-tui[serve]'\n"
    )


def test_open_opens_the_printed_url_in_the_browser(tmp_path):
    # webbrowser runs $BROWSER with the URL for %s: here a script that keeps it.
    opened = tmp_path / "opened.txt"
    keep = tmp_path / "keep.py"
    keep.write_text(f"import sys\nopen({str(opened)!r}, 'w').write(sys.argv[1])\n")
    served = start_serve(
        tmp_path,
        "--workdir",
        "w",
        "--db",
        "none.db",
        "--open",
        env={"BROWSER": f"{sys.executable} {keep} %s"},
    )
    try:
        wait_until(opened.exists, 20, "the browser was never opened")
        wait_until(lambda: opened.read_text(), 20, "the browser got no URL")
        assert opened.read_text() == served.url
    finally:
        served.stop()


def test_a_loopback_address_is_printed_as_given(tmp_path):
    served = start_serve(tmp_path, "--host", "127.0.0.1", "--workdir", "w", "--db", "none.db")
    try:
        assert served.url.startswith(f"http://127.0.0.1:{served.port}/?token=")
        assert get(served, f"/?token={served.token}", host="127.0.0.1")[0] == 303
    finally:
        served.stop()


def test_a_port_in_use_is_said_and_no_url_printed(tmp_path):
    with socket.socket() as busy:
        busy.bind(("127.0.0.1", 0))
        busy.listen()
        port = busy.getsockname()[1]
        done = sass_serve(
            "--host",
            "127.0.0.1",
            "--port",
            str(port),
            "--workdir",
            "w",
            "--db",
            "none.db",
            cwd=tmp_path,
        )
    assert done.returncode == 2
    assert "address already in use" in done.stderr
    assert "Traceback" not in done.stderr
    assert "token=" not in done.stdout + done.stderr
