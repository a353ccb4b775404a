"""Options more than one verb takes: the database, and the figure's description."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from sass_tui.model.vocabulary import FIGURE_TYPES, GENDERS

if TYPE_CHECKING:
    from sass_tui.model.figure import Figure

DB_HELP = "database file (default: $SASS_DB, else $XDG_DATA_HOME/sass/sass.db)"


def add_db_option(parser: argparse.ArgumentParser) -> None:
    """`--db` after the verb; SUPPRESS keeps a `--db` given before the verb."""
    parser.add_argument("--db", metavar="PATH", default=argparse.SUPPRESS, help=DB_HELP)


def open_db(args: argparse.Namespace, create: bool = False):  # -> sqlite3.Connection
    from sass_tui.db.default import open_database
    from sass_tui.model.paths import user_path

    path = getattr(args, "db", None)
    return open_database(user_path(path) if path else None, create=create)


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
    parser.add_argument("--gender", choices=GENDERS, default="male")
    parser.add_argument(
        "--percentile",
        type=percentile,
        default=50.0,
        help="percentile of every group, mass and stature (default 50)",
    )
    parser.add_argument("--girth-percentile", type=percentile)
    parser.add_argument("--joint-limit-percentile", type=percentile)
    parser.add_argument("--cmass-percentile", type=percentile)
    mass = parser.add_mutually_exclusive_group()
    mass.add_argument("--mass", help="total mass, e.g. 80 or '176 lb' (kg if no unit)")
    mass.add_argument("--mass-percentile", type=percentile)
    stature = parser.add_mutually_exclusive_group()
    stature.add_argument("--stature", help="stature, e.g. 175 or '70 in' (cm if no unit)")
    stature.add_argument("--stature-percentile", type=percentile)
    parser.add_argument("--figure-type", choices=FIGURE_TYPES, default="skinny")
    parser.add_argument("--girth", metavar="F", help="girth population file")
    parser.add_argument("--jntlmt", metavar="F", help="joint-limit population file")
    parser.add_argument("--cmass", metavar="F", help="center-of-mass population file")


def figure_from_args(args: argparse.Namespace) -> tuple[Figure, list[str]]:
    """Build the figure the options describe, through a Session as the TUI
    does (each edit checked the same way); returns it and the load warnings."""
    from sass_tui.model.figure import Figure
    from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
    from sass_tui.model.popfile import read_population_file
    from sass_tui.model.session import Session
    from sass_tui.model.units import parse_quantity

    session = Session(Figure.default(args.gender))
    warnings: list[str] = []
    for group, option in (
        (GIRTH, args.girth),
        (JOINT_LIMITS, args.jntlmt),
        (CENTER_OF_MASS, args.cmass),
    ):
        if option:
            data = read_population_file(option, group)
            warnings += data.warnings
            session.load_group(group, data)
    for group, option in (
        (GIRTH, args.girth_percentile),
        (JOINT_LIMITS, args.joint_limit_percentile),
        (CENTER_OF_MASS, args.cmass_percentile),
    ):
        session.set_group_percentile(group, option if option is not None else args.percentile)
    if args.mass is not None:
        session.set_mass(parse_quantity(args.mass, "kg"))
    else:
        session.set_mass_percentile(args.mass_percentile or args.percentile)
    if args.stature is not None:
        session.set_stature(parse_quantity(args.stature, "cm"))
    else:
        session.set_stature_percentile(args.stature_percentile or args.percentile)
    session.set_figure_type(args.figure_type)
    return session.figure, warnings


def print_warnings(warnings: list[str]) -> None:
    import sys

    for warning in warnings:
        print(f"warning: {warning}", file=sys.stderr)
