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
  `STOP_WAIT_S` twice over of its tab closing;
- each session's process runs in the served working directory, which its
  prompts do not leave (model/served.py, model/paths.py's `inside`), and is
  told whether the database is read-only.

Every refusal is an HTTP 403 (503 for a full house) sent before any process
is started, and is logged on the server's console without the token.
"""

from __future__ import annotations

import asyncio
import hmac
import logging
import signal
import socket
import sys
import threading
from collections.abc import Awaitable, Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING
from urllib.parse import urlsplit

from sass_tui.model.served import READ_ONLY_ENV, WORKDIR_ENV

if TYPE_CHECKING:
    import ssl

    from aiohttp import web

log = logging.getLogger("sass.serve")

TOKEN_PARAMETER = "token"
# A session's process gets this long to quit on textual-serve's "quit"
# message, then as long again to exit once its output has closed; then it is
# killed.  Twice this is under the 5 s promised in docs/user-guide.md.
STOP_WAIT_S = 2.0
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
    """Serve until Ctrl+C (or SIGTERM)."""
    _server_class()(options).serve()
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
    options: ServeOptions, host_header: str, origin: str | None, fetch_site: str | None
) -> str | None:
    """Why a WebSocket upgrade or a download does not come from this server's
    own pages, or None.  Browsers send `Origin` with every WebSocket upgrade
    (RFC 6455 §4.1) and `Sec-Fetch-Site` with every request they make (W3C
    Fetch Metadata); a client that is not a browser (a script with the token)
    sends neither."""
    if fetch_site is not None and fetch_site not in ("same-origin", "none"):
        return f"Sec-Fetch-Site {fetch_site!r}: the request came from another site"
    if origin is None:
        return None
    own = {f"{options.scheme}://{host_header}".lower()}
    if options.public_url:
        parts = urlsplit(options.public_url)
        own.add(f"{parts.scheme}://{parts.netloc}".lower())
    return None if origin.lower() in own else f"Origin {origin!r} is not this server's"


def _hostname(host_header: str) -> str:
    """'localhost:8000' -> 'localhost'; '[::1]:8000' -> '::1'."""
    return (urlsplit(f"//{host_header}").hostname or "").lower()


# --- the server ---------------------------------------------------------------------


def _server_class():  # -> type[textual_serve.server.Server]
    """The server class, made when first served: textual-serve and aiohttp are
    imported only by `sass serve`."""
    # deferred: aiohttp_jinja2, aiohttp.web, textual_serve.app_service, textual_serve.server — off sass serve (sass_tui/startup.py)
    import aiohttp_jinja2
    from aiohttp import web
    from textual_serve.app_service import AppService
    from textual_serve.server import Server

    class SessionService(AppService):
        """One browser session's `sass` process: started without a shell in the
        served working directory, and surely gone when the session stops."""

        def __init__(self, options: ServeOptions, **kwargs) -> None:
            super().__init__(" ".join(options.command()), **kwargs)
            self.options = options

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
            self._process = process = await asyncio.create_subprocess_exec(
                *self.options.command(),
                stdin=pipe,
                stdout=pipe,
                stderr=pipe,
                env=self._build_environment(width=width, height=height),
                cwd=self.options.workdir,
            )
            assert process.stdin is not None
            self._stdin = process.stdin
            return process

        @property
        def pid(self) -> int | None:
            return self._process.pid if self._process is not None else None

        async def stop(self) -> None:
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

    class SassServer(Server):
        session_class = SessionService

        def __init__(self, options: ServeOptions) -> None:
            super().__init__(
                " ".join(options.command()),
                host=options.host,
                port=options.port,
                title="sass",
                public_url=options.base_url.rstrip("/"),
            )
            self.options = options
            self.sessions: set[SessionService] = set()

        async def _make_app(self) -> web.Application:
            app = await super()._make_app()
            app.middlewares.append(self.guard)
            return app

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
            if self.options.public_url:
                return await super().handle_index(request)
            # textual-serve's page, its socket pointed back at the name the page
            # was opened by, where the cookie is (the printed name, 127.0.0.1,
            # or this machine's address).
            scheme = "wss" if self.options.ssl_context is not None else "ws"
            context = {
                "font_size": _int(request.query.get("fontsize"), 16),
                "app_websocket_url": f"{scheme}://{request.host}/ws",
                "config": {"static": {"url": "/static/"}},
                "application": {"name": self.title},
            }
            return aiohttp_jinja2.render_template("app_index.html", request, context)

        async def handle_websocket(self, request: web.Request) -> web.WebSocketResponse:
            if len(self.sessions) >= self.options.max_sessions:
                log.warning("refused a session: %d live (--max-sessions)", len(self.sessions))
                raise web.HTTPServiceUnavailable(
                    text=f"503: {self.options.max_sessions} sessions are open "
                    "(sass serve --max-sessions); close one and reload.\n"
                )
            websocket = web.WebSocketResponse(heartbeat=15)
            width = _int(request.query.get("width"), 80)
            height = _int(request.query.get("height"), 24)
            service = self.session_class(
                self.options,
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
                # deferred: webbrowser — off sass serve (sass_tui/startup.py)
                import webbrowser

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
            web.run_app(
                self._make_app(),
                host=self.host,
                port=self.port,
                ssl_context=self.options.ssl_context,
                handle_signals=False,
                loop=loop,
                print=self.listening,
                access_log=None,
                shutdown_timeout=2 * STOP_WAIT_S,
            )

    return SassServer


def _int(text: str | None, default: int) -> int:
    try:
        return int(text) if text is not None else default
    except ValueError:
        return default
