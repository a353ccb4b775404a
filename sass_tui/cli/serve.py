"""`sass serve`: the spreadsheet in a web browser (textual-serve, ui/serve/serve.py).

The options are checked here, before anything listens: a remote address only
with --allow-remote, TLS files that can be read, a token file's token; then
cli/serving.py makes the working directory, finds the database and serves
(ui/serve/serve.py).
"""

from __future__ import annotations

import argparse
import importlib.util
import secrets
import socket
import ssl
from ipaddress import ip_address
from urllib.parse import urlsplit

from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    file_name,
    positive_number,
    whole_number,
)
from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import LARGEST_TOKEN_FILE, regular_file

# secrets.token_urlsafe(32): 256 bits.  A token file's must have at least
# 128 bits: 22 characters of the 64 a URL carries unquoted (6 bits each).
TOKEN_BYTES = 32
MIN_TOKEN_CHARACTERS = 22
TOKEN_ALPHABET = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_")
DEFAULT_MAX_SESSIONS = 8


class ServeError(ValueError, SassError):
    """Options `sass serve` cannot serve with."""


def port_number(text: str) -> int:
    """An argparse type: a TCP port, 0-65535 (the system resolved 99999 to a
    port of its own and the server printed a URL nobody could open; -1 said
    "Servname not supported for ai_socktype")."""
    port = whole_number(text)
    if port > 65535:
        raise argparse.ArgumentTypeError(f"{port} is no port: expected 0-65535")
    return port


def register(commands: SubParsers) -> None:
    serve = commands.add_parser(
        "serve",
        help="serve the spreadsheet to a web browser",
        description="Serve the same app to web browsers (one session per browser tab) "
        "until Ctrl+C.  Prints the one URL to open: it carries a secret token, and "
        "every request without it is refused.  Web sessions read and write files "
        "only inside --workdir.",
    )
    serve.add_argument(
        "--host",
        default="localhost",
        help="address to listen on (default localhost: this machine only; "
        "any other needs --allow-remote)",
    )
    serve.add_argument(
        "--port",
        type=port_number,
        default=8000,
        help="port (default 8000; 0: a free port the system chooses, printed)",
    )
    serve.add_argument(
        "--allow-remote",
        action="store_true",
        help="allow a --host other machines reach (traffic is plain HTTP unless "
        "--certfile/--keyfile or a TLS reverse proxy)",
    )
    serve.add_argument(
        "--certfile", metavar="F", type=file_name, help="TLS certificate (PEM): serve https/wss"
    )
    serve.add_argument(
        "--keyfile", metavar="F", type=file_name, help="TLS private key (PEM) of --certfile"
    )
    serve.add_argument(
        "--public-url",
        metavar="URL",
        help="the URL users open when a reverse proxy serves sass "
        "(e.g. https://sass.example.org/): its origin is this server's",
    )
    serve.add_argument(
        "--token-file",
        metavar="F",
        type=file_name,
        help="read the token from F (at least 22 characters of A-Z a-z 0-9 - _) "
        "instead of making a new one",
    )
    serve.add_argument(
        "--workdir",
        metavar="DIR",
        type=file_name,
        help="the directory web sessions read and write files in (default: a new "
        "directory under the user's data directory, printed at start)",
    )
    serve.add_argument(
        "--read-only",
        action="store_true",
        help="web sessions query the database but cannot change it (no Input DB)",
    )
    serve.add_argument(
        "--max-sessions",
        type=positive_number,
        default=DEFAULT_MAX_SESSIONS,
        metavar="N",
        help=f"at most N live sessions (default {DEFAULT_MAX_SESSIONS})",
    )
    serve.add_argument(
        "--open", action="store_true", help="open the URL in this machine's web browser"
    )
    add_db_option(serve)
    serve.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if importlib.util.find_spec("textual_serve") is None:  # the [serve] extra is not installed
        raise ServeError("sass serve needs textual-serve: pip install 'sass-tui[serve]'")
    loopback = is_loopback(args.host)
    if not loopback and not args.allow_remote:
        raise ServeError(
            f"--host {args.host} is reachable from other machines: whoever reaches it "
            "with the token drives sass as you. Add --allow-remote if you mean it "
            "(with --certfile/--keyfile, or behind a TLS reverse proxy: docs/user-guide.md)"
        )
    ssl_context = tls_context(args.certfile, args.keyfile)
    if args.public_url is not None:
        check_public_url(args.public_url)
    token = read_token(args.token_file) if args.token_file else new_token()
    # After the checks: cli/serving.py brings the database and the web
    # server (ui/serve/serve.py: textual-serve, aiohttp).
    # deferred: cli.serving (the db package, ui.serve, tempfile) — off sass serve (sass_tui/startup.py)
    from sass_tui.cli.serving import start

    return start(args, token=token, loopback=loopback, ssl_context=ssl_context)


def is_loopback(host: str) -> bool:
    """True when every address `host` names is this machine's loopback."""
    try:
        infos = socket.getaddrinfo(host, None)
    except (OSError, UnicodeError):
        return False  # not resolvable here: not known to be local
    return bool(infos) and all(
        ip_address(str(info[4][0]).split("%")[0]).is_loopback for info in infos
    )


def tls_context(certfile: str | None, keyfile: str | None):  # -> ssl.SSLContext | None
    if certfile is None and keyfile is None:
        return None
    if certfile is None:
        raise ServeError("--keyfile needs --certfile (the certificate it belongs to)")

    cert = regular_file(certfile)
    key = regular_file(keyfile) if keyfile else None
    context = ssl.create_default_context(ssl.Purpose.CLIENT_AUTH)
    try:
        context.load_cert_chain(cert, key)
    except (ssl.SSLError, OSError) as exc:
        raise ServeError(
            f"{cert}{f' with {key}' if key else ''}: not a usable TLS certificate "
            f"and private key (PEM): {exc}"
        ) from None
    return context


def check_public_url(url: str) -> None:
    """An http(s) URL with a host and, if any, a port of 0-65535: urlsplit
    raises on an unclosed IPv6 bracket and `.port` on a port that is no
    number or out of range, which would end the server later instead."""
    expected = f"--public-url {url!r}: expected http(s)://HOST[:PORT]/"
    try:
        parts = urlsplit(url)
        parts.port  # noqa: B018 (read for its ValueError)
    except ValueError as exc:
        raise ServeError(f"{expected} ({exc})") from None
    if parts.scheme not in ("http", "https") or not parts.hostname:
        raise ServeError(expected)


def new_token() -> str:
    return secrets.token_urlsafe(TOKEN_BYTES)


def read_token(name: str) -> str:
    """The token in file `name` (its first line, spaces around it dropped)."""
    path = regular_file(name, largest=LARGEST_TOKEN_FILE, kind="a token file")
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except UnicodeDecodeError:
        raise ServeError(f"{path}: not UTF-8 text; expected a token") from None
    token = lines[0].strip() if lines else ""
    bad = sorted(set(token) - TOKEN_ALPHABET)
    if len(token) < MIN_TOKEN_CHARACTERS or bad:
        why = f"characters {''.join(bad)!r} are not allowed" if bad else f"{len(token)} characters"
        raise ServeError(
            f"{path}:1: the token must be at least {MIN_TOKEN_CHARACTERS} characters of "
            f"A-Z a-z 0-9 - _ (128 bits); {why}"
        )
    return token
