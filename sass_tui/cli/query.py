"""`sass query`: the people a query selects, as a table, CSV or JSON."""

from __future__ import annotations

import argparse
import sys

from sass_tui.cli.options import add_db_option, open_db


def register(commands: argparse._SubParsersAction) -> None:
    query = commands.add_parser("query", help="query the anthropometric database")
    add_db_option(query)
    query.add_argument("--format", choices=("table", "csv", "json"), default="table")
    query.add_argument(
        "query", metavar="QUERY", help='e.g. "gender = male AND girth.right_upper_arm.z > 28 cm"'
    )
    query.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import csv
    import json

    from sass_tui.db.query import PERSON_FIELDS, Query, compile_query
    from sass_tui.model.text import printable

    compiled = compile_query(args.query)  # before opening: a bad query touches nothing
    conn = open_db(args)
    query = Query(conn, compiled)
    count = query.count()
    people = ({k: row[k] for k in PERSON_FIELDS} for row in query.iter_all())
    out = sys.stdout
    if args.format == "json":
        persons = [_finite(p) for p in people]
        json.dump({"count": count, "persons": persons}, out, indent=1, allow_nan=False)
        out.write("\n")
    elif args.format == "csv":
        writer = csv.DictWriter(out, fieldnames=PERSON_FIELDS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(people)
    else:
        out.write(
            f"{'id':>7}  {'name':<20} {'gender':<6} {'mass kg':>7} {'stature cm':>10} "
            f"{'hand':<6} {'age':>4}  source\n"
        )
        for p in people:
            # Names and sources come from files: no escape sequence reaches the terminal.
            out.write(
                f"{p['id']:>7}  {printable(p['name']):<20.20} {printable(p['gender']):<6} "
                f"{_num(p['mass']):>7} {_num(p['stature']):>10} {printable(p['handedness']):<6} "
                f"{_num(p['age'], 0):>4}  {printable(p['source'])}\n"
            )
        out.write(f"{count} {'person' if count == 1 else 'people'}\n")
    return 0


def _num(value: float | None, digits: int = 1) -> str:
    return "" if value is None else f"{value:.{digits}f}"


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
