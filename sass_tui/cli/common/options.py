"""Options more than one verb takes: the database's, the figure's description
and plain argparse types.  Only argparse here: opening the database is
cli/common/database_access.py, building the figure cli/common/figure_from_options.py, so a
verb imports at its top only what it uses."""

from __future__ import annotations

import argparse
import sys
from typing import TypeAlias

from sass_tui.model.errors import SassError
from sass_tui.model.text import address_password, printable
from sass_tui.model.vocabulary import FIGURE_TYPES, GENDERS

# What a verb's register() adds its parser to (argparse's class is generic only to type checkers).
SubParsers: TypeAlias = "argparse._SubParsersAction[argparse.ArgumentParser]"

DB_HELP = (
    "database file, or a PostgreSQL database postgresql://user@host/db "
    "(default: $SASS_DB, else $XDG_DATA_HOME/sass/sass.db)"
)


def add_db_option(parser: argparse.ArgumentParser) -> None:
    """`--db` after the verb; SUPPRESS keeps a `--db` given before the verb."""
    parser.add_argument(
        "--db", metavar="PATH|URL", type=database_address, default=argparse.SUPPRESS, help=DB_HELP
    )


PASSWORD_IN_PS = (
    "warning: the password in --db shows in `ps` to every user of this machine; "
    "keep it in ~/.pgpass (or the file $PGPASSFILE names) or in $PGPASSWORD, "
    "which the PostgreSQL driver reads, and give --db without it"
)


def warn_of_a_password(args: argparse.Namespace) -> None:
    """Say so when `--db` on the command line carries a password (a
    PostgreSQL address, postgresql://user:pw@host/db): the command line of a
    process is every local user's to read; $SASS_DB is not."""
    given = getattr(args, "db", None)
    if isinstance(given, str) and "://" in given and address_password(given):
        print(f"sass {getattr(args, 'command', '')}: {PASSWORD_IN_PS}", file=sys.stderr)


class WeightingArgumentError(ValueError, SassError):
    """--target and --virtual together."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


# = sass_tui.db.query.scope.VIRTUAL_PREFIX (no database import on `sass --help`)
VIRTUAL_PREFIX = "virtual:"


def add_virtual_option(parser: argparse.ArgumentParser | argparse._ArgumentGroup) -> None:
    """`--virtual NAME`: the people of a virtual population, weighted by its survey weights."""
    parser.add_argument(
        "--virtual",
        metavar="NAME",
        help="the VIRTUAL people of a virtual population (sass target NAME --virtual; shipped: "
        "nhanes-2017-2020), weighted by their survey's weights; never mixed with real people",
    )


def add_within_range_option(parser: argparse.ArgumentParser | argparse._ArgumentGroup) -> None:
    """`--within-range`: with `--virtual NAME`, leave out the virtual people
    predicted from a value beyond the real people's range (the answer says
    how many); read by `within_range_of`."""
    parser.add_argument(
        "--within-range",
        action="store_true",
        help="with --virtual: leave out the VIRTUAL people predicted from a stature, mass, "
        "hip or waist beyond every real person's of their gender (flagged when made; "
        "the answer says how many)",
    )


def within_range_of(args: argparse.Namespace) -> bool:
    """Whether `--within-range` was given (refused without --virtual)."""
    wanted = bool(getattr(args, "within_range", False))
    if wanted and getattr(args, "virtual", None) is None:
        raise WeightingArgumentError(
            "--within-range leaves out VIRTUAL people beyond the real people's range: "
            "give --virtual NAME too",
            where="--within-range",
        )
    return wanted


def weighting_name(args: argparse.Namespace) -> str | None:
    """The stored weights `--target NAME` or `--virtual NAME` asks for (a
    virtual population's are stored as the target `virtual:NAME`)."""
    target, virtual = getattr(args, "target", None), getattr(args, "virtual", None)
    if target is not None and virtual is not None:
        raise WeightingArgumentError("give --target NAME or --virtual NAME, not both")
    return f"{VIRTUAL_PREFIX}{virtual}" if virtual is not None else target


def file_name(text: str) -> str:
    """An argparse type for a file's or a folder's name: not empty.  The
    shell's `''`, or `"$OUT"` with OUT unset, is a name to argparse; as a
    path it is the current folder, and each verb said something else of it
    (`.: a directory`, `cannot write .`, or wrote its default file)."""
    return _not_blank(text, "a file's name")


def database_address(text: str) -> str:
    """An argparse type for --db: not empty (an empty --db was taken for no
    --db, and the default database opened without a word)."""
    return _not_blank(text, "a database file or a postgresql:// address")


def _not_blank(text: str, expected: str) -> str:
    if not text.strip():
        raise argparse.ArgumentTypeError(f"{text!r}: expected {expected}")
    return text


def whole_number(text: str, minimum: int = 0) -> int:
    """An argparse type: a whole number of at least `minimum` (0: a count)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < minimum:
        why = "is negative" if minimum == 0 else f"is not {minimum} or more"
        raise argparse.ArgumentTypeError(f"{value} {why}")
    return value


def positive_number(text: str) -> int:
    """An argparse type: a whole number of 1 or more."""
    return whole_number(text, 1)


def percentile(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0.5 <= value <= 99.5:
        raise argparse.ArgumentTypeError(f"percentile {value:g} is outside 0.5-99.5")
    return value


def add_figure_options(parser: argparse.ArgumentParser) -> None:
    """The options that describe a figure (shared by `fig` and `export hanim`)."""
    parser.add_argument(
        "--person",
        metavar="ID",
        help="a real person from the database (--db): the id or the name, e.g. "
        "'ANSUR II M 10037'; unmeasured values come from the population at the "
        "group percentiles",
    )
    add_db_option(parser)
    parser.add_argument("--gender", choices=GENDERS, help="default male (a person's own)")
    parser.add_argument(
        "--percentile",
        type=percentile,
        default=50.0,
        help="percentile of every group, mass and stature (default 50)",
    )
    parser.add_argument(
        "--girth-percentile",
        type=percentile,
        help="percentile of the girth group (default --percentile)",
    )
    parser.add_argument(
        "--joint-limit-percentile",
        type=percentile,
        help="percentile of the joint-limit group (default --percentile)",
    )
    parser.add_argument(
        "--cmass-percentile",
        type=percentile,
        help="percentile of the center-of-mass group (default --percentile)",
    )
    mass = parser.add_mutually_exclusive_group()
    mass.add_argument("--mass", help="total mass, e.g. 80 or '176 lb' (kg if no unit)")
    mass.add_argument(
        "--mass-percentile",
        type=percentile,
        help="percentile of the total mass (default --percentile)",
    )
    stature = parser.add_mutually_exclusive_group()
    stature.add_argument("--stature", help="stature, e.g. 175 or '70 in' (cm if no unit)")
    stature.add_argument(
        "--stature-percentile", type=percentile, help="percentile of stature (default --percentile)"
    )
    parser.add_argument(
        "--figure-type",
        choices=FIGURE_TYPES,
        default="skinny",
        help="the JACK body model the .fig is for (report figure 2; default skinny)",
    )
    parser.add_argument("--girth", metavar="F", type=file_name, help="girth population file")
    parser.add_argument("--jntlmt", metavar="F", type=file_name, help="joint-limit population file")
    parser.add_argument(
        "--cmass", metavar="F", type=file_name, help="center-of-mass population file"
    )
    parser.add_argument(
        "--target",
        metavar="NAME",
        help="size the figure from a target population's people (sass target), weighted: "
        "stature, mass, girths and centers of mass at the weighted --percentile of --gender, "
        "as sass population --target then --girth/--cmass/--global give",
    )
    add_virtual_option(parser)
    parser.add_argument(
        "--global",
        dest="global_file",
        metavar="F",
        type=file_name,
        help="stature and mass statistics file (default: FILE-global.dat beside --girth FILE, "
        "as sass population writes it)",
    )


def person_file_name(name: str, suffix: str) -> str:
    """'ANSUR II M 10037' -> 'ANSUR_II_M_10037.fig'."""
    stem = "".join(ch if ch.isalnum() or ch in "-." else "_" for ch in name).strip("_")
    return f"{stem or 'person'}{suffix}"


def print_warnings(warnings: list[str]) -> None:
    for warning in warnings:
        print(f"warning: {printable(warning)}", file=sys.stderr)
