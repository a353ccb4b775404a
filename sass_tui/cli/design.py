"""`sass design`: the limits that accommodate a share of a population (`?` solved)."""

from __future__ import annotations

import argparse
import json
import math
import sys

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    add_virtual_option,
    add_within_range_option,
)
from sass_tui.cli.fit import DEFAULT_POPULATION, mix_argument, weighted_population
from sass_tui.db.populations.design import design, format_design
from sass_tui.db.populations.fit import check_mix
from sass_tui.db.query.query import joined, parse, parse_option
from sass_tui.model.population.design import DesignError
from sass_tui.model.vocabulary import GENDERS


def percent_argument(text: str) -> float:
    try:
        value = float(text.strip().removesuffix("%"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a percentage, e.g. 95") from None
    if not 0.0 < value < 100.0:
        raise argparse.ArgumentTypeError(f"{text!r}: expected a share between 0 and 100")
    return value


def split_argument(text: str) -> tuple[list[float], list[float | None]]:
    """`2,1,1` (each limit's relative share of the exclusion, in the order of the
    limits with a ?); a range's item `2:1/3` splits its share between its lower
    and upper end (here a third below)."""
    shares: list[float] = []
    below: list[float | None] = []
    for item in text.split(","):
        share, _, low = item.strip().partition(":")
        try:
            value = float(share)
            fraction = None if not low else _fraction(low)
        except (ValueError, ZeroDivisionError):
            raise argparse.ArgumentTypeError(
                f"{item.strip()!r}: expected a share >= 0, or SHARE:LOW/HIGH for a range "
                "(e.g. 1:1/3: a third of its share below the range), e.g. 2,1,1"
            ) from None
        if not math.isfinite(value) or value < 0:
            raise argparse.ArgumentTypeError(f"{item.strip()!r}: a share is a number >= 0")
        if fraction is not None and not 0.0 <= fraction <= 1.0:
            raise argparse.ArgumentTypeError(
                f"{item.strip()!r}: the share below a range is from 0 to 1, e.g. 1/3"
            )
        shares.append(value)
        below.append(fraction)
    return shares, below


def _fraction(text: str) -> float:
    top, _, bottom = text.partition("/")
    return float(top) / float(bottom) if bottom else float(top)


def register(commands: SubParsers) -> None:
    parser = commands.add_parser(
        "design",
        help="design limits: solve the ? of limits so that they accommodate a share",
        description="Solve the unknowns ? of design limits so that the population's share "
        "passing every limit is --accommodate (the share sass fit reports, same weighting). "
        "One unknown is the weighted quantile; with several the exclusion is split equally "
        "between the limits with a ? (--split otherwise) and each range is the shortest "
        "(docs/accommodation.md).",
    )
    add_db_option(parser)
    parser.add_argument(
        "--population",
        metavar="QUERY",
        default=DEFAULT_POPULATION,
        help=f"the people to design for (default: {DEFAULT_POPULATION!r})",
    )
    parser.add_argument(
        "--target",
        metavar="NAME",
        help="the people of a target population (sass target), weighted by its weights, "
        "the genders in the survey's proportions",
    )
    add_virtual_option(parser)
    add_within_range_option(parser)
    parser.add_argument("--gender", choices=GENDERS, help="one gender only")
    parser.add_argument(
        "--mix",
        type=mix_argument,
        metavar="male=W,female=W",
        help="weights of the genders (default: equal; with --target/--virtual the survey's)",
    )
    parser.add_argument(
        "--accommodate",
        type=percent_argument,
        required=True,
        metavar="PCT",
        help="the share of the population every limit together must accommodate, e.g. 95",
    )
    parser.add_argument(
        "--split",
        type=split_argument,
        metavar="W1,W2,...",
        help="each limit with a ?'s relative share of the exclusion, in order (default: "
        "equal); a range's W:L/H splits its share between its ends (default: shortest)",
    )
    parser.add_argument(
        "--format", choices=("table", "json"), default="table", help="output format (default table)"
    )
    parser.add_argument(
        "limits",
        metavar="LIMITS",
        help='e.g. "measure.poplitealheight BETWEEN ? AND ? AND '
        'measure.buttockpopliteallength >= ? AND measure.hipbreadthsitting <= ?"',
    )
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    # Everything is checked before the database opens: a bad query touches nothing.
    limits = parse(args.limits, unknowns=True)
    population = parse_option(args.population, "--population")
    check_mix(args.mix)
    if args.gender is not None and args.mix is not None:
        raise DesignError("give --gender or --mix, not both")
    conn = open_db(args)
    target, population = weighted_population(conn, args, population)
    mix = args.mix
    if args.gender is not None:
        population = joined(
            population,
            f"gender = {args.gender}",
            text=f"({population.text}) AND gender = {args.gender}",
        )
        mix = {args.gender: 1.0}
    split, range_split = args.split if args.split is not None else (None, None)
    result = design(
        conn,
        limits,
        args.accommodate,
        population,
        mix,
        target,
        split,
        range_split,
    )
    if args.format == "json":
        json.dump(result.to_json(), sys.stdout, indent=1, allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(format_design(result))
    return 0
