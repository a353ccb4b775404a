"""The `sass` command line: one parser, one error edge, one module per verb.

Each verb is a row of VERBS (its name and one-line help, all `sass --help`
needs) and a module with `register(commands)` (its arguments) that sets
`func` to a function of the parsed arguments returning the exit status.  Only
the verb being run has its module imported, so a verb's module imports what
it needs at its top.  Only plain `sass` (the TUI) imports Textual, and only
when run.
"""

from __future__ import annotations

import argparse
import errno
import gc
import os
import re
import sys
from types import ModuleType
from typing import Any, NamedTuple, cast

from sass_tui.cli.common.options import DB_HELP, SubParsers, database_address, file_name
from sass_tui.model.errors import SassError, error_text
from sass_tui.model.text import printable


class Verb(NamedTuple):
    """One row of `sass --help`: what it lists, without importing the verb."""

    name: str
    help: str  # the one line `sass --help` shows (the verb's register() gives the same)
    module: str  # sass_tui.cli.MODULE: register(commands) and the verb's code


# The verbs in `sass --help`'s order.  A new verb is a module with
# `register(commands)` and a row here: `sass --help` lists the rows without
# importing any verb, and a command imports only the module of the verb it
# runs (as git's and Click's lazy groups do), so a verb's module imports what
# it needs at its top (tests/cli/test_verbs.py checks each row against its module).
VERBS: tuple[Verb, ...] = (
    Verb("fig", "write a PEABODY body description file (.fig)", "fig"),
    Verb("export", "export the figure to another format", "export"),
    Verb("strength", "print a strength at a joint configuration (stored or predicted)", "strength"),
    Verb("query", "query the anthropometric database", "query"),
    Verb("person", "show people of the database, every value", "person"),
    Verb("population", "make population files from the people a query selects", "population"),
    Verb(
        "predict",
        "predict every value of a person from the known ones (with 90 %% intervals)",
        "predict",
    ),
    Verb("fit", "fit test: the share of a population that design limits accommodate", "fit"),
    Verb(
        "design",
        "design limits: solve the ? of limits so that they accommodate a share",
        "design",
    ),
    Verb("task", "a task's joint moments and the percent capable of doing it", "task"),
    Verb("reach", "where the figure's hands can go: reach measures, a point, an envelope", "reach"),
    Verb(
        "niosh",
        "the Revised NIOSH Lifting Equation: recommended weight limit and lifting index",
        "niosh",
    ),
    Verb(
        "handling",
        "Liberty Mutual equations: loads women and men accept to lift, lower, push, pull, carry",
        "handling",
    ),
    Verb(
        "family",
        "manikin family: boundary figures of a coverage ellipsoid, coverage counted",
        "family",
    ),
    Verb(
        "target", "make a target population: the real people weighted to match a sample", "target"
    ),
    Verb(
        "stats",
        "percentile table: n, effective n, mean, SD and percentiles of any measures",
        "stats",
    ),
    Verb("db", "create the database or import data into it", "db"),
    Verb("serve", "serve the spreadsheet to a web browser", "serve"),
)


def verb_module(verb: Verb) -> ModuleType:
    """The verb's module, imported now (the only place a verb's module is imported)."""
    module = f"sass_tui.cli.{verb.module}"
    __import__(module)  # importlib.import_module's package costs a command its import
    return sys.modules[module]


def build_parser(argv: list[str] | None = None) -> _Parser:
    """The parser; given the command line, only the verb it names is built
    (with no verb, or before -h, every verb is listed from VERBS with its help,
    no verb's module imported: `sass --help` is whole), since argparse costs
    start-up time for every parser and option.  With no command line every
    verb is built (the tests' walk over every option)."""
    parser = _Parser(
        prog="sass",
        description="Spreadsheet Anthropometry Scaling System. "
        "With no command, opens the spreadsheet (TUI).",
    )
    # --db may stand before the verb or after it; the verb's own option (see
    # options.add_db_option) overrides this one only when it is given.
    parser.add_argument("--db", metavar="PATH", type=database_address, help=DB_HELP)
    parser.add_argument(
        "--version", action=_VersionAction, nargs=0, help="print the version and exit"
    )
    parser.add_argument(
        "--open",
        type=file_name,
        metavar="FILE",
        help="open the spreadsheet on a worksheet saved with Save (ctrl+s) or Save As (S)",
    )
    commands = cast(SubParsers, parser.add_subparsers(dest="command", metavar="COMMAND"))
    parser.verbs = commands
    chosen = None if argv is None else _verb_named(argv)
    names = {verb.name for verb in VERBS}
    for verb in VERBS:
        if argv is None or chosen == verb.name:
            verb_module(verb).register(commands)
        elif chosen not in names:  # sass --help, the TUI, or an unknown verb's error
            commands.add_parser(verb.name, help=verb.help)
        # else another verb runs: this one is not built at all (each parser
        # argparse makes costs ~0.2 ms, most of it gettext looking for
        # translations).
    return parser


def _verb_named(argv: list[str]) -> str | None:
    """The verb on a command line (the first word that is not an option or
    --db's value); None if none, or if help or the version is asked first."""
    words = iter(argv)
    for word in words:
        if word in ("-h", "--help", "--version"):
            return None
        if word == "--db":
            next(words, None)
        elif not word.startswith("-"):
            return word
    return None


class _HelpFormatter(argparse.HelpFormatter):
    """argparse's own, given the terminal's width without importing shutil
    (argparse makes a formatter for every option it is given, and its own
    imports shutil, and with it bz2 and lzma: 1.5 ms of every command)."""

    def __init__(
        self,
        prog: str,
        indent_increment: int = 2,
        max_help_position: int = 24,
        width: int | None = None,
    ) -> None:
        width = _terminal_columns() - 2 if width is None else width
        super().__init__(prog, indent_increment, max_help_position, width)


def _terminal_columns() -> int:
    """shutil.get_terminal_size().columns: $COLUMNS, else the terminal's, else 80."""
    try:
        columns = int(os.environ.get("COLUMNS", "0"))
    except ValueError:
        columns = 0
    stdout = sys.__stdout__
    if columns <= 0 and stdout is not None:
        try:
            columns = os.get_terminal_size(stdout.fileno()).columns
        except (AttributeError, ValueError, OSError):
            columns = 0
    return columns if columns > 0 else 80


class _Parser(argparse.ArgumentParser):
    """An ArgumentParser whose help is made by _HelpFormatter (the verbs'
    parsers are of this class too: add_subparsers makes its own kind)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("formatter_class", _HelpFormatter)
        super().__init__(*args, **kwargs)
        self.verbs: SubParsers | None = None  # the verbs' parsers (build_parser's)
        # A value that starts as a negative number does ("--a -30deg", "--load
        # -3kg") is the option's value, not an option: argparse's own matcher
        # takes bare numbers only, and "-30deg" failed with "expected one
        # argument".  No sass option looks like a number.  argparse's private
        # attribute (Python 3.11-3.13): tests/cli/test_negative_values.py
        # fails if it stops being read.
        self._negative_number_matcher = _NEGATIVE_VALUE
        # An option that takes one value refuses a second (`--load 10kg --load
        # 20kg`): argparse kept the last one and said nothing.
        self.register("action", None, _StoreOnce)  # no action named
        self.register("action", "store", _StoreOnce)


_NEGATIVE_VALUE = re.compile(r"^-\.?\d")


class _StoreOnce(argparse._StoreAction):
    """argparse's `store` (every option's action unless it names another; a
    list option says `append`), refusing an option given twice on one
    command line: `sass niosh: error: --load given twice ('20kg' after
    '10kg'); give it once`."""

    _parsed: object = None  # the namespace of the command line being read
    _first: object = None

    def __call__(
        self,
        parser: argparse.ArgumentParser,
        namespace: argparse.Namespace,
        values: Any,
        option_string: str | None = None,
    ) -> None:
        if option_string is not None:
            if self._parsed is namespace:
                parser.error(
                    f"{option_string} given twice ({_shown(values)} after "
                    f"{_shown(self._first)}); give it once"
                )
            self._parsed, self._first = namespace, values
        super().__call__(parser, namespace, values, option_string)


def _shown(value: Any) -> str:
    return " ".join(map(repr, value)) if isinstance(value, list) else repr(value)


class _VersionAction(argparse.Action):
    """--version, looked up only when asked (importlib.metadata costs start-up time)."""

    def __call__(self, parser: argparse.ArgumentParser, *_: object) -> None:
        # deferred: importlib.metadata — off sass query, sass query --count, sass fig … (sass_tui/startup.py)
        from importlib.metadata import PackageNotFoundError, version

        try:
            number = version("sass-tui")
        except PackageNotFoundError:
            number = "unknown (not installed)"
        print(f"sass {number}")  # standard output, as the --version of most commands
        parser.exit()


# A one-shot command makes ~50,000 objects starting (modules, classes, the
# parser); at Python's default threshold (700) the cyclic collector walks the
# young ones some 50 times, 5-8 ms of `sass fig` (docs/performance.md).  At
# this threshold it runs only when a command keeps allocating, so memory held
# by unreachable cycles stays bounded by about this many objects.
COLLECT_AFTER_OBJECTS = 50_000
# Python's own thresholds, read before main() raises them, for the command
# that lives on: `sass serve` (cli/serving.py).
PYTHON_COLLECT_THRESHOLD = gc.get_threshold()


def command_line() -> int:
    """The `sass` command: main() on this process's arguments, then the process ends."""
    status = main()
    # Whatever the command made is freed as the process ends, but the
    # interpreter's last cyclic collection walks all of it first: 7-9 ms of
    # `sass query`'s ~49 (docs/performance.md).  Frozen, it walks none.
    gc.freeze()
    return status


# The most words a command line may hold (a verb takes some tens).
MAX_ARGUMENTS = 1000


def main(argv: list[str] | None = None) -> int:
    gc.set_threshold(COLLECT_AFTER_OBJECTS, *gc.get_threshold()[1:])
    words = sys.argv[1:] if argv is None else argv
    if not words:  # plain `sass`: the TUI, with no parser to build (a sooner first screen)
        return run_tui(None)
    if len(words) > MAX_ARGUMENTS:
        # argparse's time grows with the square of the arguments: 54,000 took 35 s
        print(
            f"sass: error: {len(words):,} arguments; sass takes at most {MAX_ARGUMENTS:,} "
            "(a list of people or measures goes in a file)",
            file=sys.stderr,
        )
        return 2
    parser = build_parser(words)
    args, unknown = parser.parse_known_args(words)
    if unknown and isinstance(getattr(args, "angles", None), list):
        angles = [word for word in unknown if _is_angle(word)]
        args.angles = [*args.angles, *angles]
        unknown = [word for word in unknown if not _is_angle(word)]
    if unknown:  # said by the verb's parser: its usage, `sass niosh: error: ...`
        verbs = parser.verbs.choices if parser.verbs is not None else {}
        verbs.get(args.command, parser).error(f"unrecognized arguments: {' '.join(unknown)}")
    if args.command is None:
        return run_tui(args.db, args.open)
    return run_verb(args)


def _is_angle(word: str) -> bool:
    """A JOINT=ANGLE word argparse left over: typed after the verb's options
    (`sass strength elbow_flexion --side left elbow_y=90`).  argparse hands a
    verb all its positionals at their first word, and later JOINT=ANGLE words
    were "unrecognized arguments"; a verb that takes angles takes them too."""
    return "=" in word and not word.startswith("-")


def run_tui(db: str | None, worksheet: str | None = None) -> int:
    # Starting creates ~77,000 objects that live as long as the app (modules,
    # classes, CSS rules, widgets); the cyclic collector would walk them some
    # 200 times before the first screen (50-85 ms, docs/performance.md).  It
    # is off until the app has drawn that screen (SassApp.first_screen_drawn).
    gc.disable()
    try:
        # deferred: ui.app — off sass query, sass query --count, sass fig … (sass_tui/startup.py)
        from sass_tui.ui.app import run_app

        try:
            return run_app(db, worksheet)
        except SassError as exc:  # e.g. --db '~nosuchuser/x.db'
            print(f"sass: error: {exc}", file=sys.stderr)
            return 2
    finally:
        gc.enable()  # also when the app ended before its first screen


# An OSError naming no file while a verb runs: its output could not be written.
_OUTPUT_FULL = (errno.ENOSPC, errno.EDQUOT, errno.EFBIG, errno.EIO)


def run_verb(args: argparse.Namespace) -> int:
    """Run the chosen verb; every error a user can cause ends here as a message."""
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
        # Messages quote file names and file text: show no control characters.
        shown = exc
        if isinstance(exc, OSError) and exc.filename is None and exc.errno in _OUTPUT_FULL:
            # a full disk or quota under `> file`: it said only "[Errno 28] ..."
            shown = OSError(f"cannot write the output (standard output): {exc.strerror}")
        print(f"sass {args.command}: error: {printable(error_text(shown))}", file=sys.stderr)
        pointer = exc.pointer() if isinstance(exc, SassError) else ""
        for line in pointer.splitlines():
            print(printable(line), file=sys.stderr)
        return 2
    except Exception as exc:
        if "sass_tui.db.engine.database" not in sys.modules:
            raise  # no database was opened: not an engine's error
        # deferred: db.database — off sass fig, sass strength, sass export hanim … (sass_tui/startup.py)
        from sass_tui.db.engine.database import engine_error

        error = engine_error(exc)
        if error is None:
            raise
        print(f"sass {args.command}: error: {printable(error)}", file=sys.stderr)
        return 2
