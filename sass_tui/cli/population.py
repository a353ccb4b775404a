"""`sass population --query QUERY -o FILE.dat`: population files (report
figure 7) made from the people a query selects: the empirical 5th/50th/95th
percentile, per gender, of every girth and center-of-mass row.

`-o young.dat` writes the girth file to young.dat and the center-of-mass
file beside it as young-cmass.dat (`sass fig --girth young.dat --cmass
young-cmass.dat`)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from sass_tui.cli.options import SubParsers, add_db_option, open_db


def register(commands: SubParsers) -> None:
    population = commands.add_parser(
        "population", help="make population files from the people a query selects"
    )
    add_db_option(population)
    population.add_argument("--query", required=True, metavar="QUERY")
    population.add_argument(
        "-o",
        "--output",
        required=True,
        metavar="FILE.dat",
        help="girth file; the center-of-mass file is FILE-cmass.dat beside it",
    )
    population.add_argument("--title", metavar="T", help="title (default: the query)")
    population.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from sass_tui.db.population import people_words, population_of
    from sass_tui.db.population_files import write_population_files
    from sass_tui.db.query import compile_query
    from sass_tui.model.names import GROUP_TITLES

    compile_query(args.query)  # a bad query touches nothing
    conn = open_db(args)
    try:
        result = population_of(conn, args.query, title=args.title)
    finally:
        conn.close()
    for group, path in write_population_files(result, Path(args.output)).items():
        print(f"wrote {path} ({GROUP_TITLES[group].lower()})")
    for group in result.empty_groups:
        print(
            f"no {GROUP_TITLES[group].lower()} file: none of these people has a value of it",
            file=sys.stderr,
        )
    print(f"from {people_words(result.counts)} selected by: {result.query}")
    return 0
