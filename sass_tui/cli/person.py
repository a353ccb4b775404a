"""`sass person ID...`: everything the database holds about people (the
headless Disp. Indv.): global data, every group's values, the ANSUR II
measurements, and which values are unmeasured; canonical units (cm, kg, deg,
N-m)."""

from __future__ import annotations

import argparse
import json
import sys

from sass_tui.cli.options import SubParsers, add_db_option, open_database
from sass_tui.db.scope import DEMONSTRATION_SOURCE
from sass_tui.model.measures import MEASURE_UNITS
from sass_tui.model.text import printable


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
        records = db.person_records(args.ids)
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


def _num(value: object) -> str:
    return "—" if value is None else f"{value:.2f}" if isinstance(value, float) else str(value)


def _table(record: dict, out) -> None:  # out: TextIO
    values: dict[str, object] = record["values"]
    source = str(record["source"])
    demonstration = (
        ", a synthetic demonstration person, not a real one"
        if source.lower() == DEMONSTRATION_SOURCE
        else ""
    )
    # Names, sources and survey fields come from files: shown escaped (model/text.py).
    out.write(
        f"{printable(record['name'])} (id {record['id']}{demonstration}): "
        f"{printable(record['gender'])}, stature "
        f"{_num(record['stature'])} cm, mass {_num(record['mass'])} kg, age "
        f"{_num(record['age'])}; source {printable(source)}\n"
    )
    attributes = [
        f"{name} {printable(values[name])}"
        for name in (
            "handedness",
            "component",
            "branch",
            "subjectnumericrace",
            "dodrace",
            "ethnicity",
        )
        if name in values
    ]
    if attributes:
        out.write("  " + "; ".join(attributes) + "\n")
    for word, unit in (("girth", "cm"), ("joint_limit", "deg"), ("center_of_mass", "cm")):
        rows: dict[str, list[object]] = {}
        for name, value in values.items():
            if name.startswith(word + "."):
                _group, row, axis = name.split(".")
                rows.setdefault(row, [None, None, None])["xyz".index(axis)] = value
        out.write(f"{word} ({unit}):{'' if rows else ' nothing measured'}\n")
        for row, cells in rows.items():
            out.write(f"  {row:<22} " + " ".join(f"{_num(c):>8}" for c in cells) + "\n")
    strengths = {k: v for k, v in values.items() if k.startswith("strength.")}
    out.write(
        f"strength (N-m, largest of the person's experiments):{'' if strengths else ' none'}\n"
    )
    for name, value in strengths.items():
        out.write(f"  {name.split('.')[1]:<26} {_num(value):>8}\n")
    measures: dict[str, float] = record["measures"]
    out.write(f"measures:{'' if measures else ' none'}\n")
    for name, value in measures.items():
        out.write(f"  {name:<32} {value:>8.2f} {MEASURE_UNITS[name]}\n")
    out.write(f"unmeasured: {len(record['unmeasured'])} values\n")
