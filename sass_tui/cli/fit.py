"""`sass fit`: the share of a population a set of design limits accommodates."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from sass_tui.cli.options import SubParsers, add_db_option, open_db
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.fit import FitResult

DEFAULT_POPULATION = "source = ansur2"  # = sass_tui.db.fit.DEFAULT_POPULATION (no import here)


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
        help="weights of the genders in the weighted share (default: equal)",
    )
    fit.add_argument("--format", choices=("table", "json"), default="table")
    fit.add_argument("--failing", action="store_true", help="list who fails which limits")
    fit.add_argument(
        "limits",
        metavar="LIMITS",
        help='e.g. "stature <= 190 cm AND mass <= 110 kg"',
    )
    fit.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import json

    from sass_tui.db.fit import check_mix, fit_test
    from sass_tui.db.query import QueryError, compile_conjuncts, compile_query

    # Check everything before opening the database: a bad query touches nothing.
    compile_conjuncts(args.limits)
    try:
        compile_query(args.population)
    except QueryError as exc:
        error = QueryError(f"--population: {exc}", exc.text)
        error.column = exc.column
        raise error from None
    check_mix(args.mix)
    conn = open_db(args)
    result = fit_test(conn, args.limits, args.population, args.mix, failing=args.failing)
    if args.format == "json":
        json.dump(result.to_json(), sys.stdout, indent=1, allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(format_table(result))
    return 0


def _percent(value: float | None) -> str:
    return "-" if value is None else f"{value:.1f} %"


def format_table(result: FitResult) -> str:
    lines = [
        f"Design limits: {' AND '.join(result.limits)}",
        f"Population: {result.population} ({result.population_size} people)",
    ]
    if result.not_measured:
        lines.append(
            f"Not measured for {result.not_measured} people (lacking a limited value): "
            "left out of every share"
        )
    lines += ["", f"{'':<10} {'people':>7} {'fit':>7} {'accommodated':>13} {'naive':>9}"]
    for share in result.genders.values():
        lines.append(
            f"{share.gender:<10} {share.n:>7} {share.fit:>7} {_percent(share.percent):>13} "
            f"{_percent(share.naive_percent):>9}"
        )
    mix = ", ".join(f"{g} {100 * w:.0f} %" for g, w in result.mix.items())
    lines.append(
        f"{'weighted':<10} {'':>7} {'':>7} {_percent(result.weighted_percent):>13} "
        f"{_percent(result.naive_percent):>9}   ({mix})"
    )
    lines += [
        "",
        "naive = the product of each limit's own share (what univariate percentiles suggest)",
        "",
    ]
    width = max(len("limit"), *(len(b.limit) for b in result.by_limit))
    lines.append(
        f"{'limit':<{width}} {'excluded':>9} {'only limit':>11} {'not measured':>13}"
        + "".join(f" {g + ' share':>13}" for g in result.genders)
    )
    for b in result.by_limit:
        lines.append(
            f"{b.limit:<{width}} {b.excluded:>9} {b.only_limit:>11} {b.not_measured:>13}"
            + "".join(f" {_percent(b.percent.get(g)):>13}" for g in result.genders)
        )
    if result.failing is not None:
        lines += ["", f"{len(result.failing)} people fail a limit:"]
        for person in result.failing:
            lines.append(
                f"{person.id:>7}  {person.name:<20.20} {person.gender:<6} "
                + "; ".join(person.limits)
            )
    return "\n".join(lines) + "\n"
