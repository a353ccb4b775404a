"""`sass family`: a manikin family over 2-6 measurements, with its coverage counted."""

from __future__ import annotations

import argparse
import sys
from types import ModuleType

from sass_tui.cli.common.database_access import open_db
from sass_tui.cli.common.options import (
    SubParsers,
    add_db_option,
    add_virtual_option,
    add_within_range_option,
    file_name,
    weighting_name,
    within_range_of,
)
from sass_tui.db.populations.family import BOTH, load_family
from sass_tui.db.query.query import parse_option
from sass_tui.model.body.figure import Figure
from sass_tui.model.files.family_files import write_family
from sass_tui.model.population.measure_fields import measure_field
from sass_tui.model.vocabulary import GENDERS

DEFAULT_POPULATION = (
    "source = ansur2"  # = sass_tui.db.populations.fit.DEFAULT_POPULATION (no import here)
)


def coverage_argument(text: str) -> float:
    try:
        value = float(text.strip().rstrip("%"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0 < value < 100:
        raise argparse.ArgumentTypeError(f"coverage {value:g} % is outside 0-100 %")
    return value


def measures_argument(text: str) -> list[str]:
    names = [name.strip() for name in text.split(",") if name.strip()]
    if not 2 <= len(names) <= 6:
        raise argparse.ArgumentTypeError(
            f"give 2 to 6 measurements separated by commas, not {len(names)}"
        )
    return names


def register(commands: SubParsers) -> None:
    family = commands.add_parser(
        "family",
        help="manikin family: boundary figures of a coverage ellipsoid, coverage counted",
        description="Build the manikins on (or inside) the ellipsoid that a normal "
        "population would have COVERAGE %% of its people in, complete each into a "
        "whole figure, pair it with its nearest real person, and count the share "
        "of the real people the family covers.",
    )
    add_db_option(family)
    family.add_argument(
        "--gender",
        choices=GENDERS,
        help="the gender of the people covered (default: one family of both genders, "
        "weighted: equal genders, or a target's survey weights)",
    )
    family.add_argument(
        "--space",
        choices=("log-mass", "measured"),
        default="log-mass",
        help="where the coverage ellipsoid is fitted: log-mass (default: mass as its "
        "logarithm, near normal; no manikin lighter than a living adult) or measured",
    )
    family.add_argument(
        "--gltf", action="store_true", help="write each manikin's body as glTF (.glb) too"
    )
    family.add_argument(
        "--measures",
        type=measures_argument,
        required=True,
        metavar="M1,M2[,...]",
        help="2-6 measurements: stature, mass, ANSUR II names (sittingheight) or measure.NAME",
    )
    family.add_argument(
        "--coverage",
        type=coverage_argument,
        default=90.0,
        metavar="PERCENT",
        help="target coverage in percent (default 90)",
    )
    family.add_argument(
        "--kind",
        choices=("boundary", "distributed"),
        default="boundary",
        help="figures on the ellipsoid's surface, or also on an inner shell at half its "
        "radius (default boundary)",
    )
    family.add_argument(
        "--population",
        metavar="QUERY",
        default=DEFAULT_POPULATION,
        help=f"the people (default: {DEFAULT_POPULATION!r})",
    )
    family.add_argument(
        "--target",
        metavar="NAME",
        help="the people of a target population (sass target), weighted: the ellipsoid "
        "and the coverage of the weighted people",
    )
    add_virtual_option(family)
    add_within_range_option(family)
    family.add_argument(
        "-o", "--output", metavar="DIR", type=file_name, required=True, help="output directory"
    )
    family.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    for name in args.measures:
        measure_field(name)  # a typo is reported before the database is opened
    population = parse_option(args.population, "--population")  # parsed once, passed on
    weighting = weighting_name(args)
    within_range = within_range_of(args)
    conn = open_db(args)
    extras: ModuleType | None = None
    if weighting is not None or args.gltf:
        # deferred: cli.common.family_extras (db.shipped, model.gltf) — off sass family (sass_tui/startup.py)
        from sass_tui.cli.common import family_extras as extras
    weighted_to = None
    if weighting is not None:
        assert extras is not None
        weighted_to = extras.load_weights(conn, weighting, only_within_range=within_range)
        if weighted_to.target.is_virtual and args.population == DEFAULT_POPULATION:
            # its virtual people
            population = parse_option(weighted_to.target.population, weighting)
    gender = args.gender or BOTH
    family = load_family(
        conn,
        gender,
        args.measures,
        args.coverage / 100.0,
        args.kind,
        population,
        weighted_to=weighted_to,
        space="log mass" if args.space == "log-mass" else "as measured",
    )
    written = write_family(
        family,
        args.output,
        Figure.default(args.gender or "male"),
        gltf=extras.export_gltf if extras is not None and args.gltf else None,
    )
    out = sys.stdout
    coverage = written.coverage
    people = "people" if weighted_to is None else "people unweighted"
    out.write(
        f"{gender} {args.kind} family over {', '.join(written.measures)}: "
        f"{len(written.manikins)} manikins in {args.output}\n"
        + (f"weighted: {weighted_to.target.words()}\n" if weighted_to is not None else "")
        + f"fitted with {written.to_json()['space']}\n"
        + "".join(f"note: {note}\n" for note in written.notes)
        + f"coverage of the {coverage.n} {'' if gender == BOTH else gender + ' '}people"
        + (" (weighted shares)" if weighted_to is not None else "")
        + (f" ({coverage.missing} not measured, left out)" if coverage.missing else "")
        + ":\n"
        f"  inside the ellipsoid  {coverage.inside_percent:5.1f} % "
        f"({coverage.inside_ellipsoid} {people}; the chi-square promise is "
        f"{coverage.promised_percent:g} %)\n"
        f"  within every range    {coverage.within_ranges_percent:5.1f} % "
        f"({coverage.within_ranges} {people})\n"
    )
    width = max(len(m.name) for m in written.manikins)
    header = "".join(f" {f.removeprefix('measure.'):>17.17}" for f in written.measures)
    out.write(f"\n{'manikin':<{width}}{header}   nearest person (distance, SD)\n")
    for manikin in written.manikins:
        cells = "".join(f" {manikin.values[f]:>17.1f}" for f in written.measures)
        out.write(
            f"{manikin.name:<{width}}{cells}   {manikin.nearest.id} {manikin.nearest.name} "
            f"({manikin.nearest.distance:.2f})\n"
        )
    return 0
