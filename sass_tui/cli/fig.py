"""`sass fig`: write a PEABODY body description file (.fig)."""

from __future__ import annotations

import argparse
import sys

from sass_tui.cli.common.figure_from_options import figure_from_args
from sass_tui.cli.common.options import (
    SubParsers,
    add_figure_options,
    file_name,
    person_file_name,
    print_warnings,
)
from sass_tui.model.files.figfile import default_fig_name, write_fig
from sass_tui.model.names import GIRTH
from sass_tui.model.strength.published_strength import EXAMPLE_DATA_SET, EXAMPLE_SOURCE
from sass_tui.model.strength.strength import (
    StrengthSheet,
    fig_section,
    lower_limb_fig_section,
    read_strength_file,
)


def register(commands: SubParsers) -> None:
    fig = commands.add_parser("fig", help="write a PEABODY body description file (.fig)")
    fig.add_argument(
        "-o",
        "--output",
        metavar="OUT.fig",
        type=file_name,
        help="output file (default: the report's MALE50.FIG convention; a person's name)",
    )
    add_figure_options(fig)
    strength = fig.add_mutually_exclusive_group()
    strength.add_argument(
        "--strength",
        metavar="F",
        type=file_name,
        help="a strength file (measured data) for the arm's strength variables; by default "
        "the figure carries only published strength (Anderson et al. 2007's hip, knee and "
        "ankle)",
    )
    strength.add_argument(
        "--strength-data",
        choices=(EXAMPLE_DATA_SET,),
        help=f"{EXAMPLE_DATA_SET}: also the arm's strength from the invented example data "
        "(datasets/strength.dat), said so in the file and on the terminal",
    )
    strength.add_argument("--no-strength", action="store_true", help="leave strength out")
    fig.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    figure, warnings = figure_from_args(args)
    extra_sections = []
    notes: list[str] = []
    if not args.no_strength:
        # No invented strength unless asked for by name: the arm's lines come
        # from a strength file the user gives, or the example data named.
        if args.strength is not None or args.strength_data == EXAMPLE_DATA_SET:
            strength = read_strength_file(args.strength)
            warnings += strength.warnings
            extra_sections.append(fig_section(StrengthSheet(strength, figure)))
            if strength.source == EXAMPLE_SOURCE:
                notes.append(
                    f"the arm's strength variables are {EXAMPLE_SOURCE}, not measured "
                    "strength (--strength-data example)"
                )
        extra_sections.append(lower_limb_fig_section(figure))
    print_warnings(warnings)
    if args.output:
        out = args.output
    elif figure.person is not None:
        out = person_file_name(figure.person, ".fig")
    else:
        out = default_fig_name(figure.gender, figure.groups[GIRTH].percentile, figure.figure_type)
    write_fig(figure, out, extra_sections)
    print(f"wrote {out}")
    for note in notes:
        print(f"note: {note}", file=sys.stderr)
    return 0
