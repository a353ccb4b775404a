"""`sass query --format csv`: the people, or the fields (--fields), as CSV.

A module of its own so that `sass query` (the table) never imports csv (the
`sass query` row of sass_tui/startup.py); cli/query.py imports it only for
--format csv.
"""

from __future__ import annotations

import csv
from typing import TextIO

from sass_tui.db.query.query import PERSON_FIELDS
from sass_tui.db.query.query_fields import FieldDoc
from sass_tui.model.text import is_printable, may_start_a_formula, printable, spreadsheet_text


def write_people(out: TextIO, rows) -> int:  # rows: a cursor of PERSON_FIELDS tuples
    """The people as CSV, a header first; returns how many."""
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
    return found


def write_fields(out: TextIO, fields: list[FieldDoc]) -> None:
    """Every field a query can name, with its unit and description."""
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(("field", "unit", "description"))
    writer.writerows(fields)


def _cell(text: object) -> object:
    """A text cell of the CSV: printable, and never a formula; None stays empty."""
    return text if text is None else spreadsheet_text(printable(text))
