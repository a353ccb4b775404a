"""Options more than one verb takes: the database, and the figure's description."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING, TypeAlias
from urllib.parse import urlsplit

from sass_tui.cli.progress import progress_for
from sass_tui.model.errors import SassError
from sass_tui.model.paths import user_path
from sass_tui.model.text import printable
from sass_tui.model.vocabulary import FIGURE_TYPES, GENDERS

if TYPE_CHECKING:
    from sass_tui.model.figure import Figure

# What a verb's register() adds its parser to (argparse's class is generic only to type checkers).
SubParsers: TypeAlias = "argparse._SubParsersAction[argparse.ArgumentParser]"

DB_HELP = (
    "database file, or a PostgreSQL database postgresql://user@host/db "
    "(default: $SASS_DB, else $XDG_DATA_HOME/sass/sass.db)"
)


def add_db_option(parser: argparse.ArgumentParser) -> None:
    """`--db` after the verb; SUPPRESS keeps a `--db` given before the verb."""
    parser.add_argument("--db", metavar="PATH|URL", default=argparse.SUPPRESS, help=DB_HELP)


def open_database(args: argparse.Namespace, create: bool = False):  # -> db.database.Database
    """The Database `--db` (or $SASS_DB) names, or the default file (built on
    first use, with a progress bar on a terminal)."""
    # deferred: db.addresses, db.database, db.default, db.schema — off sass fig, sass strength, sass serve … (sass_tui/startup.py)
    from sass_tui.db.addresses import is_url
    from sass_tui.db.database import Database, configured_target
    from sass_tui.db.default import needs_building
    from sass_tui.db.schema import default_db_path

    warn_of_a_password(args)
    target = configured_target(getattr(args, "db", None))
    bar = None
    if target is None and needs_building(default_db_path()):
        bar = progress_for(sys.stderr, f"building {default_db_path()}")
    if target is not None and not is_url(target):
        target = user_path(target)
    db = Database.open(target, create=create, progress=bar)
    if bar:
        bar.finish()
    return db


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
    if isinstance(given, str) and "://" in given and urlsplit(given).password:
        print(f"sass {getattr(args, 'command', '')}: {PASSWORD_IN_PS}", file=sys.stderr)


def open_db(args: argparse.Namespace, create: bool = False):  # -> the db layer's connection
    """The connection of the database `--db` names, or of the default one, for
    the db layer's functions that take one: a SQLite file, or a PostgreSQL
    database for the verbs of POSTGRES_COMMANDS (db/addresses.py; for the
    others an address is refused, saying which verbs serve it)."""
    # deferred: db.addresses, db.database, db.schema — off sass fig, sass strength, sass serve … (sass_tui/startup.py)
    from sass_tui.db.addresses import POSTGRES_COMMANDS, is_url, sqlite_only
    from sass_tui.db.database import configured_target
    from sass_tui.db.schema import DatabaseError

    if (
        is_url(configured_target(getattr(args, "db", None)))
        and args.command not in POSTGRES_COMMANDS
    ):
        raise DatabaseError(sqlite_only(f"`sass {args.command}`"))
    db = open_database(args, create=create)
    with db.connection() as conn:
        return conn


class WeightingArgumentError(ValueError, SassError):
    """--target and --virtual together."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


# = sass_tui.db.scope.VIRTUAL_PREFIX (no database import on `sass --help`)
VIRTUAL_PREFIX = "virtual:"


def add_virtual_option(parser: argparse.ArgumentParser | argparse._ArgumentGroup) -> None:
    """`--virtual NAME`: the people of a virtual population, weighted by its survey weights."""
    parser.add_argument(
        "--virtual",
        metavar="NAME",
        help="the VIRTUAL people of a virtual population (sass target NAME --virtual; shipped: "
        "nhanes-2017-2020), weighted by their survey's weights; never mixed with real people",
    )


def weighting_name(args: argparse.Namespace) -> str | None:
    """The stored weights `--target NAME` or `--virtual NAME` asks for (a
    virtual population's are stored as the target `virtual:NAME`)."""
    target, virtual = getattr(args, "target", None), getattr(args, "virtual", None)
    if target is not None and virtual is not None:
        raise WeightingArgumentError("give --target NAME or --virtual NAME, not both")
    return f"{VIRTUAL_PREFIX}{virtual}" if virtual is not None else target


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
    parser.add_argument("--girth", metavar="F", help="girth population file")
    parser.add_argument("--jntlmt", metavar="F", help="joint-limit population file")
    parser.add_argument("--cmass", metavar="F", help="center-of-mass population file")
    parser.add_argument(
        "--global",
        dest="global_file",
        metavar="F",
        help="stature and mass statistics file (default: FILE-global.dat beside --girth FILE, "
        "as sass population writes it)",
    )


def figure_from_args(args: argparse.Namespace) -> tuple[Figure, list[str]]:
    """Build the figure the options describe, through a Session as the TUI
    does (each edit checked the same way); returns it and the load warnings."""
    # deferred: model.figure, model.names, model.popfile, model.session, model.units — off sass query (sass_tui/startup.py)
    from sass_tui.model.figure import Figure, FigureError
    from sass_tui.model.names import CENTER_OF_MASS, GIRTH, GLOBAL, JOINT_LIMITS
    from sass_tui.model.popfile import PopulationData, read_global_beside, read_population_file
    from sass_tui.model.session import Session
    from sass_tui.model.units import parse_quantity

    if args.person is not None:
        given = [o for o, v in (("--mass", args.mass), ("--stature", args.stature)) if v]
        given += [o for o, v in (("--gender", args.gender),) if v]
        if given:
            raise FigureError(f"--person takes the person's own {', '.join(given)}; leave it out")
    files = {
        group: read_population_file(option, group)
        for group, option in (
            (GIRTH, args.girth),
            (JOINT_LIMITS, args.jntlmt),
            (CENTER_OF_MASS, args.cmass),
        )
        if option
    }
    gender = args.gender
    if gender is None and args.person is None and files:
        # A population of one gender (e.g. `sass population` over women) sizes that gender.
        held = set.intersection(*(set(data.sections) for data in files.values()))
        gender = held.pop() if len(held) == 1 else None
    session = Session(Figure.default(gender or "male"))
    warnings: list[str] = []
    for group, data in files.items():
        session.load_group(group, data)
        warnings += [w for w in data.warnings if w not in warnings]
    # The people's own stature and mass `sass population` wrote beside its girth file.
    stature_and_mass: PopulationData | None
    if args.global_file:
        stature_and_mass = read_population_file(args.global_file, GLOBAL)
    else:
        beside = read_global_beside(args.girth) if args.girth else None
        # a gender the girth file lacks is said by the girth's own error
        stature_and_mass = beside if beside and beside.has(session.figure.gender) else None
    if stature_and_mass is not None:
        session.load_global(stature_and_mass)
        warnings += [w for w in stature_and_mass.warnings if w not in warnings]
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
    # A warning is about a file the user named: the shipped girth.dat's misprints
    # are not news to one who passed only the shipped cmass.dat.
    named = {data.path for data in files.values()}
    if stature_and_mass is not None:
        named.add(stature_and_mass.path)
    warnings = [w for w in warnings if w.split(":", 1)[0] in named]
    if args.person is not None:
        return person_figure(args, session.figure), warnings
    return session.figure, warnings


def person_figure(args: argparse.Namespace, population: Figure) -> Figure:
    """The person `--person` names, measured against the population figure."""
    # deferred: db.individual — off sass query, sass query --count, sass fig … (sass_tui/startup.py)
    from sass_tui.db.individual import fetch_individual, find_person
    from sass_tui.db.individual import person_figure as figure_of

    conn = open_db(args)
    try:
        person = fetch_individual(conn, find_person(conn, args.person))
    finally:
        conn.close()
    figure = figure_of(person, population)
    figure.set_figure_type(population.figure_type)
    return figure


def person_file_name(name: str, suffix: str) -> str:
    """'ANSUR II M 10037' -> 'ANSUR_II_M_10037.fig'."""
    stem = "".join(ch if ch.isalnum() or ch in "-." else "_" for ch in name).strip("_")
    return f"{stem or 'person'}{suffix}"


def print_warnings(warnings: list[str]) -> None:
    for warning in warnings:
        print(f"warning: {printable(warning)}", file=sys.stderr)
