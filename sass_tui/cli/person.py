"""`sass person ID...`: everything the database holds about people (the
headless Disp. Indv.): global data, every group's values, the ANSUR II
measurements, and which values are unmeasured; canonical units (cm, kg, deg,
N-m)."""

from __future__ import annotations

import argparse
import json
import sys

from sass_tui.cli.common.database_access import open_database
from sass_tui.cli.common.options import SubParsers, add_db_option
from sass_tui.db.people.individual import person_records
from sass_tui.db.people.person_text import person_lines


def register(commands: SubParsers) -> None:
    person = commands.add_parser("person", help="show people of the database, every value")
    add_db_option(person)
    person.add_argument(
        "--format", choices=("table", "json"), default="table", help="output format (default table)"
    )
    person.add_argument(
        "ids",
        nargs="+",
        metavar="ID",
        help='database id or name, e.g. 17 or "ANSUR II M 10037"',
    )
    person.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    db = open_database(args)
    try:
        records = person_records(db, args.ids)
    finally:
        db.close()
    out = sys.stdout
    if args.format == "json":
        json.dump({"persons": records}, out, indent=1, allow_nan=False)
        out.write("\n")
        return 0
    for k, record in enumerate(records):
        if k:
            out.write("\n")
        _table(record, out)
    return 0


def _table(record: dict, out) -> None:  # out: TextIO
    out.write("".join(line + "\n" for line in person_lines(record)))
