"""`sass export hanim|gltf`: the figure of `sass fig` as an HAnim humanoid (X3D)
or as a skinned glTF 2.0 body built from the same humanoid."""

from __future__ import annotations

import argparse
import sys
from typing import TYPE_CHECKING

from sass_tui.cli.common.figure_from_options import figure_from_args
from sass_tui.cli.common.options import SubParsers, add_figure_options, file_name, print_warnings
from sass_tui.model.body.hanim import not_in_humanoid_note
from sass_tui.model.files.paths import user_path

if TYPE_CHECKING:
    from sass_tui.model.body.figure import Figure


def register(commands: SubParsers) -> None:
    export = commands.add_parser("export", help="export the figure to another format")
    formats = export.add_subparsers(dest="format", metavar="FORMAT", required=True)
    hanim = formats.add_parser(
        "hanim", help="ISO/IEC 19774 HAnim humanoid, LOA-1, X3D XML encoding"
    )
    hanim.add_argument(
        "-o", "--output", metavar="NAME.x3d", type=file_name, required=True, help="output file"
    )
    add_figure_options(hanim)
    hanim.set_defaults(func=run_hanim)
    gltf = formats.add_parser(
        "gltf",
        help="glTF 2.0 skinned body (.glb; .gltf + .bin), the HAnim joints and sites",
    )
    gltf.add_argument(
        "-o",
        "--output",
        metavar="NAME.glb",
        type=file_name,
        required=True,
        help="output file: NAME.glb (binary) or NAME.gltf (writes NAME.bin beside it)",
    )
    gltf.add_argument(
        "--pose",
        choices=("standing", "seated"),
        default="standing",
        help="standing (the HAnim I pose, default) or seated (hips and knees at 90 degrees)",
    )
    add_figure_options(gltf)
    gltf.set_defaults(func=run_gltf)


def run_hanim(args: argparse.Namespace) -> int:
    # deferred: model.hanim_x3d (xml.etree) — off sass export gltf (sass_tui/startup.py)
    from sass_tui.model.files.hanim_x3d import export_hanim

    figure, warnings = figure_from_args(args)
    print_warnings(warnings)
    path = export_hanim(figure, user_path(args.output))
    print(f"wrote {path}")
    _note(figure)
    return 0


def run_gltf(args: argparse.Namespace) -> int:
    # deferred: model.gltf — off sass export hanim (sass_tui/startup.py)
    from sass_tui.model.files.gltf import check_path, export_gltf

    path = check_path(user_path(args.output))  # refused before the database is opened
    figure, warnings = figure_from_args(args)
    print_warnings(warnings)
    for written in export_gltf(figure, path, args.pose):
        print(f"wrote {written}")
    _note(figure)
    return 0


def _note(figure: Figure) -> None:
    """What of the figure the humanoid (HAnim and glTF alike) leaves out."""
    note = not_in_humanoid_note(figure).strip()
    if note:
        print(f"note: {note.replace(' (Create Figure)', ' (sass fig)')}", file=sys.stderr)
