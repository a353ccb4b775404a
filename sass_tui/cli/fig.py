"""`sass fig`: write a PEABODY body description file (.fig)."""

from __future__ import annotations

import argparse

from sass_tui.cli.options import (
    SubParsers,
    add_figure_options,
    figure_from_args,
    person_file_name,
    print_warnings,
)
from sass_tui.model.figfile import default_fig_name, write_fig
from sass_tui.model.names import GIRTH
from sass_tui.model.strength import (
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
        help="output file (default: the report's MALE50.FIG convention; a person's name)",
    )
    add_figure_options(fig)
    strength = fig.add_mutually_exclusive_group()
    strength.add_argument(
        "--strength",
        metavar="F",
        help="strength file for the strength variables (default datasets/strength.dat)",
    )
    strength.add_argument("--no-strength", action="store_true", help="leave strength out")
    fig.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    figure, warnings = figure_from_args(args)
    extra_sections = []
    if not args.no_strength:
        strength = read_strength_file(args.strength)
        warnings += strength.warnings
        extra_sections.append(fig_section(StrengthSheet(strength, figure)))
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
    return 0
