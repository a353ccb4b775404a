"""`sass serve`: the spreadsheet in a web browser (textual-serve)."""

from __future__ import annotations

import argparse

from sass_tui.cli.options import SubParsers, add_db_option


def register(commands: SubParsers) -> None:
    serve = commands.add_parser(
        "serve",
        help="serve the spreadsheet to a web browser",
        description="Serve the same app to web browsers (one session per browser tab) "
        "until Ctrl+C.",
    )
    serve.add_argument(
        "--host",
        default="localhost",
        help="address to listen on (default localhost: this machine only)",
    )
    serve.add_argument("--port", type=int, default=8000, help="port (default 8000)")
    add_db_option(serve)
    serve.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from sass_tui.ui.serve import serve

    db = getattr(args, "db", None)
    if db:
        from pathlib import Path

        db = str(Path(db).expanduser().resolve())
    return serve(args.host, args.port, db)
