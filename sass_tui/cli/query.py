"""`sass query`: the people a query selects, as a table, CSV or JSON."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterable
from itertools import islice
from typing import Any, TextIO

from sass_tui.cli.common.database_access import open_database
from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    add_virtual_option,
    weighting_name,
)
from sass_tui.db.query.query import (
    QueryError,
    compile_query,
    demonstration_hint,
    unlikely_numbers,
)
from sass_tui.db.query.query_fields import FieldDoc, field_reference
from sass_tui.model.text import is_printable_lines, printable


def register(commands: SubParsers) -> None:
    query = commands.add_parser("query", help="query the anthropometric database")
    add_db_option(query)
    query.add_argument(
        "--format",
        choices=("table", "csv", "json"),
        default="table",
        help="output format (default table)",
    )
    query.add_argument(
        "--count",
        action="store_true",
        help="print only how many people match (on 200,000 people and more in a "
        "SQLite file counted by DuckDB from a column copy, see `sass db copy`)",
    )
    query.add_argument(
        "--target",
        metavar="NAME",
        help="with --count: also the weighted count and share of a target population (sass target)",
    )
    add_virtual_option(query)
    query.add_argument(
        "--fields",
        action="store_true",
        help="list every field a query can name, with its unit and what it is "
        "(docs/query-language.md), and nothing else",
    )
    query.add_argument(
        "query",
        metavar="QUERY",
        nargs="?",
        help='e.g. "gender = male AND stature BETWEEN 160 cm AND 180 cm" (docs/query-language.md)',
    )
    query.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.fields:
        _list_fields(args.format)
        return 0
    if args.query is None:
        raise QueryError('give a QUERY, e.g. "stature > 180 cm", or --fields to list the fields')
    compiled = compile_query(args.query)  # before opening: a bad query touches nothing
    for note in unlikely_numbers(compiled.tree):
        print(note, file=sys.stderr)
    db = open_database(args)
    with db.connection() as conn:  # engine errors (a server gone mid-listing) as messages
        _answer(args, db.query(compiled), conn)
    return 0


def _answer(args: argparse.Namespace, query, conn) -> None:  # query: db.query.Query
    weighting = weighting_name(args)
    if weighting is not None:
        # deferred: cli.query_weighted (db.shipped, db.targets) — off sass query, sass query --count (sass_tui/startup.py)
        from sass_tui.cli.query_weighted import answer_weighted

        answer_weighted(args.count, conn, query.compiled, weighting)
        return
    if args.count:
        found = query.count()
        print(found)
        if not found:
            _say_who_else(conn, query.compiled, found)
        return
    rows = query.person_rows()  # tuples in PERSON_FIELDS order
    found = _writers(args.format)[0](sys.stdout, rows)
    if not found:
        _say_who_else(conn, query.compiled, found)


def _list_fields(form: str) -> None:
    """Every field with its unit and description (db/query/query_fields.py)."""
    _writers(form)[1](sys.stdout, field_reference())


def _writers(form: str) -> tuple[Callable[[TextIO, Any], int], Callable[[TextIO, Any], None]]:
    """What writes --format `form`, the people and the field list: the
    table's here; csv's and json's each in their own module, imported only
    for that format."""
    if form == "csv":
        # deferred: cli.query_csv (csv) — off sass query (sass_tui/startup.py)
        from sass_tui.cli.query_csv import write_fields, write_people
    elif form == "json":
        # deferred: cli.query_json (json) — off sass query, sass query --format csv (sass_tui/startup.py)
        from sass_tui.cli.query_json import write_fields, write_people
    else:
        write_people, write_fields = _write_table, _write_field_table
    return write_people, write_fields


def _say_who_else(conn, query, found: int) -> None:  # query: db.query.CompiledQuery
    """A query that found no real person: the demonstration people it would find."""
    hint = demonstration_hint(conn, query, found)
    if hint:
        print(hint, file=sys.stderr)


def _write_field_table(out: TextIO, fields: list[FieldDoc]) -> None:
    """Every field a query can name, with its unit and description, as a table."""
    width = max(len(f.name) for f in fields)
    unit_width = max(len(f.unit) for f in fields)
    out.write(f"{'field':<{width}}  {'unit':<{unit_width}}  description\n")
    out.writelines(f"{f.name:<{width}}  {f.unit:<{unit_width}}  {f.description}\n" for f in fields)
    out.write(f"{len(fields)} fields\n")


def _write_table(out: TextIO, rows: Iterable[tuple]) -> int:
    """The people as the table, a header first and the count last; returns the count."""
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
    return count


# A row of the table when every value is there and of its type (the fast
# path of _table_lines; the same text as the f-strings below).
_LINE = "%7s  %-20.20s %-6s %7.1f %10.1f %-6s %4.0f  %s\n"


def _table_lines(rows: list[tuple]) -> str:
    """The rows as lines of the table.  Names and sources come from files, so
    no escape sequence may reach the terminal: the text is first made as
    stored, with one format per row, and checked once; only a chunk that holds
    a control character, a missing value or a value of another type is made
    again with every text through printable() (docs/performance.md)."""
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
