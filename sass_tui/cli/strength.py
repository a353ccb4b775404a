"""`sass strength` (spec §5): one strength value, stored or predicted.

    sass strength shoulder_abduction shoulder_x=30 shoulder_y=45 elbow_y=90

Angles not given keep the motion's first stored configuration.
"""

from __future__ import annotations

import argparse

from sass_tui.cli.options import SubParsers
from sass_tui.model.vocabulary import (
    GENDERS,
    HANDEDNESS,
    JOINT_AXES,
    MOTION_NAMES,
    SIDES,
    STRENGTH_PARAMETERS,
    STRENGTH_TYPES,
)


def register(commands: SubParsers) -> None:
    parser = commands.add_parser(
        "strength",
        help="print a strength at a joint configuration (stored or predicted)",
        description="Print the strength of MOTION at the given joint angles: the stored "
        "value when the configuration is in the data, else the prediction equation.",
    )
    parser.add_argument("motion", metavar="MOTION", help=", ".join(MOTION_NAMES))
    parser.add_argument(
        "angles",
        nargs="*",
        metavar="JOINT_AXIS=ANGLE",
        help=f"{', '.join(JOINT_AXES)}; e.g. shoulder_x=30 or "
        "'elbow_y=1.5 rad' (deg without a unit)",
    )
    parser.add_argument("--gender", choices=GENDERS, default="male")
    parser.add_argument("--side", choices=SIDES, default="right")
    parser.add_argument("--unit", choices=("ft-lb", "N-m"), default="ft-lb")
    parser.add_argument(
        "--percentile", type=float, default=50.0, help="strength percentile (default 50)"
    )
    parser.add_argument(
        "--joint-limit-percentile",
        type=float,
        default=50.0,
        help="percentile of the joint limits the angles must respect",
    )
    parser.add_argument("--strength-type", choices=STRENGTH_TYPES, default="isometric")
    parser.add_argument("--motion-speed", type=float, default=0.0, help="deg/s")
    parser.add_argument("--handedness", choices=HANDEDNESS, default="right")
    parser.add_argument("--training-level", type=float, default=0.0)
    parser.add_argument(
        "--fatigue-level",
        type=float,
        default=0.0,
        help="seconds a maximal exertion has been held (0 = rested)",
    )
    parser.add_argument(
        "--factor", default="", help="non-dominant limb scaling factor (default 1/1.116)"
    )
    parser.add_argument("--file", metavar="F", help="strength file (default datasets/strength.dat)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from sass_tui.model.figure import Figure
    from sass_tui.model.names import JOINT_LIMITS
    from sass_tui.model.strength import (
        EXTRAPOLATION_MARGIN_DEG,
        StrengthError,
        StrengthSheet,
        motion_index,
        parse_joint_axis,
        parse_side_factor,
        read_strength_file,
    )

    data = read_strength_file(args.file)
    figure = Figure.default(args.gender)
    figure.set_group_percentile(JOINT_LIMITS, args.joint_limit_percentile)
    for name in STRENGTH_PARAMETERS:
        figure.set_strength_parameter(name, getattr(args, name))
    sheet = StrengthSheet(data, figure)
    sheet.side = args.side
    sheet.non_dominant_factor = parse_side_factor(args.factor)
    sheet.set_percentile(args.percentile)
    sheet.set_unit(args.unit)
    index = motion_index(args.motion)
    for item in args.angles:
        axis, sep, value = item.partition("=")
        if not sep or not value.strip():
            raise StrengthError(f"{item!r}: expected JOINT_AXIS=ANGLE, e.g. shoulder_x=30")
        sheet.set_angle(index, parse_joint_axis(axis), value)
    row = sheet.row(index)
    if row.source == "predicted":
        note, refused = data.model(figure.gender, sheet.side).coverage(index, sheet.angles[index])
        if refused:
            raise StrengthError(
                f"{row.label.lower()}: {note}; sass strength refuses a prediction more than "
                f"{EXTRAPOLATION_MARGIN_DEG:g} deg outside the data (docs/model.md, Strength)"
            )
    if row.source == "no data":
        raise StrengthError(f"{data.path}: no {args.gender} data for {row.label.lower()}")
    where = " ".join(f"{axis}={angle:g}" for axis, angle in zip(JOINT_AXES, row.angles))
    how = row.source
    if row.source == "predicted":
        fit = data.model(figure.gender, sheet.side).fits[index]
        assert fit is not None  # a predicted row's motion has data, so a fit
        how += f" by the least-squares equation, fit error {fit.rms_percent:.1f} % RMS"
    if row.extrapolated:
        how += f"; EXTRAPOLATED: {row.extrapolated}"
    print(
        f"{row.side} {row.label.lower()}: {row.value:.2f} {row.unit} ({how}; "
        f"{figure.gender}, {sheet.percentile:g}th percentile) at {where}"
    )
    if data.test_data:
        print(f"note: {data.label}: values made for testing (docs/data-sources.md, Strength)")
    return 0
