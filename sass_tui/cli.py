"""The `sass` command line.  Subcommands call the model and the database
directly; only plain `sass` (the TUI) imports Textual, and only when run."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from sass_tui.model.figure import GENDERS, FIGURE_TYPES, Figure, FigureError
from sass_tui.model.names import CENTER_OF_MASS, GIRTH, JOINT_LIMITS
from sass_tui.model.percentile import PercentileError
from sass_tui.model.popfile import PopulationFileError, read_population_file
from sass_tui.model.units import UnitError, parse_quantity


def _percentile(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not 0.5 <= value <= 99.5:
        raise argparse.ArgumentTypeError(f"percentile {value:g} is outside 0.5-99.5")
    return value


def add_figure_options(parser: argparse.ArgumentParser) -> None:
    """The options that describe a figure (shared by `fig` and `export hanim`)."""
    parser.add_argument("--gender", choices=GENDERS, default="male")
    parser.add_argument("--percentile", type=_percentile, default=50.0,
                        help="percentile of every group, mass and stature (default 50)")
    parser.add_argument("--girth-percentile", type=_percentile)
    parser.add_argument("--joint-limit-percentile", type=_percentile)
    parser.add_argument("--cmass-percentile", type=_percentile)
    mass = parser.add_mutually_exclusive_group()
    mass.add_argument("--mass", help="total mass, e.g. 80 or '176 lb' (kg if no unit)")
    mass.add_argument("--mass-percentile", type=_percentile)
    stature = parser.add_mutually_exclusive_group()
    stature.add_argument("--stature", help="stature, e.g. 175 or '70 in' (cm if no unit)")
    stature.add_argument("--stature-percentile", type=_percentile)
    parser.add_argument("--figure-type", choices=FIGURE_TYPES, default="skinny")
    parser.add_argument("--girth", metavar="F", help="girth population file")
    parser.add_argument("--jntlmt", metavar="F", help="joint-limit population file")
    parser.add_argument("--cmass", metavar="F", help="center-of-mass population file")


def figure_from_args(args: argparse.Namespace) -> tuple[Figure, list[str]]:
    """Build the figure the options describe; returns it and the load warnings."""
    figure = Figure.default(args.gender)
    warnings: list[str] = []
    for group, option in ((GIRTH, args.girth), (JOINT_LIMITS, args.jntlmt),
                          (CENTER_OF_MASS, args.cmass)):
        if option:
            data = read_population_file(option, group)
            warnings += data.warnings
            figure.load_group(group, data)
    for group, option in ((GIRTH, args.girth_percentile),
                          (JOINT_LIMITS, args.joint_limit_percentile),
                          (CENTER_OF_MASS, args.cmass_percentile)):
        figure.set_group_percentile(group, option if option is not None else args.percentile)
    if args.mass is not None:
        figure.set_mass(parse_quantity(args.mass, "kg"))
    else:
        figure.set_mass_percentile(args.mass_percentile or args.percentile)
    if args.stature is not None:
        figure.set_stature(parse_quantity(args.stature, "cm"))
    else:
        figure.set_stature_percentile(args.stature_percentile or args.percentile)
    figure.set_figure_type(args.figure_type)
    return figure, warnings


def cmd_fig(args: argparse.Namespace) -> int:
    from sass_tui.model.figfile import default_fig_name, write_fig

    figure, warnings = figure_from_args(args)
    extra_sections = []
    if not args.no_strength:
        from sass_tui.model.strength import StrengthSheet, fig_section, read_strength_file

        strength = read_strength_file(args.strength)
        warnings += strength.warnings
        extra_sections.append(fig_section(StrengthSheet(strength, figure)))
    for warning in warnings:
        print(f"warning: {warning}", file=sys.stderr)
    out = args.output or default_fig_name(
        figure.gender, figure.groups[GIRTH].percentile, figure.figure_type)
    write_fig(figure, out, extra_sections)
    print(f"wrote {out}")
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="sass", description="Spreadsheet Anthropometry Scaling System. "
        "With no command, opens the spreadsheet (TUI).")
    parser.add_argument("--db", metavar="PATH", dest="tui_db",
                        help="database the spreadsheet's Query uses (default: $SASS_DB, "
                             "else $XDG_DATA_HOME/sass/sass.db)")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND")
    fig = commands.add_parser("fig", help="write a PEABODY body description file (.fig)")
    fig.add_argument("-o", "--output", metavar="OUT.fig",
                     help="output file (default: the report's MALE50.FIG convention)")
    add_figure_options(fig)
    strength = fig.add_mutually_exclusive_group()
    strength.add_argument("--strength", metavar="F",
                          help="strength file for the strength variables (default datasets/strength.dat)")
    strength.add_argument("--no-strength", action="store_true", help="leave strength out")
    fig.set_defaults(func=cmd_fig)
    from sass_tui.cli_export import add_export_command

    add_export_command(commands)
    from sass_tui.cli_strength import add_strength_command

    add_strength_command(commands)
    from sass_tui.db.commands import register as register_db_commands

    register_db_commands(commands)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        from sass_tui.ui.app import run_app

        return run_app(args.tui_db)
    try:
        return args.func(args)
    except BrokenPipeError:
        # The reader went away (`sass query ... | head`): not an error, and
        # Python must not complain again when it flushes stdout at exit.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except (FigureError, PercentileError, PopulationFileError, UnitError, ValueError, OSError) as exc:
        print(f"sass {args.command}: error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
