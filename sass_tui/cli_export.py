"""`sass export hanim`: the figure of `sass fig` as an HAnim humanoid (X3D).

Kept out of cli.py so the export formats grow here; no Textual import.
"""

from __future__ import annotations

import argparse
import sys


def add_export_command(commands) -> None:
    from sass_tui.cli import add_figure_options

    export = commands.add_parser("export", help="export the figure to another format")
    formats = export.add_subparsers(dest="format", metavar="FORMAT", required=True)
    hanim = formats.add_parser(
        "hanim", help="ISO/IEC 19774 HAnim humanoid, LOA-1, X3D XML encoding")
    hanim.add_argument("-o", "--output", metavar="NAME.x3d", required=True, help="output file")
    add_figure_options(hanim)
    hanim.set_defaults(func=cmd_export_hanim)


def cmd_export_hanim(args: argparse.Namespace) -> int:
    from sass_tui.cli import figure_from_args
    from sass_tui.model.hanim import export_hanim

    figure, warnings = figure_from_args(args)
    for warning in warnings:
        print(f"warning: {warning}", file=sys.stderr)
    path = export_hanim(figure, args.output)
    print(f"wrote {path}")
    return 0
