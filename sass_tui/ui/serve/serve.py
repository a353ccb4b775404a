"""`sass serve`: the same app in a web browser, through textual-serve.

textual-serve starts one `sass` process per browser session with Textual's
web driver; each session is the full TUI on the same database.  Whoever
drives a session reads every person in the database and writes files as
the user who started the server, so this module puts textual-serve's aiohttp
application behind the checks Jupyter's users know (its server's token and
origin checks), as a subclass and a middleware, not a fork:

- a secret per run: every request (page, WebSocket, static file, download)
  carries the token, in the URL once (`?token=`), then in an HttpOnly,
  SameSite=Strict cookie; compared in constant time (`hmac.compare_digest`);
- the Host a request names is one of the server's own (a page of another
  site that rebinds its name to 127.0.0.1 is refused);
- the WebSocket upgrade and downloads come from the server's own origin
  (cross-site WebSocket hijacking: a page of another site opening
  `ws://localhost:8000/ws` from the user's browser);
- at most `max_sessions` live sessions; a session's process is gone within
  `STOP_WAIT_S` twice over of its tab closing, when it ends by itself its tab
  is told and its slot freed, and it dies with the server (ui/serve/serve_session.py);
- every response forbids framing by other pages, sends no Referer and holds
  the page to its own scripts, styles, fonts and socket (`SECURITY_HEADERS`,
  `content_security_policy`); the page's font is the one textual-serve ships,
  not Google's (ui/serve/serve_page/app_index.html);
- each session's process runs in the served working directory, which its
  prompts do not leave (model/served.py, model/files/paths.py's `inside`), and is
  told whether the database is read-only.

Every refusal is an HTTP 403 (503 for a full house) sent before any process
is started, and is logged on the server's console without the token.

Imported only by `sass serve` (cli/serve.py), so textual-serve and aiohttp
are imported here at the top.
"""

from __future__ import annotations

import asyncio
import base64
import hashlib
import hmac
import logging
import re
import signal
import socket
import sys
import threading
import webbrowser
from collections.abc import Awaitable, Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import urlsplit

import aiohttp_jinja2
from aiohttp import web
from textual_serve.server import Server

from sass_tui.ui.serve.serve_session import STOP_WAIT_S, SessionService, clamped_size

if TYPE_CHECKING:
    import ssl

log = logging.getLogger("sass.serve")

TOKEN_PARAMETER = "token"
# Names that reach a loopback address from this machine only.
LOOPBACK_NAMES = frozenset({"localhost", "127.0.0.1", "::1"})


@dataclass(frozen=True)
class ServeOptions:
    """What `sass serve` was asked for (checked by cli/serve.py)."""

    host: str
    port: int
    token: str
    workdir: Path
    db: Path | str | None = None  # a SQLite file, or a PostgreSQL address (str)
    read_only: bool = False
    max_sessions: int = 8
    loopback: bool = True  # bound to this machine only
    public_url: str | None = None  # the URL users open, when a reverse proxy serves it
    ssl_context: ssl.SSLContext | None = None
    open_browser: bool = False

    @property
    def scheme(self) -> str:
        return "https" if self.ssl_context is not None else "http"

    @property
    def secure(self) -> bool:
        """Browsers reach it over TLS: its own, or a reverse proxy's."""
        return self.ssl_context is not None or (self.public_url or "").startswith("https:")

    @property
    def base_url(self) -> str:
        """The URL to open (without the token)."""
        if self.public_url:
            return self.public_url.rstrip("/") + "/"
        host = self.host  # the name or address given, which the server listens on
        if host in ("0.0.0.0", "::", ""):  # every interface: name this machine
            host = socket.getfqdn()
        if ":" in host:
            host = f"[{host}]"
        return f"{self.scheme}://{host}:{self.port}/"

    @property
    def url(self) -> str:
        """The URL to open, with the token: printed, and opened by --open."""
        return f"{self.base_url}?{TOKEN_PARAMETER}={self.token}"

    @property
    def cookie_name(self) -> str:
        # Cookies are not kept apart by port: two servers on localhost must not
        # overwrite each other's.
        return f"sass-token-{self.port}"

    def command(self) -> list[str]:
        command = [sys.executable, "-m", "sass_tui"]
        if isinstance(self.db, Path):  # an address travels in $SASS_DB, not in `ps`
            command += ["--db", str(self.db)]
        return command


def serve(options: ServeOptions) -> int:
    """Serve until Ctrl+C (or SIGTERM).  `--port 0`: the system chooses a
    free port, which is the one printed (and the one the cookie names)."""
    listener = None
    if options.port == 0:
        listener = socket.create_server((options.host, 0))
        options = replace(options, port=listener.getsockname()[1])
    SassServer(options, listener).serve()
    return 0


# --- the checks, one function each (the middleware calls them in turn) -------------


def host_refusal(options: ServeOptions, host_header: str) -> str | None:
    """Why the Host a request names is not this server's, or None.  Bound to
    loopback, only loopback names (and --public-url's host) are this server's:
    a page whose own name resolves to 127.0.0.1 (DNS rebinding) is refused."""
    if not options.loopback:
        return None  # every interface: the machine's names are not known
    name = _hostname(host_header)
    allowed = set(LOOPBACK_NAMES)
    if options.public_url:
        allowed.add((urlsplit(options.public_url).hostname or "").lower())
    return None if name in allowed else f"Host {host_header!r} is not this server's"


def token_matches(options: ServeOptions, given: str | None) -> bool:
    """The token given is this run's; compared in constant time."""
    if not given:
        return False
    return hmac.compare_digest(given.encode("utf-8", "replace"), options.token.encode("utf-8"))


def origin_refusal(
    options: ServeOptions,
    host_header: str,
    origin: str | None,
    fetch_site: str | None,
    *,
    websocket: bool = False,
) -> str | None:
    """Why a WebSocket upgrade or a download does not come from this server's
    own pages, or None.  Browsers send `Origin` with every WebSocket upgrade
    (RFC 6455 §4.1) and `Sec-Fetch-Site` with every request they make (W3C
    Fetch Metadata): an upgrade without `Origin` comes from no page of ours
    and is refused; a download by a client that is not a browser (a script
    with the token) sends neither and is served."""
    if fetch_site is not None and fetch_site not in ("same-origin", "none"):
        return f"Sec-Fetch-Site {fetch_site!r}: the request came from another site"
    if origin is None:
        return "a WebSocket upgrade without Origin (every browser sends one)" if websocket else None
    own = {f"{options.scheme}://{host_header}".lower()}
    if options.public_url:
        parts = urlsplit(options.public_url)
        own.add(f"{parts.scheme}://{parts.netloc}".lower())
    return None if origin.lower() in own else f"Origin {origin!r} is not this server's"


# RFC 9110 §7.2's Host: a name or an address, then an optional port; no
# user part (urlsplit reads `evil.com@localhost:8000` as the host localhost).
_HOST_HEADER = re.compile(r"(?:\[[0-9A-Fa-f:.]+\]|[A-Za-z0-9._-]+)(?::[0-9]{1,5})?")


def _hostname(host_header: str) -> str:
    """'localhost:8000' -> 'localhost'; '[::1]:8000' -> '::1'; '' for what
    is not a host and port ('evil.com@localhost:8000')."""
    if not _HOST_HEADER.fullmatch(host_header):
        return ""
    try:
        return (urlsplit(f"//{host_header}").hostname or "").lower()
    except ValueError:  # brackets around no IPv6 address ('[1.2.3]'): urlsplit checks them
        return ""


# --- the page's headers --------------------------------------------------------------

# The page sass serves in place of textual-serve's (which loads its font from
# fonts.googleapis.com and runs inline event handlers).
PAGE_DIRECTORY = Path(__file__).with_name("serve_page")
# On every response: no page of another origin may frame the live TUI
# (clickjacking: X-Frame-Options for older browsers, CSP frame-ancestors for
# the rest), no URL leaves in a Referer, and no type is sniffed.
SECURITY_HEADERS = {
    "X-Frame-Options": "DENY",
    "Referrer-Policy": "no-referrer",
    "X-Content-Type-Options": "nosniff",
    "Cross-Origin-Opener-Policy": "same-origin",
}


def _page_script_hash() -> str:
    """The CSP source of the page's one inline script: its SHA-256 (CSP 3
    §8.3), so that no other inline script runs."""
    page = (PAGE_DIRECTORY / "app_index.html").read_text(encoding="utf-8")
    found = re.search(r"<script>(.*?)</script>", page, re.DOTALL)
    assert found is not None, "ui/serve/serve_page/app_index.html lost its inline script"
    digest = hashlib.sha256(found.group(1).encode("utf-8")).digest()
    return f"'sha256-{base64.b64encode(digest).decode('ascii')}'"


def content_security_policy(websocket_origins: str, script_hash: str) -> str:
    """What the page may load: its own scripts (and its inline script by
    hash), styles (xterm.js sets style attributes), fonts and images, and
    its own WebSocket; no plugin, no <base>, no form, no framing by anyone."""
    return (
        f"default-src 'self'; script-src 'self' {script_hash}; "
        "style-src 'self' 'unsafe-inline'; font-src 'self'; img-src 'self' data:; "
        f"connect-src 'self' {websocket_origins}; object-src 'none'; base-uri 'none'; "
        "form-action 'none'; frame-ancestors 'none'"
    )


# --- the server ---------------------------------------------------------------------


class SassServer(Server):
    """textual-serve's server behind the checks above, with sessions of
    ui/serve/serve_session.py and the page of ui/serve/serve_page."""

    session_class = SessionService

    def __init__(self, options: ServeOptions, listener: socket.socket | None = None) -> None:
        super().__init__(
            " ".join(options.command()),
            host=options.host,
            port=options.port,
            title="sass",
            public_url=options.base_url.rstrip("/"),
        )
        self.templates_path = PAGE_DIRECTORY
        self.listener = listener  # a socket bound already (--port 0), or None
        self.options = options
        self.sessions: set[SessionService] = set()
        self.script_hash = _page_script_hash()

    async def _make_app(self) -> web.Application:
        app = await super()._make_app()
        app.middlewares.append(self.guard)
        app.on_response_prepare.append(self.add_security_headers)
        return app

    async def add_security_headers(
        self, request: web.Request, response: web.StreamResponse
    ) -> None:
        response.headers.update(SECURITY_HEADERS)
        host = request.host if _hostname(request.host) else "localhost"
        sockets = f"ws://{host} wss://{host}"
        if self.options.public_url:
            public = urlsplit(self.options.public_url).netloc
            sockets += f" ws://{public} wss://{public}"
        response.headers["Content-Security-Policy"] = content_security_policy(
            sockets, self.script_hash
        )

    @web.middleware
    async def guard(
        self,
        request: web.Request,
        handler: Callable[[web.Request], Awaitable[web.StreamResponse]],
    ) -> web.StreamResponse:
        options = self.options
        host = request.host
        problem = host_refusal(options, host)
        given = request.query.get(TOKEN_PARAMETER)
        if problem is None and not token_matches(
            options, given or request.cookies.get(options.cookie_name)
        ):
            problem = "no token, or not this run's" if given is None else "wrong token"
        route = request.match_info.route.name
        if problem is None and route in ("websocket", "download"):
            problem = origin_refusal(
                options,
                host,
                request.headers.get("Origin"),
                request.headers.get("Sec-Fetch-Site"),
                websocket=route == "websocket",
            )
        if problem is not None:
            log.warning(
                "refused %s %s from %s: %s",
                request.method,
                request.path,
                request.remote,
                problem,
            )
            raise web.HTTPForbidden(
                text="403 Forbidden: open the URL `sass serve` printed "
                f"(with its token).\n{problem}\n"
            )
        if given is not None and route == "index":
            # The token leaves the address bar (and the history) at once;
            # the cookie carries it from now on.
            query = {k: v for k, v in request.query.items() if k != TOKEN_PARAMETER}
            response = web.Response(status=303)
            response.headers["Location"] = str(request.rel_url.with_query(query))
            response.set_cookie(
                options.cookie_name,
                options.token,
                path="/",
                httponly=True,
                samesite="Strict",
                secure=options.secure,
            )
            return response
        return await handler(request)

    async def handle_index(self, request: web.Request) -> web.StreamResponse:
        # The page, its socket pointed back at the name the page was opened
        # by, where the cookie is (the printed name, 127.0.0.1, or this
        # machine's address); behind a reverse proxy, at --public-url.
        if self.options.public_url:
            parts = urlsplit(self.public_url)
            scheme = "wss" if parts.scheme == "https" else "ws"
            websocket_url = f"{scheme}://{parts.netloc}{parts.path}/ws"
            static_url = f"{self.public_url}/static/"
        else:
            scheme = "wss" if self.options.ssl_context is not None else "ws"
            websocket_url = f"{scheme}://{request.host}/ws"
            static_url = "/static/"
        context = {
            "font_size": _int(request.query.get("fontsize"), 16),
            "app_websocket_url": websocket_url,
            "config": {"static": {"url": static_url}},
            "application": {"name": self.title},
        }
        return aiohttp_jinja2.render_template("app_index.html", request, context)

    async def handle_websocket(self, request: web.Request) -> web.WebSocketResponse:
        live = sum(not session.ended for session in self.sessions)
        if live >= self.options.max_sessions:
            log.warning("refused a session: %d live (--max-sessions)", live)
            raise web.HTTPServiceUnavailable(
                text=f"503: {self.options.max_sessions} sessions are open "
                "(sass serve --max-sessions); close one and reload.\n"
            )
        websocket = web.WebSocketResponse(heartbeat=15)
        width, height = clamped_size(request.query.get("width"), request.query.get("height"))

        async def close_with(code: int, reason: str) -> bool:
            return await websocket.close(code=code, message=reason.encode("utf-8")[:120])

        service = self.session_class(
            self.options,
            close_with=close_with,
            write_bytes=websocket.send_bytes,
            write_str=websocket.send_str,
            close=websocket.close,
            download_manager=self.download_manager,
            debug=self.debug,
        )
        self.sessions.add(service)
        try:
            await websocket.prepare(request)
            await service.start(width, height)
            log.info("session %s started (%d live)", service.pid, len(self.sessions))
            await self._process_messages(websocket, service)
        except asyncio.CancelledError:
            await websocket.close()
        except Exception as error:  # textual-serve's own handler logs and goes on
            log.exception(error)
        finally:
            await service.stop()
            self.sessions.discard(service)
            log.info("session %s ended (%d live)", service.pid, len(self.sessions))
        return websocket

    async def on_startup(self, app: web.Application) -> None:
        pass  # textual-serve prints its logo here; `listening` says what matters

    def listening(self, *_: object) -> None:
        """Called by aiohttp once the server listens (run_app's `print`):
        the URL is printed, and opened, only when it can be opened."""
        options = self.options
        print(f"sass serve: open {options.url}", flush=True)
        if options.open_browser:
            # In a thread: a browser that runs in this terminal would block the server.
            threading.Thread(target=webbrowser.open, args=(options.url,), daemon=True).start()

    async def on_shutdown(self, app: web.Application) -> None:
        await asyncio.gather(*(service.stop() for service in list(self.sessions)))

    def serve(self, debug: bool = False) -> None:
        # textual-serve's serve(), with TLS and without the access log
        # (its lines would carry the token of every first request).
        self.debug = debug
        self.initialize_logging()
        loop = asyncio.new_event_loop()
        asyncio.set_event_loop(loop)
        try:
            loop.add_signal_handler(signal.SIGINT, self.request_exit)
            loop.add_signal_handler(signal.SIGTERM, self.request_exit)
        except NotImplementedError:
            pass
        where: dict = (
            {"sock": self.listener}
            if self.listener is not None
            else {"host": self.host, "port": self.port}
        )
        web.run_app(
            self._make_app(),
            **where,
            ssl_context=self.options.ssl_context,
            handle_signals=False,
            loop=loop,
            print=self.listening,
            access_log=None,
            shutdown_timeout=2 * STOP_WAIT_S,
        )


def _int(text: str | None, default: int) -> int:
    try:
        return int(text) if text is not None else default
    except ValueError:
        return default
