"""The `sass` command line: one parser, one error edge, one module per verb.

Each verb module has `register(commands)` (its arguments; imports nothing
heavy) and sets `func` to a function of the parsed arguments that returns
the exit status.  Only plain `sass` (the TUI) imports Textual, and only
when run; numpy, sqlite3, lark and pint wait until a verb needs them.
"""

from __future__ import annotations

import argparse
import os
import sys

from sass_tui.cli import db, export, fig, query, strength
from sass_tui.cli.options import DB_HELP

VERBS = (fig, export, strength, query, db)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="sass",
        description="Spreadsheet Anthropometry Scaling System. "
        "With no command, opens the spreadsheet (TUI).",
    )
    # --db may stand before the verb or after it; the verb's own option (see
    # options.add_db_option) overrides this one only when it is given.
    parser.add_argument("--db", metavar="PATH", help=DB_HELP)
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")
    for verb in VERBS:
        verb.register(commands)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        from sass_tui.model.errors import SassError
        from sass_tui.ui.app import run_app

        try:
            return run_app(args.db)
        except SassError as exc:  # e.g. --db '~nosuchuser/x.db'
            print(f"sass: error: {exc}", file=sys.stderr)
            return 2
    return run_verb(args)


def run_verb(args: argparse.Namespace) -> int:
    """Run the chosen verb; every error a user can cause ends here as a message."""
    from sass_tui.model.errors import SassError

    try:
        status: int = args.func(args)
        return status
    except BrokenPipeError:
        # The reader went away (`sass query ... | head`): not an error, and
        # Python must not complain again when it flushes stdout at exit.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except KeyboardInterrupt:
        print(f"sass {args.command}: interrupted", file=sys.stderr)
        return 130
    except (SassError, OSError) as exc:
        print(f"sass {args.command}: error: {exc}", file=sys.stderr)
        pointer = exc.pointer() if isinstance(exc, SassError) else ""
        if pointer:
            print(pointer, file=sys.stderr)
        return 2
    except Exception as exc:
        sqlite3 = sys.modules.get("sqlite3")
        if sqlite3 is not None and isinstance(exc, sqlite3.Error):
            print(f"sass {args.command}: database error: {exc}", file=sys.stderr)
            return 2
        raise


if __name__ == "__main__":
    sys.exit(main())
