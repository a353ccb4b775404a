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
from typing import TYPE_CHECKING, TextIO

from sass_tui.cli.options import SubParsers, add_db_option, open_db
from sass_tui.db.query import QueryError, compile_query
from sass_tui.db.targets import (
    TargetExistsError,
    check_name,
    drop_target,
    list_targets,
    make_target,
    store_target,
    target_exists,
)
from sass_tui.model.errors import SassError
from sass_tui.model.paths import regular_file
from sass_tui.model.target_sample import SampleError, is_weighting_field, read_sample
from sass_tui.model.vocabulary import GENDERS

if TYPE_CHECKING:
    from sass_tui.db.targets import Target
    from sass_tui.model.targets import Weighting

DEFAULT_POPULATION = "source = ansur2"  # = sass_tui.db.targets.DEFAULT_POPULATION (no import)
DEFAULT_BY = "stature,mass"


class TargetArgumentError(ValueError, SassError):
    """Options of `sass target` that do not go together."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


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
        "--gender", choices=GENDERS, help="the gender of the people weighted (with NAME)"
    )
    target.add_argument(
        "--sample",
        metavar="FILE.csv",
        help="one person a row; columns stature, mass, measure.<name>, units in the header "
        "(stature[cm], mass[lb]) or on the values",
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
    target.add_argument("--force", action="store_true", help="replace a target of that name")
    target.add_argument("--list", action="store_true", help="list the stored targets")
    target.add_argument("--drop", metavar="NAME", help="delete a stored target")
    target.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.list or args.drop is not None:
        if args.name or args.sample or args.gender or (args.list and args.drop is not None):
            raise TargetArgumentError("--list and --drop NAME take no other arguments")
        conn = open_db(args)
        try:
            if args.list:
                _list(conn, sys.stdout)
            else:
                drop_target(conn, args.drop)
                print(f"dropped target {args.drop}")
        finally:
            conn.close()
        return 0
    if not args.name or not args.sample or not args.gender:
        raise TargetArgumentError(
            "give NAME, --gender and --sample FILE.csv (or --list, or --drop NAME)"
        )
    return _make(args)


def by_fields(text: str) -> list[str]:
    """`--by stature,mass,sittingheight` -> query-language fields."""
    # deferred: model.accommodation — off sass target (sass_tui/startup.py)
    from sass_tui.model.accommodation import measure_field

    fields: list[str] = []
    for name in (n.strip() for n in text.split(",")):
        if not name:
            continue
        try:
            field = measure_field(name)
        except SassError as exc:
            raise TargetArgumentError(f"--by: {exc}", where=name) from None
        if not is_weighting_field(field):
            raise TargetArgumentError(
                f"--by: {name!r} is not a measurement; expected stature, mass or an "
                "ANSUR II measurement",
                where=name,
            )
        if field in fields:
            raise TargetArgumentError(f"--by: {name!r} is listed twice", where=name)
        fields.append(field)
    if not 1 <= len(fields) <= 6:
        raise TargetArgumentError(f"--by: give 1 to 6 measurements, not {len(fields)}")
    return fields


def _make(args: argparse.Namespace) -> int:
    # Everything that needs no database first: a bad input touches nothing.
    check_name(args.name)
    fields = by_fields(args.by)
    try:
        compile_query(args.population)
    except QueryError as exc:
        error = QueryError(f"--population: {exc}", exc.text)
        error.column = exc.column
        raise error from None
    path = regular_file(args.sample)
    try:
        text = path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise SampleError(f"{args.sample}: not UTF-8 text ({exc.reason})") from None
    sample = read_sample(text, fields, args.sample)
    conn = open_db(args)
    try:
        if target_exists(conn, args.name) and not args.force and not _replace(args.name):
            print("nothing changed", file=sys.stderr)
            return 1
        target, weights, weighting = make_target(
            conn, args.name, args.gender, sample, args.sample, args.population
        )
        store_target(conn, weights, replace=True)
    finally:
        conn.close()
    _report(target, weighting, sample.incomplete, sys.stdout)
    return 0


def _replace(name: str) -> bool:
    if not (sys.stdin.isatty() and sys.stderr.isatty()):
        raise TargetExistsError(f"a target named {name!r} exists; give --force to replace it")
    sys.stderr.write(f"a target named {name!r} exists; replace it? [y/N] ")
    sys.stderr.flush()
    return sys.stdin.readline().strip().lower() in ("y", "yes")


def _report(target: Target, weighting: Weighting, incomplete: int, out: TextIO) -> None:
    out.write(
        f"target {target.name}: {target.people} {target.gender} people of "
        f"{target.population!r} weighted to {target.sample_rows} rows of {target.sample}"
        + (f" ({incomplete} rows lacking a --by value left out)" if incomplete else "")
        + "\n"
    )
    out.write(f"{'':<24} {'':<10} {'mean':>8} {'SD':>7} {'5th':>8} {'50th':>8} {'95th':>8}\n")
    for check in weighting.checks:
        for word, summary in (
            ("target", check.target),
            ("weighted", check.weighted),
            ("unweighted", check.unweighted),
        ):
            field = check.field.removeprefix("measure.") if word == "target" else ""
            m, sd, p5, p50, p95 = summary.as_list()
            out.write(
                f"{field:<24} {word:<10} {m:8.2f} {sd:7.2f} {p5:8.2f} {p50:8.2f} {p95:8.2f}\n"
            )
    out.write(
        f"effective sample size (Kish): {target.effective_n:.0f} of {target.people} people "
        f"({target.percent_effective:.1f} %)\n"
    )
    for warning in weighting.warnings():
        print(f"warning: {warning}", file=sys.stderr)


def _list(conn, out: TextIO) -> None:  # conn: the database layer's connection
    targets = list_targets(conn)
    if not targets:
        out.write("no targets (make one with `sass target NAME --gender G --sample FILE.csv`)\n")
        return
    for t in targets:
        out.write(
            f"{t.name}  {t.gender}, by {', '.join(t.fields)}, {t.sample_rows} rows of "
            f"{t.sample}; effective n {t.effective_n:.0f} of {t.people} "
            f"({t.percent_effective:.1f} %); {t.created}\n"
        )
