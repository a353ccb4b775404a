"""`sass fit`: the share of a population a set of design limits accommodates."""

from __future__ import annotations

import argparse
import json
import sys
from typing import TYPE_CHECKING, Any

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    add_virtual_option,
    add_within_range_option,
    weighting_name,
    within_range_of,
)
from sass_tui.db.populations.fit import check_mix, fit_test
from sass_tui.db.populations.fit_table import format_table
from sass_tui.db.query.query import ParsedQuery, compile_conjuncts, parse, parse_option
from sass_tui.model.strength.published_strength import parse_strength_limit
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.populations.targets import TargetWeights

DEFAULT_POPULATION = (
    "source = ansur2"  # = sass_tui.db.populations.fit.DEFAULT_POPULATION (no import here)
)


def mix_argument(text: str) -> dict[str, float]:
    """`male=0.5,female=0.5` -> {"male": 0.5, "female": 0.5} (the engine checks the sum)."""
    mix: dict[str, float] = {}
    for part in text.split(","):
        gender, sep, weight = part.partition("=")
        gender = gender.strip().lower()
        if not sep or gender not in GENDERS:
            raise argparse.ArgumentTypeError(
                f"{part.strip()!r}: expected GENDER=WEIGHT with GENDER one of "
                f"{', '.join(GENDERS)}, e.g. male=0.5,female=0.5"
            )
        if gender in mix:
            raise argparse.ArgumentTypeError(f"{part.strip()!r}: {gender} is given twice")
        try:
            mix[gender] = float(weight)
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"{part.strip()!r}: {weight!r} is not a number"
            ) from None
    return mix


def register(commands: SubParsers) -> None:
    fit = commands.add_parser(
        "fit",
        help="fit test: the share of a population that design limits accommodate",
        description="Count the people of the population who pass every design limit. "
        "LIMITS is a query whose terms joined by AND are the limits.",
    )
    add_db_option(fit)
    fit.add_argument(
        "--population",
        metavar="QUERY",
        default=DEFAULT_POPULATION,
        help=f"the people to test (default: {DEFAULT_POPULATION!r})",
    )
    fit.add_argument(
        "--mix",
        type=mix_argument,
        metavar="male=W,female=W",
        help="weights of the genders in the weighted share (default: equal); one alone "
        "is its share and the other gender has the rest (male=0.8: female 0.2)",
    )
    fit.add_argument(
        "--target",
        metavar="NAME",
        help="test the people of a target population (sass target), weighted; "
        "the unweighted figures beside",
    )
    add_virtual_option(fit)
    add_within_range_option(fit)
    fit.add_argument(
        "--format", choices=("table", "json"), default="table", help="output format (default table)"
    )
    fit.add_argument(
        "--strength",
        action="append",
        default=[],
        metavar="LIMIT",
        help="a limit on each person's hip, knee or ankle strength predicted from their "
        "own gender, age, mass and stature (Anderson et al. 2007), e.g. "
        "'knee_extension >= 150 N-m at knee_y=60'; repeatable (docs/strength.md)",
    )
    fit.add_argument("--failing", action="store_true", help="list who fails which limits")
    fit.add_argument(
        "limits",
        metavar="LIMITS",
        help='e.g. "stature <= 190 cm AND mass <= 110 kg"',
    )
    fit.set_defaults(func=run)


def weighted_population(
    conn: Any, args: argparse.Namespace, population: ParsedQuery
) -> tuple[TargetWeights | None, ParsedQuery]:
    """The target `--target`/`--virtual` names (None without) and the people
    to test: a virtual population's own people unless --population says."""
    weighting = weighting_name(args)
    if weighting is None:
        return None, population
    # deferred: db.shipped (db.targets) — off sass fit (sass_tui/startup.py)
    from sass_tui.db.populations.shipped import load_weights

    target = load_weights(conn, weighting, only_within_range=within_range_of(args))
    if target.target.is_virtual and args.population == DEFAULT_POPULATION:
        # its virtual people, not the soldiers
        population = parse_option(target.target.population, weighting)
    return target, population


def run(args: argparse.Namespace) -> int:
    # Check everything before opening the database: a bad query touches nothing.
    # Each query is parsed here once and passed on parsed.
    limits = parse(args.limits)
    compile_conjuncts(limits)  # an OR at the top level is refused here too
    population = parse_option(args.population, "--population")
    check_mix(args.mix)
    strength = [parse_strength_limit(text) for text in args.strength]
    conn = open_db(args)
    target, population = weighted_population(conn, args, population)
    result = fit_test(
        conn,
        limits,
        population,
        args.mix,
        failing=args.failing,
        target=target,
        strength_limits=strength,
    )
    if args.format == "json":
        json.dump(result.to_json(), sys.stdout, indent=1, allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(format_table(result))
    return 0
