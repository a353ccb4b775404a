"""`sass target NAME --sample FILE.csv` and `sass target --drop NAME`:
making and dropping a target population (cli/target.py holds the verb's
options and `--list`).

A module of its own because making a target reads a sample (the ANSUR II
measure names and the prediction's units, model/files/sample_file.py) and may
make virtual people (db/populations/virtual.py), and dropping one may drop virtual
people: listing the stored targets needs none of them (the `sass target` row
of sass_tui/startup.py).
"""

from __future__ import annotations

import argparse
import gzip
import io
import sys
from typing import TYPE_CHECKING, TextIO

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import VIRTUAL_PREFIX
from sass_tui.db.populations.targets import (
    BOTH,
    TargetExistsError,
    check_name,
    drop_target,
    make_target,
    store_target,
    target_exists,
)
from sass_tui.db.populations.virtual import (
    MEASURED,
    drop_virtual,
    make_virtual,
    store_target_and_virtual,
)
from sass_tui.db.query.query import parse_option
from sass_tui.model.datasets import NHANES, NHANES_NAME, shipped_text
from sass_tui.model.errors import SassError
from sass_tui.model.files.paths import LARGEST_PEOPLE_TABLE, regular_file
from sass_tui.model.files.sample_file import read_sample
from sass_tui.model.population.measure_fields import measure_field
from sass_tui.model.population.target_sample import SampleError, is_weighting_field

if TYPE_CHECKING:
    from sass_tui.db.populations.targets import Target
    from sass_tui.model.population.targets import Weighting


# The most rows `--virtual` makes people of (one person a row): a million
# took 5 min, 7.4 GB of memory and grew the database by 4.1 GB; the shipped
# NHANES sample has 8,381.  Counted before the sample is read.
MAX_VIRTUAL_PEOPLE = 100_000


class TargetArgumentError(ValueError, SassError):
    """Options of `sass target` that do not go together."""

    def __init__(self, message: str = "", *, where: str | None = None) -> None:
        SassError.__init__(self, message, where=where)


def change(args: argparse.Namespace) -> int:
    """Drop the target --drop names, or make NAME from --sample; refuse
    options that do not go together."""
    if args.list or args.drop is not None:
        if args.name or args.sample or args.gender or (args.list and args.drop is not None):
            raise TargetArgumentError("--list and --drop NAME take no other arguments")
        conn = open_db(args)
        try:
            if args.drop.startswith(VIRTUAL_PREFIX):
                people = drop_virtual(conn, args.drop)
                print(f"dropped virtual population {args.drop} and its {people} virtual people")
            else:
                drop_target(conn, args.drop)
                print(f"dropped target {args.drop}")
        finally:
            conn.close()
        return 0
    if not args.name or not args.sample:
        raise TargetArgumentError("give NAME and --sample FILE.csv (or --list, or --drop NAME)")
    return _make(args)


def by_fields(text: str) -> list[str]:
    """`--by stature,mass,sittingheight` -> query-language fields."""
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
    population = parse_option(args.population, "--population")  # parsed once, passed on
    gender = args.gender or BOTH
    text = sample_text(args.sample)
    rows = sum(1 for line in text.splitlines() if line.strip()) - 1
    if args.virtual and rows > MAX_VIRTUAL_PEOPLE:
        raise TargetArgumentError(
            f"{args.sample}: {rows:,} rows; --virtual makes one person a row, at most "
            f"{MAX_VIRTUAL_PEOPLE:,} (a million took 5 min and 4 GB of database); weight "
            "the sample without --virtual, or take a sample of its rows"
        )
    sample = read_sample(
        text,
        fields,
        args.sample,
        weight=args.weight,
        gender=args.gender,
        need_gender=args.gender is None,
        optional=MEASURED if args.virtual else (),
    )
    for column in sample.unused_weights:
        print(
            f"warning: {args.sample}: column {column!r} looks like a survey weight and is not "
            f"used: every row counts once (give --weight {column} to use it)",
            file=sys.stderr,
        )
    conn = open_db(args)
    try:
        taken = target_exists(conn, args.name) or (
            args.virtual and target_exists(conn, VIRTUAL_PREFIX + args.name)
        )
        if taken and not args.force and not _replace(args.name):
            print("nothing changed", file=sys.stderr)
            return 1
        target, weights, weightings = make_target(
            conn,
            args.name,
            gender,
            sample,
            args.sample,
            population,
            within_range=args.within_range,
        )
        if args.virtual:
            virtual = make_virtual(conn, args.name, sample, args.sample, gender)
            store_target_and_virtual(conn, weights, virtual)
        else:
            virtual = None
            store_target(conn, weights, replace=True)
    finally:
        conn.close()
    _report(target, weightings, sample.incomplete, sys.stdout)
    if virtual is not None:
        beyond = ", ".join(f"{n} {g}" for g, n in virtual.beyond.items())
        kept = [f.removeprefix("measure.") for f in sample.optional_fields]
        measured = f", and their measured {' and '.join(kept)}" if kept else ""
        print(
            f"virtual population {args.name}: {len(virtual.people)} VIRTUAL people (their own "
            f"stature, mass, age and gender{measured}; every other measure predicted from the "
            f"real people); beyond the range the prediction was fitted on: {beyond} "
            f"(flagged: --within-range leaves them out); "
            f"effective n {virtual.target.effective_n:.0f} (sass fit --virtual {args.name})"
        )
    return 0


def sample_text(name: str) -> str:
    """The text of a sample: the shipped NHANES adults by name, a .gz file
    decompressed, else the file; at most LARGEST_PEOPLE_TABLE bytes, a .gz
    file by what it expands to (a 1 MB file held a 1 GiB field)."""
    if name == NHANES_NAME:
        return shipped_text(NHANES)
    path = regular_file(name, largest=LARGEST_PEOPLE_TABLE, kind="a sample")
    try:
        data = path.read_bytes()
        if name.endswith(".gz"):
            with gzip.GzipFile(fileobj=io.BytesIO(data)) as expanding:
                data = expanding.read(LARGEST_PEOPLE_TABLE + 1)
            if len(data) > LARGEST_PEOPLE_TABLE:
                raise SampleError(
                    f"{name}: expands to more than {LARGEST_PEOPLE_TABLE // 2**20} MB; "
                    "a sample is at most that"
                )
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SampleError(f"{name}: not UTF-8 text ({exc.reason})") from None
    except (gzip.BadGzipFile, EOFError) as exc:
        raise SampleError(f"{name}: not a gzip file ({exc})") from None


def _replace(name: str) -> bool:
    if not (sys.stdin.isatty() and sys.stderr.isatty()):
        raise TargetExistsError(f"a target named {name!r} exists; give --force to replace it")
    sys.stderr.write(f"a target named {name!r} exists; replace it? [y/N] ")
    sys.stderr.flush()
    return sys.stdin.readline().strip().lower() in ("y", "yes")


def _report(target: Target, weightings: dict[str, Weighting], incomplete: int, out: TextIO) -> None:
    survey = f" (each row weighted by its {target.weighted_by})" if target.weighted_by else ""
    who = "male and female" if len(weightings) > 1 else target.gender
    out.write(
        f"target {target.name}: {target.people} {who} people of "
        f"{target.population!r} weighted to {target.sample_rows} rows of {target.sample}{survey}"
        + (f" ({incomplete} rows lacking a --by value left out)" if incomplete else "")
        + "\n"
    )
    for gender, weighting in weightings.items():
        if len(weightings) > 1:
            out.write(f"{gender}: {weighting.people} people, {weighting.sample_rows} sample rows\n")
        out.write(
            f"{'':<24} {'':<10} {'mean':>8} {'SD':>7} {'5th':>8} {'50th':>8} {'95th':>8} "
            f"{'outside':>8}\n"
        )
        for check in weighting.checks:
            for word, summary in (
                ("target", check.target),
                ("weighted", check.weighted),
                ("unweighted", check.unweighted),
            ):
                field = check.field.removeprefix("measure.") if word == "target" else ""
                outside = f"{100 * check.outside_share:7.1f}%" if word == "target" else ""
                m, sd, p5, p50, p95 = summary.as_list()
                out.write(
                    f"{field:<24} {word:<10} {m:8.2f} {sd:7.2f} {p5:8.2f} {p50:8.2f} {p95:8.2f} "
                    f"{outside:>8}".rstrip()
                    + "\n"
                )
        for warning in weighting.warnings():
            prefix = f"{gender}: " if len(weightings) > 1 else ""
            print(f"warning: {prefix}{warning}", file=sys.stderr)
    out.write(
        "outside: the share of the target's weight beyond every person's value "
        "(weighting cannot reach it)\n"
        f"effective sample size (Kish): {target.effective_n:.0f} of {target.people} people "
        f"({target.percent_effective:.1f} %)\n"
    )
