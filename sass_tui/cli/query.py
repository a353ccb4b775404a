"""`sass query`: the people a query selects, as a table, CSV or JSON."""

from __future__ import annotations

import argparse
import math  # already imported by db.query: no start-up cost
import sys
from collections.abc import Iterable
from itertools import islice
from operator import itemgetter
from typing import TextIO

from sass_tui.cli.database_access import open_database
from sass_tui.cli.options import SubParsers, add_db_option, add_virtual_option, weighting_name
from sass_tui.db.query import PERSON_FIELDS, QueryError, compile_query, demonstration_hint
from sass_tui.db.query_fields import field_reference
from sass_tui.model.text import (
    is_printable,
    is_printable_lines,
    may_start_a_formula,
    printable,
    spreadsheet_text,
)


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
    db = open_database(args)
    with db.connection() as conn:  # engine errors (a server gone mid-listing) as messages
        _answer(args, db.query(compiled), conn)
    return 0


def _answer(args: argparse.Namespace, query, conn) -> None:  # query: db.query.Query
    weighting = weighting_name(args)
    if args.count:
        if weighting is not None:
            # deferred: cli.query_weighted (db.shipped, db.targets) — off sass query, sass query --count (sass_tui/startup.py)
            from sass_tui.cli.query_weighted import print_weighted_count

            print_weighted_count(conn, query.compiled, weighting)
            return
        found = query.count()
        print(found)
        if not found:
            _say_who_else(conn, query.compiled, found)
        return
    if weighting is not None:
        # deferred: model.targets — off sass query, sass query --count (sass_tui/startup.py)
        from sass_tui.model.targets import TargetError

        raise TargetError("--target and --virtual weight a count: give --count too")
    rows = query.person_rows()  # tuples in PERSON_FIELDS order
    out = sys.stdout
    if args.format == "csv":
        # deferred: csv — off sass query (sass_tui/startup.py)
        import csv

        # Names and sources come from files and the CSV may go to a terminal: a
        # control character is written escaped.  The CSV is opened in
        # spreadsheets too: a text cell that would start a formula (an import's
        # source label `=HYPERLINK(...)`) is written as text.  One check over a
        # chunk's texts joined; only when it fails is each text made safe.
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(PERSON_FIELDS)
        found = 0
        while chunk := rows.fetchmany(1000):
            try:
                texts = [row[k] for row in chunk for k in (1, 2, 5, 7)]
                plain = is_printable("".join(texts)) and not may_start_a_formula(texts)
            except TypeError:  # a name stored as a number, or no gender
                plain = False
            if not plain:
                chunk = [
                    (i, _cell(name), _cell(g), mass, stature, _cell(hand), age, _cell(source))
                    for i, name, g, mass, stature, hand, age, source in chunk
                ]
            writer.writerows(chunk)
            found += len(chunk)
    elif args.format == "json":
        found = _write_json(out, rows)
    else:
        found = _write_table(out, rows)
    if not found:
        _say_who_else(conn, query.compiled, found)


def _list_fields(form: str) -> None:
    """Every field with its unit and description (db/query_fields.py)."""
    fields = field_reference()
    out = sys.stdout
    if form == "csv":
        # deferred: csv — off sass query, sass query --count (sass_tui/startup.py)
        import csv

        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(("field", "unit", "description"))
        writer.writerows(fields)
    elif form == "json":
        # deferred: json — only --format json writes JSON; off sass query (sass_tui/startup.py)
        import json

        listed = [dict(zip(("field", "unit", "description"), f)) for f in fields]
        out.write(json.dumps({"fields": listed}, indent=1) + "\n")
    else:
        width = max(len(f.name) for f in fields)
        unit_width = max(len(f.unit) for f in fields)
        out.write(f"{'field':<{width}}  {'unit':<{unit_width}}  description\n")
        out.writelines(
            f"{f.name:<{width}}  {f.unit:<{unit_width}}  {f.description}\n" for f in fields
        )
        out.write(f"{len(fields)} fields\n")


def _cell(text: object) -> object:
    """A text cell of the CSV: printable, and never a formula; None stays empty."""
    return text if text is None else spreadsheet_text(printable(text))


def _say_who_else(conn, query, found: int) -> None:  # query: db.query.CompiledQuery
    """A query that found no real person: the demonstration people it would find."""
    hint = demonstration_hint(conn, query, found)
    if hint:
        print(hint, file=sys.stderr)


def _write_table(out: TextIO, rows: Iterable[tuple]) -> int:
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


# A person of the JSON listing when every value is there and of its type (the
# fast path of _write_json; the same text json's encoder makes of the dict).
_JSON_PERSON = (
    '{"id": %d, "name": %s, "gender": %s, "mass": %r, "stature": %r, '
    '"handedness": %s, "age": %r, "source": %s}'
)


def _write_json(out: TextIO, rows: Iterable[tuple]) -> int:
    """`{"persons": [...], "count": N}`, one person a line, streamed a chunk
    of rows at a time (every row held at once took 224 MB at 200,000 people,
    against 43 MB for CSV); the count comes last, once it is known.
    json.dump with `indent` runs the pure-Python encoder (2.96 times the
    table's time); each person is made here with one format, its texts
    quoted by json's own C function, when the numbers are all finite numbers
    (their sum is finite; None or a text raises TypeError); otherwise by the
    encoder, person by person (benchmarks/query_formats.py)."""
    out.write('{"persons": [')
    count = 0
    remaining = iter(rows)
    while chunk := list(islice(remaining, 1000)):
        out.write(("\n" if not count else ",\n") + _json_people(chunk))
        count += len(chunk)
    out.write(f'\n], "count": {count}}}\n' if count else f'], "count": {count}}}\n')
    return count


def _json_people(rows: list[tuple]) -> str:
    """Some people of the JSON listing, one a line, joined by ",\n"."""
    # deferred: json — only --format json writes JSON; off sass query (sass_tui/startup.py)
    import json
    from json.encoder import encode_basestring_ascii as quote

    try:
        finite = all(math.isfinite(sum(map(itemgetter(k), rows))) for k in (3, 4, 6))
        if finite:
            return ",\n".join(
                [
                    _JSON_PERSON
                    % (id_num, quote(name), quote(g), mass, stature, quote(hand), age, quote(src))
                    for id_num, name, g, mass, stature, hand, age, src in rows
                ]
            )
    except TypeError:
        pass
    encode = json.JSONEncoder(allow_nan=False).encode
    return ",\n".join([encode(_finite(dict(zip(PERSON_FIELDS, row)))) for row in rows])


def _finite(person: dict) -> dict:
    """The person for JSON, which has no Infinity or NaN: refuse one stored so."""
    for key, value in person.items():
        if isinstance(value, float) and not math.isfinite(value):
            raise QueryError(
                f"person {person['id']} ({printable(person['name'])}): {key} is {value} "
                "in the database, which JSON cannot hold; fix or re-import the person"
            )
    return person
