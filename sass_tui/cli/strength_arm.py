"""`sass strength arm_force`: the Arm Force Field (La Delfa & Potvin 2017)
for one hand, one force direction and women or men (docs/strength.md).

    sass strength arm_force shoulder_y=90 elbow_y=0 --side right --direction up --load 60N
    sass strength arm_force --posture reach.json --side left --direction=-0.2,-0.3,0.9
    sass strength arm_force shoulder_y=60 --person "ANSUR II F 10037" --direction forward

Where the hand is: the figure (or --person's) in the posture JOINT=ANGLE
gives (model/body/posture.py, on the figure's own HAnim joint centres), or the
joint centres of a posture file (--posture).  Imported only when the motion
is arm_force (cli/strength.py).
"""

from __future__ import annotations

import argparse
import json

import numpy as np
import numpy.typing as npt

from sass_tui.model.body.figure import Figure
from sass_tui.model.body.posture import parse_angles, pose_figure, read_posture_file
from sass_tui.model.names import JOINT_LIMITS
from sass_tui.model.strength.arm_force_field import (
    ArmForce,
    ArmForceError,
    arm_force,
    check_capable,
    parse_direction,
)
from sass_tui.model.strength.published_strength import text_plot
from sass_tui.model.units import DISPLAY, convert, parse_quantity, unit_name

FORCE_UNITS = ("N", "lbf")
# The data's precision: the authors' bounds are given to 0.1 N; the hand's
# place to the millimetre; shares to 0.1 percentage point.
FORCE_DECIMALS = 1
PERCENT_DECIMALS = 1
PLACE_DECIMALS = 3


def refuse_options(args: argparse.Namespace) -> None:
    """What the Arm Force Field does not depend on is refused, not ignored."""
    given = [
        option
        for option, used in (
            ("--age", args.age is not None),
            ("--file", args.file is not None),
            ("--factor", bool(args.factor)),
            ("--training-level", bool(args.training_level)),
            ("--fatigue-level", bool(args.fatigue_level)),
            (f"--strength-type {args.strength_type}", args.strength_type != "isometric"),
            ("--motion-speed", bool(args.motion_speed)),
            ("--strength-data", args.strength_data is not None),
        )
        if used
    ]
    if given:
        raise ArmForceError(
            f"{', '.join(given)}: the Arm Force Field predicts a static (isometric) "
            "arm strength from the hand's place and the force's direction only"
        )
    if args.direction is None:
        raise ArmForceError(
            "arm_force needs --direction: up, down, forward, back, left, right or X,Y,Z"
        )
    if args.posture is not None and args.angles:
        raise ArmForceError("--posture gives every joint centre; leave out JOINT=ANGLE")
    if args.posture is not None and args.stature is not None:
        raise ArmForceError("--posture gives every joint centre; --stature changes none of them")
    if args.person is not None:
        given = [o for o, v in (("--gender", args.gender), ("--mass", args.mass)) if v]
        given += ["--stature"] if args.stature is not None else []
        if given:
            raise ArmForceError(
                f"--person takes the person's own gender, mass and stature; "
                f"leave out {', '.join(given)}"
            )


def _figure(args: argparse.Namespace) -> Figure:
    figure = Figure.default(args.gender or "male")
    figure.set_group_percentile(JOINT_LIMITS, args.joint_limit_percentile)
    if args.person is not None:
        # deferred: cli.person_option (the db package) — off sass strength arm_force (sass_tui/startup.py)
        from sass_tui.cli.common.person_option import person_figure

        return person_figure(args, figure)
    if args.mass is not None:
        figure.set_mass(parse_quantity(args.mass, "kg"))
    if args.stature is not None:
        figure.set_stature(parse_quantity(args.stature, "cm"))
    return figure


def run_arm_force(args: argparse.Namespace) -> int:
    refuse_options(args)
    direction = parse_direction(args.direction, "--direction")
    unit = unit_name(args.unit or "N")
    if args.unit is not None and args.unit not in FORCE_UNITS:
        raise ArmForceError(f"--unit {args.unit}: an arm force is given in N or lbf")
    capable = 75.0 if args.capable is None else float(args.capable)
    check_capable(capable)
    load = None if args.load is None else parse_quantity(args.load, "N")
    if args.posture is not None:
        points = read_posture_file(args.posture)
        where = f"posture file {args.posture}"
        mass = None if args.mass is None else parse_quantity(args.mass, "kg")
        gender = args.gender or "male"
        if args.person is not None:
            figure = _figure(args)
            mass, gender = figure.output_mass(), figure.gender
    else:
        figure = _figure(args)
        body = pose_figure(figure, parse_angles(args.angles))
        points, mass, gender = body.points, body.body_mass, figure.gender
        named = " ".join(args.angles) or "standing"
        where = f"{figure.person or 'the ' + gender + ' figure'} in posture {named}"
    answer = arm_force(points, args.side, direction, gender, mass)
    if args.person is not None:
        where += f"; {figure.person}'s own gender and body mass"
    strength = answer.strength(capable)
    share = None if load is None else answer.percent_capable(load)
    curve = capable_curve(answer) if args.plot else []
    if args.format == "json":
        print(
            json.dumps(_json(args, answer, direction, capable, load, strength, share, curve, where))
        )
        return 0
    shown = DISPLAY[unit]

    def force(value: float) -> str:
        return f"{float(convert(value, 'N', unit)):.{FORCE_DECIMALS}f} {shown}"

    print(
        f"{args.side} hand, force {args.direction.strip()}: {force(strength)} for "
        f"{capable:g} % capable (mean {force(answer.mean)} at zero gravity, SD {force(answer.sd)}; "
        f"arm's weight {force(answer.gravity)} along the force)"
    )
    if share is not None and load is not None:
        print(f"percent capable of {force(load)}: {share:.{PERCENT_DECIMALS}f} %")
    forward, up, lateral = (round(v, PLACE_DECIMALS) + 0.0 for v in answer.hand)
    print(
        f"hand {forward:.{PLACE_DECIMALS}f} m forward, {up:.{PLACE_DECIMALS}f} m up, "
        f"{lateral:.{PLACE_DECIMALS}f} m lateral of the shoulder ({where})"
    )
    if answer.outside_fitted:
        print(f"note: {answer.outside_fitted}")
    print(f"source: {answer.source}")
    if curve:
        print(f"percent capable against the load ({args.side} hand, {args.direction.strip()}):")
        points_shown = [(float(convert(x, "N", unit)), y) for x, y in curve]
        mark = None
        if share is not None and load is not None:
            mark = (float(convert(load, "N", unit)), share)
        for line in text_plot(points_shown, "%", mark, what="percent capable", across=shown):
            print(line)
    return 0


def capable_curve(answer: ArmForce, points: int = 61) -> list[tuple[float, float]]:
    """(load N, percent capable) from no load to where 0.5 % remain."""
    top = max(answer.strength(0.5), 1.0)
    step = top / (points - 1)
    return [(i * step, answer.percent_capable(i * step)) for i in range(points)]


def _json(
    args: argparse.Namespace,
    answer: ArmForce,
    direction: npt.NDArray[np.float64],
    capable: float,
    load: float | None,
    strength: float,
    share: float | None,
    curve: list[tuple[float, float]],
    where: str,
) -> dict[str, object]:
    def n(value: float) -> float:
        return round(value, FORCE_DECIMALS) + 0.0  # no -0.0

    return {
        "motion": "arm_force",
        "side": args.side,
        "direction": [round(float(v), 4) for v in direction],
        "gender": answer.gender,
        "body_mass_kg": round(answer.body_mass, 1),
        "mean_N": n(answer.mean),
        "sd_N": n(answer.sd),
        "gravity_N": n(answer.gravity),
        "capable": capable,
        "strength_N": n(strength),
        "load_N": None if load is None else n(load),
        "percent_capable": None if share is None else round(share, PERCENT_DECIMALS),
        "hand_m": {
            "forward": round(answer.hand[0], PLACE_DECIMALS) + 0.0,
            "up": round(answer.hand[1], PLACE_DECIMALS) + 0.0,
            "lateral": round(answer.hand[2], PLACE_DECIMALS) + 0.0,
        },
        "posture": where,
        "outside_fitted": answer.outside_fitted or None,
        "person": args.person,
        "curve": [[n(x), round(y, PERCENT_DECIMALS)] for x, y in curve] if curve else None,
        "source": answer.source,
    }
