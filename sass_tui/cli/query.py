"""`sass query`: the people a query selects, as a table, CSV or JSON."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable
from itertools import islice
from typing import TextIO

from sass_tui.cli.options import SubParsers, add_db_option, open_database


def register(commands: SubParsers) -> None:
    query = commands.add_parser("query", help="query the anthropometric database")
    add_db_option(query)
    query.add_argument("--format", choices=("table", "csv", "json"), default="table")
    query.add_argument(
        "--count",
        action="store_true",
        help="print only how many people match (on 200,000 people and more in a "
        "SQLite file counted by DuckDB from a column copy, see `sass db copy`)",
    )
    query.add_argument(
        "query", metavar="QUERY", help='e.g. "gender = male AND girth.right_upper_arm.z > 28 cm"'
    )
    query.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from sass_tui.db.query import compile_query

    compiled = compile_query(args.query)  # before opening: a bad query touches nothing
    db = open_database(args)
    with db.connection():  # engine errors (a server gone mid-listing) as messages
        _answer(args, db.query(compiled))
    return 0


def _answer(args: argparse.Namespace, query) -> None:  # query: db.query.Query
    from sass_tui.db.query import PERSON_FIELDS

    if args.count:
        print(query.count())
        return
    rows = query.person_rows()  # tuples in PERSON_FIELDS order
    out = sys.stdout
    if args.format == "csv":
        import csv

        # Data as stored (no escaping): CSV is for programs, not for a terminal.
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(PERSON_FIELDS)
        writer.writerows(rows)
    elif args.format == "json":
        import json

        persons = [_finite(dict(zip(PERSON_FIELDS, row))) for row in rows]
        json.dump({"count": len(persons), "persons": persons}, out, indent=1, allow_nan=False)
        out.write("\n")
    else:
        _write_table(out, rows)


def _write_table(out: TextIO, rows: Iterable[tuple]) -> None:
    out.write(
        f"{'id':>7}  {'name':<20} {'gender':<6} {'mass kg':>7} {'stature cm':>10} "
        f"{'hand':<6} {'age':>4}  source\n"
    )
    count = 0
    remaining = iter(rows)
    while chunk := list(islice(remaining, 1000)):
        out.write(_table_lines(chunk))
        count += len(chunk)
    out.write(f"{count} {'person' if count == 1 else 'people'}\n")


# A row of the table when every value is there and of its type (the fast
# path of _table_lines; the same text as the f-strings below).
_LINE = "%7s  %-20.20s %-6s %7.1f %10.1f %-6s %4.0f  %s\n"


def _table_lines(rows: list[tuple]) -> str:
    """The rows as lines of the table.  Names and sources come from files, so
    no escape sequence may reach the terminal: the text is first made as
    stored, with one format per row, and checked once; only a chunk that holds
    a control character, a missing value or a value of another type is made
    again with every text through printable() (docs/performance.md)."""
    from sass_tui.model.text import is_printable_lines, printable

    if not any(None in row for row in rows):
        try:
            text = "".join([_LINE % row for row in rows])
        except (TypeError, ValueError):  # e.g. text stored as a mass
            pass
        else:
            if is_printable_lines(text, len(rows)):
                return text
    return "".join(
        [
            f"{id_num:>7}  {printable(name):<20.20} {printable(gender):<6} "
            f"{'' if mass is None else f'{mass:.1f}':>7} "
            f"{'' if stature is None else f'{stature:.1f}':>10} {printable(hand):<6} "
            f"{'' if age is None else f'{age:.0f}':>4}  {printable(source)}\n"
            for id_num, name, gender, mass, stature, hand, age, source in rows
        ]
    )


def _finite(person: dict) -> dict:
    """The person for JSON, which has no Infinity or NaN: refuse one stored so."""
    import math

    from sass_tui.db.query import QueryError
    from sass_tui.model.text import printable

    for key, value in person.items():
        if isinstance(value, float) and not math.isfinite(value):
            raise QueryError(
                f"person {person['id']} ({printable(person['name'])}): {key} is {value} "
                "in the database, which JSON cannot hold; fix or re-import the person"
            )
    return person
