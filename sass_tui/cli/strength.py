"""`sass strength` (spec §5): one strength value, stored or predicted, and
the source it comes from.

    sass strength shoulder_abduction shoulder_x=30 shoulder_y=45 elbow_y=90
    sass strength knee_extension knee_y=60 --age 30 --mass 80 --stature 180cm --plot

Arm motions come from the example strength file (invented values, said so
on every answer; angles not given keep the motion's first stored
configuration).  Hip, knee and ankle motions come from Anderson et al. 2007
(docs/strength.md; an angle not given is the motion's peak angle).  Hand
and thumb-finger grip forces come from FAA HFDS 2003 exhibit 14.5.2.1, as
printed (5th percentile men, momentary hold).

    sass strength hand_grip --side left
"""

from __future__ import annotations

import argparse
import json

from sass_tui.cli.common.options import SubParsers, add_db_option, file_name
from sass_tui.model.body.figure import Figure
from sass_tui.model.names import JOINT_LIMITS
from sass_tui.model.strength.published_grip import (
    CITATION as GRIP_CITATION,
)
from sass_tui.model.strength.published_grip import (
    GRIP_DATA_SET,
    GRIP_LABELS,
    GRIP_MOTIONS,
    grip_motion,
    grip_strength,
)
from sass_tui.model.strength.published_strength import (
    AGE_GROUPS,
    CITATION,
    DATA_SET,
    EXAMPLE_DATA_SET,
    GENDER_WORDS,
    LOWER_LIMB_AXES,
    LOWER_LIMB_MOTIONS,
    MOTION_AXIS,
    PublishedStrengthError,
    Subject,
    beyond_curve,
    lower_limb_curve,
    lower_limb_motion,
    lower_limb_percent_capable,
    lower_limb_strength,
    ordinal,
    text_plot,
)
from sass_tui.model.strength.strength import (
    ASSUMED_LABEL,
    ASSUMED_MODIFIERS,
    EXTRAPOLATION_MARGIN_DEG,
    StrengthError,
    StrengthSheet,
    assumed_modifiers_asked,
    check_angle,
    joint_limit_range,
    motion_index,
    parse_joint_axis,
    parse_side_factor,
    read_strength_file,
)
from sass_tui.model.units import DISPLAY, convert, parse_quantity, unit_name
from sass_tui.model.vocabulary import (
    GENDERS,
    HANDEDNESS,
    JOINT_AXES,
    MOTION_NAMES,
    SIDES,
    STRENGTH_PARAMETERS,
    STRENGTH_TYPES,
)

# JSON numbers to the data's precision: Table 3's coefficients carry three
# significant digits (a torque to 0.01 N-m or ft-lb), angles to 0.1 deg, the
# grips' forces are printed to 0.1 N.
TORQUE_DECIMALS = 2
ANGLE_DECIMALS = 1
# The Arm Force Field's motion (cli/strength_arm.py).
ARM_FORCE = "arm_force"
# Joint torques and the grips' forces (HFDS 2003 prints newtons), defaults first.
TORQUE_UNITS = ("ft-lb", "N-m")
FORCE_UNITS = ("N", "lbf")


def register(commands: SubParsers) -> None:
    parser = commands.add_parser(
        "strength",
        help="print a strength at a joint configuration (stored or predicted)",
        description="Print the strength of MOTION at the given joint angles and its source. "
        "Arm motions: the example data (invented), the stored value when the configuration "
        "is in the data, else the prediction equation.  Hip, knee and ankle: Anderson et "
        "al. 2007's published model for the figure's (or --person's) body.  Hand and "
        "thumb-finger grip: the force FAA HFDS 2003 exhibit 14.5.2.1 prints (5th "
        "percentile men, momentary hold) (docs/strength.md).",
    )
    parser.add_argument(
        "motion",
        metavar="MOTION",
        help=", ".join((*MOTION_NAMES, *LOWER_LIMB_MOTIONS, *GRIP_MOTIONS, ARM_FORCE)),
    )
    parser.add_argument(
        "angles",
        nargs="*",
        metavar="JOINT_AXIS=ANGLE",
        help=f"{', '.join((*JOINT_AXES, *LOWER_LIMB_AXES))}; e.g. shoulder_x=30 or "
        "'elbow_y=1.5 rad' (deg without a unit); hip_y, knee_y and ankle_y are degrees "
        "of flexion from standing (hip and knee flexion, ankle dorsiflexion positive); "
        f"for {ARM_FORCE}: the figure's posture, both arms or left_/right_ before the joint",
    )
    parser.add_argument(
        "--posture",
        metavar="FILE.json",
        type=file_name,
        help=f"{ARM_FORCE}: HAnim joint centres in metres (+x left, +y up, +z forward): "
        "l_/r_metacarpophalangeal_3, l_/r_radiocarpal, l_/r_elbow, l_/r_shoulder, vc7, vl5",
    )
    parser.add_argument(
        "--direction",
        metavar="DIRECTION",
        help=f"{ARM_FORCE}: the hand force's direction: up, down, forward, back, left, right "
        "or X,Y,Z on HAnim's axes (a vector with negative parts as --direction=-0.2,-0.3,0.9)",
    )
    parser.add_argument(
        "--load",
        metavar="LOAD",
        help=f"{ARM_FORCE}: a hand force, e.g. 60N or '15 lbf' (N without a unit); hip, knee "
        "and ankle: a torque, e.g. '120 N-m'; prints the percent capable of it",
    )
    parser.add_argument(
        "--capable",
        type=float,
        metavar="PERCENT",
        help=f"{ARM_FORCE}: the force this percent of people can exert (default 75)",
    )
    parser.add_argument(
        "--strength-data",
        choices=(DATA_SET, GRIP_DATA_SET, EXAMPLE_DATA_SET),
        help=f"{DATA_SET}: Anderson et al. 2007 (the default for hip, knee and ankle); "
        f"{GRIP_DATA_SET}: FAA HFDS 2003 exhibit 14.5.2.1 (the default for the grips); "
        f"{EXAMPLE_DATA_SET}: the invented example file (the default for the arm)",
    )
    parser.add_argument(
        "--age",
        type=float,
        help="years, 18-100: picks Anderson et al. 2007's age group (default 18-25)",
    )
    parser.add_argument(
        "--mass", help="body mass, e.g. 80 or '176 lb' (kg if no unit; default the figure's)"
    )
    parser.add_argument(
        "--stature", help="stature, e.g. 175 or '70 in' (cm if no unit; default the figure's)"
    )
    parser.add_argument(
        "--plot",
        action="store_true",
        help="also draw the torque-angle curve over the joint's range (hip, knee, ankle)",
    )
    parser.add_argument(
        "--format", choices=("text", "json"), default="text", help="output format (default text)"
    )
    parser.add_argument(
        "--person",
        metavar="ID",
        help="a person of the database (id or name): hip, knee and ankle strength "
        "predicted from their own gender, age, mass and stature",
    )
    add_db_option(parser)
    parser.add_argument("--gender", choices=GENDERS, help="default male")
    parser.add_argument(
        "--side", choices=SIDES, default="right", help="the body side of the joint (default right)"
    )
    parser.add_argument(
        "--unit",
        choices=(*TORQUE_UNITS, *FORCE_UNITS),
        help="default the source's unit: N-m (Anderson et al. 2007), ft-lb (the example "
        "data), N (the grips, arm_force); else ft-lb or N-m for a torque, N or lbf for a force",
    )
    parser.add_argument(
        "--percentile",
        type=float,
        help="strength percentile (default 50; the grips: the table's, 5)",
    )
    parser.add_argument(
        "--joint-limit-percentile",
        type=float,
        default=50.0,
        help="percentile of the joint limits the angles must respect",
    )
    parser.add_argument(
        "--strength-type",
        choices=STRENGTH_TYPES,
        default="isometric",
        help="the kind of exertion (report section 12.2.1; default isometric)",
    )
    parser.add_argument("--motion-speed", type=float, default=0.0, help="deg/s")
    parser.add_argument(
        "--handedness",
        choices=HANDEDNESS,
        default="right",
        help="the figure's dominant hand (default right)",
    )
    parser.add_argument(
        "--training-level",
        type=float,
        default=0.0,
        help="level of strength training (report section 12.2.1; 0 = none)",
    )
    parser.add_argument(
        "--fatigue-level",
        type=float,
        default=0.0,
        help="seconds a maximal exertion has been held (0 = rested)",
    )
    parser.add_argument(
        "--factor", default="", help="non-dominant limb scaling factor (default 1/1.116)"
    )
    parser.add_argument(
        "--assumed-modifiers",
        action="store_true",
        help="the example data: apply the isokinetic decay (--strength-type, --motion-speed) "
        "and the training gain (--training-level), which have no published source for these "
        "motions (off unless asked for; labelled when on)",
    )
    parser.add_argument(
        "--file", metavar="F", type=file_name, help="strength file (default datasets/strength.dat)"
    )
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if args.motion.strip().lower().replace(" ", "_") == ARM_FORCE:
        # deferred: cli.strength_arm (model.posture, model.hanim) — off sass strength (sass_tui/startup.py)
        from sass_tui.cli.strength_arm import run_arm_force

        return run_arm_force(args)
    for option in ("posture", "direction", "capable"):
        if getattr(args, option) is not None:
            raise StrengthError(f"--{option} is for {ARM_FORCE} (the Arm Force Field)")
    motion = lower_limb_motion(args.motion)
    grip = grip_motion(args.motion)
    if args.strength_data is not None:
        data_set = args.strength_data
    elif grip is not None and args.file is None:
        data_set = GRIP_DATA_SET
    elif motion is not None and args.file is None:
        data_set = DATA_SET
    else:
        data_set = EXAMPLE_DATA_SET
    if data_set != GRIP_DATA_SET and grip is not None:
        raise StrengthError(
            f"{grip}: the {data_set} strength data have no hand or thumb-finger grip; "
            f"--strength-data {GRIP_DATA_SET} (FAA HFDS 2003 exhibit 14.5.2.1) has them"
        )
    if data_set == EXAMPLE_DATA_SET and motion is not None:
        raise StrengthError(
            f"{motion}: the example strength data have no hip, knee or ankle motions; "
            f"--strength-data {DATA_SET} (Anderson et al. 2007) has them"
        )
    units = FORCE_UNITS if data_set == GRIP_DATA_SET else TORQUE_UNITS
    if args.unit is not None and args.unit not in units:
        what = "a grip force" if data_set == GRIP_DATA_SET else "a joint torque"
        raise StrengthError(f"--unit {args.unit}: {what} is given in {' or '.join(units)}")
    # Each answer in its source's unit unless --unit: the example data's (the
    # report's) ft-lb, Anderson et al. 2007's N-m, HFDS 2003's N.
    args.unit = args.unit or {DATA_SET: "N-m", EXAMPLE_DATA_SET: "ft-lb"}.get(data_set, units[0])
    if data_set == GRIP_DATA_SET:
        return _grip(args, grip)
    if args.percentile is None:
        args.percentile = 50.0
    if data_set == EXAMPLE_DATA_SET and args.person is not None:
        # Refused before the database is opened (or built).
        raise StrengthError(
            "--person predicts hip, knee and ankle strength (Anderson et al. 2007); "
            "the example arm data have no model of a person"
        )
    if args.person is not None:
        _take_person(args)
    args.gender = args.gender or "male"
    if data_set == DATA_SET:
        return _published(args, motion)
    return _example(args)


def _take_person(args: argparse.Namespace) -> None:
    """A database person's own gender, age, mass and stature into `args`."""
    given = [
        option
        for option, value in (
            ("--gender", args.gender),
            ("--age", args.age),
            ("--mass", args.mass),
            ("--stature", args.stature),
        )
        if value is not None
    ]
    if given:
        raise PublishedStrengthError(
            f"--person takes the person's own gender, age, mass and stature; "
            f"{', '.join(given)} cannot be given with it"
        )
    # deferred: cli.person_option (the db package, numpy) — off sass strength (sass_tui/startup.py)
    from sass_tui.cli.common.person_option import named_person_record

    record = named_person_record(args)
    missing = [k for k in ("gender", "age", "mass", "stature") if record[k] is None]
    if missing:
        raise PublishedStrengthError(
            f"{record['name']} (id {record['id']}) has no {', '.join(missing)} in the "
            "database; strength cannot be predicted"
        )
    args.gender, args.age = record["gender"], float(record["age"])  # type: ignore[arg-type]
    args.mass, args.stature = f"{record['mass']} kg", f"{record['stature']} cm"
    args.person = f"{record['name']} (id {record['id']})"


def _figure(args: argparse.Namespace):  # -> Figure
    """The figure whose mass, stature and joint limits the answer uses."""
    figure = Figure.default(args.gender)
    figure.set_group_percentile(JOINT_LIMITS, args.joint_limit_percentile)
    if args.mass is not None:
        figure.set_mass(parse_quantity(args.mass, "kg"))
    if args.stature is not None:
        figure.set_stature(parse_quantity(args.stature, "cm"))
    return figure


def _angles(args: argparse.Namespace) -> list[tuple[str, str]]:
    """The JOINT_AXIS=ANGLE words, each axis once (the last was kept silently)."""
    out = []
    given: dict[str, str] = {}
    for item in args.angles:
        axis, sep, value = item.partition("=")
        if not sep or not value.strip():
            raise StrengthError(f"{item!r}: expected JOINT_AXIS=ANGLE, e.g. shoulder_x=30")
        key = axis.strip().lower().replace(".", "_")
        if key in given:
            raise StrengthError(f"{item!r}: {axis.strip()} is given twice (also {given[key]!r})")
        given[key] = item
        out.append((axis, value))
    return out


def _published(args: argparse.Namespace, motion: str | None) -> int:
    """A hip, knee or ankle motion from Anderson et al. 2007."""
    if motion is None:
        raise PublishedStrengthError(
            f"{args.motion.strip()!r}: {CITATION} covers {', '.join(LOWER_LIMB_MOTIONS)}"
        )
    for option, value in (
        ("--training-level", args.training_level),
        ("--fatigue-level", args.fatigue_level),
    ):
        if value:
            raise PublishedStrengthError(
                f"{option}: {CITATION} measured rested, untrained-for-the-test people; "
                "sass applies no training or fatigue to its torques"
            )
    axis = MOTION_AXIS[motion]
    angle: float | None = None
    for given, value in _angles(args):
        key = given.strip().lower().replace(".", "_")
        if key != axis:
            raise PublishedStrengthError(
                f"{given.strip()!r}: {motion} is about {axis} only (degrees of flexion "
                "from standing)"
            )
        angle = parse_quantity(value, "deg")
    figure = _figure(args)
    age = args.age if args.age is not None else AGE_GROUPS[0][1]
    subject = Subject(args.gender, age, figure.mass, figure.stature / 100.0)
    speed = 0.0 if args.strength_type == "isometric" else args.motion_speed
    if angle is None:
        # The motion's peak angle (the paper's C3), within the joint's limits:
        # hip flexion peaks at -11 deg, which the limits' 0 deg stops.
        lower, upper = joint_limit_range(figure, args.side, axis)
        peak = lower_limb_strength(motion, subject, None, 0.0, args.percentile).peak_angle
        angle = min(max(peak, lower), upper)
    answer = lower_limb_strength(motion, subject, angle, speed, args.percentile)
    check_angle(figure, args.side, axis, answer.angle)
    outside = beyond_curve(motion, args.gender, [answer.group], answer.angle)
    load = None if args.load is None else parse_quantity(args.load, "N_m")
    share = (
        None
        if load is None
        else lower_limb_percent_capable(motion, subject, load, answer.angle, speed)
    )
    unit = unit_name(args.unit)
    value = float(convert(answer.torque, "N_m", unit))
    how = "isometric" if speed == 0 else f"{args.strength_type} at {speed:g} deg/s"
    age_note = f"age {args.age:g}" if args.age is not None else "age not given"
    source = answer.source
    if args.person is not None:
        source += f"; predicted for {args.person} from their own gender, age, mass and stature"
    shown: list[tuple[float, float]] = []
    capable: list[tuple[float, float]] = []
    if args.plot:
        lower, upper = joint_limit_range(figure, args.side, axis)
        curve = lower_limb_curve(motion, subject, lower, upper, speed, args.percentile)
        shown = [(x, float(convert(y, "N_m", unit))) for x, y in curve]
        if load is not None:
            # percent capable against the torque, at the angle asked, to the 99.5th percentile
            top = lower_limb_strength(motion, subject, answer.angle, speed, 99.5).torque
            capable = [
                (
                    float(convert(top * i / 60, "N_m", unit)),
                    lower_limb_percent_capable(motion, subject, top * i / 60, answer.angle, speed),
                )
                for i in range(61)
            ]
    if args.format == "json":
        print(
            json.dumps(
                {
                    "motion": motion,
                    "side": args.side,
                    "value": round(value, TORQUE_DECIMALS),
                    "unit": DISPLAY[unit],
                    "angles": {axis: round(answer.angle, ANGLE_DECIMALS)},
                    "strength_type": args.strength_type,
                    "motion_speed": speed,
                    "gender": args.gender,
                    "age_group": answer.group,
                    "mass_kg": round(figure.mass, 1),
                    "stature_m": round(figure.stature / 100.0, 3),
                    "percentile": args.percentile,
                    "peak_angle": round(answer.peak_angle, ANGLE_DECIMALS),
                    "load_N_m": None if load is None else round(load, 2),
                    "capable_curve": [[round(x, TORQUE_DECIMALS), round(y, 1)] for x, y in capable]
                    or None,
                    "percent_capable": None if share is None else round(share, 1),
                    "outside_fitted": outside or None,
                    "source": source,
                    "person": args.person,
                    "predicted": args.person is not None,
                    "curve": [
                        [round(x, ANGLE_DECIMALS), round(y, TORQUE_DECIMALS)] for x, y in shown
                    ]
                    if args.plot
                    else None,
                }
            )
        )
        return 0
    print(
        f"{args.side} {motion.replace('_', ' ')}: {value:.2f} {DISPLAY[unit]} "
        f"({CITATION} model, {how}; {args.gender}, {age_note}: age group {answer.group}, "
        f"{figure.mass:g} kg, {figure.stature / 100.0:g} m, "
        f"{args.percentile:g}th percentile) at {axis}={answer.angle:.4g}"
    )
    if share is not None and load is not None:
        print(
            f"percent capable of {float(convert(load, 'N_m', unit)):.2f} {DISPLAY[unit]} at "
            f"{axis}={answer.angle:.4g}: {share:.1f} % of {GENDER_WORDS[args.gender]} "
            f"{answer.group} (C1's spread, {CITATION} Table 3)"
        )
    print(f"source: {source}")
    if outside:
        print(f"note: {outside}")
    if args.plot:
        lower, upper = shown[0][0], shown[-1][0]
        print(f"{motion.replace('_', ' ')} over {axis} {lower:g} to {upper:g} deg (joint limits):")
        for line in text_plot(shown, DISPLAY[unit], (answer.angle, value)):
            print(line)
    if capable and share is not None and load is not None:
        print(f"percent capable against the torque at {axis}={answer.angle:.4g}:")
        mark = (float(convert(load, "N_m", unit)), share)
        for line in text_plot(capable, "%", mark, what="percent capable", across=DISPLAY[unit]):
            print(line)
    return 0


def _example(args: argparse.Namespace) -> int:
    """An arm motion from the example strength file (or --file)."""
    if args.load is not None:
        raise StrengthError(
            "--load: the example data have no spread of people; percent capable is given "
            "for arm_force and the hip, knee and ankle motions"
        )
    data = read_strength_file(args.file)
    figure = _figure(args)
    for name in STRENGTH_PARAMETERS:
        figure.set_strength_parameter(name, getattr(args, name))
    sheet = StrengthSheet(data, figure)
    if assumed_modifiers_asked(figure) and not args.assumed_modifiers:
        raise StrengthError(
            f"--strength-type {args.strength_type}, --training-level {args.training_level:g}: "
            f"the {ASSUMED_MODIFIERS} have no published source for these motions; "
            "--assumed-modifiers applies sass's assumptions, labelled (docs/model.md)"
        )
    sheet.assumed_modifiers = args.assumed_modifiers
    sheet.side = args.side
    sheet.non_dominant_factor = parse_side_factor(args.factor)
    sheet.set_percentile(args.percentile)
    sheet.set_unit(args.unit)
    index = motion_index(args.motion)
    for axis, value in _angles(args):
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
    if args.plot:
        raise StrengthError(
            "--plot draws the published hip, knee and ankle curves; the example data "
            "have no curve of one angle"
        )
    if args.format == "json":
        print(
            json.dumps(
                {
                    "motion": MOTION_NAMES[index],
                    "side": row.side,
                    "value": round(row.value, TORQUE_DECIMALS),
                    "unit": row.unit,
                    "angles": dict(zip(JOINT_AXES, row.angles)),
                    "how": row.source,
                    "extrapolated": row.extrapolated,
                    "gender": figure.gender,
                    "percentile": sheet.percentile,
                    "assumed_modifiers": ASSUMED_LABEL if sheet.assumed_modifiers else None,
                    "source": data.source,
                }
            )
        )
        return 0
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
    print(f"source: {data.source}")
    if sheet.assumed_modifiers:
        print(f"note: {ASSUMED_LABEL}")
    if data.test_data:
        print(f"note: {data.label}: values made for testing (docs/data-sources.md, Strength)")
    return 0


def _grip(args: argparse.Namespace, motion: str | None) -> int:
    """A hand or thumb-finger grip force from FAA HFDS 2003 exhibit 14.5.2.1."""
    if motion is None:
        raise PublishedStrengthError(
            f"{args.motion.strip()!r}: {GRIP_CITATION} as shipped covers {', '.join(GRIP_MOTIONS)} "
            "(its arm-strength table was not reachable as printed)"
        )
    # What the exhibit does not depend on is refused, not silently ignored.
    given = [
        option
        for option, used in (
            ("JOINT_AXIS=ANGLE", bool(args.angles)),
            ("--person", args.person is not None),
            ("--age", args.age is not None),
            ("--mass", args.mass is not None),
            ("--stature", args.stature is not None),
            ("--plot", args.plot),
            ("--load", args.load is not None),
            ("--file", args.file is not None),
            ("--factor", bool(args.factor)),
            ("--training-level", bool(args.training_level)),
            ("--fatigue-level", bool(args.fatigue_level)),
            ("--handedness left", args.handedness != "right"),
            (f"--strength-type {args.strength_type}", args.strength_type != "isometric"),
            ("--motion-speed", bool(args.motion_speed)),
        )
        if used
    ]
    if given:
        raise PublishedStrengthError(
            f"{', '.join(given)}: {GRIP_CITATION} prints one momentary-hold force per hand for "
            f"{motion}, with no joint angle, body size, age, person, curve, modifier or "
            "dominant hand"
        )
    answer = grip_strength(motion, args.side, args.gender or "male", args.percentile)
    unit = unit_name(args.unit)
    value = float(convert(answer.force, "N", unit))
    printed = f"{answer.force:g} N ({answer.printed_lb:g} lb)"
    # The page prints the thumb-finger grips without left or right.
    what = (
        f"{args.side} {GRIP_LABELS[motion]}"
        if answer.sided
        else (f"{GRIP_LABELS[motion]}, either hand")
    )
    if args.format == "json":
        print(
            json.dumps(
                {
                    "motion": motion,
                    "side": args.side,
                    "sided": answer.sided,
                    "value": round(value, 1),
                    "unit": DISPLAY[unit],
                    "force_N": answer.force,
                    "printed": printed,
                    "column": answer.column,
                    "condition": answer.condition,
                    "gender": answer.gender,
                    "percentile": answer.percentile,
                    "source": answer.source,
                }
            )
        )
        return 0
    print(
        f"{what}: {value:.2f} {DISPLAY[unit]} ({GRIP_CITATION}, {answer.condition}; "
        f"{answer.gender}, {ordinal(answer.percentile)} percentile); as printed {printed}, "
        f"column {answer.column}"
    )
    print(f"source: {answer.source}")
    return 0
