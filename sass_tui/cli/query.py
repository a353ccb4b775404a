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

    compiled = compile_query(args.query)  # before opening: a bad query touches nothing
    conn = open_db(args)
    query = Query(conn, compiled)
    count = query.count()
    people = ({k: row[k] for k in PERSON_FIELDS} for row in query.iter_all())
    out = sys.stdout
    if args.format == "json":
        json.dump({"count": count, "persons": list(people)}, out, indent=1)
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
            out.write(
                f"{p['id']:>7}  {p['name']:<20.20} {p['gender']:<6} {_num(p['mass']):>7} "
                f"{_num(p['stature']):>10} {p['handedness'] or '':<6} "
                f"{_num(p['age'], 0):>4}  {p['source']}\n"
            )
        out.write(f"{count} {'person' if count == 1 else 'people'}\n")
    return 0


def _num(value: float | None, digits: int = 1) -> str:
    return "" if value is None else f"{value:.{digits}f}"
