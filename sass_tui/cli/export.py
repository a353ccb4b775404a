"""`sass export hanim`: the figure of `sass fig` as an HAnim humanoid (X3D)."""

from __future__ import annotations

import argparse
import sys

from sass_tui.cli.options import SubParsers, add_figure_options, figure_from_args, print_warnings


def register(commands: SubParsers) -> None:
    export = commands.add_parser("export", help="export the figure to another format")
    formats = export.add_subparsers(dest="format", metavar="FORMAT", required=True)
    hanim = formats.add_parser(
        "hanim", help="ISO/IEC 19774 HAnim humanoid, LOA-1, X3D XML encoding"
    )
    hanim.add_argument("-o", "--output", metavar="NAME.x3d", required=True, help="output file")
    add_figure_options(hanim)
    hanim.set_defaults(func=run_hanim)


def run_hanim(args: argparse.Namespace) -> int:
    from sass_tui.model.hanim import export_hanim, not_in_humanoid_note

    figure, warnings = figure_from_args(args)
    print_warnings(warnings)
    path = export_hanim(figure, args.output)
    print(f"wrote {path}")
    note = not_in_humanoid_note(figure).strip()
    if note:
        print(f"note: {note.replace(' (Create Figure)', ' (sass fig)')}", file=sys.stderr)
    return 0
