"""`sass stats`: the percentile table engineers look up every day.

    sass stats stature mass sittingheight --gender female
    sass stats --virtual nhanes-2017-2020 --query "age >= 20 AND age <= 59" --format json
    sass stats --target nhanes-2017-2020 --gender female mass
    sass stats --percentiles 1,5,50,95,99 --unit in --format csv

n, effective n (Kish), mean, SD and percentiles of each measure (no
MEASURE: stature, mass and every ANSUR II measure) over the people a query
selects: real people unless the query names a source, the people of a
target population weighted (`--target`), or the VIRTUAL people of a virtual
population weighted by their survey's weights (`--virtual`).  Lengths in
cm, mass in kg unless `--unit`.  db/populations/stats.py computes it.

`sass --help` imports this module to list the verb: the database and numpy
are imported in `run`.
"""

from __future__ import annotations

import argparse
import csv
import json
import math
import sys
from typing import TYPE_CHECKING, Any, TextIO

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    add_virtual_option,
    add_within_range_option,
    weighting_name,
    within_range_of,
)
from sass_tui.db.populations.shipped import load_weights
from sass_tui.db.populations.stats import EVERY_MEASURE, check_unit, format_stats, stats_table
from sass_tui.db.query.query import QueryError, compile_query
from sass_tui.model.population.measure_fields import measure_field
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.populations.stats import StatsTable

# = sass_tui.db.populations.stats.DEFAULT_PERCENTILES (no database import on `sass --help`)
DEFAULT_PERCENTILES = (1.0, 5.0, 50.0, 95.0, 99.0)


def percentile_list(text: str) -> tuple[float, ...]:
    """`--percentiles 1,5,50,95,99` -> (1.0, 5.0, 50.0, 95.0, 99.0): each over
    0 and under 100, none twice."""
    values: list[float] = []
    for part in text.split(","):
        word = part.strip()
        try:
            value = float(word)
        except ValueError:
            raise argparse.ArgumentTypeError(
                f"{word!r}: expected a percentile, a number over 0 and under 100, e.g. 1,5,50,95,99"
            ) from None
        if not 0 < value < 100:
            raise argparse.ArgumentTypeError(f"{word!r}: a percentile must be over 0 and under 100")
        if value in values:
            raise argparse.ArgumentTypeError(f"{word!r} is listed twice")
        same = [v for v in values if _key(v) == _key(value)]
        if same:  # 50.00001 and 50.00002: two p50 columns, one JSON key
            raise argparse.ArgumentTypeError(
                f"{word!r} is shown as p{_key(value)}, as {same[0]!r} is; give percentiles that "
                "differ within 6 significant digits"
            )
        values.append(value)
    return tuple(values)


def register(commands: SubParsers) -> None:
    stats = commands.add_parser(
        "stats",
        help="percentile table: n, effective n, mean, SD and percentiles of any measures",
        description="The percentiles of stature, mass and ANSUR II's measures over the people "
        "a query selects; weighted to a target population (--target) or a virtual "
        "population's survey weights (--virtual).",
    )
    add_db_option(stats)
    stats.add_argument(
        "measures",
        metavar="MEASURE",
        nargs="*",
        help="stature, mass or an ANSUR II measure (sittingheight, ...); none: every one",
    )
    stats.add_argument("--gender", choices=GENDERS, help="one gender's people only")
    stats.add_argument("--query", metavar="QUERY", help="the people (default: every real person)")
    stats.add_argument(
        "--target",
        metavar="NAME",
        help="the people of a target population (sass target), weighted; with the share "
        "of the target beyond every person (outside_share)",
    )
    add_virtual_option(stats)
    add_within_range_option(stats)
    stats.add_argument(
        "--percentiles",
        type=percentile_list,
        default=DEFAULT_PERCENTILES,
        metavar="P1,P2,...",
        help="the percentiles (default 1,5,50,95,99)",
    )
    stats.add_argument(
        "--unit", metavar="UNIT", help="lengths (cm, mm, in) or mass (kg, lb) in this unit"
    )
    stats.add_argument(
        "--format",
        choices=("text", "json", "csv"),
        default="text",
        help="output format (default text)",
    )
    stats.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    # Everything that needs no database first: a bad input touches nothing.
    fields = [measure_field(name) for name in args.measures] or list(EVERY_MEASURE)
    fields = list(dict.fromkeys(fields))
    if args.query is not None:
        try:
            compile_query(args.query)
        except QueryError as exc:
            error = QueryError(f"--query: {exc}", exc.text)
            error.column = exc.column
            raise error from None
    unit = check_unit(args.unit)
    weighting = weighting_name(args)
    within_range = within_range_of(args)
    conn = open_db(args)
    try:
        weights = (
            None
            if weighting is None
            else load_weights(conn, weighting, only_within_range=within_range)
        )
        table = stats_table(
            conn,
            fields,
            args.query,
            gender=args.gender,
            weights=weights,
            percentiles=args.percentiles,
            unit=unit,
        )
    finally:
        conn.close()
    if args.format == "json":
        json.dump(table_json(table), sys.stdout, indent=1, allow_nan=False)
        sys.stdout.write("\n")
    elif args.format == "csv":
        write_csv(table, sys.stdout)
    else:
        sys.stdout.write(format_stats(table))
    return 0


def _number(value: float | None, digits: int = 2) -> float | None:
    return None if value is None or not math.isfinite(value) else round(value, digits)


def _key(p: float) -> str:  # = db.stats.percentile_key (no database import on `sass --help`)
    return f"{p:g}"


def table_json(table: StatsTable) -> dict[str, Any]:
    return {
        "n": table.n,
        "effective_n": round(table.effective_n, 1),
        "weighted_by": table.weighted_by,
        "virtual": table.virtual,
        "population": table.population,
        "query": table.query,
        "measures": {
            m.field: {
                "unit": m.unit,
                "n": m.n,
                "mean": _number(m.mean),
                "sd": _number(m.sd),
                "percentiles": {_key(p): _number(v) for p, v in m.percentiles.items()},
                "outside_share": _number(m.outside_share, 4),
            }
            for m in table.measures
        },
    }


def write_csv(table: StatsTable, out: TextIO) -> None:
    """One row a measure; the population column says whose (VIRTUAL people said so)."""
    keys = [_key(p) for p in (table.measures[0].percentiles if table.measures else {})]
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(
        ["measure", "unit", "n", "mean", "sd", *(f"p{k}" for k in keys), "outside_share"]
        + ["effective_n", "population"]
    )
    for m in table.measures:
        writer.writerow(
            [m.field, m.unit, m.n, _number(m.mean), _number(m.sd)]
            + [_number(v) for v in m.percentiles.values()]
            + [
                "" if m.outside_share is None else _number(m.outside_share, 4),
                round(table.effective_n, 1),
                ("VIRTUAL: " if table.virtual else "") + table.population,
            ]
        )
