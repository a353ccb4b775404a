"""`sass query --format json`: the people, or the fields (--fields), as JSON.

A module of its own so that `sass query` (the table) and `--format csv`
never import json (their rows of sass_tui/startup.py); cli/query.py imports
it only for --format json.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable
from itertools import islice
from json.encoder import encode_basestring_ascii as quote
from operator import itemgetter
from typing import TextIO

from sass_tui.db.query.query import PERSON_FIELDS, QueryError
from sass_tui.db.query.query_fields import FieldDoc
from sass_tui.model.text import printable

# A person of the JSON listing when every value is there and of its type (the
# fast path of write_people; the same text json's encoder makes of the dict).
_JSON_PERSON = (
    '{"id": %d, "name": %s, "gender": %s, "mass": %r, "stature": %r, '
    '"handedness": %s, "age": %r, "source": %s}'
)


def write_people(out: TextIO, rows: Iterable[tuple]) -> int:
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


def write_fields(out: TextIO, fields: list[FieldDoc]) -> None:
    """Every field a query can name, with its unit and description."""
    listed = [dict(zip(("field", "unit", "description"), f)) for f in fields]
    out.write(json.dumps({"fields": listed}, indent=1) + "\n")


def _json_people(rows: list[tuple]) -> str:
    """Some people of the JSON listing, one a line, joined by ",\n"."""
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
