"""`sass serve` once its options are checked (cli/serve.py): the working
directory, the database the sessions open, and the web server (ui/serve/serve.py:
textual-serve, aiohttp).

A module of its own, with all of these at its top, because cli/serve.py
refuses an address it will not serve on (and unusable TLS files, a bad
token file) before any of them is imported (the `sass serve` row of
sass_tui/startup.py); it imports this module only then.
"""

from __future__ import annotations

import argparse
import gc
import sys
import tempfile
import time
from pathlib import Path

from sass_tui.cli import PYTHON_COLLECT_THRESHOLD
from sass_tui.cli.common.database_access import open_db
from sass_tui.db.engine.addresses import is_url, shown
from sass_tui.db.engine.database import configured_target
from sass_tui.db.engine.postgres import connect_postgres
from sass_tui.db.engine.schema import default_db_path
from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import data_dir, user_path
from sass_tui.ui.serve.serve import ServeOptions, serve


class WorkdirError(ValueError, SassError):
    """A --workdir sessions cannot work in."""


def start(args: argparse.Namespace, *, token: str, loopback: bool, ssl_context) -> int:
    """Serve until Ctrl+C, with the options cli/serve.py checked."""
    workdir = served_workdir(args.workdir)
    db = database_path(args, args.read_only)
    options = ServeOptions(
        host=args.host,
        port=args.port,
        token=token,
        workdir=workdir,
        db=db,
        read_only=args.read_only,
        max_sessions=args.max_sessions,
        loopback=loopback,
        public_url=args.public_url,
        ssl_context=ssl_context,
        open_browser=args.open,
    )
    err = sys.stderr
    print(f"sass serve: web sessions read and write files in {workdir}", file=err)
    if db is not None:
        named = shown(db) if isinstance(db, str) else db  # never the password
        print(f"sass serve: database {named}{' (read-only)' if args.read_only else ''}", file=err)
    if not loopback and ssl_context is None:
        print(
            f"sass serve: warning: {args.host} serves plain HTTP: anyone on the network "
            "between the browser and this machine can read the token and every session. "
            "Give --certfile/--keyfile, or serve it behind a TLS reverse proxy "
            "(docs/user-guide.md).",
            file=err,
        )
    print(
        f"sass serve: at most {args.max_sessions} sessions; Ctrl+C stops the server.",
        file=err,
        flush=True,
    )
    # A server lives on: each browser session leaves ~77 objects in reference
    # cycles inside aiohttp and asyncio (the request, the WebSocket, the
    # session process's pipes).  At main()'s threshold for one-shot commands
    # they waited some 500 sessions (~10 MB) for a collection; at Python's own
    # they go within a few (docs/reliability.md, benchmarks/serve_memory.py).
    gc.set_threshold(*PYTHON_COLLECT_THRESHOLD)
    try:
        return serve(options)
    finally:
        if args.workdir is None:
            # The folder sass made for this run: left behind by every run; gone
            # when the sessions saved nothing in it, kept (and named) when they did.
            try:
                workdir.rmdir()
            except OSError:
                print(f"sass serve: the sessions' files stay in {workdir}", file=err)


def served_workdir(name: str | None) -> Path:
    """--workdir (made if missing), or a new directory under the user's data
    directory; its real path, so that no link in it moves later."""
    if name is None:
        base = data_dir() / "serve"
        base.mkdir(parents=True, exist_ok=True)
        stamp = time.strftime("%Y%m%d-%H%M%S-")
        return Path(tempfile.mkdtemp(prefix=stamp, dir=base)).resolve()

    path = user_path(name)
    try:
        path.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise WorkdirError(f"--workdir {path}: not a directory") from None
    return path.resolve()


def database_path(args: argparse.Namespace, read_only: bool) -> Path | str | None:
    """The database the sessions open: a SQLite file, or a PostgreSQL address
    (`--db` or $SASS_DB).  A read-only database is opened (and the default
    file built on first use) here, since a session cannot build it and a
    server that cannot be reached is better said once than in every session.
    Each session's connections to a PostgreSQL database are then read-only
    by the server's rule ($SASS_READ_ONLY, db/engine/postgres.py)."""
    db = getattr(args, "db", None)
    target = configured_target(db)
    if is_url(target):
        if read_only:
            connect_postgres(str(target), read_only=True).close()
        return str(target)
    if not read_only:
        return user_path(db).resolve() if db else None
    open_db(args).close()
    return user_path(db).resolve() if db else default_db_path().resolve()
