"""`sass serve`: the same app in a web browser, through textual-serve.

textual-serve starts one `sass` process per browser session with Textual's
web driver; each session is the full TUI on the same database.
"""

from __future__ import annotations

import shlex
import sys


def serve(host: str, port: int, db: str | None) -> int:
    from textual_serve.server import Server

    command = [sys.executable, "-m", "sass_tui"]
    if db:
        command += ["--db", db]
    Server(shlex.join(command), host=host, port=port, title="sass").serve()
    return 0
