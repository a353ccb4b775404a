"""`sass target`: target populations, the real people weighted to match a
sample of the people a design is for (docs/target-populations.md).

    sass target civilian-women --gender female --sample nhanes_women.csv
    sass target --list
    sass target --drop civilian-women

`--target NAME` then weights `fit`, `family`, `population` and `query --count`.
"""

from __future__ import annotations

import argparse
import sys
from typing import TextIO

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import SubParsers, add_db_option, file_name
from sass_tui.db.populations.shipped import REMAKE
from sass_tui.db.populations.targets import SHIPPED, list_targets
from sass_tui.model.datasets import NHANES_NAME, NHANES_WEIGHT
from sass_tui.model.vocabulary import GENDERS

DEFAULT_POPULATION = (
    "source = ansur2"  # = sass_tui.db.populations.targets.DEFAULT_POPULATION (no import)
)
DEFAULT_BY = "stature,mass"


def register(commands: SubParsers) -> None:
    target = commands.add_parser(
        "target",
        help="make a target population: the real people weighted to match a sample",
        description="Weight the real people of one gender so that the joint distribution "
        "of the --by measurements matches a sample of the target population (calibration "
        "weighting, docs/target-populations.md), and store the weights under NAME for "
        "--target in fit, family, population and query --count.",
    )
    add_db_option(target)
    target.add_argument("name", metavar="NAME", nargs="?", help="the target's name")
    target.add_argument(
        "--gender",
        choices=GENDERS,
        help="the gender to weight (default: both, each to the sample's rows of its gender)",
    )
    target.add_argument(
        "--sample",
        type=file_name,
        metavar="FILE.csv",
        help="one person a row; columns stature, mass, measure.<name>, units in the header "
        "(stature[cm], mass[lb]) or on the values; gender, age; a .csv.gz file is read "
        f"decompressed; {NHANES_NAME!r} is the shipped NHANES 2017-March 2020 adults",
    )
    target.add_argument(
        "--weight",
        metavar="COLUMN",
        help="the sample's survey weight column: each row stands for that many people "
        f"(the shipped {NHANES_NAME}: {NHANES_WEIGHT})",
    )
    target.add_argument(
        "--by",
        metavar="M1,M2,...",
        default=DEFAULT_BY,
        help=f"the measurements to match (default {DEFAULT_BY})",
    )
    target.add_argument(
        "--population",
        metavar="QUERY",
        default=DEFAULT_POPULATION,
        help=f"the people to weight (default: {DEFAULT_POPULATION!r}, of --gender)",
    )
    target.add_argument(
        "--within-range",
        action="store_true",
        help="match only the sample's rows inside the people's range of every --by "
        "measurement (the report's 'outside' column says how much lies beyond)",
    )
    target.add_argument(
        "--virtual",
        action="store_true",
        help="also store the virtual population NAME: one VIRTUAL person per sample row, "
        "its own stature, mass, age and gender, every other measure predicted from the "
        "real people (docs/target-populations.md); reached with --virtual NAME",
    )
    target.add_argument("--force", action="store_true", help="replace a target of that name")
    target.add_argument("--list", action="store_true", help="list the stored targets")
    target.add_argument("--drop", metavar="NAME", help="delete a stored target")
    target.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.list and not (args.name or args.sample or args.gender or args.drop is not None):
        conn = open_db(args)
        try:
            _list(conn, sys.stdout)
        finally:
            conn.close()
        return 0
    # Making or dropping a target (and refusing options that do not go
    # together) needs the sample reader, the virtual people and the weighting.
    # deferred: cli.target_change (db.virtual, model.sample_file) — off sass target (sass_tui/startup.py)
    from sass_tui.cli.target_change import change

    return change(args)


def _list(conn, out: TextIO) -> None:  # conn: the database layer's connection
    targets = list_targets(conn)
    stored = {t.name for t in targets}
    if not targets:
        out.write("no targets (make one with `sass target NAME --gender G --sample FILE.csv`)\n")
    for t in targets:
        kind = "VIRTUAL population (predicted people), " if t.is_virtual else ""
        survey = f" weighted by {t.weighted_by}" if t.weighted_by else ""
        out.write(
            f"{t.name}  {kind}{t.gender}, by {', '.join(t.fields)}, {t.sample_rows} rows of "
            f"{t.sample}{survey}; effective n {t.effective_n:.0f} of {t.people} "
            f"({t.percent_effective:.1f} %); {t.created}\n"
        )
    for name in SHIPPED:
        if name not in stored:
            out.write(
                f"{name}  shipped (NHANES 2017-March 2020 adults), not stored: "
                f"`sass db init` or `{REMAKE}` makes it again\n"
            )
